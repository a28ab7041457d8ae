// What the solution looks like: the fold lines of eq. 6 and the deformed cloth of MODEL.md item 7.
// Coordinates in mm: x across (0 midway between the supports), y down, z out of the initial plane.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "foldlab/parameters.hpp"
#include "foldlab/solver.hpp"

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
  std::vector<Eigen::Vector3d> points_mm;  // (x, a_i cos(pi x/l), sign z_max cos(pi x/l))
};

struct FoldLines {
  std::vector<FoldLine> lines;
  int stride = 1;  // 1 when every line is drawn
};

// samples >= 2 points per line from x = -l/2 to l/2. Empty when the solution has no folds.
FoldLines fold_lines(const Solution& s, int samples, int max_lines = kMaxDrawnFoldLines);

// The deformed cloth: an nx x ny grid over the flat cloth (X across, Y down the fibre), row-major
// with X fastest, two triangles per cell, and per-vertex normals (area weighted, unit length).
struct DeformedGrid {
  int nx = 0;
  int ny = 0;
  std::vector<Eigen::Vector3f> positions_mm;
  std::vector<Eigen::Vector3f> normals;
  std::vector<std::uint32_t> triangle_indices;
  // max over the grid's columns of |deformed polyline length - flat fibre length| / h: how well the
  // grid resolves the zig-zag of folds (it shrinks as ny grows past 2n).
  double worst_fibre_error = 0.0;
};

// nx, ny >= 2. The flat cloth is the cosine membrane: the fibre at X has length h cos(pi X/L) and
// its points sit at arc-length fraction Y/h of the zig-zag through the fold points at
// x = X l/L. The supports (X = +-L/2) stay fixed.
DeformedGrid deformed_grid(const Solution& s, const Parameters& p, int nx, int ny);
// The same without normals (left empty): the scene computes them as a stage of their own.
DeformedGrid deformed_grid_positions(const Solution& s, const Parameters& p, int nx, int ny);

// Per-vertex unit normals of an indexed triangle mesh, area weighted; (0, 0, 1) where degenerate.
std::vector<Eigen::Vector3f> vertex_normals(const std::vector<Eigen::Vector3f>& positions,
                                            const std::vector<std::uint32_t>& triangle_indices);

}  // namespace foldlab
