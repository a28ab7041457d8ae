// Run time against error: the case set, the long-double references, the method
// variants (with the paper method's trapezoid option), the accuracy and Pareto bookkeeping, the
// CSV and SVG writers, and the parallel grid.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/geometry/parallel_grid.hpp"
#include "core/io/preset.hpp"
#include "core/model/equations.hpp"
#include "core/model/settings.hpp"
#include "core/tools/benchmark_cases.hpp"

namespace foldlab {
namespace {

namespace fs = std::filesystem;

Parameters preset_parameters(const std::string& name) {
  return load_preset(fs::path(FOLDLAB_PRESETS_DIR) / (name + ".json")).parameters;
}

// --- The case set and the references. ---

TEST(BenchmarkCases, FixedSeedGivesTheSameValidCases) {
  const std::vector<BenchmarkCase> a = realistic_cases(50);
  const std::vector<BenchmarkCase> b = realistic_cases(50);
  ASSERT_EQ(a.size(), 50u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].parameters, b[i].parameters);
    EXPECT_TRUE(validate(a[i].parameters).empty());
    const Hanging& g = a[i].parameters.hanging;
    EXPECT_GE(g.support_displacement_mm, 1.0);
    EXPECT_LE(g.support_displacement_mm, 0.3 * g.length_mm);
  }
  EXPECT_NE(realistic_cases(1, 1)[0].parameters, realistic_cases(1, 2)[0].parameters);
}

TEST(Reference, AgreesWithTheExactMethodOnTheTablesAndTheReadme) {
  // docs/calibration.md's comparison table (exact method, defaults): n, z_max to 0.1 mm, Q to
  // 0.001.
  struct Row {
    const char* preset;
    int n;
    double z_max_mm;
    double Q;
  };
  for (const Row& row :
       {Row{"paper-table1-h900", 5, 56.6, 1.317}, Row{"paper-table1-h1400", 8, 43.0, 1.253},
        Row{"paper-table1-h2350", 14, 29.5, 1.180}, Row{"paper-table2-w33", 6, 47.1, 1.435}}) {
    SCOPED_TRACE(row.preset);
    const Parameters p = preset_parameters(row.preset);
    const ReferenceSolution ref = reference_solution(p);
    EXPECT_EQ(ref.n, row.n);
    EXPECT_NEAR(static_cast<double>(ref.z_max_mm), row.z_max_mm, 0.05);
    EXPECT_NEAR(static_cast<double>(ref.Q), row.Q, 0.0005);
    EXPECT_TRUE(ref.n_is_fixed_point);
    // The long-double solution satisfies its own eqs. 8 and 9 to long-double rounding.
    EXPECT_LT(ref.residual_length, 1e-17L);
    EXPECT_LT(ref.residual_height, 1e-17L);
    Parameters exact = p;
    exact.model.method = Method::exact;
    const Solution s = solve(exact);
    EXPECT_NEAR(s.z_max_mm / static_cast<double>(ref.z_max_mm), 1.0, 1e-12);
    EXPECT_NEAR(s.Q / static_cast<double>(ref.Q), 1.0, 1e-13);
  }
}

TEST(Reference, KnownErrorOverTheCaseSet) {
  // The double-precision exact method against the long-double references over 300 cases:
  // measured at most 8.8e-13 (z_max), 8.4e-14 (Q) over 1000 cases; the issue asks for 1e-12.
  const std::vector<BenchmarkCase> cases = realistic_cases(300);
  std::vector<ReferenceSolution> references;
  std::vector<Solution> exact;
  for (const BenchmarkCase& c : cases) {
    references.push_back(reference_solution(c.parameters));
    Parameters p = c.parameters;
    p.model.method = Method::exact;
    exact.push_back(solve(p));
  }
  const ReferenceCheck check = check_references(exact, references);
  EXPECT_GT(check.cases, 250);
  EXPECT_LT(check.max_z_difference, 1e-12);
  EXPECT_LT(check.max_Q_difference, 1e-12);
  EXPECT_LT(check.max_an_difference, 1e-12);
  EXPECT_LT(check.max_reference_residual, 1e-16);
  EXPECT_EQ(check.n_not_fixed_point, 0);
  const MethodAccuracy accuracy = method_accuracy(exact, references);
  EXPECT_EQ(accuracy.n_exact, accuracy.cases);
  EXPECT_EQ(accuracy.max_abs_n_error, 0);
}

// --- The method variants and the bookkeeping. ---

