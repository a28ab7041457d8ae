#include "core/geometry/level_of_detail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Geometry>

namespace foldlab {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The fibre length of column i: the material Y of its lowest vertex.
float fibre_length_mm(const DeformedGrid& grid, int i) {
  return grid.material_mm[static_cast<std::size_t>(grid.ny - 1) * grid.nx + i].y();
}

const Eigen::Vector3f& at(const DeformedGrid& grid, int i, int j) {
  return grid.positions_mm[static_cast<std::size_t>(j) * grid.nx + i];
}

// The mean on-screen step between consecutive vertices of one grid line, given by `vertex(k)` for
// k = 0 .. count - 1.
template <class Vertex>
float mean_step_px(int count, Vertex vertex, const Eigen::Matrix4f& model_to_clip,
                   const Eigen::Vector2f& viewport_px) {
  float length = 0.0f;
  Eigen::Vector2f previous = Eigen::Vector2f::Zero();
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector4f clip = model_to_clip * vertex(k).homogeneous();
    if (!(clip.w() > 1e-6f)) {
      return kInfinity;
    }
    const Eigen::Vector2f pixel = (clip.head<2>() / clip.w()).cwiseProduct(0.5f * viewport_px);
    if (k > 0) {
      length += (pixel - previous).norm();
    }
    previous = pixel;
  }
  return length / static_cast<float>(std::max(1, count - 1));
}

std::vector<int> every(int stride, int count, std::vector<int> always) {
  std::vector<int> kept;
  for (int k = 0; k < count; k += stride) {
    kept.push_back(k);
  }
  always.push_back(count - 1);
  kept.insert(kept.end(), always.begin(), always.end());
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  return kept;
}

// At least this many rows and columns are kept: a grid seen edge-on has no spacing on screen
// along one direction, yet its outline there is made by the fibres kept.
constexpr int kFewestKept = 16;

int stride_for(float spacing_px, float goal_px, int count) {
  const int coarsest = std::max(1, (count - 1) / kFewestKept);
  if (!std::isfinite(spacing_px)) {
    return 1;
  }
  if (!(spacing_px > 0.0f)) {
    return coarsest;
  }
  const float stride = std::floor(goal_px / spacing_px);
  return static_cast<int>(std::clamp(stride, 1.0f, static_cast<float>(coarsest)));
}

}  // namespace

DrawnLattice full_lattice(const DeformedGrid& grid) {
  DrawnLattice lattice;
  lattice.columns.resize(static_cast<std::size_t>(grid.nx));
  lattice.rows.resize(static_cast<std::size_t>(grid.ny));
  std::iota(lattice.columns.begin(), lattice.columns.end(), 0);
  std::iota(lattice.rows.begin(), lattice.rows.end(), 0);
  return lattice;
}

ScreenSpacing screen_spacing(const DeformedGrid& grid, const Eigen::Matrix4f& model_to_clip,
                             const Eigen::Vector2f& viewport_px) {
  ScreenSpacing spacing;
  if (grid.nx < 2 || grid.ny < 2 || grid.positions_mm.empty()) {
    return spacing;
  }
  // Every column of a shape is its longest fibre scaled down (or as long), so the longest fibre
  // has the widest rows; the upper edge and the middle row are the widest columns.
  int longest = 0;
  for (int i = 1; i < grid.nx; ++i) {
    if (fibre_length_mm(grid, i) > fibre_length_mm(grid, longest)) {
      longest = i;
    }
  }
  spacing.down_px = mean_step_px(
      grid.ny, [&](int j) -> const Eigen::Vector3f& { return at(grid, longest, j); }, model_to_clip,
      viewport_px);
  for (int j : {0, grid.ny / 2}) {
    spacing.across_px =
        std::max(spacing.across_px,
                 mean_step_px(
                     grid.nx, [&](int i) -> const Eigen::Vector3f& { return at(grid, i, j); },
                     model_to_clip, viewport_px));
  }
  return spacing;
}

DrawnLattice drawn_lattice(const DeformedGrid& grid, const ScreenSpacing& spacing, int folds,
                           const DetailGoal& goal) {
  if (grid.nx < 2 || grid.ny < 2) {
    return full_lattice(grid);
  }
  const int column_stride = stride_for(spacing.across_px, goal.cell_px, grid.nx);
  const int fold_limit =
      std::max(1, (grid.ny - 1) / (std::max(1, goal.rows_per_fold) * (std::max(0, folds) + 1)));
  const int row_stride = std::min(stride_for(spacing.down_px, goal.cell_px, grid.ny), fold_limit);
  // A fibre pinned between two spans is shorter than its neighbours, the longest fibre of a span
  // reaches lowest and makes the outline seen edge-on: keep both.
  std::vector<int> extremes;
  for (int i = 1; i + 1 < grid.nx; ++i) {
    const float here = fibre_length_mm(grid, i);
    const float left = fibre_length_mm(grid, i - 1);
    const float right = fibre_length_mm(grid, i + 1);
    const bool lowest = (here < left && here <= right) || (here <= left && here < right);
    const bool highest = (here > left && here >= right) || (here >= left && here > right);
    if (lowest || highest) {
      extremes.push_back(i);
    }
  }
  return {every(column_stride, grid.nx, std::move(extremes)), every(row_stride, grid.ny, {})};
}

std::vector<std::uint32_t> lattice_triangles(int columns, int rows) {
  std::vector<std::uint32_t> indices;
  if (columns < 2 || rows < 2) {
    return indices;
  }
  indices.reserve(static_cast<std::size_t>(columns - 1) * (rows - 1) * 6);
  for (int j = 0; j + 1 < rows; ++j) {
    for (int i = 0; i + 1 < columns; ++i) {
      const auto v00 = static_cast<std::uint32_t>(j * columns + i);
      const auto v10 = v00 + 1;
      const auto v01 = v00 + static_cast<std::uint32_t>(columns);
      const auto v11 = v01 + 1;
      for (std::uint32_t v : {v00, v01, v10, v10, v01, v11}) {
        indices.push_back(v);
      }
    }
  }
  return indices;
}

}  // namespace foldlab
