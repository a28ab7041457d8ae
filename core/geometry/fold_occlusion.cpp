#include "core/geometry/fold_occlusion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace foldlab {
namespace {

struct Horizons {
  float front = 0.0f;  // sin of the highest elevation above the tangent plane, 0 if none above
  float back = 0.0f;   // the same below it
};

// Along one direction (di, dj), in units of `stride` vertices: neighbours 1, 2, 4, ... strides
// away while within `reach`, and always the first.
Horizons horizons(const std::vector<Eigen::Vector3f>& positions, const Eigen::Vector3f& normal,
                  int nx, int ny, int i, int j, int di, int dj, int stride, float reach) {
  const Eigen::Vector3f& p = positions[static_cast<std::size_t>(j) * nx + i];
  Horizons h;
  for (int step = stride;; step *= 2) {
    const int qi = i + step * di;
    const int qj = j + step * dj;
    if (qi < 0 || qi >= nx || qj < 0 || qj >= ny) {
      break;
    }
    const Eigen::Vector3f d = positions[static_cast<std::size_t>(qj) * nx + qi] - p;
    const float distance = d.norm();
    if (step > stride && distance > reach) {
      break;
    }
    if (distance > 0.0f) {
      const float elevation_sin = d.dot(normal) / distance;
      h.front = std::max(h.front, elevation_sin);
      h.back = std::max(h.back, -elevation_sin);
    }
  }
  return h;
}

}  // namespace

int fold_occlusion_stride(int nx, int ny) {
  const int intervals = std::max(nx, ny) - 1;
  return std::max(1, (intervals + kFoldOcclusionSamples - 1) / kFoldOcclusionSamples);
}

namespace {

// The lattice along one side: every stride-th row or column, and the last one.
std::vector<int> lattice_at(int size, int stride) {
  std::vector<int> at;
  for (int k = 0; k < size; k += stride) {
    at.push_back(k);
  }
  if (at.back() != size - 1) {
    at.push_back(size - 1);
  }
  return at;
}

// Vertex (i, j)'s horizons averaged over the sides that have cloth (none at all: zero).
Horizons mean_horizons(const std::vector<Eigen::Vector3f>& positions, const Eigen::Vector3f& normal,
                       int nx, int ny, int i, int j, int stride, float reach) {
  constexpr std::array<std::array<int, 2>, 8> kDirections{
      {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}}};
  float front = 0.0f;
  float back = 0.0f;
  int directions = 0;
  for (const auto& [di, dj] : kDirections) {
    const int qi = i + stride * di;
    const int qj = j + stride * dj;
    if (qi < 0 || qi >= nx || qj < 0 || qj >= ny) {
      continue;  // the cloth's edge: the mean is over the sides that have cloth
    }
    const Horizons h = horizons(positions, normal, nx, ny, i, j, di, dj, stride, reach);
    front += h.front;
    back += h.back;
    ++directions;
  }
  if (directions == 0) {
    return {};
  }
  return {front / static_cast<float>(directions), back / static_cast<float>(directions)};
}

// Where k lies between the lattice's entries: `lower` moves up to the entry at or below k (k
// asked for in increasing order), and the return is the fraction of the way to the next.
float bracket(const std::vector<int>& at, int k, std::size_t& lower) {
  while (lower + 2 < at.size() && at[lower + 1] <= k) {
    ++lower;
  }
  const int a = at[lower];
  const int b = at[lower + 1];
  return static_cast<float>(k - a) / static_cast<float>(b - a);
}

// Between the lattice's vertices, bilinear: occlusion varies over a fold's width, which a
// lattice of kFoldOcclusionSamples a side still resolves.
void interpolate_between(std::vector<float>& o, int nx, int ny, const std::vector<int>& columns,
                         const std::vector<int>& rows) {
  const auto at = [nx](int ii, int jj) { return static_cast<std::size_t>(jj) * nx + ii; };
  std::size_t row = 0;
  for (int j = 0; j < ny; ++j) {
    const float fj = rows.size() > 1 ? bracket(rows, j, row) : 0.0f;
    const int j0 = rows[row];
    const int j1 = rows[std::min(row + 1, rows.size() - 1)];
    std::size_t column = 0;
    for (int i = 0; i < nx; ++i) {
      const float fi = columns.size() > 1 ? bracket(columns, i, column) : 0.0f;
      const int i0 = columns[column];
      const int i1 = columns[std::min(column + 1, columns.size() - 1)];
      // (1 - f) a + f b, which is exactly a or b at f = 0 or 1: lattice values stay as they are.
      const float top = (1.0f - fi) * o[at(i0, j0)] + fi * o[at(i1, j0)];
      const float bottom = (1.0f - fi) * o[at(i0, j1)] + fi * o[at(i1, j1)];
      o[at(i, j)] = (1.0f - fj) * top + fj * bottom;
    }
  }
}

}  // namespace

FoldOcclusion fold_occlusion(const std::vector<Eigen::Vector3f>& positions,
                             const std::vector<Eigen::Vector3f>& normals, int nx, int ny,
                             float reach) {
  FoldOcclusion result;
  const std::size_t count = positions.size();
  result.front.assign(count, 0.0f);
  result.back.assign(count, 0.0f);
  if (nx < 1 || ny < 1 || count != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) ||
      normals.size() != count) {
    return result;
  }
  const int stride = fold_occlusion_stride(nx, ny);
  const std::vector<int> columns = lattice_at(nx, stride);
  const std::vector<int> rows = lattice_at(ny, stride);
  for (int j : rows) {
    for (int i : columns) {
      const std::size_t v = static_cast<std::size_t>(j) * nx + i;
      const Horizons h = mean_horizons(positions, normals[v], nx, ny, i, j, stride, reach);
      result.front[v] = h.front;
      result.back[v] = h.back;
    }
  }
  if (stride > 1) {
    interpolate_between(result.front, nx, ny, columns, rows);
    interpolate_between(result.back, nx, ny, columns, rows);
  }
  return result;
}

}  // namespace foldlab
