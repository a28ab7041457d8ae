#include "core/geometry/fold_occlusion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace foldlab {
namespace {

// sin of the horizon's elevation above the tangent plane of `normal` along one direction, or a
// negative number when the direction has no neighbour inside the grid.
float horizon_sin(const std::vector<Eigen::Vector3f>& positions, const Eigen::Vector3f& normal,
                  int nx, int ny, int i, int j, int di, int dj, float reach) {
  const Eigen::Vector3f& p = positions[static_cast<std::size_t>(j) * nx + i];
  float best = -1.0f;
  for (int step = 1;; step *= 2) {
    const int qi = i + step * di;
    const int qj = j + step * dj;
    if (qi < 0 || qi >= nx || qj < 0 || qj >= ny) {
      break;
    }
    const Eigen::Vector3f d = positions[static_cast<std::size_t>(qj) * nx + qi] - p;
    const float distance = d.norm();
    if (step > 1 && distance > reach) {
      break;
    }
    if (distance > 0.0f) {
      best = std::max(best, d.dot(normal) / distance);  // sin(elevation) of this neighbour
    }
  }
  return best;
}

}  // namespace

FoldOcclusion fold_occlusion(const std::vector<Eigen::Vector3f>& positions,
                             const std::vector<Eigen::Vector3f>& normals, int nx, int ny,
                             float reach) {
  constexpr std::array<std::array<int, 2>, 8> kDirections{
      {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}}};
  FoldOcclusion result;
  const std::size_t count = positions.size();
  result.front.assign(count, 0.0f);
  result.back.assign(count, 0.0f);
  if (nx < 1 || ny < 1 || count != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) ||
      normals.size() != count) {
    return result;
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const std::size_t v = static_cast<std::size_t>(j) * nx + i;
      float front = 0.0f;
      float back = 0.0f;
      int directions = 0;
      for (const auto& [di, dj] : kDirections) {
        if (i + di < 0 || i + di >= nx || j + dj < 0 || j + dj >= ny) {
          continue;  // the cloth's edge: the mean is over the sides that have cloth
        }
        const float up = horizon_sin(positions, normals[v], nx, ny, i, j, di, dj, reach);
        const float down = horizon_sin(positions, -normals[v], nx, ny, i, j, di, dj, reach);
        front += std::max(0.0f, up);
        back += std::max(0.0f, down);
        ++directions;
      }
      if (directions > 0) {
        result.front[v] = front / static_cast<float>(directions);
        result.back[v] = back / static_cast<float>(directions);
      }
    }
  }
  return result;
}

}  // namespace foldlab
