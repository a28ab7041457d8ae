#include "core/field/field_case.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace foldlab::field {

std::vector<Eigen::Vector2d> support_targets(const Outline& outline) {
  std::vector<Eigen::Vector2d> out;
  for (const Support& s : outline.supports) {
    out.push_back(s.to_mm);
  }
  return out;
}

Solution transferred_start(const Mesh& from, const Solution& solved, const Mesh& to) {
  Solution start;
  start.positions_mm.reserve(to.nodes_mm.size());
  for (const Eigen::Vector2d& p : to.nodes_mm) {
    Eigen::Vector2d q = hung_position(from, solved, p);
    if (!std::isfinite(q.x())) {
      std::size_t nearest = 0;
      for (std::size_t n = 1; n < from.nodes_mm.size(); ++n) {
        if ((from.nodes_mm[n] - p).squaredNorm() < (from.nodes_mm[nearest] - p).squaredNorm()) {
          nearest = n;
        }
      }
      q = p + (solved.positions_mm[nearest] - from.nodes_mm[nearest]);
    }
    start.positions_mm.push_back(q);
  }
  return start;
}

namespace {

// The coarse-to-fine ladder: the cut solved on meshes of half the cells first, each solution the
// next one's start.
// The budget is the whole solve's: each later rung gets what the earlier ones left. Once it is
// spent a rung takes no step and only states the residual where it stands (every solve takes at
// least one step otherwise, so a ladder of rungs each taking one would overrun by all of them).
SolveOptions rest_of(const SolveOptions& options, double spent_ms) {
  SolveOptions rest = options;
  if (options.time_budget_ms > 0.0) {
    rest.time_budget_ms = options.time_budget_ms - spent_ms;
    if (!(rest.time_budget_ms > 0.0)) {
      rest.time_budget_ms = 0.0;
      rest.max_iterations = 0;
    }
  }
  return rest;
}

Solution solve_ladder(Solver& solver, const Outline& outline, const Material& material,
                      const MeshResolution& resolution, const SolveOptions& options) {
  const std::vector<Eigen::Vector2d> targets = support_targets(outline);
  if (resolution.cells_x < 16 || resolution.cells_y < 4) {
    return solver.solve(material, targets, options);
  }
  MeshResolution coarse = resolution;
  coarse.cells_x = resolution.cells_x / 2;
  coarse.cells_y = std::max(2, resolution.cells_y / 2);
  Solver coarse_solver(make_mesh(outline, coarse));
  const Solution coarse_solution = solve_ladder(coarse_solver, outline, material, coarse, options);
  const Solution start = transferred_start(coarse_solver.mesh(), coarse_solution, solver.mesh());
  Solution fine =
      solver.solve(material, targets, rest_of(options, coarse_solution.solve_ms), &start);
  fine.solve_ms += coarse_solution.solve_ms;
  fine.iterations += coarse_solution.iterations;
  return fine;
}

// A stiff cloth's field is that of an almost inextensible one: from the flat start it must swing
// through large rotations, and a Newton step on a membrane whose stretch under its weight is e
// can rotate it by little more than sqrt(e) before its quadratic model fails, so a stiff cloth
// (e of 1e-8) crept for thousands of steps; and every rung's start, carried from a coarser mesh,
// is off by strains far above e. So the ladder is climbed by a cloth of the same weight that
// stretches kSoftStretch under it, and on the finest mesh Y is then raised tenfold at a time,
// each solve from the last field: each step moves the field by about its stretch, which Newton
// settles in a few steps.
constexpr double kStiffStretch = 1e-5;
constexpr double kSoftStretch = 1e-4;

}  // namespace

namespace {

// The stiffening of a cloth solved softened as `soft` into `solution`: Y raised tenfold at a time
// up to the material's, each solve from the last field. Where a rung does not converge (its
// budget spent), the first such rung's stiffness is where a resumed solve goes on.
Solution stiffen(Solver& solver, const Outline& outline, const Material& material, Material soft,
                 Solution solution, const SolveOptions& options) {
  double resume = solution.converged ? 0.0 : soft.stiffness_N_per_mm;
  int iterations = solution.iterations;
  double solve_ms = solution.solve_ms;
  const std::vector<Eigen::Vector2d> targets = support_targets(outline);
  while (soft.stiffness_N_per_mm < material.stiffness_N_per_mm) {
    soft.stiffness_N_per_mm = std::min(material.stiffness_N_per_mm, 10.0 * soft.stiffness_N_per_mm);
    const Solution softer = std::move(solution);
    solution = solver.solve(soft, targets, rest_of(options, solve_ms), &softer);
    iterations += solution.iterations;
    solve_ms += solution.solve_ms;
    if (!solution.converged && resume == 0.0) {
      resume = soft.stiffness_N_per_mm;
    }
  }
  solution.iterations = iterations;
  solution.solve_ms = solve_ms;
  solution.resume_stiffness_N_per_mm =
      solution.converged || resume >= material.stiffness_N_per_mm ? 0.0 : resume;
  return solution;
}

}  // namespace

