// The tension field's stress test: `foldlab stress --solver field` run as a user runs it, and the
// samples it draws solved again here, their statics checked against each cut's weight by hand
// (w times the area from the outline's own formula, not the solver's sum over its triangles).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/field/field_case.hpp"
#include "core/tools/field_stress.hpp"
#include "core/tools/stress.hpp"
#include "process.hpp"
#include "temp_dir.hpp"

namespace foldlab {
namespace {

using field::OutlineKind;

// The flat area of each cut by its formula (docs/field.md, The outlines).
double area_by_hand(const Parameters& p, OutlineKind kind) {
  const double h = p.hanging.height_mm;
  const double L = p.hanging.length_mm;
  switch (kind) {
    case OutlineKind::rectangular:
    case OutlineKind::inclined:  // a parallelogram of base L and height h
      return L * h;
    case OutlineKind::strip:
      return (p.shape.supports - 1) * L * h;
    case OutlineKind::cosine:  // (a_0 - a_n) times the integral of cos(pi X / L) over L
      return 2.0 * L * h / std::numbers::pi;
    case OutlineKind::triangle:
    case OutlineKind::pennant:
      return 0.5 * L * h;
    case OutlineKind::wedge:  // a trapezoid: h deep at the left, h / 4 at the right
      return 0.5 * L * (h + 0.25 * h);
  }
  return 0.0;
}

// The mesh follows the cosine's edges by chords between its columns: the trapezoid rule on
// cos over [-pi/2, pi/2] with n equal steps falls short by about (pi / n)² / 12 of the area.
double area_tolerance(OutlineKind kind, int cells_x) {
  if (kind != OutlineKind::cosine) {
    return 1e-9;
  }
  const double step = std::numbers::pi / cells_x;
  return 1.2 * step * step / 12.0;
}

class FieldStressRun : public testing::TempDirTest {
 protected:
  FieldStressRun() : TempDirTest("foldlab_field_stress_") {}
};

// A solve past its budget by more than this is a hang. The budget is checked between Newton
// steps: the margin is the longest a step may take, a few milliseconds natively; a sanitized
// build is several times slower, and on a loaded machine one of its steps took a second.
#if defined(__SANITIZE_ADDRESS__)
constexpr const char* kHangMarginS = "10";
#else
constexpr const char* kHangMarginS = "1";
#endif

// 42 samples: every outline three times on each mesh. About 20 s on two loaded cores.
TEST_F(FieldStressRun, EveryOutlineOnBothMeshesNoNaNNoHangNoFalseConvergence) {
  const testing::RunResult r = testing::run_process(
      FOLDLAB_EXECUTABLE,
      {"stress", "--solver", "field", "--samples", "42", "--hang-margin", kHangMarginS, "--json"},
      dir_);
  ASSERT_EQ(r.exit_status, 0) << r.err << r.out.substr(0, 4000);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("solver"), "field");
  EXPECT_EQ(j.at("samples"), 42);
  EXPECT_TRUE(j.at("passed").get<bool>());
  for (const char* count : {"non_finite", "hangs", "false_converged", "unmarked", "unbalanced",
                            "region_sums", "folds_non_finite", "refused"}) {
    EXPECT_EQ(j.at(count), 0) << count;
  }
  EXPECT_LE(j.at("worst_balance").get<double>(), 1e-6);
  EXPECT_EQ(j.at("budget").at("hang_s").get<double>(), 10.0 + std::stod(kHangMarginS));
  EXPECT_LE(j.at("worst_converged_recomputed_residual").get<double>(), 1e-8);
  std::set<std::pair<std::string, int>> groups;
  int samples = 0;
  int converged = 0;
  for (const nlohmann::json& g : j.at("groups")) {
    groups.insert({g.at("outline").get<std::string>(), g.at("cells_x").get<int>()});
    samples += g.at("samples").get<int>();
    converged += g.at("converged").get<int>();
    EXPECT_EQ(g.at("samples"), 3) << g.dump();
    EXPECT_LE(g.at("iterations").at("median").get<int>(), g.at("iterations").at("max").get<int>());
  }
  EXPECT_EQ(groups.size(), 14u);  // 7 outlines x 2 meshes
  EXPECT_EQ(samples, 42);
  EXPECT_EQ(converged, j.at("converged").get<int>());
  // What did not converge says so, with a residual above the tolerance, and can be run again.
  EXPECT_EQ(j.at("not_converged").size(), static_cast<std::size_t>(42 - converged));
  for (const nlohmann::json& c : j.at("not_converged")) {
    EXPECT_FALSE(c.at("converged").get<bool>());
    EXPECT_GT(c.at("relative_residual").get<double>(), 1e-8);
    EXPECT_GE(c.at("index").get<int>(), 0);
  }
}

TEST_F(FieldStressRun, OneSampleRunsAgainByItsIndex) {
  const testing::RunResult r = testing::run_process(
      FOLDLAB_EXECUTABLE, {"stress", "--solver", "field", "--index", "9", "--json"}, dir_);
  ASSERT_EQ(r.exit_status, 0) << r.err << r.out.substr(0, 2000);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("samples"), 1);
  EXPECT_EQ(j.at("first_index"), 9);
  ASSERT_EQ(j.at("groups").size(), 1u);
  // Index 9: the third outline (strip) on the refined mesh (the second seven of fourteen).
  EXPECT_EQ(j.at("groups")[0].at("outline"), "strip");
  EXPECT_EQ(j.at("groups")[0].at("cells_x"), kFieldStressRefinedCells);
}

