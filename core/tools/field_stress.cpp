#include "core/tools/field_stress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>

#include <nlohmann/json.hpp>

#include "core/field/field_case.hpp"
#include "core/field/field_folds.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"
#include "core/tools/stress.hpp"

namespace foldlab {
namespace {

using Clock = std::chrono::steady_clock;
using field::OutlineKind;

constexpr OutlineKind kKinds[] = {
    OutlineKind::rectangular, OutlineKind::cosine,  OutlineKind::strip, OutlineKind::inclined,
    OutlineKind::triangle,    OutlineKind::pennant, OutlineKind::wedge};
constexpr int kKindCount = static_cast<int>(std::size(kKinds));
constexpr double kConvergedResidual = 1e-8;  // SolveOptions' relative_tolerance
constexpr double kBalanceTolerance = 1e-6;
constexpr std::size_t kMaxFailuresKept = 20;
constexpr std::size_t kMaxNotConvergedKept = 200;

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

bool finite(const Eigen::Vector2d& v) {
  return v.allFinite();
}

bool all_finite(const field::FieldReport& r) {
  const field::Solution& s = r.solution;
  bool ok = std::isfinite(s.relative_residual) && std::isfinite(s.energy_Nmm) &&
            std::isfinite(s.potential_Nmm) && std::isfinite(s.weight_N) &&
            std::isfinite(s.taut_share) && std::isfinite(s.wrinkled_share) &&
            std::isfinite(s.slack_share) && std::isfinite(s.folded_share) &&
            std::isfinite(s.element_slack_share) && std::isfinite(s.solve_ms);
  for (const Eigen::Vector2d& p : s.positions_mm)
    ok = ok && finite(p);
  for (const Eigen::Vector2d& f : s.reactions_N)
    ok = ok && finite(f);
  for (const field::TriangleResult& t : s.triangles) {
    ok = ok && std::isfinite(t.tension_N_per_mm) && std::isfinite(t.minor_tension_N_per_mm) &&
         finite(t.direction) && finite(t.flat_direction) && std::isfinite(t.slack_strain);
  }
  ok = ok && std::isfinite(r.thrust_N) && std::isfinite(r.pencil_thrust_N) &&
       std::isfinite(r.span_mm) && std::isfinite(r.centre_top_depth_mm) &&
       std::isfinite(r.centre_bottom_depth_mm);
  for (const field::Ray& ray : r.rays) {
    ok = ok && std::isfinite(ray.depth_mm) && std::isfinite(ray.fitted_amplitude_mm) &&
         std::isfinite(ray.fit_rms_mm);
    for (const Eigen::Vector2d& p : ray.points_mm)
      ok = ok && finite(p);
  }
  return ok;
}

bool all_finite(const field::FieldFolds& f) {
  bool ok = std::isfinite(f.Q) && std::isfinite(f.z_max_mm) && std::isfinite(f.slack_width_mm) &&
            std::isfinite(f.kept_length_mm) && std::isfinite(f.count_argument) &&
            std::isfinite(f.mean_ray_tension_N_per_mm) && f.n >= 0;
  for (double a : f.a_mm)
    ok = ok && std::isfinite(a);
  return ok;
}

void add_problem(FieldStressCase& c, const std::string& what) {
  c.problem += (c.problem.empty() ? "" : "; ") + what;
}

template <typename T>
T quantile(std::vector<T> values, double q) {
  if (values.empty()) {
    return T{};
  }
  std::sort(values.begin(), values.end());
  const auto at = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::min(values.size() - 1, at == 0 ? 0 : at - 1)];
}

int group_of(const FieldStressSample& s) {
  const int kind = static_cast<int>(std::find(std::begin(kKinds), std::end(kKinds), s.kind) -
                                    std::begin(kKinds));
  return 2 * kind + (s.resolution.cells_x == kFieldStressLiveCells ? 0 : 1);
}

void count(FieldStressReport& r, const FieldStressCase& c) {
  r.converged += c.converged;
  r.non_finite += c.non_finite;
  r.hangs += c.hung;
  r.false_converged += c.false_converged;
  r.unmarked += c.unmarked;
  r.unbalanced += c.unbalanced;
  r.region_sums += c.region_sum;
  r.folds_non_finite += c.folds_non_finite;
  r.refused += c.refused;
  if (c.converged) {
    r.rays += c.rays;
    r.rays_turning_back += c.rays_turning_back;
    r.rays_turning_back_by_kind[static_cast<std::size_t>(group_of(c.sample) / 2)] +=
        c.rays_turning_back;
    r.worst_balance = std::max(r.worst_balance, c.balance);
    r.worst_converged_recomputed_residual =
        std::max(r.worst_converged_recomputed_residual, c.recomputed_residual);
  }
  FieldStressGroup& g = r.groups[static_cast<std::size_t>(group_of(c.sample))];
  ++g.samples;
  g.converged += c.converged;
  g.iterations.push_back(c.iterations);
  g.solve_ms.push_back(c.solve_ms);
  if (!c.converged && !c.refused && r.not_converged.size() < kMaxNotConvergedKept) {
    r.not_converged.push_back(c);
  }
  if (!c.problem.empty() && r.failures.size() < kMaxFailuresKept) {
    r.failures.push_back(c);
  }
}

FieldStressReport empty_report() {
  FieldStressReport r;
  r.rays_turning_back_by_kind.assign(std::size(kKinds), 0);
  for (OutlineKind k : kKinds) {
    for (int cells : {kFieldStressLiveCells, kFieldStressRefinedCells}) {
      FieldStressGroup g;
      g.kind = k;
      g.cells_x = cells;
      r.groups.push_back(g);
    }
  }
  return r;
}

// The inputs a sample draws and the cut's own (k, incline), so that a case can be read off.
std::string describe_inputs(const FieldStressSample& s) {
  std::string out;
  for (const InputSpec& spec : input_table()) {
    const bool own = (s.kind == OutlineKind::strip && spec.key == "supports") ||
                     (s.kind == OutlineKind::inclined && spec.key == "incline_deg");
    if (spec.sampled || own) {
      out += (out.empty() ? "" : ", ") + std::string(spec.key) + " = " +
             detail::shortest_number(*spec.value(s.parameters)) +
             (spec.unit.empty() ? "" : " " + std::string(spec.unit));
    }
  }
  return out;
}

nlohmann::json inputs_json(const FieldStressSample& s) {
  nlohmann::json out = nlohmann::json::object();
  for (const InputSpec& spec : input_table()) {
    const bool own = (s.kind == OutlineKind::strip && spec.key == "supports") ||
                     (s.kind == OutlineKind::inclined && spec.key == "incline_deg");
    if (spec.sampled || own) {
      out[std::string(spec.key)] = *spec.value(s.parameters);
    }
  }
  return out;
}

nlohmann::json case_json(const FieldStressCase& c) {
  return {{"index", c.sample.index},
          {"outline", to_string(c.sample.kind)},
          {"cells_x", c.sample.resolution.cells_x},
          {"cells_y", c.sample.resolution.cells_y},
          {"nodes", c.nodes},
          {"converged", c.converged},
          {"relative_residual", c.relative_residual},
          {"recomputed_residual", c.recomputed_residual},
          {"iterations", c.iterations},
          {"solve_ms", c.solve_ms},
          {"wall_ms", c.wall_ms},
          {"problem", c.problem},
          {"inputs", inputs_json(c.sample)}};
}

}  // namespace