Solution solve_cold(Solver& solver, const Outline& outline, const Material& material,
                    const MeshResolution& resolution, const SolveOptions& options) {
  const double weight_stress_N_per_mm = material.weight_N_per_mm2 * outline.height_mm();
  const double stretch = weight_stress_N_per_mm / material.stiffness_N_per_mm;
  if (!(stretch > 0.0) || stretch >= kStiffStretch) {
    return solve_ladder(solver, outline, material, resolution, options);
  }
  Material soft = material;
  soft.stiffness_N_per_mm = weight_stress_N_per_mm / kSoftStretch;
  return stiffen(solver, outline, material, soft,
                 solve_ladder(solver, outline, soft, resolution, options), options);
}

Solution resume_cold(Solver& solver, const Outline& outline, const Material& material,
                     const Solution& from, const SolveOptions& options) {
  Material soft = material;
  soft.stiffness_N_per_mm =
      from.resume_stiffness_N_per_mm > 0.0
          ? std::min(from.resume_stiffness_N_per_mm, material.stiffness_N_per_mm)
          : material.stiffness_N_per_mm;
  return stiffen(solver, outline, material, soft,
                 solver.solve(soft, support_targets(outline), options, &from), options);
}

namespace {

double pencil_N(const Material& material, double span_mm, double top_mm, double bottom_mm) {
  if (top_mm > 0.0 && bottom_mm > top_mm) {
    return material.weight_N_per_mm2 * span_mm * span_mm / (std::numbers::pi * std::numbers::pi) *
           std::log(bottom_mm / top_mm);
  }
  return 0.0;
}

SpanReport report_span(const Mesh& mesh, const Solution& solution, const SupportSpan& span,
                       const Material& material) {
  SpanReport r;
  r.left_support = span.left_support;
  r.right_support = span.right_support;
  r.span_mm = span.frame.span_mm();
  double left_N = 0.0;
  double right_N = 0.0;
  for (std::size_t i = 0; i < mesh.support_nodes.size() && i < solution.reactions_N.size(); ++i) {
    const double X = mesh.nodes_mm[mesh.support_nodes[i]].x();
    const double across_N = solution.reactions_N[i].x();
    if (X < span.flat_x_mm) {
      left_N += across_N;
    } else if (X > span.flat_x_mm) {
      right_N += across_N;
    } else {
      left_N += 0.5 * across_N;
      right_N += 0.5 * across_N;
    }
  }
  r.thrust_N = 0.5 * (std::abs(left_N) + std::abs(right_N));
  const CentreLine centre = column_line(mesh, solution, span.flat_x_mm, span.frame);
  if (!centre.depth_mm.empty()) {
    r.centre_top_depth_mm = centre.depth_mm.front();
    r.centre_bottom_depth_mm = centre.depth_mm.back();
    r.pencil_thrust_N =
        pencil_N(material, r.span_mm, r.centre_top_depth_mm, r.centre_bottom_depth_mm);
  }
  return r;
}

}  // namespace

FieldReport report_field(const Solver& solver, Solution solution, const Outline& outline,
                         const Material& material, int ray_count) {
  FieldReport r;
  const std::vector<Eigen::Vector2d> targets = support_targets(outline);
  const std::vector<SupportSpan> spans = top_spans(solver.mesh(), outline);
  r.rays = spans.empty() ? trace_rays(solver.mesh(), solution, targets, ray_count)
                         : trace_span_rays(solver.mesh(), solution, spans, ray_count);
  for (const SupportSpan& span : spans) {
    r.spans.push_back(report_span(solver.mesh(), solution, span, material));
    if (r.widest_span < 0 || r.spans.back().span_mm > r.spans[r.widest_span].span_mm) {
      r.widest_span = static_cast<int>(r.spans.size()) - 1;
    }
  }
  if (targets.size() > 2 && r.widest_span >= 0) {
    const SpanReport& w = r.spans[r.widest_span];
    r.span_mm = w.span_mm;
    r.thrust_N = w.thrust_N;
    r.pencil_thrust_N = w.pencil_thrust_N;
    r.centre_top_depth_mm = w.centre_top_depth_mm;
    r.centre_bottom_depth_mm = w.centre_bottom_depth_mm;
  } else if (targets.size() >= 2) {
    const SupportFrame frame = support_frame(targets);
    r.span_mm = frame.span_mm();
    int left = 0;
    int right = 0;
    for (std::size_t i = 0; i < targets.size(); ++i) {
      if (targets[i].x() < targets[left].x())
        left = static_cast<int>(i);
      if (targets[i].x() > targets[right].x())
        right = static_cast<int>(i);
    }
    r.thrust_N = 0.5 * (std::abs(solution.reactions_N[left].x()) +
                        std::abs(solution.reactions_N[right].x()));
    const CentreLine centre = centre_line(solver.mesh(), solution, targets);
    if (!centre.depth_mm.empty()) {
      r.centre_top_depth_mm = centre.depth_mm.front();
      r.centre_bottom_depth_mm = centre.depth_mm.back();
      r.pencil_thrust_N =
          pencil_N(material, r.span_mm, r.centre_top_depth_mm, r.centre_bottom_depth_mm);
    }
  }
  r.solution = std::move(solution);
  return r;
}

FieldReport solve_outline(const Outline& outline, const Material& material,
                          const MeshResolution& resolution, const SolveOptions& options,
                          int ray_count) {
  Solver solver(make_mesh(outline, resolution));
  Solution solution = solve_cold(solver, outline, material, resolution, options);
  return report_field(solver, std::move(solution), outline, material, ray_count);
}

}  // namespace foldlab::field
