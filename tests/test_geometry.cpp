// Fold lines (eq. 6 and eq. 4) and the deformed grid (docs/model.md, "The deformed cloth").
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/geometry/geometry.hpp"
#include "core/model/solver.hpp"

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
  const FoldLines lines = fold_lines(s, p, 33);
  const FoldRounding rounding = fold_rounding(s, p);
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
      // Eq. 4 with the depth the rounded folds keep: z_max at the upper edge, a little less below.
      const double depth = line.index == s.n ? s.z_max_mm : rounding.depth_scale * s.z_max_mm;
      EXPECT_NEAR(q.z(), line.sign * depth * c, 1e-9);
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
  const FoldLines lines = fold_lines(s, p, 5, 100);
  EXPECT_LE(static_cast<int>(lines.lines.size()), 100);
  EXPECT_GT(lines.stride, 1);
  EXPECT_EQ(lines.lines[1].index, lines.stride);
  EXPECT_EQ(s.a_mm.size(), static_cast<std::size_t>(s.n) + 1);  // the solution keeps every fold
}

TEST(FoldLines, PointCountMatchesTheLinesBuilt) {
  // The export budget counts points before building them: the count must be what is built.
  for (const double thickness_mm : {0.25, 0.01}) {
    for (const int supports : {2, 5}) {
      Parameters p = exact_default();
      p.fabric.thickness_mm = thickness_mm;
      p.shape.kind = supports == 2 ? ShapeKind::cosine_membrane : ShapeKind::strip;
      p.shape.supports = supports;
      const Solution s = solve(p);
      const FoldLines lines = fold_lines(s, p, 7, 100);
      std::int64_t built = 0;
      for (const FoldLine& line : lines.lines) {
        built += static_cast<std::int64_t>(line.points_mm.size());
      }
      EXPECT_EQ(fold_line_point_count(s, p.shape, 7, 100), built)
          << "t = " << thickness_mm << ", supports = " << supports;
    }
  }
}