// The variants asked for, written out: the paper method with Simpson's rule and the trapezoid
// rule, each at tolerances of 5 %, 1 % and 0.1 % and N = 4, 8, 16, 20, 32, 64 and 128 intervals,
// then the exact method. Each set of parameters a variant gives is one of these, and each is given
// once.
TEST(BenchmarkMethods, EveryVariantOfTheIssue) {
  std::set<std::tuple<LengthQuadrature, double, int>> wanted;
  for (const LengthQuadrature rule : {LengthQuadrature::simpson, LengthQuadrature::trapezoid}) {
    for (const double tolerance : {0.05, 0.01, 0.001}) {
      for (const int intervals : {4, 8, 16, 20, 32, 64, 128}) {
        wanted.insert({rule, tolerance, intervals});
      }
    }
  }
  ASSERT_EQ(wanted.size(), 42u);
  const std::vector<BenchmarkMethod> methods = benchmark_methods();
  ASSERT_EQ(methods.size(), 43u);
  for (std::size_t i = 0; i + 1 < methods.size(); ++i) {
    const Parameters p = with_method(Parameters{}, methods[i]);
    SCOPED_TRACE(methods[i].name);
    EXPECT_EQ(p.model.method, Method::paper);
    EXPECT_EQ(wanted.erase(
                  {p.model.length_quadrature, p.model.length_tolerance, p.model.simpson_intervals}),
              1u);
    EXPECT_TRUE(validate(p).empty());
  }
  EXPECT_TRUE(wanted.empty()) << wanted.size() << " variants are missing";
  EXPECT_EQ(with_method(Parameters{}, methods.back()).model.method, Method::exact);
  EXPECT_EQ(methods.front().name, "paper simpson N=4 tol=5%");
}

TEST(BenchmarkAccuracy, CountsAndMediansOverCasesWithFolds) {
  auto reference = [](int n, double Q, double z) {
    ReferenceSolution r;
    r.regime = Regime::wrinkled;
    r.n = n;
    r.Q = Q;
    r.z_max_mm = z;
    return r;
  };
  auto solution = [](int n, double Q, double z) {
    Solution s;
    s.n = n;
    s.Q = Q;
    s.z_max_mm = z;
    return s;
  };
  const std::vector<ReferenceSolution> refs = {reference(3, 2.0, 10.0), reference(5, 1.5, 20.0),
                                               reference(0, 1.0, 0.0), reference(7, 1.2, 40.0)};
  const std::vector<Solution> sols = {solution(3, 2.0, 11.0), solution(6, 1.5, 20.0),
                                      solution(0, 1.0, 0.0), solution(4, 1.32, 30.0)};
  const MethodAccuracy a = method_accuracy(sols, refs);
  EXPECT_EQ(a.cases, 3);  // the reference without folds is left out
  EXPECT_EQ(a.n_exact, 1);
  EXPECT_EQ(a.max_abs_n_error, 3);
  EXPECT_NEAR(a.median_z_error, 0.1, 1e-12);  // errors 0.1, 0, 0.25
  EXPECT_NEAR(a.max_z_error, 0.25, 1e-12);
  EXPECT_NEAR(a.max_Q_error, 0.1, 1e-12);
  EXPECT_NEAR(a.median_Q_error, 0.0, 1e-12);
}

BenchmarkRow row(const std::string& name, double ns, double error) {
  BenchmarkRow r;
  r.method.name = name;
  r.timing.median_ns = ns;
  r.accuracy.median_z_error = error;
  return r;
}

TEST(BenchmarkPareto, MarksTheRowsNothingDominates) {
  std::vector<BenchmarkRow> rows = {row("fast rough", 100, 1e-2),  row("slow rough", 300, 1e-2),
                                    row("mid", 200, 1e-5),         row("slow exact", 1000, 1e-15),
                                    row("dominated", 1200, 1e-14), row("tie", 200, 1e-5)};
  mark_pareto_front(rows);
  EXPECT_TRUE(rows[0].pareto);
  EXPECT_FALSE(rows[1].pareto);
  EXPECT_TRUE(rows[2].pareto);
  EXPECT_TRUE(rows[3].pareto);
  EXPECT_FALSE(rows[4].pareto);
  EXPECT_TRUE(rows[5].pareto);  // equal to "mid": neither dominates the other
}

