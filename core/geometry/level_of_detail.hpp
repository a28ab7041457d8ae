// Which of the deformed grid's rows and columns a view needs to draw. A fine grid seen small puts
// several vertices in one pixel; a software rasterizer (llvmpipe) pays for every triangle however
// small, so the view draws a sub-lattice whose cells are a few pixels on screen. Two things keep
// it faithful: a fold keeps enough rows to show its turn, and the columns where a fibre is pinned
// (the supports of a strip, where the fibre length falls to a minimum) are always kept, so that no
// cell bridges a support. The detail is chosen by the cells' size on screen, the usual criterion
// of level of detail (Luebke et al., "Level of Detail for 3D Graphics", 2003); a regular grid
// needs no simplification beyond whole strides.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/geometry.hpp"

namespace foldlab {

struct DetailGoal {
  // A drawn cell should span about this many pixels in each direction.
  float cell_px = 5.0f;
  // Rows kept per fold (per mean spacing of the centre fibre's n + 1 segments), at the least: the
  // turn at a crest stays a curve of several segments, not a single kink.
  int rows_per_fold = 6;
  // A dropped vertex may lie this far from the drawn cell's edge, in pixels at its distance from
  // the eye (the usual screen-space error of level of detail). It counts the deviation along the
  // view direction too, which moves no pixel but decides which surface hides which line.
  float error_px = 0.5f;
};

struct DrawnLattice {
  std::vector<int> columns;  // kept grid columns, ascending, the first and the last among them
  std::vector<int> rows;     // kept grid rows, the same
  bool is_full(const DeformedGrid& grid) const {
    return static_cast<int>(columns.size()) == grid.nx && static_cast<int>(rows.size()) == grid.ny;
  }
};

// Every row and column.
DrawnLattice full_lattice(const DeformedGrid& grid);

// How the grid looks on screen along its widest column lines (across: the upper edge and the
// middle row) and its longest fibre (down). `model_to_clip` takes the grid's positions (mm) to
// clip coordinates of a viewport of `viewport_px`; the view's world is the model scaled by
// `world_scale` (an exaggerated z, a flipped y), which the matrix includes.
struct ScreenSpacing {
  float across_px = 0.0f;  // the mean distance between neighbouring vertices, in pixels
  float down_px = 0.0f;    // (infinite when a vertex is behind the eye)
  // The largest strides whose dropped vertices all stay within the goal's error_px of the kept
  // ones' chords.
  int faithful_across = std::numeric_limits<int>::max();
  int faithful_down = std::numeric_limits<int>::max();
};
ScreenSpacing screen_spacing(const DeformedGrid& grid, const Eigen::Matrix4f& model_to_clip,
                             const Eigen::Vector2f& viewport_px,
                             const Eigen::Vector3f& world_scale = Eigen::Vector3f::Ones(),
                             const DetailGoal& goal = {});

// Strides of whole rows and columns with cells of about goal.cell_px, no coarser than the spacing's
// faithful strides, the rows limited by goal.rows_per_fold for a solution of `folds` folds; the
// last row and column always kept.
DrawnLattice drawn_lattice(const DeformedGrid& grid, const ScreenSpacing& spacing, int folds,
                           const DetailGoal& goal = {});

// Two triangles per cell of a columns x rows lattice whose vertices are numbered row by row, with
// the diagonal deformed_grid uses.
std::vector<std::uint32_t> lattice_triangles(int columns, int rows);

}  // namespace foldlab
