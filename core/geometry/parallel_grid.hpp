// The deformed grid of geometry.hpp with its normals computed on several threads. It returns
// exactly what deformed_grid returns, bit for bit (the tests compare them): every vertex's normal
// sums its faces in the same order as vertex_normals' one-thread scatter, so the two differ in
// time only.
#pragma once

#include "core/geometry/geometry.hpp"

namespace foldlab {

// threads <= 0 means std::thread::hardware_concurrency(). The grid's rows are split into one
// band per thread; below 128 x 128 vertices one thread is used (starting threads costs more than
// it saves there).
DeformedGrid deformed_grid_parallel(const Solution& s, const Parameters& p, int nx, int ny,
                                    int threads = 0);

// vertex_normals for a grid laid out as deformed_grid_positions lays it out (row-major, X
// fastest, two triangles per cell), gathered per vertex on `threads` threads.
std::vector<Eigen::Vector3f> grid_vertex_normals(const DeformedGrid& grid, int threads);

}  // namespace foldlab
