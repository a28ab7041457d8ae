#include "core/geometry/level_of_detail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

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

// One grid line's vertices on screen, and how many pixels a millimetre of the view's world spans
// around each of them: the largest over the three axes, since an offset along the view direction
// shows no length and one across it its full length. Empty when a vertex is behind the eye.
struct ScreenLine {
  std::vector<Eigen::Vector3f> model;
  std::vector<Eigen::Vector2f> pixel;
  std::vector<float> pixels_per_mm;
};

std::optional<Eigen::Vector2f> to_pixel(const Eigen::Vector3f& model,
                                        const Eigen::Matrix4f& model_to_clip,
                                        const Eigen::Vector2f& viewport_px) {
  const Eigen::Vector4f clip = model_to_clip * model.homogeneous();
  if (!(clip.w() > 1e-6f)) {
    return std::nullopt;
  }
  return Eigen::Vector2f((clip.head<2>() / clip.w()).cwiseProduct(0.5f * viewport_px));
}

template <class Vertex>
std::optional<ScreenLine> screen_line(int count, Vertex vertex,
                                      const Eigen::Matrix4f& model_to_clip,
                                      const Eigen::Vector2f& viewport_px,
                                      const Eigen::Vector3f& world_scale) {
  ScreenLine line;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3f& model = vertex(k);
    const std::optional<Eigen::Vector2f> pixel = to_pixel(model, model_to_clip, viewport_px);
    if (!pixel) {
      return std::nullopt;
    }
    float scale = 0.0f;
    for (int axis = 0; axis < 3; ++axis) {
      if (world_scale[axis] == 0.0f) {
        continue;  // a flattened axis has no millimetre to show
      }
      const Eigen::Vector3f one_mm = Eigen::Vector3f::Unit(axis) / world_scale[axis];
      const std::optional<Eigen::Vector2f> moved =
          to_pixel(model + one_mm, model_to_clip, viewport_px);
      if (!moved) {
        return std::nullopt;
      }
      scale = std::max(scale, (*moved - *pixel).norm());
    }
    line.model.push_back(model);
    line.pixel.push_back(*pixel);
    line.pixels_per_mm.push_back(scale);
  }
  return line;
}

float mean_step_px(const ScreenLine& line) {
  float length = 0.0f;
  for (std::size_t k = 1; k < line.pixel.size(); ++k) {
    length += (line.pixel[k] - line.pixel[k - 1]).norm();
  }
  return length / static_cast<float>(std::max<std::size_t>(1, line.pixel.size() - 1));
}

// The largest stride up to `most` for which every dropped vertex lies within `error_px` of the
// segment between the kept vertices around it, measured in the view's world (mm) and scaled by
// the pixels a millimetre spans there.
int faithful_stride(const ScreenLine& line, const Eigen::Vector3f& world_scale, int most,
                    float error_px) {
  const int count = static_cast<int>(line.model.size());
  const auto world = [&](int k) -> Eigen::Vector3f {
    return line.model[static_cast<std::size_t>(k)].cwiseProduct(world_scale);
  };
  for (int stride = std::min(most, count - 1); stride > 1; --stride) {
    bool faithful = true;
    for (int a = 0; a + 1 < count && faithful; a += stride) {
      const int b = std::min(a + stride, count - 1);
      const Eigen::Vector3f from = world(a);
      const Eigen::Vector3f chord = world(b) - from;
      const float chord_squared = std::max(chord.squaredNorm(), 1e-20f);
      for (int j = a + 1; j < b && faithful; ++j) {
        const Eigen::Vector3f offset = world(j) - from;
        const float t = std::clamp(offset.dot(chord) / chord_squared, 0.0f, 1.0f);
        const float off_mm = (offset - t * chord).norm();
        faithful = off_mm * line.pixels_per_mm[static_cast<std::size_t>(j)] <= error_px;
      }
    }
    if (faithful) {
      return stride;
    }
  }
  return 1;
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
                             const Eigen::Vector2f& viewport_px, const Eigen::Vector3f& world_scale,
                             const DetailGoal& goal) {
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
  const auto behind_the_eye = [&] {
    spacing.across_px = spacing.down_px = kInfinity;
    spacing.faithful_across = spacing.faithful_down = 1;
    return spacing;
  };
  // Strides coarser than the spacing allows are never drawn: no need to check them.
  const auto candidate = [&](float spacing_px, int count) {
    return stride_for(spacing_px, goal.cell_px, count);
  };
  const std::optional<ScreenLine> fibre = screen_line(
      grid.ny, [&](int j) -> const Eigen::Vector3f& { return at(grid, longest, j); }, model_to_clip,
      viewport_px, world_scale);
  if (!fibre) {
    return behind_the_eye();
  }
  spacing.down_px = mean_step_px(*fibre);
  spacing.faithful_down =
      faithful_stride(*fibre, world_scale, candidate(spacing.down_px, grid.ny), goal.error_px);
  std::vector<ScreenLine> rows;
  for (int j : {0, grid.ny / 2}) {
    std::optional<ScreenLine> row = screen_line(
        grid.nx, [&](int i) -> const Eigen::Vector3f& { return at(grid, i, j); }, model_to_clip,
        viewport_px, world_scale);
    if (!row) {
      return behind_the_eye();
    }
    spacing.across_px = std::max(spacing.across_px, mean_step_px(*row));
    rows.push_back(std::move(*row));
  }
  for (const ScreenLine& row : rows) {
    spacing.faithful_across = std::min(
        spacing.faithful_across,
        faithful_stride(row, world_scale, candidate(spacing.across_px, grid.nx), goal.error_px));
  }
  return spacing;
}

DrawnLattice drawn_lattice(const DeformedGrid& grid, const ScreenSpacing& spacing, int folds,
                           const DetailGoal& goal) {
  if (grid.nx < 2 || grid.ny < 2) {
    return full_lattice(grid);
  }
  const int column_stride =
      std::min(stride_for(spacing.across_px, goal.cell_px, grid.nx), spacing.faithful_across);
  const int fold_limit =
      std::max(1, (grid.ny - 1) / (std::max(1, goal.rows_per_fold) * (std::max(0, folds) + 1)));
  const int row_stride = std::min(
      {stride_for(spacing.down_px, goal.cell_px, grid.ny), fold_limit, spacing.faithful_down});
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
