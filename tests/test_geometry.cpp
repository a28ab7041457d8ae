// Fold lines (eq. 6 and eq. 4) and the deformed grid (MODEL.md item 7).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "foldlab/geometry.hpp"
#include "foldlab/solver.hpp"

namespace foldlab {
namespace {

Parameters exact_default() {
  Parameters p;
  p.model.method = Method::exact;
  return p;
}

TEST(FoldLines, FollowTheCosineOfEq6) {
  const Parameters p = exact_default();
  const Solution s = solve(p);
  const FoldLines lines = fold_lines(s, 33);
  ASSERT_EQ(lines.lines.size(), static_cast<std::size_t>(s.n) + 1);
  EXPECT_EQ(lines.stride, 1);
  const double l = s.span_mm;
  for (const FoldLine& line : lines.lines) {
    ASSERT_EQ(line.points_mm.size(), 33u);
    EXPECT_EQ(line.sign, line.index % 2 == 0 ? 1 : -1);
    const double a = s.a_mm[static_cast<std::size_t>(line.index)];
    for (const Eigen::Vector3d& q : line.points_mm) {
      const double c = std::cos(std::numbers::pi * q.x() / l);
      EXPECT_NEAR(q.y(), a * c, 1e-9);
      EXPECT_NEAR(q.z(), line.sign * s.z_max_mm * c, 1e-9);
    }
    // Ends at the supports, x = -+l/2, where y = z = 0.
    EXPECT_NEAR(line.points_mm.front().x(), -l / 2, 1e-9);
    EXPECT_NEAR(line.points_mm.back().x(), l / 2, 1e-9);
    EXPECT_NEAR(line.points_mm.front().y(), 0.0, 1e-9);
    EXPECT_NEAR(line.points_mm.back().z(), 0.0, 1e-9);
    // Mid-span: the amplitude itself.
    EXPECT_NEAR(line.points_mm[16].y(), a, 1e-9);
  }
}

TEST(FoldLines, ManyFoldsAreThinnedForDrawingOnly) {
  Parameters p = exact_default();
  p.fabric.thickness_mm = 0.01;  // s ~ 1e-6: thousands of folds
  const Solution s = solve(p);
  ASSERT_GT(s.n, 1000);
  const FoldLines lines = fold_lines(s, 5, 100);
  EXPECT_LE(static_cast<int>(lines.lines.size()), 100);
  EXPECT_GT(lines.stride, 1);
  EXPECT_EQ(lines.lines[1].index, lines.stride);
  EXPECT_EQ(s.a_mm.size(), static_cast<std::size_t>(s.n) + 1);  // the solution keeps every fold
}

TEST(FoldLines, NoneWithoutFolds) {
  Parameters p = exact_default();
  p.hanging.support_displacement_mm = 0.0;
  EXPECT_TRUE(fold_lines(solve(p), 10).lines.empty());
}

TEST(DeformedGrid, ShapeSupportsAndCentralFibre) {
  const Parameters p = exact_default();
  const Solution s = solve(p);
  const int nx = 21;
  const int ny = 401;
  const DeformedGrid grid = deformed_grid(s, p, nx, ny);
  ASSERT_EQ(grid.positions_mm.size(), static_cast<std::size_t>(nx * ny));
  ASSERT_EQ(grid.normals.size(), grid.positions_mm.size());
  EXPECT_EQ(grid.triangle_indices.size(), static_cast<std::size_t>((nx - 1) * (ny - 1) * 6));
  auto at = [&](int i, int j) { return grid.positions_mm[static_cast<std::size_t>(j * nx + i)]; };
  // Supports stay fixed: both edge columns collapse onto (-+l/2, 0, 0).
  for (int j = 0; j < ny; ++j) {
    EXPECT_NEAR(at(0, j).x(), -s.span_mm / 2, 1e-3);
    EXPECT_NEAR(at(nx - 1, j).x(), s.span_mm / 2, 1e-3);
    EXPECT_NEAR(at(0, j).y(), 0.0, 1e-3);
    EXPECT_NEAR(at(0, j).z(), 0.0, 1e-3);
  }
  // The central column starts at the upper edge (a_n, sign_n z) and ends at a_0 (+z).
  const int mid = nx / 2;
  EXPECT_NEAR(at(mid, 0).x(), 0.0, 1e-3);
  EXPECT_NEAR(at(mid, 0).y(), s.a_mm.back(), 1e-3);
  EXPECT_NEAR(at(mid, 0).z(), fold_sign(s.n) * s.z_max_mm, 1e-3);
  EXPECT_NEAR(at(mid, ny - 1).y(), s.a_mm.front(), 1e-2);
  EXPECT_NEAR(at(mid, ny - 1).z(), s.z_max_mm, 1e-2);
  // The central fibre is inextensible (eq. 9): its sampled length approaches h from below.
  double length = 0.0;
  for (int j = 1; j < ny; ++j) {
    length += (at(mid, j) - at(mid, j - 1)).cast<double>().norm();
  }
  EXPECT_LE(length, p.hanging.height_mm * (1.0 + 1e-6));
  EXPECT_GT(length, p.hanging.height_mm * 0.995);
  for (const Eigen::Vector3f& n : grid.normals) {
    EXPECT_NEAR(n.norm(), 1.0f, 1e-5f);
  }
}

TEST(DeformedGrid, FibreErrorShrinksWithResolution) {
  const Parameters p = exact_default();
  const Solution s = solve(p);
  // ny below the number of folds cuts corners of the zig-zag; the error is a real diagnostic.
  const double coarse = deformed_grid(s, p, 8, 6).worst_fibre_error;
  const double medium = deformed_grid(s, p, 8, 64).worst_fibre_error;
  const double fine = deformed_grid(s, p, 8, 1024).worst_fibre_error;
  EXPECT_GT(coarse, medium);
  EXPECT_GT(medium, fine);
  EXPECT_GT(coarse, 0.05);
  EXPECT_LT(fine, 2e-3);
}

TEST(DeformedGrid, NoSlackIsTheFlatMembrane) {
  Parameters p = exact_default();
  p.hanging.support_displacement_mm = 0.0;
  const Solution s = solve(p);
  const DeformedGrid grid = deformed_grid(s, p, 9, 5);
  const double L = p.hanging.length_mm;
  const double h = p.hanging.height_mm;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 9; ++i) {
      const Eigen::Vector3f v = grid.positions_mm[static_cast<std::size_t>(j * 9 + i)];
      const double X = L * (i / 8.0 - 0.5);
      EXPECT_NEAR(v.x(), X, 1e-3);
      // Cosine membrane: fibre length h cos(pi X / L), point at fraction Y/h of it.
      EXPECT_NEAR(v.y(), (j / 4.0) * h * std::cos(std::numbers::pi * X / L), 1e-3);
      EXPECT_EQ(v.z(), 0.0f);
    }
  }
  EXPECT_NEAR(grid.worst_fibre_error, 0.0, 1e-12);
  // Interior normals of a flat sheet are +-z.
  EXPECT_NEAR(std::abs(grid.normals[2 * 9 + 4].z()), 1.0f, 1e-6f);
}

TEST(VertexNormals, AreaWeightedOnAKnownMesh) {
  // Two triangles of a unit square in the xy plane, wound so their normals are +z.
  const std::vector<Eigen::Vector3f> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 1, 3, 2};
  for (const Eigen::Vector3f& n : vertex_normals(positions, indices)) {
    EXPECT_NEAR(n.z(), 1.0f, 1e-7f);
  }
  // A degenerate triangle gives the documented fallback.
  const auto degenerate = vertex_normals({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, {0, 1, 2});
  EXPECT_EQ(degenerate[0], Eigen::Vector3f::UnitZ());
}

}  // namespace
}  // namespace foldlab