int field_view_rows(const field::Outline& outline, int cells_x) {
  const double width = std::max(1e-9, outline.right_mm() - outline.left_mm());
  return std::clamp(static_cast<int>(std::lround(cells_x * outline.height_mm() / width)), 4,
                    2 * cells_x);
}

FieldStressSample field_stress_sample(std::uint64_t seed, int index) {
  FieldStressSample s;
  s.index = index;
  s.parameters = stress_sample(seed, index);
  s.kind = kKinds[index % kKindCount];
  // The cut's own inputs from a generator of their own, so that the closed form's draw stays
  // what stress_sample gives.
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(index), 1u};
  std::mt19937_64 random(sequence);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const InputSpec& supports = *find_input("supports");
  const InputSpec& incline = *find_input("incline_deg");
  const double k = std::floor(supports.typical_lo +
                              unit(random) * (supports.typical_hi - supports.typical_lo + 1.0));
  supports.access.set(s.parameters, std::min(k, supports.typical_hi));
  incline.access.set(s.parameters,
                     incline.typical_lo + unit(random) * (incline.typical_hi - incline.typical_lo));
  const bool refined = (index / kKindCount) % 2 == 1;
  s.resolution.cells_x = refined ? kFieldStressRefinedCells : kFieldStressLiveCells;
  s.resolution.split = field::MeshSplit::union_jack;
  try {
    s.resolution.cells_y =
        field_view_rows(field::make_outline(s.parameters, s.kind), s.resolution.cells_x);
  } catch (const field::OutlineError&) {
    s.resolution.cells_y = s.resolution.cells_x;  // refused again, and counted, when solved
  }
  return s;
}

