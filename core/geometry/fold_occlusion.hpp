// How much of the sky each point of a folded cloth sees: a cheap ambient occlusion from the fold
// geometry alone, so that the inside of a pleat reads darker than its crest even under flat light.
// Horizon-based: along each of the grid's eight directions, the highest neighbour (within a few
// rows and columns) above the point's tangent plane hides the sky below that elevation.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace foldlab {

struct FoldOcclusion {
  // Per vertex, 0 (open sky) to 1 (fully hidden), for the face the normal points out of (front)
  // and for the other one (back): a valley on one face is a crest on the other.
  std::vector<float> front;
  std::vector<float> back;
};

// Finer grids are looked at every stride-th row and column (the lattice, with the last row and
// column), at most kFoldOcclusionSamples + 1 a side, and interpolated bilinearly in between: the
// cost stays that of a 65^2 grid (under a millisecond) however fine the mesh. A fold is a few
// lattice steps wide even for chiffon at the default grid, and occlusion varies smoothly across it.
inline constexpr int kFoldOcclusionSamples = 64;
int fold_occlusion_stride(int nx, int ny);

// `positions` and `normals` are an nx x ny grid, row j's vertex i at j * nx + i (DeformedGrid's
// layout), in any length unit. The horizon along a direction is looked for at 1, 2, 4, ... strides
// while the neighbour stays within `reach` (the same unit) of the point, and at least one stride;
// a point's occlusion is the mean, over the directions that have a neighbour, of sin(elevation)
// of the horizon, 0 for a horizon below the tangent plane.
FoldOcclusion fold_occlusion(const std::vector<Eigen::Vector3f>& positions,
                             const std::vector<Eigen::Vector3f>& normals, int nx, int ny,
                             float reach);

}  // namespace foldlab
