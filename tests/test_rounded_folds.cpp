// Rounded folds: the invariants of the model (folds at a_i, centre fibre h long, upper edge L long)
// measured on the rounded geometry by quadrature, and the bending-stiffness rule for the radius.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/geometry.hpp"
#include "core/geometry/rounded_folds.hpp"
#include "core/geometry/scene.hpp"
#include "core/model/solver.hpp"

namespace foldlab {
namespace {

// The three fabric presets (presets/fabric-*.json), solved exactly so that eqs. 8 and 9 hold to
// machine precision and every difference below is the rounding's.
Parameters fabric(double thickness_mm, double youngs_modulus_MPa, double weight_N_per_mm2) {
  Parameters p;
  p.fabric.thickness_mm = thickness_mm;
  p.fabric.youngs_modulus_MPa = youngs_modulus_MPa;
  p.fabric.weight_N_per_mm2 = weight_N_per_mm2;
  p.model.method = Method::exact;
  return p;
}
Parameters chiffon() {
  return fabric(0.09, 78.0, 3.434e-7);
}
Parameters poplin() {
  return fabric(0.2, 160.0, 1.177e-6);
}
Parameters denim() {
  return fabric(0.8, 150.0, 4.326e-6);
}

// Points every `step_mm` of arc length along the centre fibre, in double precision.
std::vector<Eigen::Vector2d> sample(const CentreFibre& fibre, int count) {
  std::vector<Eigen::Vector2d> points;
  std::size_t piece = 0;
  for (int k = 0; k < count; ++k) {
    points.push_back(fibre.at_length(fibre.length_mm() * k / (count - 1), piece));
  }
  return points;
}

template <class Point>
double polyline_length(const std::vector<Point>& points) {
  double length = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) {
    length += (points[k] - points[k - 1]).template cast<double>().norm();
  }
  return length;
}

// The centre column (X = 0, nx odd) of a grid, in double precision.
std::vector<Eigen::Vector3d> centre_column(const DeformedGrid& grid) {
  std::vector<Eigen::Vector3d> column;
  for (int j = 0; j < grid.ny; ++j) {
    column.push_back(
        grid.positions_mm[static_cast<std::size_t>(j * grid.nx + grid.nx / 2)].cast<double>());
  }
  return column;
}

TEST(BendingStiffness, PlateFormulaAndPeircesBendingLength) {
  // Table 1's fabric: 165 MPa x (0.25 mm)³ / (12 x 0.91) = 0.2360920 N mm, and the cube root of
  // B / 1.5e-6 N/mm² = 157394.7 mm³ is 53.99208 mm (values computed by hand, not by the code).
  const Fabric table1;
  EXPECT_NEAR(bending_stiffness_Nmm(table1), 0.2360920330, 1e-9);
  EXPECT_NEAR(bending_length_mm(table1), 53.992076, 1e-5);
  // The three presets: chiffon bends at 24.75 mm, poplin at 46.35 mm, denim at 117.58 mm.
  EXPECT_NEAR(bending_length_mm(chiffon().fabric), 24.7514, 1e-3);
  EXPECT_NEAR(bending_length_mm(poplin().fabric), 46.3522, 1e-3);
  EXPECT_NEAR(bending_length_mm(denim().fabric), 117.5847, 1e-3);
}

TEST(RoundedFolds, CentreFibreKeepsLengthHByIndependentQuadrature) {
  for (const Parameters& p : {chiffon(), poplin(), denim(), Parameters{}}) {
    const Solution s = solve(p);
    ASSERT_GE(s.n, 2);
    const double h = p.hanging.height_mm;
    const FoldRounding rounding = fold_rounding(s, p);
    ASSERT_TRUE(rounding.rounded);
    ASSERT_TRUE(rounding.length_kept);
    const CentreFibre fibre(s, h, rounding);
    // Chords of 200000 steps along the path: the sum converges on its length with an error of
    // about (step / radius)² / 24, far below 1e-7 here; it uses none of the code's arc lengths.
    const std::vector<Eigen::Vector2d> points = sample(fibre, 200001);
    const double quadrature = polyline_length(points);
    EXPECT_NEAR(quadrature / h, 1.0, 1e-7);
    EXPECT_NEAR(fibre.length_mm() / h, 1.0, 1e-12);
    // The points are spaced by arc length: no chord longer than the step (a wrong arc formula
    // would stretch or squeeze some).
    const double step = fibre.length_mm() / 200000.0;
    for (std::size_t k = 1; k < points.size(); ++k) {
      EXPECT_LE((points[k] - points[k - 1]).norm(), step * (1.0 + 1e-9)) << k;
    }
    // As an export samples it (129 x 513), the centre column keeps h within 0.5 %.
    const DeformedGrid grid = deformed_grid(s, p, 129, 513);
    EXPECT_NEAR(polyline_length(centre_column(grid)) / h, 1.0, 5e-3);
  }
}

TEST(RoundedFolds, UpperEdgeKeepsZMaxAndLengthL) {
  for (const Parameters& p : {chiffon(), poplin(), denim()}) {
    const Solution s = solve(p);
    const double L = p.hanging.length_mm;
    const double l = s.span_mm;
    const int nx = 8193;
    const DeformedGrid grid = deformed_grid(s, p, nx, 3);
    std::vector<Eigen::Vector3d> edge;
    for (int i = 0; i < nx; ++i) {
      const Eigen::Vector3d v = grid.positions_mm[static_cast<std::size_t>(i)].cast<double>();
      // Eq. 6 and eq. 4 at the upper edge with the solution's own a_n and z_max.
      const double c = std::cos(std::numbers::pi * v.x() / l);
      ASSERT_NEAR(v.y(), s.a_mm.back() * c, 1e-3);
      ASSERT_NEAR(v.z(), fold_sign(s.n) * s.z_max_mm * c, 1e-3);
      edge.push_back(v);
    }
    // Eq. 8 by quadrature (8192 chords of float vertices): L to a few parts in a million.
    EXPECT_NEAR(polyline_length(edge) / L, 1.0, 2e-5);
  }
}

TEST(RoundedFolds, CrestsSitAtTheFoldDepthsAi) {
  for (const Parameters& p : {chiffon(), poplin(), denim()}) {
    const Solution s = solve(p);
    const FoldRounding rounding = fold_rounding(s, p);
    const CentreFibre fibre(s, p.hanging.height_mm, rounding);
    const std::vector<Eigen::Vector2d> points = sample(fibre, 400001);
    const double step = fibre.length_mm() / 400000.0;
    // Ends: the upper edge (a_n, z_max) and the lower boundary (a_0, +depth).
    EXPECT_NEAR(points.front().x(), s.a_mm.back(), 1e-9);
    EXPECT_NEAR(points.front().y(), fold_sign(s.n) * s.z_max_mm, 1e-9);
    EXPECT_NEAR(points.back().x(), s.a_mm.front(), 1e-6);
    EXPECT_NEAR(points.back().y(), rounding.depth_scale * s.z_max_mm, 1e-6);
    // Interior crests are the extremes of z: one per fold, at y = a_i with z = +-depth.
    std::vector<Eigen::Vector2d> crests;
    for (std::size_t k = 1; k + 1 < points.size(); ++k) {
      const double before = points[k].y() - points[k - 1].y();
      const double after = points[k + 1].y() - points[k].y();
      if ((before > 0.0 && after <= 0.0) || (before < 0.0 && after >= 0.0)) {
        crests.push_back(points[k]);
      }
      // Gravity pulls every fibre down: the rounded fibre never climbs.
      ASSERT_GE(points[k + 1].x() - points[k].x(), -1e-9) << k;
    }
    ASSERT_EQ(crests.size(), static_cast<std::size_t>(s.n) - 1);
    for (int i = 1; i < s.n; ++i) {
      const Eigen::Vector2d& crest = crests[static_cast<std::size_t>(s.n - 1 - i)];
      EXPECT_NEAR(crest.x(), s.a_mm[static_cast<std::size_t>(i)], step) << "fold " << i;
      EXPECT_NEAR(crest.y(), fold_sign(i) * rounding.depth_scale * s.z_max_mm, 1e-6) << i;
    }
    // The fold lines drawn on the cloth follow the same depths.
    const FoldLines lines = fold_lines(s, p, 3);
    for (const FoldLine& line : lines.lines) {
      const double depth = line.index == s.n ? s.z_max_mm : rounding.depth_scale * s.z_max_mm;
      EXPECT_NEAR(line.points_mm[1].z(), line.sign * depth, 1e-9);
    }
  }
}

TEST(RoundedFolds, AStifferFabricGivesRounderFolds) {
  // One solution, two fabrics: only the bending stiffness differs, so only the rounding can.
  const Parameters base = poplin();
  const Solution s = solve(base);
  Parameters soft = base;
  soft.fabric.youngs_modulus_MPa = 20.0;  // c_b = 46.35 mm x (20/160)^(1/3) = 23.18 mm
  const FoldRounding soft_rounding = fold_rounding(s, soft);
  const FoldRounding stiff_rounding = fold_rounding(s, base);
  ASSERT_EQ(soft_rounding.radius_mm.size(), stiff_rounding.radius_mm.size());
  double soft_sum = 0.0;
  double stiff_sum = 0.0;
  for (std::size_t i = 0; i < soft_rounding.radius_mm.size(); ++i) {
    EXPECT_LE(soft_rounding.radius_mm[i], stiff_rounding.radius_mm[i]) << i;
    soft_sum += soft_rounding.radius_mm[i];
    stiff_sum += stiff_rounding.radius_mm[i];
  }
  EXPECT_GT(stiff_sum, soft_sum * 1.2);
  // Wider crests need more length, so the stiffer fabric's folds come in further.
  EXPECT_LT(stiff_rounding.depth_scale, soft_rounding.depth_scale);
  const double h = base.hanging.height_mm;
  const double soft_turn = sharpest_turn_deg(sample(CentreFibre(s, h, soft_rounding), 513));
  const double stiff_turn = sharpest_turn_deg(sample(CentreFibre(s, h, stiff_rounding), 513));
  const double sharp_turn =
      sharpest_turn_deg(sample(CentreFibre(s, h, fold_rounding(s, h, 0)), 513));
  EXPECT_LT(stiff_turn, soft_turn);
  EXPECT_LT(soft_turn, sharp_turn);

  // Across the presets, each with its own solution: chiffon < poplin < denim in bending length,
  // and the 129 x 513 export's sharpest turn falls in the same order, each far below the sharp
  // zig-zag's.
  double previous_turn = 180.0;
  double previous_length = 0.0;
  for (const Parameters& p : {chiffon(), poplin(), denim()}) {
    const Solution here = solve(p);
    const DeformedGrid rounded = deformed_grid(here, p, 129, 513);
    const DeformedGrid sharp = deformed_grid_positions(
        here, p,
        CentreFibre(here, p.hanging.height_mm, fold_rounding(here, p.hanging.height_mm, 0)), 129,
        513);
    EXPECT_GT(bending_length_mm(p.fabric), previous_length);
    EXPECT_LT(rounded.sharpest_turn_deg, previous_turn);
    EXPECT_LT(rounded.sharpest_turn_deg, 0.3 * sharp.sharpest_turn_deg);
    previous_length = bending_length_mm(p.fabric);
    previous_turn = rounded.sharpest_turn_deg;
  }
}

TEST(RoundedFolds, SharpestTurnIsMeasuredOnTheGridItself) {
  // Independent of the diagnostic: the angle between neighbouring segments of the centre column.
  const Parameters p = chiffon();
  const Solution s = solve(p);
  const DeformedGrid grid = deformed_grid(s, p, 129, 513);
  const std::vector<Eigen::Vector3d> column = centre_column(grid);
  double sharpest = 0.0;
  for (std::size_t j = 1; j + 1 < column.size(); ++j) {
    const Eigen::Vector3d a = column[j] - column[j - 1];
    const Eigen::Vector3d b = column[j + 1] - column[j];
    sharpest =
        std::max(sharpest, std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0)));
  }
  EXPECT_NEAR(grid.sharpest_turn_deg, sharpest * 180.0 / std::numbers::pi, 0.1);
  // A crest of radius R sampled every h/512 turns by (h/512)/R between rows: chiffon's tightest
  // crests are limited by their flanks, not by c_b.
  const FoldRounding rounding = fold_rounding(s, p);
  const double tightest = *std::min_element(rounding.radius_mm.begin(), rounding.radius_mm.end());
  EXPECT_NEAR(grid.sharpest_turn_deg, p.hanging.height_mm / 512 / tightest * 180 / std::numbers::pi,
              0.5);
}