TEST_F(FieldStressRun, TooManySamplesAreRefused) {
  const testing::RunResult r = testing::run_process(
      FOLDLAB_EXECUTABLE, {"stress", "--solver", "field", "--samples", "10001"}, dir_);
  EXPECT_EQ(r.exit_status, 2) << r.out;
  EXPECT_NE(r.err.find("--samples"), std::string::npos) << r.err;
}

TEST(FieldStress, SamplesCoverEveryOutlineOnBothMeshesReproducibly) {
  std::set<std::pair<OutlineKind, int>> seen;
  for (int i = 0; i < 14; ++i) {
    const FieldStressSample a = field_stress_sample(5, i);
    const FieldStressSample b = field_stress_sample(5, i);
    EXPECT_EQ(a.parameters, b.parameters);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.resolution, b.resolution);
    seen.insert({a.kind, a.resolution.cells_x});
    EXPECT_GE(a.parameters.shape.supports, 2);
    EXPECT_LE(a.parameters.shape.supports, 8);
    EXPECT_GE(a.parameters.shape.incline_deg, -45.0);
    EXPECT_LE(a.parameters.shape.incline_deg, 45.0);
    EXPECT_GE(a.resolution.cells_y, 4);
    EXPECT_LE(a.resolution.cells_y, 2 * a.resolution.cells_x);
    // The closed form's draw, unchanged.
    Parameters closed = stress_sample(5, i);
    closed.shape = a.parameters.shape;
    EXPECT_EQ(a.parameters, closed);
  }
  EXPECT_EQ(seen.size(), 14u);
}

// Each sample solved again here: when it converged, the reactions hold up w times the cut's area
// by its formula (the cosine's chords aside) and sum to nothing across.
TEST(FieldStress, ConvergedSamplesCarryTheWeightOfTheCutByHand) {
  int converged = 0;
  for (int i = 0; i < 28; ++i) {
    const FieldStressSample s = field_stress_sample(3, i);
    SCOPED_TRACE("sample " + std::to_string(i) + ", " + std::string(to_string(s.kind)));
    const field::Outline outline = field::make_outline(s.parameters, s.kind);
    const field::Material material = field::material_of(s.parameters.fabric);
    field::SolveOptions options;
    options.time_budget_ms = 10e3;
    const field::FieldReport r = field::solve_outline(outline, material, s.resolution, options, 0);
    if (!r.solution.converged) {
      EXPECT_GT(r.solution.relative_residual, 1e-8);
      continue;
    }
    ++converged;
    const double weight = s.parameters.fabric.weight_N_per_mm2 * area_by_hand(s.parameters, s.kind);
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& f : r.solution.reactions_N) {
      sum += f;
    }
    const double tolerance = area_tolerance(s.kind, s.resolution.cells_x);
    EXPECT_NEAR(-sum.y(), weight, (tolerance + 1e-6) * weight);
    EXPECT_NEAR(sum.x(), 0.0, 1e-6 * weight);
    EXPECT_NEAR(r.solution.taut_share + r.solution.wrinkled_share + r.solution.slack_share, 1.0,
                1e-12);
  }
  EXPECT_GT(converged, 20);
}

// A budget too small to converge in: every sample says it did not, with its residual, and the
// run passes (not converging is reported, never an error).
TEST(FieldStress, ABudgetTooSmallIsReportedNotConverged) {
  FieldStressOptions o;
  o.samples = 14;
  o.threads = 2;
  o.max_iterations = 2;
  const FieldStressReport r = run_field_stress(o);
  EXPECT_TRUE(r.passed());
  EXPECT_EQ(r.converged, 0);
  EXPECT_EQ(r.not_converged.size(), 14u);
  for (const FieldStressCase& c : r.not_converged) {
    EXPECT_FALSE(c.converged);
    EXPECT_GT(c.relative_residual, 1e-8);
    EXPECT_NEAR(c.recomputed_residual, c.relative_residual, 1e-9 * c.relative_residual);
    // Two steps a solve at most: 16 cells solve on two rungs (16, 8), 32 on three, and a stiff
    // cloth (stretch under its weight below 1e-5) climbs them as one that stretches 1e-4 and is
    // then stiffened tenfold a solve (docs/field.md, The first step).
    const field::Outline outline = field::make_outline(c.sample.parameters, c.sample.kind);
    double top = outline.top_mm.front().y();
    double bottom = outline.bottom_mm.front().y();
    for (const Eigen::Vector2d& v : outline.top_mm)
      top = std::min(top, v.y());
    for (const Eigen::Vector2d& v : outline.bottom_mm)
      bottom = std::max(bottom, v.y());
    const Fabric& f = c.sample.parameters.fabric;
    const double stretch =
        f.weight_N_per_mm2 * (bottom - top) / (f.youngs_modulus_MPa * f.thickness_mm);
    const int stiffenings =
        stretch < 1e-5 ? static_cast<int>(std::ceil(std::log10(1e-4 / stretch))) : 0;
    const int rungs = c.sample.resolution.cells_x == kFieldStressLiveCells ? 2 : 3;
    EXPECT_LE(c.iterations, 2 * (rungs + stiffenings)) << stretch;
  }
  const std::string table = field_stress_table(r);
  EXPECT_NE(table.find("not converged (14;"), std::string::npos) << table;
  EXPECT_NE(table.find("PASSED"), std::string::npos) << table;
}

}  // namespace
}  // namespace foldlab