FieldStressCase run_field_stress_sample(const FieldStressSample& sample,
                                        const FieldStressOptions& options) {
  FieldStressCase c;
  c.sample = sample;
  const Clock::time_point began = Clock::now();
  try {
    const field::Outline outline = field::make_outline(sample.parameters, sample.kind);
    const field::Material material = field::material_of(sample.parameters.fabric);
    field::Solver solver(field::make_mesh(outline, sample.resolution));
    c.nodes = static_cast<int>(solver.mesh().nodes_mm.size());
    field::SolveOptions solve_options;
    solve_options.max_iterations = options.max_iterations;
    solve_options.time_budget_ms = 1e3 * options.time_budget_s;
    field::Solution solution =
        field::solve_cold(solver, outline, material, sample.resolution, solve_options);
    const double solve_wall_ms = ms_since(began);
    const std::vector<Eigen::Vector2d> targets = field::support_targets(outline);
    const field::FieldReport report =
        field::report_field(solver, std::move(solution), outline, material);
    const field::FieldFolds folds =
        field::field_folds(solver.mesh(), report.solution, targets, sample.parameters);
    c.wall_ms = ms_since(began);
    const field::Solution& s = report.solution;
    c.converged = s.converged;
    c.relative_residual = s.relative_residual;
    c.iterations = s.iterations;
    c.solve_ms = s.solve_ms;
    // The residual again from the returned positions alone, by a solver that has seen nothing of
    // this solve: no step taken, so it is the imbalance of exactly what was returned.
    field::Solver fresh(field::make_mesh(outline, sample.resolution));
    field::SolveOptions look;
    look.max_iterations = 0;
    c.recomputed_residual = fresh.solve(material, targets, look, &s).relative_residual;

    c.non_finite = !all_finite(report) || !std::isfinite(c.recomputed_residual);
    if (c.non_finite) {
      add_problem(c, "NaN or inf in the field");
    }
    const double hang_ms = 1e3 * (options.time_budget_s + options.hang_margin_s);
    c.hung = options.time_budget_s > 0.0 && solve_wall_ms > hang_ms;
    if (c.hung) {
      add_problem(c,
                  detail::printf_string("the solve took %.0f ms, over its budget", solve_wall_ms));
    }
    if (s.converged && !(s.relative_residual <= kConvergedResidual &&
                         c.recomputed_residual <= kConvergedResidual)) {
      c.false_converged = true;
      add_problem(c, detail::printf_string("said converged at a residual of %.3g (recomputed %.3g)",
                                           s.relative_residual, c.recomputed_residual));
    }
    if (!s.converged && !(s.relative_residual > kConvergedResidual)) {
      c.unmarked = true;
      add_problem(c, detail::printf_string("said not converged at a residual of %.3g",
                                           s.relative_residual));
    }
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& f : s.reactions_N) {
      sum += f;
    }
    // The reactions are the forces on the cloth (y down): they hold up its weight.
    c.balance = std::max(std::abs(sum.x()), std::abs(sum.y() + s.weight_N)) / s.weight_N;
    if (s.converged && !(c.balance <= kBalanceTolerance)) {
      c.unbalanced = true;
      add_problem(c, detail::printf_string(
                         "converged, yet the reactions (%.6g, %.6g) N miss the weight %.6g N by "
                         "%.3g of it",
                         sum.x(), sum.y(), s.weight_N, c.balance));
    }
    const double shares = s.taut_share + s.wrinkled_share + s.slack_share;
    if (!(std::abs(shares - 1.0) <= 1e-12)) {
      c.region_sum = true;
      add_problem(c, detail::printf_string("region shares sum to %.17g", shares));
    }
    for (const field::Ray& ray : report.rays) {
      ++c.rays;
      for (std::size_t i = 2; i < ray.points_mm.size(); ++i) {
        const Eigen::Vector2d a = ray.points_mm[i - 1] - ray.points_mm[i - 2];
        const Eigen::Vector2d b = ray.points_mm[i] - ray.points_mm[i - 1];
        if (a.dot(b) < 0.0) {
          ++c.rays_turning_back;
          break;
        }
      }
    }
    c.folds_non_finite = !all_finite(folds);
    if (c.folds_non_finite) {
      add_problem(c, "NaN or inf in the folds read from the field");
    }
  } catch (const field::OutlineError& e) {
    c.refused = true;
    c.wall_ms = ms_since(began);
    add_problem(c, std::string("refused: ") + e.what());
  }
  return c;
}

