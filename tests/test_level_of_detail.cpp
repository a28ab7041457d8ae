// The rows and columns the 3D view draws: strides from the cells' size on screen, a floor of rows
// per fold, the pinned and the longest fibres kept, and the triangles over the kept lattice.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/level_of_detail.hpp"
#include "core/model/solver.hpp"

namespace foldlab {
namespace {

// A flat nx x ny grid, column i at x = i * dx mm, row j at y = j * dy mm, every fibre as long.
DeformedGrid flat_grid(int nx, int ny, float dx, float dy) {
  DeformedGrid grid;
  grid.nx = nx;
  grid.ny = ny;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      grid.positions_mm.emplace_back(static_cast<float>(i) * dx, static_cast<float>(j) * dy, 0.0f);
      grid.material_mm.emplace_back(static_cast<float>(i) * dx, static_cast<float>(j) * dy);
    }
  }
  return grid;
}

// Model mm to clip coordinates such that one mm is one pixel of a width x height viewport.
Eigen::Matrix4f pixel_per_mm(float width, float height) {
  return Eigen::Vector4f(2.0f / width, 2.0f / height, 1.0f, 1.0f).asDiagonal().toDenseMatrix();
}

TEST(LevelOfDetail, TrianglesOfASmallLatticeAreTheTwoPerCellWrittenOut) {
  // 3 x 2 vertices, numbered row by row: 0 1 2 / 3 4 5.
  const std::vector<std::uint32_t> expected = {0, 3, 1, 1, 3, 4, 1, 4, 2, 2, 4, 5};
  EXPECT_EQ(lattice_triangles(3, 2), expected);
  EXPECT_TRUE(lattice_triangles(1, 5).empty());
}

TEST(LevelOfDetail, ScreenSpacingIsTheMeanStepInPixels) {
  const DeformedGrid grid = flat_grid(11, 21, 3.0f, 2.0f);
  const ScreenSpacing spacing = screen_spacing(grid, pixel_per_mm(800, 600), {800, 600});
  EXPECT_NEAR(spacing.across_px, 3.0f, 1e-4f);
  EXPECT_NEAR(spacing.down_px, 2.0f, 1e-4f);
  // Scaling the clip coordinates, w too, moves no pixel; scaling x and y alone is a zoom.
  const ScreenSpacing same = screen_spacing(grid, 2.0f * pixel_per_mm(800, 600), {800, 600});
  EXPECT_NEAR(same.across_px, 3.0f, 1e-4f);
  Eigen::Matrix4f closer = pixel_per_mm(800, 600);
  closer(0, 0) *= 2.0f;
  closer(1, 1) *= 2.0f;
  const ScreenSpacing doubled = screen_spacing(grid, closer, {800, 600});
  EXPECT_NEAR(doubled.across_px, 6.0f, 1e-4f);
  EXPECT_NEAR(doubled.down_px, 4.0f, 1e-4f);
}

TEST(LevelOfDetail, ADeviationAlongTheViewStillKeepsItsRows) {
  // Every fourth row, from row 2, 4 mm towards the eye: no pixel moves, but a lattice that skips
  // those rows would cut through the pleats and change what hides what. Stride 2 keeps them all.
  DeformedGrid grid = flat_grid(65, 65, 0.1f, 0.1f);
  for (int j = 2; j < grid.ny; j += 4) {
    for (int i = 0; i < grid.nx; ++i) {
      grid.positions_mm[static_cast<std::size_t>(j) * grid.nx + i].z() = 4.0f;
    }
  }
  const ScreenSpacing deep = screen_spacing(grid, pixel_per_mm(800, 600), {800, 600});
  EXPECT_NEAR(deep.down_px, 0.1f, 1e-4f);  // the view direction shows no length
  EXPECT_EQ(deep.faithful_down, 2);
  EXPECT_GE(deep.faithful_across, 4);  // the rows themselves are straight
  EXPECT_EQ(drawn_lattice(grid, deep, 0).rows.size(), 33u);
  // The same pleats scaled down to 0.04 mm (a world scale of 0.01 in z) are within half a pixel.
  const ScreenSpacing shallow =
      screen_spacing(grid, pixel_per_mm(800, 600), {800, 600}, Eigen::Vector3f(1.0f, 1.0f, 0.01f));
  EXPECT_GE(shallow.faithful_down, 4);
  EXPECT_LT(drawn_lattice(grid, shallow, 0).rows.size(), 20u);
}

TEST(LevelOfDetail, AGridBehindTheEyeIsDrawnInFull) {
  const DeformedGrid grid = flat_grid(40, 40, 1.0f, 1.0f);
  Eigen::Matrix4f behind = pixel_per_mm(800, 600);
  behind(3, 3) = -1.0f;
  const ScreenSpacing spacing = screen_spacing(grid, behind, {800, 600});
  EXPECT_TRUE(std::isinf(spacing.across_px));
  EXPECT_TRUE(drawn_lattice(grid, spacing, 0).is_full(grid));
}

