// The fold occlusion against surfaces whose horizons are known in closed form: a flat sheet, a
// V-shaped pleat and its crest, and a pleat wider than the reach.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/fold_occlusion.hpp"

namespace foldlab {
namespace {

struct Sheet {
  int nx = 0;
  int ny = 0;
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;
  std::size_t at(int i, int j) const { return static_cast<std::size_t>(j) * nx + i; }
};

// A grid over (x, y) = (i, j) * spacing with height z(x, y); every normal +z, so that the test
// states the normal rather than taking it from the code under test.
Sheet height_field(int nx, int ny, float spacing, const std::function<float(float, float)>& z) {
  Sheet s{nx, ny, {}, {}};
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const float x = static_cast<float>(i) * spacing;
      const float y = static_cast<float>(j) * spacing;
      s.positions.emplace_back(x, y, z(x, y));
      s.normals.emplace_back(0.0f, 0.0f, 1.0f);
    }
  }
  return s;
}

TEST(FoldOcclusion, AFlatSheetSeesTheWholeSkyOnBothFaces) {
  const Sheet s = height_field(9, 7, 2.0f, [](float, float) { return 0.0f; });
  const FoldOcclusion o = fold_occlusion(s.positions, s.normals, s.nx, s.ny, 10.0f);
  ASSERT_EQ(o.front.size(), s.positions.size());
  for (std::size_t v = 0; v < s.positions.size(); ++v) {
    EXPECT_FLOAT_EQ(o.front[v], 0.0f);
    EXPECT_FLOAT_EQ(o.back[v], 0.0f);
  }
}

// A pleat z = tan(theta) |y - y0| running along x. From its bottom the walls across the pleat
// stand at theta, the diagonals at atan(tan(theta) / sqrt 2) (they run sqrt 2 as far for the same
// rise) and the two directions along the pleat at 0: the mean of the eight sines.
TEST(FoldOcclusion, TheBottomOfAVPleatIsHiddenByItsWalls) {
  const float theta = 0.6f;
  const float y0 = 8.0f;
  const Sheet s =
      height_field(9, 9, 1.0f, [&](float, float y) { return std::tan(theta) * std::abs(y - y0); });
  const FoldOcclusion o = fold_occlusion(s.positions, s.normals, s.nx, s.ny, 100.0f);
  const float expected =
      (2.0f * std::sin(theta) + 4.0f * std::sin(std::atan(std::tan(theta) / std::sqrt(2.0f)))) /
      8.0f;
  // Row 8 is the last one: its bottom has no cloth beyond it, so take a pleat in the middle.
  const Sheet middle =
      height_field(9, 17, 1.0f, [&](float, float y) { return std::tan(theta) * std::abs(y - y0); });
  const FoldOcclusion m = fold_occlusion(middle.positions, middle.normals, 9, 17, 100.0f);
  EXPECT_NEAR(m.front[middle.at(4, 8)], expected, 1e-5f);
  EXPECT_NEAR(m.back[middle.at(4, 8)], 0.0f, 1e-6f);  // seen from below it is a crest
  // At the last row only the five directions that have cloth count: up the wall (theta), two
  // diagonals, and along the pleat.
  const float edge =
      (std::sin(theta) + 2.0f * std::sin(std::atan(std::tan(theta) / std::sqrt(2.0f)))) / 5.0f;
  EXPECT_NEAR(o.front[s.at(4, 8)], edge, 1e-5f);
}

TEST(FoldOcclusion, ACrestHidesTheBackFaceAsAPleatHidesTheFront) {
  const float theta = 0.4f;
  const auto pleat = [&](float, float y) { return std::tan(theta) * std::abs(y - 9.0f); };
  const Sheet a = height_field(7, 13, 1.5f, pleat);
  const Sheet b = height_field(7, 13, 1.5f, [&](float x, float y) { return -pleat(x, y); });
  const FoldOcclusion oa = fold_occlusion(a.positions, a.normals, 7, 13, 50.0f);
  const FoldOcclusion ob = fold_occlusion(b.positions, b.normals, 7, 13, 50.0f);
  EXPECT_GT(oa.front[a.at(3, 6)], 0.1f);
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    EXPECT_NEAR(oa.front[v], ob.back[v], 1e-6f);
    EXPECT_NEAR(oa.back[v], ob.front[v], 1e-6f);
  }
}

