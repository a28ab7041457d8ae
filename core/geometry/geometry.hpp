// What the solution looks like: the fold lines of eq. 6 and the deformed cloth (docs/model.md,
// "The deformed cloth").
// Coordinates in mm: x across (0 midway between the supports), y down, z out of the initial plane.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/rounded_folds.hpp"
#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

// Sign of the out-of-plane offset of wrinkle line i (eq. 4): +1 for even i (a_0, the lower
// boundary, is a positive fold), -1 for odd i (the paper draws these negative folds red).
inline int fold_sign(int i) {
  return i % 2 == 0 ? 1 : -1;
}

// Above this many lines a drawing shows every stride-th line only (the solve keeps every fold).
inline constexpr int kMaxDrawnFoldLines = 1000;

struct FoldLine {
  int index = 0;  // i: 0 is the lower boundary a_0, n the upper edge a_n
  int sign = 1;
  int span = 0;                            // which span of a strip (0 otherwise)
  std::vector<Eigen::Vector3d> points_mm;  // (x, a_i cos(pi x/l), sign z_i cos(pi x/l))
};

struct FoldLines {
  std::vector<FoldLine> lines;
  int stride = 1;  // 1 when every line is drawn
};

// samples >= 2 points per line and span, from x = -l/2 to l/2 of each span. Empty when the
// solution has no folds. The shape repeats the lines per span (strip) or shears them (inclined).
// z_i is the depth of fold i once rounded (FoldRounding::fold_depth_mm), so the lines lie on the
// grid's crests.
FoldLines fold_lines(const Solution& s, const FoldRounding& rounding, const Shape& shape,
                     int samples, int max_lines = kMaxDrawnFoldLines);
// With the fabric's rounding and the parameters' shape.
FoldLines fold_lines(const Solution& s, const Parameters& p, int samples,
                     int max_lines = kMaxDrawnFoldLines);
// How many points fold_lines() would return, without building them: exports check it against their
// budget before allocating.
std::int64_t fold_line_point_count(const Solution& s, const Shape& shape, int samples,
                                   int max_lines = kMaxDrawnFoldLines);

// Where the shape puts a point (x, y, z) of one span's solution: span j of a strip is shifted by
// its offset, and an inclined pattern is sheared so that the right support sits higher.
Eigen::Vector3d place_on_shape(const Eigen::Vector3d& span_point, int span, double span_mm,
                               const Shape& shape);

// How far below the supports' line the cloth reaches at the centre (mm): a_0, or A + h when there
// are no folds (no slack, short cloth). The 3D view's ground, the breeze's depth and the flat
// cloth's outline all start from it.
double lowest_point_mm(const Solution& s, double height_mm);

// Where the supports are once moved (k of them on a strip, the right one raised when inclined).
std::vector<Eigen::Vector3d> support_points(double span_mm, const Shape& shape);

// The deformed cloth: an nx x ny grid over the flat cloth (X across, Y down the fibre), row-major
// with X fastest, two triangles per cell, and per-vertex normals (area weighted, unit length).
struct DeformedGrid {
  int nx = 0;
  int ny = 0;
  std::vector<Eigen::Vector3f> positions_mm;
  std::vector<Eigen::Vector2f> material_mm;  // (X, Y) of each vertex on the flat cloth: for prints
  std::vector<Eigen::Vector3f> normals;
  std::vector<std::uint32_t> triangle_indices;
  // max over the grid's columns of |deformed polyline length - flat fibre length| / h: how well the
  // grid resolves the folds (it shrinks as ny grows past 2n).
  double worst_fibre_error = 0.0;
  // Largest angle (degrees) between neighbouring segments of the centre fibre as the grid's ny rows
  // sample it: how sharp the sharpest crease looks. Every column of the cosine membrane is the
  // centre fibre scaled, so it holds for all of them.
  double sharpest_turn_deg = 0.0;
};

// nx, ny >= 2, over the whole flat cloth (all spans of a strip; each span gets a whole number of
// the nx - 1 intervals when there are enough, so that a column falls on every support). The cosine
// membrane: the fibre at X has length h cos(pi X/L) and its points sit at arc-length fraction Y/h
// of the centre fibre through the fold points, scaled by cos(pi X/L), at x = X l/L. The centre
// fibre has rounded crests (rounded_folds.hpp) where the paper has a sharp zig-zag. The rectangular
// cloth: every fibre is h long; its point Y sits at arc length Y along the scaled centre fibre, and
// below the lowest fold it hangs straight down (as the paper does; near the supports, where the
// folds shrink to nothing, this is where the model stops describing a real cloth). The supports
// stay fixed.
DeformedGrid deformed_grid(const Solution& s, const Parameters& p, int nx, int ny);
// The same without normals (left empty): the scene computes them as a stage of their own.
DeformedGrid deformed_grid_positions(const Solution& s, const Parameters& p, int nx, int ny);
// The same along a given centre fibre (the scene keeps one per solution; a sharp one reproduces
// the paper's zig-zag).
DeformedGrid deformed_grid_positions(const Solution& s, const Parameters& p,
                                     const CentreFibre& fibre, int nx, int ny);

// Per-vertex unit normals of an indexed triangle mesh, area weighted; (0, 0, 1) where degenerate.
std::vector<Eigen::Vector3f> vertex_normals(const std::vector<Eigen::Vector3f>& positions,
                                            const std::vector<std::uint32_t>& triangle_indices);

}  // namespace foldlab

namespace foldlab {

// A breeze on top of the static wrinkles (paper Fig. 5, "combined with other displacements"): a
// smooth offset that grows from nothing at the line of the supports (y = 0) to `amplitude_mm` at
// depth `depth_mm`, as a wave running down the cloth. Model coordinates (y down), mm, seconds.
// The 3D view computes the same function on the GPU (app/gui/cloth_renderer.cpp, kBreezeGlsl);
// the solver never re-runs for it.
Eigen::Vector3f breeze_offset(const Eigen::Vector3f& position_mm, float depth_mm,
                              float amplitude_mm, float time_s);

}  // namespace foldlab