FieldStressReport run_field_stress(const FieldStressOptions& options) {
  const Clock::time_point began = Clock::now();
  const int samples = std::max(0, options.samples);
  int threads = options.threads > 0
                    ? options.threads
                    : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::max(1, std::min(threads, samples));
  // Every thread takes every threads-th sample, so that each gets every outline and mesh alike.
  std::vector<std::vector<FieldStressCase>> parts(static_cast<std::size_t>(threads));
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) {
    workers.emplace_back([&options, &parts, t, threads, samples] {
      for (int i = t; i < samples; i += threads) {
        parts[static_cast<std::size_t>(t)].push_back(run_field_stress_sample(
            field_stress_sample(options.seed, options.first_index + i), options));
      }
    });
  }
  for (std::thread& w : workers) {
    w.join();
  }
  std::vector<FieldStressCase> cases;
  for (auto& part : parts) {
    std::move(part.begin(), part.end(), std::back_inserter(cases));
  }
  std::sort(cases.begin(), cases.end(), [](const FieldStressCase& a, const FieldStressCase& b) {
    return a.sample.index < b.sample.index;
  });
  FieldStressReport r = empty_report();
  for (const FieldStressCase& c : cases) {
    count(r, c);
  }
  r.samples = samples;
  r.seed = options.seed;
  r.first_index = options.first_index;
  r.threads = threads;
  r.max_iterations = options.max_iterations;
  r.time_budget_s = options.time_budget_s;
  r.hang_seconds = options.time_budget_s + options.hang_margin_s;
  r.wall_seconds = ms_since(began) / 1e3;
  return r;
}

nlohmann::json field_stress_to_json(const FieldStressReport& r) {
  nlohmann::json groups = nlohmann::json::array();
  for (const FieldStressGroup& g : r.groups) {
    if (g.samples == 0) {
      continue;
    }
    groups.push_back({{"outline", to_string(g.kind)},
                      {"cells_x", g.cells_x},
                      {"samples", g.samples},
                      {"converged", g.converged},
                      {"iterations",
                       {{"median", quantile(g.iterations, 0.5)},
                        {"p95", quantile(g.iterations, 0.95)},
                        {"max", quantile(g.iterations, 1.0)}}},
                      {"solve_ms",
                       {{"median", quantile(g.solve_ms, 0.5)},
                        {"p95", quantile(g.solve_ms, 0.95)},
                        {"max", quantile(g.solve_ms, 1.0)}}}});
  }
  nlohmann::json not_converged = nlohmann::json::array();
  for (const FieldStressCase& c : r.not_converged) {
    not_converged.push_back(case_json(c));
  }
  nlohmann::json turning = nlohmann::json::object();
  for (std::size_t k = 0; k < r.rays_turning_back_by_kind.size(); ++k) {
    turning[std::string(to_string(kKinds[k]))] = r.rays_turning_back_by_kind[k];
  }
  nlohmann::json failures = nlohmann::json::array();
  for (const FieldStressCase& c : r.failures) {
    failures.push_back(case_json(c));
  }
  return {{"solver", "field"},
          {"samples", r.samples},
          {"seed", r.seed},
          {"first_index", r.first_index},
          {"threads", r.threads},
          {"wall_seconds", r.wall_seconds},
          {"budget",
           {{"max_iterations_per_rung", r.max_iterations},
            {"time_s", r.time_budget_s},
            {"hang_s", r.hang_seconds}}},
          {"passed", r.passed()},
          {"converged", r.converged},
          {"non_finite", r.non_finite},
          {"hangs", r.hangs},
          {"false_converged", r.false_converged},
          {"unmarked", r.unmarked},
          {"unbalanced", r.unbalanced},
          {"region_sums", r.region_sums},
          {"folds_non_finite", r.folds_non_finite},
          {"refused", r.refused},
          {"worst_balance", r.worst_balance},
          {"rays", r.rays},
          {"rays_turning_back", r.rays_turning_back},
          {"rays_turning_back_by_outline", turning},
          {"worst_converged_recomputed_residual", r.worst_converged_recomputed_residual},
          {"groups", groups},
          {"not_converged", not_converged},
          {"failures", failures}};
}

