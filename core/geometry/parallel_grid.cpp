#include "core/geometry/parallel_grid.hpp"

#include <algorithm>
#include <thread>
#include <vector>

#include <Eigen/Geometry>

#include "core/model/hardware_threads.hpp"

namespace foldlab {
namespace {

// Runs body(first_row, last_row) on `threads` contiguous bands of [0, rows).
template <class Body>
void for_row_bands(int rows, int threads, const Body& body) {
  if (threads <= 1) {
    body(0, rows);
    return;
  }
  std::vector<std::thread> workers;
  workers.reserve(static_cast<std::size_t>(threads) - 1);
  for (int t = 1; t < threads; ++t) {
    workers.emplace_back(body, rows * t / threads, rows * (t + 1) / threads);
  }
  body(0, rows / threads);
  for (std::thread& worker : workers) {
    worker.join();
  }
}

}  // namespace

DeformedGrid deformed_grid_parallel(const Solution& s, const Parameters& p, int nx, int ny,
                                    int threads) {
  // Positions and triangles are a few stores per vertex; the normals' cross products and square
  // roots are most of the time (measured by `foldlab bench`), so they are what is split.
  DeformedGrid grid = deformed_grid_positions(s, p, nx, ny);
  if (threads <= 0) {
    threads = hardware_threads();
  }
  if (static_cast<long long>(grid.nx) * grid.ny < 128 * 128) {
    threads = 1;
  }
  grid.normals = grid_vertex_normals(grid, std::min(threads, grid.ny));
  return grid;
}

std::vector<Eigen::Vector3f> grid_vertex_normals(const DeformedGrid& grid, int threads) {
  const int gx = grid.nx;
  const int gy = grid.ny;
  threads = std::max(1, threads);
  const std::vector<Eigen::Vector3f>& position = grid.positions_mm;
  const auto vertex = [gx](int i, int j) { return static_cast<std::size_t>(j) * gx + i; };
  // Cell (i, j) holds triangles (v00, v01, v10) and (v10, v01, v11); each face is weighted by its
  // cross product, as vertex_normals weights it. First every face once, by bands of cell rows.
  const auto cell = [gx](int i, int j) { return 2 * (static_cast<std::size_t>(j) * (gx - 1) + i); };
  std::vector<Eigen::Vector3f> faces(2 * static_cast<std::size_t>(gx - 1) * (gy - 1));
  for_row_bands(gy - 1, threads, [&](int first, int last) {
    for (int j = first; j < last; ++j) {
      for (int i = 0; i + 1 < gx; ++i) {
        const Eigen::Vector3f& p00 = position[vertex(i, j)];
        const Eigen::Vector3f& p10 = position[vertex(i + 1, j)];
        const Eigen::Vector3f& p01 = position[vertex(i, j + 1)];
        const Eigen::Vector3f& p11 = position[vertex(i + 1, j + 1)];
        faces[cell(i, j)] = (p01 - p00).cross(p10 - p00);
        faces[cell(i, j) + 1] = (p01 - p10).cross(p11 - p10);
      }
    }
  });
  // Then every vertex gathers the faces of its up to four cells in the order vertex_normals'
  // scatter visits them (by triangle index), so that its float sum rounds the same way; no two
  // threads write the same normal.
  std::vector<Eigen::Vector3f> normals(position.size());
  for_row_bands(gy, threads, [&](int first, int last) {
    for (int j = first; j < last; ++j) {
      for (int i = 0; i < gx; ++i) {
        Eigen::Vector3f sum = Eigen::Vector3f::Zero();
        const bool left = i > 0;
        const bool right = i + 1 < gx;
        const bool up = j > 0;
        const bool down = j + 1 < gy;
        if (left && up) {
          sum += faces[cell(i - 1, j - 1) + 1];  // as v11
        }
        if (right && up) {
          sum += faces[cell(i, j - 1)];  // as v01 of both
          sum += faces[cell(i, j - 1) + 1];
        }
        if (left && down) {
          sum += faces[cell(i - 1, j)];  // as v10 of both
          sum += faces[cell(i - 1, j) + 1];
        }
        if (right && down) {
          sum += faces[cell(i, j)];  // as v00
        }
        const float length = sum.norm();
        normals[vertex(i, j)] =
            length > 0.0f ? Eigen::Vector3f(sum / length) : Eigen::Vector3f::UnitZ();
      }
    }
  });
  return normals;
}

}  // namespace foldlab