// A flat-bottomed pleat 2 w wide: its walls hide the middle only when the reach gets to them.
TEST(FoldOcclusion, WallsBeyondTheReachHideNothing) {
  const float w = 4.0f;
  const Sheet s = height_field(
      33, 33, 1.0f, [&](float, float y) { return std::max(0.0f, std::abs(y - 16.0f) - w) * 2.0f; });
  const FoldOcclusion near = fold_occlusion(s.positions, s.normals, 33, 33, 3.0f);
  const FoldOcclusion far = fold_occlusion(s.positions, s.normals, 33, 33, 12.0f);
  EXPECT_FLOAT_EQ(near.front[s.at(16, 16)], 0.0f);
  // Neighbours are looked at 1, 2, 4, 8, ... steps away. Within a reach of 12, across the pleat
  // the one 8 rows away is 4 rows up the wall (rise 8, 11.3 away): sin = 8 / hypot(8, 8). The
  // diagonal one 8 steps away is |(8, 8, 8)| = 13.9 away, beyond the reach, and the one 4 steps
  // away is still on the flat bottom: the diagonals and the two sides along the pleat see 0.
  const float across = 8.0f / std::hypot(8.0f, 8.0f);
  EXPECT_NEAR(far.front[s.at(16, 16)], 2.0f * across / 8.0f, 1e-5f);
}

// A grid finer than the lattice is looked at every stride-th vertex: there it sees what the
// coarse grid of those vertices sees, and in between it is the bilinear blend.
TEST(FoldOcclusion, AFineGridIsSampledOnALatticeAndBlendedBetween) {
  const auto folds = [](float x, float y) {
    return 6.0f * std::sin(0.21f * y) + 0.5f * std::cos(0.05f * x);
  };
  const int fine = 2 * kFoldOcclusionSamples + 1;
  ASSERT_EQ(fold_occlusion_stride(fine, fine), 2);
  ASSERT_EQ(fold_occlusion_stride(kFoldOcclusionSamples + 1, kFoldOcclusionSamples + 1), 1);
  ASSERT_EQ(fold_occlusion_stride(512, 512), 8) << "65 lattice rows and columns, the last included";
  Sheet a = height_field(fine, fine, 1.0f, folds);
  Sheet b = height_field(kFoldOcclusionSamples + 1, kFoldOcclusionSamples + 1, 2.0f, folds);
  // Tilted normals, the same at the same point of both grids.
  for (Sheet* sheet : {&a, &b}) {
    for (std::size_t v = 0; v < sheet->positions.size(); ++v) {
      const Eigen::Vector3f& p = sheet->positions[v];
      sheet->normals[v] =
          Eigen::Vector3f(0.0f, -1.26f * std::cos(0.21f * p.y()), 1.0f).normalized();
    }
  }
  const FoldOcclusion oa = fold_occlusion(a.positions, a.normals, fine, fine, 20.0f);
  const FoldOcclusion ob = fold_occlusion(b.positions, b.normals, b.nx, b.ny, 20.0f);
  float largest = 0.0f;
  for (int j = 0; j < b.ny; ++j) {
    for (int i = 0; i < b.nx; ++i) {
      ASSERT_EQ(oa.front[a.at(2 * i, 2 * j)], ob.front[b.at(i, j)]) << i << ", " << j;
      ASSERT_EQ(oa.back[a.at(2 * i, 2 * j)], ob.back[b.at(i, j)]) << i << ", " << j;
      largest = std::max(largest, ob.front[b.at(i, j)]);
    }
  }
  EXPECT_GT(largest, 0.2f) << "the folds hide some sky";
  const float between = oa.front[a.at(21, 40)];
  EXPECT_NEAR(between, 0.5f * (ob.front[b.at(10, 20)] + ob.front[b.at(11, 20)]), 1e-6f);
  const float centre = oa.front[a.at(21, 41)];
  EXPECT_NEAR(centre,
              0.25f * (ob.front[b.at(10, 20)] + ob.front[b.at(11, 20)] + ob.front[b.at(10, 21)] +
                       ob.front[b.at(11, 21)]),
              1e-6f);
}

TEST(FoldOcclusion, AMismatchedGridGivesNoOcclusion) {
  const Sheet s = height_field(4, 4, 1.0f, [](float x, float) { return x * x; });
  const FoldOcclusion o = fold_occlusion(s.positions, s.normals, 5, 4, 10.0f);
  ASSERT_EQ(o.front.size(), s.positions.size());
  for (float value : o.front) {
    EXPECT_EQ(value, 0.0f);
  }
}

}  // namespace
}  // namespace foldlab