TEST(RoundedFolds, RadiusIsTheBendingLengthWhereItFitsAndDepthDropIsReported) {
  const Parameters p = denim();  // two wide flanks: every crest takes c_b
  const Solution s = solve(p);
  const FoldRounding rounding = fold_rounding(s, p);
  for (double r : rounding.radius_mm) {
    EXPECT_NEAR(r, bending_length_mm(p.fabric), 1e-12);
  }
  EXPECT_GT(rounding.depth_scale, 0.85);
  EXPECT_LT(rounding.depth_scale, 0.95);
}

TEST(RoundedFolds, DegenerateCasesStayFinite) {
  // No slack: no folds, a straight fibre of length h from the supports' line.
  Parameters flat = poplin();
  flat.hanging.support_displacement_mm = 0.0;
  const Solution none = solve(flat);
  const FoldRounding no_rounding = fold_rounding(none, flat);
  EXPECT_FALSE(no_rounding.rounded);
  const CentreFibre straight(none, flat.hanging.height_mm, no_rounding);
  EXPECT_NEAR(straight.length_mm(), flat.hanging.height_mm, 1e-12);
  // A radius of 0 is the paper's zig-zag, unchanged.
  const Parameters p = poplin();
  const Solution s = solve(p);
  const FoldRounding sharp = fold_rounding(s, p.hanging.height_mm, 0.0);
  EXPECT_FALSE(sharp.rounded);
  EXPECT_EQ(sharp.depth_scale, 1.0);
  // Thousands of folds: too many for any grid to show a crest; the zig-zag stays.
  Parameters many = fabric(0.003, 165.0, 1.5e-6);
  const Solution dense = solve(many);
  ASSERT_GT(dense.n, kMaxRoundedFolds);
  EXPECT_FALSE(fold_rounding(dense, many).rounded);
  // A huge radius on few folds: every crest is limited by its flanks, and the length still holds.
  const FoldRounding huge = fold_rounding(s, p.hanging.height_mm, 1e6);
  ASSERT_TRUE(huge.rounded);
  EXPECT_TRUE(std::isfinite(huge.depth_scale));
  EXPECT_NEAR(CentreFibre(s, p.hanging.height_mm, huge).length_mm(), p.hanging.height_mm, 1e-9);
}

}  // namespace
}  // namespace foldlab

