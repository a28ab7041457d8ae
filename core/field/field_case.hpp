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

// The report of a solved field; `solver` holds the mesh it was solved on.
FieldReport report_field(const Solver& solver, Solution solution, const Outline& outline,
                         const Material& material, int ray_count = kDefaultRayCount);

// Mesh, solve cold and report.
FieldReport solve_outline(const Outline& outline, const Material& material,
                          const MeshResolution& resolution, const SolveOptions& options = {},
                          int ray_count = kDefaultRayCount);

}  // namespace foldlab::field