TEST(BenchmarkOutput, CsvHasAHeaderAndOneLinePerMethod) {
  std::vector<BenchmarkRow> rows = {row("paper simpson N=4 tol=5%", 500, 0.5),
                                    row("exact", 900, 3e-15)};
  rows[1].method.method = Method::exact;
  mark_pareto_front(rows);
  const std::string csv = benchmark_csv(rows);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_EQ(csv.rfind("method,kind,quadrature,intervals,tolerance,median_ns", 0), 0u);
  EXPECT_NE(csv.find("\nexact,exact,,0,0,900,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("3.000e-15"), std::string::npos);
}

TEST(BenchmarkOutput, SvgDrawsEveryMethodAndTheFront) {
  std::vector<BenchmarkRow> rows;
  for (const BenchmarkMethod& m : benchmark_methods()) {
    BenchmarkRow r = row(m.name, 500.0 + m.intervals * 40.0, m.tolerance);
    r.method = m;
    rows.push_back(r);
  }
  rows.back().timing.median_ns = 800;
  rows.back().accuracy.median_z_error = 0.0;  // drawn at the chart's floor
  mark_pareto_front(rows);
  const std::string svg = benchmark_svg(rows, "test & <subtitle>");
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("test &amp; &lt;subtitle&gt;"), std::string::npos);
  auto count = [&svg](const std::string& needle) {
    std::size_t n = 0;
    for (std::size_t at = svg.find(needle); at != std::string::npos;
         at = svg.find(needle, at + 1)) {
      ++n;
    }
    return n;
  };
  EXPECT_EQ(count("<title>"), rows.size());
  EXPECT_EQ(count("< "), 0u);  // every '<' in text is escaped, so XML parsers read the file
  EXPECT_EQ(count("<polyline"), 1u);
  EXPECT_EQ(count("stroke-dasharray"), 2u);  // the front and its legend entry
}

// The timer measures the solves it is given. The same paper-method solves of Table 1's
// h = 1400 mm row, with eq. 8 by Simpson on 2 intervals and on 10 000 (the most the input allows:
// 5000 times the quadrature's work, two iterations each), are timed in one run: the second list
// must read many times slower, and what both report cannot add up to more than the run's wall
// clock nor to much less of it, most of which the heavy solves take.
TEST(BenchmarkTiming, MeasuresTheWorkOfTheSolves) {
  Parameters p = preset_parameters("paper-table1-h1400");
  p.model.method = Method::paper;
  p.model.simpson_intervals = 2;
  ASSERT_TRUE(validate(p).empty());
  const std::vector<Parameters> light(20, p);
  p.model.simpson_intervals = 10000;
  ASSERT_TRUE(validate(p).empty());
  ASSERT_EQ(solve(p).iterations, 2);
  const std::vector<Parameters> heavy(20, p);
  constexpr int kRepeats = 3;

  const auto start = std::chrono::steady_clock::now();
  const std::vector<TimingSummary> t = time_methods({light, heavy}, kRepeats);
  const double wall_ns =
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(t.size(), 2u);
  std::printf("light: median %.0f ns, heavy: median %.0f ns; %.0f of %.0f ns of wall clock\n",
              t[0].median_ns, t[1].median_ns, (t[0].mean_ns + t[1].mean_ns) * 20 * kRepeats,
              wall_ns);
  // About 300 times natively; about 10 times under AddressSanitizer, whose fake stacks slow every
  // call of the light solve some 28 times while the heavy one's quadrature loop hardly slows. Five
  // times tells the two lists apart in both.
  EXPECT_GT(t[1].median_ns, 5.0 * t[0].median_ns);
  EXPECT_GT(t[1].p10_ns, t[0].p90_ns);
  const double reported_ns = (t[0].mean_ns + t[1].mean_ns) * 20 * kRepeats;
  EXPECT_LE(reported_ns, wall_ns);
  EXPECT_GE(t[1].mean_ns * 20 * kRepeats, 0.5 * wall_ns);
}

// --- The paper method's quadrature option for eq. 8. ---

TEST(LengthQuadrature, SettingKeyPresetKeyAndValidation) {
  Parameters p;
  EXPECT_EQ(p.model.length_quadrature, LengthQuadrature::simpson);  // the paper's rule by default
  EXPECT_FALSE(apply_setting(p, "length_quadrature", "trapezoid"));
  EXPECT_EQ(p.model.length_quadrature, LengthQuadrature::trapezoid);
  const auto error = apply_setting(p, "length_quadrature", "gauss");
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("simpson, trapezoid"), std::string::npos) << *error;
  EXPECT_EQ(p.model.length_quadrature, LengthQuadrature::trapezoid);

  // Composite Simpson pairs its intervals; the trapezoid rule takes any number.
  p.model.simpson_intervals = 7;
  EXPECT_TRUE(validate(p).empty());
  p.model.length_quadrature = LengthQuadrature::simpson;
  EXPECT_FALSE(validate(p).empty());

  Preset preset = default_preset();
  preset.parameters.model.length_quadrature = LengthQuadrature::trapezoid;
  const nlohmann::json j = preset_to_json(preset);
  EXPECT_EQ(j.at("model").at("length_quadrature"), "trapezoid");
  EXPECT_EQ(preset_from_json(j, "<test>").parameters.model.length_quadrature,
            LengthQuadrature::trapezoid);
  nlohmann::json bad = j;
  bad["model"]["length_quadrature"] = "midpoint";
  try {
    (void)preset_from_json(bad, "bad.json");
    ADD_FAILURE() << "an unknown rule was accepted";
  } catch (const PresetError& e) {
    EXPECT_NE(std::string(e.what()).find("/model/length_quadrature"), std::string::npos);
  }
  nlohmann::json absent = j;
  absent["model"].erase("length_quadrature");
  EXPECT_EQ(preset_from_json(absent, "<test>").parameters.model.length_quadrature,
            LengthQuadrature::simpson);
}