namespace foldlab {
namespace {

TEST(RoundedFolds, SceneDrawsFoldLinesOnTheRoundedGrid) {
  const Parameters p = chiffon();
  Scene scene(p);
  scene.set_grid_resolution(129, 513);
  const Solution& s = scene.solution();
  const DeformedGrid reference = deformed_grid_positions(s, p, 129, 513);
  const DeformedGrid& grid = scene.grid();
  ASSERT_EQ(grid.positions_mm.size(), reference.positions_mm.size());
  for (std::size_t v = 0; v < grid.positions_mm.size(); v += 97) {
    EXPECT_EQ(grid.positions_mm[v], reference.positions_mm[v]) << v;
  }
  EXPECT_EQ(grid.sharpest_turn_deg, reference.sharpest_turn_deg);
  // The lowest fold line meets the grid's bottom row at the centre: both at the rounded depth.
  const FoldLines& lines = scene.fold_lines();
  const FoldLine& lowest = lines.lines.front();
  ASSERT_EQ(lowest.index, 0);
  const Eigen::Vector3d middle = lowest.points_mm[lowest.points_mm.size() / 2];
  const Eigen::Vector3f bottom = grid.positions_mm[static_cast<std::size_t>(512 * 129 + 64)];
  EXPECT_NEAR(middle.y(), bottom.y(), 1e-3);
  EXPECT_NEAR(middle.z(), bottom.z(), 1e-3);
  EXPECT_LT(middle.z(), s.z_max_mm * 0.95);
}

}  // namespace
}  // namespace foldlab