TEST(LevelOfDetail, StridesGiveCellsOfAboutTheGoalAndKeepTheEnds) {
  const DeformedGrid grid = flat_grid(129, 129, 1.0f, 1.0f);
  // 1 px between columns, 0.8 px between rows, a 5 px goal: every 5th column, every 6th row.
  const DrawnLattice lattice = drawn_lattice(grid, {1.0f, 0.8f}, 0, DetailGoal{5.0f, 6});
  ASSERT_GE(lattice.columns.size(), 2u);
  EXPECT_EQ(lattice.columns[1] - lattice.columns[0], 5);
  EXPECT_EQ(lattice.rows[1] - lattice.rows[0], 6);
  EXPECT_EQ(lattice.columns.front(), 0);
  EXPECT_EQ(lattice.columns.back(), 128);
  EXPECT_EQ(lattice.rows.back(), 128);
  EXPECT_EQ(lattice.columns.size(), 27u);  // 0, 5, ..., 125 and 128
  EXPECT_TRUE(std::is_sorted(lattice.rows.begin(), lattice.rows.end()));
  // Cells already larger than the goal: every vertex.
  EXPECT_TRUE(drawn_lattice(grid, {6.0f, 9.0f}, 0).is_full(grid));
}

TEST(LevelOfDetail, EachFoldKeepsItsRows) {
  const DeformedGrid grid = flat_grid(129, 129, 1.0f, 1.0f);
  // 0.1 px rows would allow a stride of 50; 7 folds (8 segments) at 6 rows each allow 128/48 = 2.
  const DrawnLattice lattice = drawn_lattice(grid, {0.1f, 0.1f}, 7, DetailGoal{5.0f, 6});
  EXPECT_EQ(lattice.rows[1] - lattice.rows[0], 2);
  EXPECT_EQ(lattice.rows.size(), 65u);
  // More folds than rows to spare: every row.
  EXPECT_EQ(drawn_lattice(grid, {0.1f, 0.1f}, 30).rows.size(), 129u);
  EXPECT_EQ(drawn_lattice(grid, {0.1f, 0.1f}, 10'000'000).rows.size(), 129u);
}

TEST(LevelOfDetail, AGridSeenEdgeOnKeepsSixteenColumns) {
  const DeformedGrid grid = flat_grid(513, 513, 1.0f, 1.0f);
  const DrawnLattice lattice = drawn_lattice(grid, {0.0f, 0.0f}, 0);
  EXPECT_GE(lattice.columns.size(), 17u);
  EXPECT_LE(lattice.columns.size(), 18u);
  EXPECT_GE(lattice.rows.size(), 17u);
}

TEST(LevelOfDetail, StripSupportsAndEachSpansLongestFibreAreAlwaysDrawn) {
  Parameters p;
  p.model.method = Method::exact;
  p.shape.kind = ShapeKind::strip;
  p.shape.supports = 4;  // three spans
  const Solution s = solve(p);
  // 103 columns over three spans: the inner supports fall at columns 34 and 68, the spans'
  // middles at 17, 51 and 85, none of them a multiple of the stride (6, the coarsest that keeps
  // 16 columns).
  const DeformedGrid grid = deformed_grid_positions(s, p, 103, 64);
  const auto fibre = [&](int i) {
    return grid.material_mm[static_cast<std::size_t>(grid.ny - 1) * grid.nx + i].y();
  };
  std::vector<int> pinned;
  std::vector<int> longest;
  for (int i = 1; i + 1 < grid.nx; ++i) {
    if (fibre(i) <= fibre(i - 1) && fibre(i) <= fibre(i + 1)) {
      pinned.push_back(i);
    }
    if (fibre(i) >= fibre(i - 1) && fibre(i) >= fibre(i + 1)) {
      longest.push_back(i);
    }
  }
  ASSERT_EQ(pinned.size(), 2u);   // the two inner supports
  ASSERT_GE(longest.size(), 3u);  // each span's middle (two columns where it falls between)
  const DrawnLattice lattice = drawn_lattice(grid, {0.2f, 0.2f}, s.n);
  EXPECT_EQ(lattice.columns[1], 6);
  ASSERT_LT(lattice.columns.size(), 30u);
  for (int i : pinned) {
    EXPECT_TRUE(std::binary_search(lattice.columns.begin(), lattice.columns.end(), i)) << i;
  }
  for (int i : longest) {
    EXPECT_TRUE(std::binary_search(lattice.columns.begin(), lattice.columns.end(), i)) << i;
  }
}

}  // namespace
}  // namespace foldlab