TEST(LengthQuadrature, PaperMethodUsesTheChosenRule) {
  // With 4 intervals the two rules disagree by more than the tolerance on the default preset, so
  // the iteration stops at different places; with 128 both are exact to rounding and agree.
  Parameters p;
  p.model.length_tolerance = 1e-3;
  p.model.simpson_intervals = 128;
  const Solution simpson_fine = solve(p);
  p.model.length_quadrature = LengthQuadrature::trapezoid;
  const Solution trapezoid_fine = solve(p);
  EXPECT_EQ(simpson_fine.n, trapezoid_fine.n);
  EXPECT_NEAR(trapezoid_fine.z_max_mm, simpson_fine.z_max_mm, 1e-9 * simpson_fine.z_max_mm);

  // The loop stops on its own quadrature; the closed form then shows how far eq. 8 really is.
  // With 8 points the trapezoid rule is within 2e-11 of the closed form here (its error falls
  // exponentially), Simpson with 8 intervals 6e-7 off: at equal cost the trapezoid wins.
  p.model.simpson_intervals = 8;
  const Solution trapezoid = solve(p);
  EXPECT_LE(std::abs(trapezoid.residual_length), 1e-3 + 1e-10);
  const double A = trapezoid.sag_amplitude_mm;
  const double l = trapezoid.span_mm;
  const double closed = upper_edge_length_closed_form(A, l);
  EXPECT_LT(std::abs(upper_edge_length_trapezoid(A, l, 8) / closed - 1.0), 1e-10);
  EXPECT_GT(std::abs(upper_edge_length_simpson(A, l, 8) / closed - 1.0), 1e-7);
}

// --- The parallel grid. ---

TEST(DeformedGridParallel, BitForBitTheOneThreadGrid) {
  Parameters p;
  p.model.method = Method::exact;
  Parameters flat = p;
  flat.hanging.support_displacement_mm = 0.0;
  Parameters many = p;
  many.fabric.thickness_mm = 0.02;  // hundreds of folds
  // Grids from 128 x 128 vertices up are split among the threads.
  for (const Parameters* q : {&p, &flat, &many}) {
    const Solution s = solve(*q);
    for (auto [nx, ny] :
         {std::pair{2, 2}, std::pair{64, 64}, std::pair{150, 130}, std::pair{257, 129}}) {
      const DeformedGrid serial = deformed_grid(s, *q, nx, ny);
      for (int threads : {1, 2, 3}) {
        SCOPED_TRACE("n = " + std::to_string(s.n) + ", " + std::to_string(nx) + "x" +
                     std::to_string(ny) + ", " + std::to_string(threads) + " threads");
        const DeformedGrid parallel = deformed_grid_parallel(s, *q, nx, ny, threads);
        EXPECT_EQ(parallel.nx, serial.nx);
        EXPECT_EQ(parallel.ny, serial.ny);
        EXPECT_TRUE(parallel.positions_mm == serial.positions_mm);
        EXPECT_TRUE(parallel.triangle_indices == serial.triangle_indices);
        EXPECT_TRUE(parallel.normals == serial.normals);
        EXPECT_EQ(parallel.worst_fibre_error, serial.worst_fibre_error);
      }
    }
  }
}

TEST(DeformedGridParallel, PipelineTimingReportsEveryStage) {
  Parameters p;
  const Solution s = solve(p);
  const std::vector<PipelineTiming> t = time_pipeline(s, p, {16, 64}, 2, 2);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[1].grid_size, 64);
  for (const PipelineTiming& stage : t) {
    EXPECT_GT(stage.grid_serial_ms, 0.0);
    EXPECT_GT(stage.grid_parallel_ms, 0.0);
    EXPECT_GE(stage.fold_lines_ms, 0.0);
    EXPECT_EQ(stage.threads, 2);
  }
}

}  // namespace
}  // namespace foldlab
