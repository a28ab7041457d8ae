// One hung cloth's tension field from start to end: its cut, mesh, solve, rays and the figures a
// report states (the supports' thrust beside the cosine pencil's).
#pragma once

#include <vector>

#include "core/field/outline.hpp"
#include "core/field/rays.hpp"
#include "core/field/solver.hpp"

namespace foldlab::field {

// One span between neighbouring supports on the top edge (SupportSpan), with its thrust beside
// its own cosine pencil's.
struct SpanReport {
  int left_support = 0;  // indices into the outline's supports
  int right_support = 0;
  double span_mm = 0.0;  // l, between its two supports, hung
  // The horizontal force the cloth carries across the span's centre line, N: by the balance of
  // the cloth on either side of that flat column (the weight is vertical), the sum of the
  // horizontal reactions of the supports left of it, equally those right of it; the mean of the
  // two sums' sizes (a support on the column counts half on each side).
  double thrust_N = 0.0;
  // Mansfield's pencil across the span: w l² / pi² ln(a_0 / a_n), a_n and a_0 the hung depths
  // of the top and bottom of its centre line below the line through its supports (0 when the
  // top is on that line or the bottom no deeper than the top).
  double pencil_thrust_N = 0.0;
  double centre_top_depth_mm = 0.0;     // a_n, hung
  double centre_bottom_depth_mm = 0.0;  // a_0, hung
};

struct FieldReport {
  Solution solution;
  // From each span's centre line (a share of the count each), or from the centre line of the
  // whole cut when fewer than two supports are on the top edge.
  std::vector<Ray> rays;
  std::vector<SpanReport> spans;  // left to right; empty with fewer than two top supports
  // With two supports: the mean horizontal reaction of the two, and the pencil through them with
  // the hung depths at the centre line between them (the one span's figures when both are on the
  // top edge). With more: the widest span's figures, or, with fewer than two of them on the top
  // edge, those of the outermost two supports as for two.
  double thrust_N = 0.0;
  double pencil_thrust_N = 0.0;
  double span_mm = 0.0;                 // l, hung
  double centre_top_depth_mm = 0.0;     // a_n, hung
  double centre_bottom_depth_mm = 0.0;  // a_0, hung
  int widest_span = -1;                 // the index into `spans` the figures above are of, or -1
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