std::string field_stress_table(const FieldStressReport& r) {
  std::string out = detail::printf_string(
      "FoldLab field stress test: %d samples from index %d (7 outlines x the live %d- and refined "
      "%d-cell meshes), seed %llu, %d threads, %.1f s\n",
      r.samples, r.first_index, kFieldStressLiveCells, kFieldStressRefinedCells,
      static_cast<unsigned long long>(r.seed), r.threads, r.wall_seconds);
  out += detail::printf_string(
      "budget per cold solve: %d Newton steps a rung, %.3g s in all (a hang: over %.3g s)\n\n",
      r.max_iterations, r.time_budget_s, r.hang_seconds);
  out += detail::printf_string("%-12s %5s %7s %9s  %-20s %-24s\n", "outline", "cells", "samples",
                               "converged", "steps med/p95/max", "solve ms med/p95/max");
  for (const FieldStressGroup& g : r.groups) {
    if (g.samples == 0) {
      continue;
    }
    const std::string steps =
        detail::printf_string("%d/%d/%d", quantile(g.iterations, 0.5), quantile(g.iterations, 0.95),
                              quantile(g.iterations, 1.0));
    const std::string ms =
        detail::printf_string("%.3g/%.3g/%.3g", quantile(g.solve_ms, 0.5),
                              quantile(g.solve_ms, 0.95), quantile(g.solve_ms, 1.0));
    out += detail::printf_string("%-12s %5d %7d %9d  %-20s %-24s\n",
                                 std::string(to_string(g.kind)).c_str(), g.cells_x, g.samples,
                                 g.converged, steps.c_str(), ms.c_str());
  }
  out += detail::printf_string("%-12s %5s %7d %9d  (%.1f %%)\n\n", "all", "", r.samples,
                               r.converged, r.samples > 0 ? 100.0 * r.converged / r.samples : 0.0);
  auto row = [&out](const char* label, int value) {
    out += detail::printf_string("%-44s %6d\n", label, value);
  };
  row("NaN or inf in any output", r.non_finite);
  row("hangs (over the time budget)", r.hangs);
  row("said converged above a residual of 1e-8", r.false_converged);
  row("not converged, not said so", r.unmarked);
  row("converged, reactions off the weight > 1e-6", r.unbalanced);
  row("region shares not summing to 1", r.region_sums);
  row("NaN or inf in the folds from the field", r.folds_non_finite);
  row("outline or mesh refused", r.refused);
  out += detail::printf_string(
      "worst over converged: reactions off the weight by %.2g of it, recomputed residual %.2g\n",
      r.worst_balance, r.worst_converged_recomputed_residual);
  std::string by_kind;
  for (std::size_t k = 0; k < r.rays_turning_back_by_kind.size(); ++k) {
    if (r.rays_turning_back_by_kind[k] > 0) {
      by_kind += detail::printf_string("%s%s %d", by_kind.empty() ? "" : ", ",
                                       std::string(to_string(kKinds[k])).c_str(),
                                       r.rays_turning_back_by_kind[k]);
    }
  }
  out += detail::printf_string(
      "rays traced on converged fields: %d, turning back on themselves: %d%s%s%s\n", r.rays,
      r.rays_turning_back, by_kind.empty() ? "" : " (", by_kind.c_str(),
      by_kind.empty() ? "" : ")");
  if (!r.not_converged.empty()) {
    out += detail::printf_string(
        "\nnot converged (%zu; one again: foldlab stress --solver field --seed %llu --index I):\n",
        r.not_converged.size(), static_cast<unsigned long long>(r.seed));
    for (const FieldStressCase& c : r.not_converged) {
      out += detail::printf_string(
          "  I = %d, %s %d x %d cells: residual %.2g after %d steps, %.0f ms; %s\n", c.sample.index,
          std::string(to_string(c.sample.kind)).c_str(), c.sample.resolution.cells_x,
          c.sample.resolution.cells_y, c.relative_residual, c.iterations, c.solve_ms,
          describe_inputs(c.sample).c_str());
    }
  }
  for (const FieldStressCase& c : r.failures) {
    out += detail::printf_string("FAILED: I = %d, %s %d x %d cells: %s; %s\n", c.sample.index,
                                 std::string(to_string(c.sample.kind)).c_str(),
                                 c.sample.resolution.cells_x, c.sample.resolution.cells_y,
                                 c.problem.c_str(), describe_inputs(c.sample).c_str());
  }
  out += r.passed() ? "\nPASSED: no NaN, no inf, no hang, no false \"converged\", statics held\n"
                    : "\nFAILED\n";
  return out;
}

}  // namespace foldlab