TEST(FoldLines, NoneWithoutFolds) {
  Parameters p = exact_default();
  p.hanging.support_displacement_mm = 0.0;
  EXPECT_TRUE(fold_lines(solve(p), p, 10).lines.empty());
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
  // The central column starts at the upper edge (a_n, sign_n z_max) and ends at a_0 (+z of the
  // rounded folds).
  const int mid = nx / 2;
  const double lowest_depth = fold_rounding(s, p).fold_depth_mm(s, 0);
  EXPECT_NEAR(at(mid, 0).x(), 0.0, 1e-3);
  EXPECT_NEAR(at(mid, 0).y(), s.a_mm.back(), 1e-3);
  EXPECT_NEAR(at(mid, 0).z(), fold_sign(s.n) * s.z_max_mm, 1e-3);
  EXPECT_NEAR(at(mid, ny - 1).y(), s.a_mm.front(), 1e-2);
  EXPECT_NEAR(at(mid, ny - 1).z(), lowest_depth, 1e-2);
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

namespace foldlab {
namespace {

TEST(Shapes, StripRepeatsTheSpanAndKeepsEverySupportFixed) {
  Parameters p = exact_default();
  p.shape.kind = ShapeKind::strip;
  p.shape.supports = 4;  // three spans
  const Solution s = solve(p);
  const double l = s.span_mm;
  const FoldLines lines = fold_lines(s, p, 21);
  ASSERT_EQ(lines.lines.size(), 3u * (s.n + 1));
  // Continuity between spans: each line of span j ends where the same line of span j+1 starts,
  // at a support on y = 0.
  for (std::size_t k = 0; k + (s.n + 1) < lines.lines.size(); ++k) {
    const FoldLine& left = lines.lines[k];
    const FoldLine& right = lines.lines[k + s.n + 1];
    ASSERT_EQ(left.index, right.index);
    EXPECT_NEAR((left.points_mm.back() - right.points_mm.front()).norm(), 0.0, 1e-9);
    EXPECT_NEAR(left.points_mm.back().y(), 0.0, 1e-9);
  }
  EXPECT_NEAR(lines.lines.front().points_mm.front().x(), -1.5 * l, 1e-9);
  EXPECT_NEAR(lines.lines.back().points_mm.back().x(), 1.5 * l, 1e-9);
  // The grid: columns at the four supports collapse onto their support points.
  const int nx = 3 * 16 + 1;
  const DeformedGrid grid = deformed_grid(s, p, nx, 33);
  for (int support = 0; support < 4; ++support) {
    const int i = support * 16;
    for (int j = 0; j < 33; ++j) {
      const Eigen::Vector3f v = grid.positions_mm[static_cast<std::size_t>(j * nx + i)];
      EXPECT_NEAR(v.x(), (support - 1.5) * l, 1e-3);
      EXPECT_NEAR(v.y(), 0.0, 1e-3);
      EXPECT_NEAR(v.z(), 0.0, 1e-3);
    }
  }
}

TEST(Shapes, EverySupportOfAStripIsAColumnWhateverTheGrid) {
  Parameters p = exact_default();
  p.shape.kind = ShapeKind::strip;
  p.shape.supports = 4;
  const Solution s = solve(p);
  // 8, 32 and 101 columns: 7, 31 and 100 intervals, none a multiple of the three spans.
  for (int nx : {8, 32, 101}) {
    const DeformedGrid grid = deformed_grid(s, p, nx, 17);
    for (int support = 0; support < 4; ++support) {
      const double x = (support - 1.5) * s.span_mm;
      int found = -1;
      for (int i = 0; i < nx && found < 0; ++i) {
        if (std::abs(grid.positions_mm[static_cast<std::size_t>(i)].x() - x) < 1e-3) {
          found = i;
        }
      }
      ASSERT_GE(found, 0) << "no column at support " << support << " of grid " << nx;
      for (int j = 0; j < 17; ++j) {  // a fibre of no length: every row at the support
        const Eigen::Vector3f v = grid.positions_mm[static_cast<std::size_t>(j * nx + found)];
        EXPECT_NEAR(v.x(), x, 1e-3);
        EXPECT_NEAR(v.y(), 0.0, 1e-3);
        EXPECT_NEAR(v.z(), 0.0, 1e-3);
      }
    }
  }
}

TEST(Shapes, InclinedSupportsShearThePatternAndKeepTheFoldCount) {
  Parameters p = exact_default();
  const Solution s = solve(p);
  const FoldLines straight = fold_lines(s, p, 41);
  p.shape.kind = ShapeKind::inclined;
  p.shape.incline_deg = 20.0;
  const FoldLines sheared = fold_lines(s, p, 41);
  ASSERT_EQ(sheared.lines.size(), straight.lines.size());
  const double rise = s.span_mm * std::tan(20.0 * std::numbers::pi / 180.0);
  for (std::size_t k = 0; k < sheared.lines.size(); ++k) {
    // The left support stays, the right one is higher by l tan(incline) (y points down).
    EXPECT_NEAR(sheared.lines[k].points_mm.front().y(), 0.0, 1e-9);
    EXPECT_NEAR(sheared.lines[k].points_mm.back().y(), -rise, 1e-9);
    for (std::size_t q = 0; q < sheared.lines[k].points_mm.size(); ++q) {
      const Eigen::Vector3d a = straight.lines[k].points_mm[q];
      const Eigen::Vector3d b = sheared.lines[k].points_mm[q];
      EXPECT_NEAR(b.y() - a.y(), -(a.x() + 0.5 * s.span_mm) * rise / s.span_mm, 1e-9);
      EXPECT_EQ(b.z(), a.z());
    }
  }
  // A shear moves every point of a fibre by the same amount: fibre lengths are unchanged.
  EXPECT_NEAR(deformed_grid(s, p, 9, 257).worst_fibre_error,
              deformed_grid(s, exact_default(), 9, 257).worst_fibre_error, 1e-6);
}

TEST(Shapes, RectangularClothHangsStraightBelowTheLowestFold) {
  Parameters p = exact_default();
  p.shape.kind = ShapeKind::rectangular;
  const Solution s = solve(p);
  const int nx = 17;
  const int ny = 801;
  const DeformedGrid grid = deformed_grid(s, p, nx, ny);
  auto at = [&](int i, int j) { return grid.positions_mm[static_cast<std::size_t>(j * nx + i)]; };
  const double h = p.hanging.height_mm;
  // At a support the whole fibre hangs straight down from it: y from 0 to h, z = 0.
  for (int j = 0; j < ny; j += 100) {
    EXPECT_NEAR(at(0, j).x(), -s.span_mm / 2, 1e-3);
    EXPECT_NEAR(at(0, j).y(), h * j / (ny - 1), 1e-2);
    EXPECT_NEAR(at(0, j).z(), 0.0, 1e-3);
  }
  // Every fibre keeps its length h (up to sampling the zig-zag's corners).
  EXPECT_LT(grid.worst_fibre_error, 5e-3);
  // Between the supports the bottom of a fibre lies below its lowest fold, straight under it.
  const int quarter = nx / 4;  // X = -L/4
  const double c = std::cos(std::numbers::pi / 4);
  EXPECT_NEAR(at(quarter, ny - 1).z(), c * fold_rounding(s, p).fold_depth_mm(s, 0), 1e-2);
  EXPECT_NEAR(at(quarter, ny - 1).y(), c * s.a_mm.front() + (h - c * h), 0.5);
  // Material coordinates run over the flat rectangle.
  EXPECT_NEAR(grid.material_mm.back().x(), p.hanging.length_mm / 2, 1e-3);
  EXPECT_NEAR(grid.material_mm.back().y(), h, 1e-3);
}

}  // namespace
}  // namespace foldlab

namespace foldlab {
namespace {

TEST(Shapes, SupportPointsFollowTheShape) {
  Shape strip;
  strip.kind = ShapeKind::strip;
  strip.supports = 4;
  const std::vector<Eigen::Vector3d> on_strip = support_points(1300.0, strip);
  ASSERT_EQ(on_strip.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(on_strip[static_cast<std::size_t>(k)].x(), (k - 1.5) * 1300.0, 1e-9);
    EXPECT_EQ(on_strip[static_cast<std::size_t>(k)].y(), 0.0);
  }
  Shape inclined;
  inclined.kind = ShapeKind::inclined;
  inclined.incline_deg = 30.0;
  const std::vector<Eigen::Vector3d> raised = support_points(1300.0, inclined);
  ASSERT_EQ(raised.size(), 2u);
  EXPECT_NEAR(raised[0].y(), 0.0, 1e-9);
  EXPECT_NEAR(raised[1].y(), -1300.0 / std::sqrt(3.0), 1e-9);  // tan 30° = 1/sqrt(3)
}

}  // namespace
}  // namespace foldlab
