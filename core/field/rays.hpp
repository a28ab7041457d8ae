// Tension rays: streamlines of the larger principal tension, traced on the flat cut (where the
// mesh is never folded) and carried to the hung cloth, and the closed form's cosine fitted to each.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/field/solver.hpp"

namespace foldlab::field {

// The hung frame the closed form is written in: x from the middle between the outermost
// supports, y down from the straight line through them, l the horizontal distance between them.
struct SupportFrame {
  Eigen::Vector2d left_mm;
  Eigen::Vector2d right_mm;
  double span_mm() const { return right_mm.x() - left_mm.x(); }
  double x_mm(const Eigen::Vector2d& p) const { return p.x() - 0.5 * (left_mm.x() + right_mm.x()); }
  double depth_mm(const Eigen::Vector2d& p) const;
};
SupportFrame support_frame(const std::vector<Eigen::Vector2d>& targets_mm);

struct Ray {
  double depth_mm = 0.0;  // a: where it crosses its span's centre line, below the span's supports
  double fitted_amplitude_mm = 0.0;        // of the cosine a cos(pi x / l) closest to it
  double fit_rms_mm = 0.0;                 // rms distance of the ray's points from that cosine
  int fitted_points = 0;                   // points between the supports (the fit's)
  std::vector<Eigen::Vector2d> points_mm;  // hung, from one end to the other
  int span = 0;  // the index of the span it was traced from (0 for the centre line of the cut)
};

// One span of a cut hung from its top edge: between two supports on the top edge that are
// neighbours by where they are pinned, its own frame (l their distance, x from their middle) and
// the flat column midway between the two on the cut, which is its centre line.
struct SupportSpan {
  int left_support = 0;  // indices into the outline's supports
  int right_support = 0;
  SupportFrame frame;
  double flat_x_mm = 0.0;
};

// Whether the flat point lies on the cut's top edge (within the outline check's tolerance).
bool on_top_edge(const Outline& outline, const Eigen::Vector2d& at_mm);

// The spans between neighbouring supports on the top edge, left to right by where they are
// pinned (of supports pinned at one x the topmost, the one the cloth hangs from there). Supports
// elsewhere on the cut take no part. Empty with fewer than two supports on the top edge.
std::vector<SupportSpan> top_spans(const Mesh& mesh, const Outline& outline);

// How many of `count` rays each span gets: all of them for one span; for several, in proportion
// to each one's l and at least 2 a span (so more than `count` when there are more than count / 2
// spans); none when count < 1.
std::vector<int> rays_per_span(const std::vector<SupportSpan>& spans, int count);

// The hung position of the flat point p, nullopt-like (NaN) outside the cut.
Eigen::Vector2d hung_position(const Mesh& mesh, const Solution& solution, const Eigen::Vector2d& p);

// The flat column midway between the outermost supports, sampled from top to bottom, with the
// hung depth of each sample below the supports' line.
struct CentreLine {
  std::vector<Eigen::Vector2d> flat_mm;
  std::vector<double> depth_mm;
};
CentreLine centre_line(const Mesh& mesh, const Solution& solution,
                       const std::vector<Eigen::Vector2d>& targets_mm);
// The same for the flat column at x = flat_x_mm, its depths below the line of `frame`'s supports.
CentreLine column_line(const Mesh& mesh, const Solution& solution, double flat_x_mm,
                       const SupportFrame& frame);

// `count` rays through the centre line at depths evenly spaced strictly between its top and
// bottom (hung); a ray is traced both ways until it leaves the cut or reaches a support.
std::vector<Ray> trace_rays(const Mesh& mesh, const Solution& solution,
                            const std::vector<Eigen::Vector2d>& targets_mm, int count);

// The rays of a cut hung from several spans: each span's share of `count` (rays_per_span)
// through its own centre line, traced the same way, each fitted to a cos(pi x / l) of its span's
// frame and marked with its span's index.
std::vector<Ray> trace_span_rays(const Mesh& mesh, const Solution& solution,
                                 const std::vector<SupportSpan>& spans, int count);

}  // namespace foldlab::field
