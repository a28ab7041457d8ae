// One hung cloth's tension field from start to end: its cut, mesh, solve, rays and the figures a
// report states (the supports' thrust beside the cosine pencil's).
#pragma once

#include <vector>

#include "core/field/outline.hpp"
#include "core/field/rays.hpp"
#include "core/field/solver.hpp"

namespace foldlab::field {

struct FieldReport {
  Solution solution;
  std::vector<Ray> rays;
  // The thrust H: the mean horizontal reaction of the outermost two supports, N.
  double thrust_N = 0.0;
  // Mansfield's pencil through the outermost supports with the hung depths at the centre line:
  // H = w l² / pi² ln(a_0 / a_n) (0 when the top of the centre line is on the supports' line).
  double pencil_thrust_N = 0.0;
  double span_mm = 0.0;                 // l, between the outermost supports, hung
  double centre_top_depth_mm = 0.0;     // a_n, hung
  double centre_bottom_depth_mm = 0.0;  // a_0, hung
};

inline constexpr int kDefaultRayCount = 8;

std::vector<Eigen::Vector2d> support_targets(const Outline& outline);

// A start for `to` from a field solved on another mesh `from` of the same cut: each node moved
// as the solved field moves its flat point (or the nearest solved node, for a point just outside
// the other mesh's chords).
Solution transferred_start(const Mesh& from, const Solution& solved, const Mesh& to);

// A cold solve by a coarse-to-fine ladder: the cut solved on meshes of half the cells (down to
// about 8 across) first, each solution the next one's start, since the slow part of a cold
// solve (the states settling, about a hundred damped steps) costs least where there are fewest
// nodes. `solver` holds the finest mesh, made with `resolution`. The iteration cap holds on each
// rung, a time budget for the whole ladder.
Solution solve_cold(Solver& solver, const Outline& outline, const Material& material,
                    const MeshResolution& resolution, const SolveOptions& options = {});
// Goes on with a cold solve that its budget stopped while the cloth was softened: from `from`,
// solved at `from.resume_stiffness_N_per_mm`, then stiffened as solve_cold does.
Solution resume_cold(Solver& solver, const Outline& outline, const Material& material,
                     const Solution& from, const SolveOptions& options = {});

// The report of a solved field; `solver` holds the mesh it was solved on.
FieldReport report_field(const Solver& solver, Solution solution, const Outline& outline,
                         const Material& material, int ray_count = kDefaultRayCount);

// Mesh, solve cold and report.
FieldReport solve_outline(const Outline& outline, const Material& material,
                          const MeshResolution& resolution, const SolveOptions& options = {},
                          int ray_count = kDefaultRayCount);

}  // namespace foldlab::field
