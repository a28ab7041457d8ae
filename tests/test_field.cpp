// The tension-field solver against what is exact: a homogeneous shear (every triangle's strain,
// state, ray and stress in closed form), a sheet hung from its whole top edge (the weight below
// carried straight up), statics for every outline, refinement, and Mansfield's cosine pencil
// beside the solver's thrust (reported, not asserted: the pencil is an equilibrium, not the
// elastic answer).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "core/field/field_case.hpp"
#include "core/field/field_folds.hpp"
#include "core/field/field_svg.hpp"
#include "core/field/mesh.hpp"
#include "core/field/outline.hpp"
#include "core/field/solver.hpp"

namespace foldlab::field {
namespace {

using Eigen::Vector2d;

// A W x H rectangle on an nx x ny grid with a support at every boundary node, each pinned
// where `map` puts it.
template <class Map>
Outline pinned_rectangle(double W, double H, int nx, int ny, Map map) {
  Outline o;
  o.top_mm = {{0.0, 0.0}, {W, 0.0}};
  o.bottom_mm = {{0.0, H}, {W, H}};
  for (int i = 0; i <= nx; ++i) {
    for (int j = 0; j <= ny; ++j) {
      if (i == 0 || i == nx || j == 0 || j == ny) {
        const Vector2d at(W * i / nx, H * j / ny);
        o.supports.push_back({at, map(at)});
      }
    }
  }
  return o;
}

// Simple shear x -> x + gamma y, no weight: F = [[1, gamma], [0, 1]], so the Green strain is
// E = 1/2 [[0, gamma], [gamma, gamma²]] everywhere. By hand: e = gamma²/4 +- (gamma/2)
// sqrt(1 + gamma²/4); the larger one's direction on the flat cut at angle 1/2 atan2(gamma,
// -gamma²/2); wrinkled when e2 <= -nu e1; then S = Y e1 v1 v1^T and the nominal stress P = F S.
TEST(FieldPatch, HomogeneousShearIsReproducedToRoundOff) {
  const double gamma = 0.1;
  const double W = 120.0;
  const double H = 80.0;
  const int nx = 6;
  const int ny = 4;
  const Outline outline = pinned_rectangle(
      W, H, nx, ny, [&](const Vector2d& p) { return Vector2d(p.x() + gamma * p.y(), p.y()); });
  const Material material{40.0, 0.3, 0.0};
  for (MeshSplit split : {MeshSplit::uniform, MeshSplit::union_jack, MeshSplit::crossed}) {
    SCOPED_TRACE(std::string(to_string(split)));
    const Mesh mesh = make_mesh(outline, {nx, ny, split});
    Solver solver(mesh);
    SolveOptions tight;
    tight.relative_tolerance = 1e-13;
    const Solution s = solver.solve(material, support_targets(outline), tight);
    ASSERT_TRUE(s.converged) << s.relative_residual;

    const double e1 = gamma * gamma / 4 + gamma / 2 * std::sqrt(1 + gamma * gamma / 4);
    const double e2 = gamma * gamma / 4 - gamma / 2 * std::sqrt(1 + gamma * gamma / 4);
    ASSERT_LE(e2, -material.poisson_ratio * e1);  // wrinkled by the table
    const double angle = 0.5 * std::atan2(gamma, -gamma * gamma / 2);
    const Vector2d v1(std::cos(angle), std::sin(angle));
    Eigen::Matrix2d F;
    F << 1, gamma, 0, 1;
    const Eigen::Matrix2d P = F * (material.stiffness_N_per_mm * e1 * v1 * v1.transpose());
    const Vector2d hung = (F * v1).normalized();
    for (std::size_t n = 0; n < mesh.nodes_mm.size(); ++n) {
      const Vector2d& X = mesh.nodes_mm[n];
      EXPECT_NEAR((s.positions_mm[n] - Vector2d(X.x() + gamma * X.y(), X.y())).norm(), 0.0,
                  1e-9 * W);
    }
    for (const TriangleResult& t : s.triangles) {
      EXPECT_EQ(t.state, State::wrinkled);
      EXPECT_NEAR(t.tension_N_per_mm, material.stiffness_N_per_mm * e1 * std::sqrt(1 + 2 * e1),
                  1e-10);
      EXPECT_NEAR(std::abs(t.flat_direction.dot(v1)), 1.0, 1e-12);
      EXPECT_NEAR(std::abs(t.direction.dot(hung)), 1.0, 1e-12);
      EXPECT_NEAR(t.slack_strain, -(e2 + material.poisson_ratio * e1), 1e-12);
    }
    // A node inside an edge takes the traction on its share of the edge: R = P n * spacing,
    // with n the outward normal (y is down: the top edge's is (0, -1)).
    for (std::size_t i = 0; i < outline.supports.size(); ++i) {
      const Vector2d at = outline.supports[i].at_mm;
      const bool top = at.y() == 0.0 && at.x() > 0.0 && at.x() < W;
      const bool right = at.x() == W && at.y() > 0.0 && at.y() < H;
      if (top) {
        const Vector2d expected = P * Vector2d(0, -1) * (W / nx);
        EXPECT_NEAR((s.reactions_N[i] - expected).norm(), 0.0, 1e-10 * expected.norm());
      }
      if (right) {
        const Vector2d expected = P * Vector2d(1, 0) * (H / ny);
        EXPECT_NEAR((s.reactions_N[i] - expected).norm(), 0.0, 1e-10 * expected.norm());
      }
    }
  }
}

// A sheet hung from every node of its top edge: below the top, each horizontal cut carries the
// weight under it, T_yy = w (h - Y), and each top support away from the corners carries the
// column of cloth under its share of the edge, w h per unit length. The latter is tension field
// theory's statement (no stress across the fibres): with nu > 0 the pinned top restrains the
// cloth's Poisson contraction, and the shear this sets up hands a share of the weight towards the
// corners over a length of the order of the width, so it is asserted for nu = 0 and reported
// for nu = 0.3.
TEST(FieldHungSheet, CarriesTheWeightBelowStraightUp) {
  const double L = 1200.0;
  const double h = 300.0;
  const int nx = 60;
  const int ny = 30;
  Outline o;
  o.top_mm = {{-0.5 * L, 0.0}, {0.5 * L, 0.0}};
  o.bottom_mm = {{-0.5 * L, h}, {0.5 * L, h}};
  for (int i = 0; i <= nx; ++i) {
    const Vector2d at(-0.5 * L + L * i / nx, 0.0);
    o.supports.push_back({at, at});
  }
  const Mesh mesh = make_mesh(o, {nx, ny, MeshSplit::union_jack});
  Solver solver(mesh);
  for (double nu : {0.0, 0.3}) {
    SCOPED_TRACE(nu);
    const Material material{41.25, nu, 1.5e-6};
    const Solution s = solver.solve(material, support_targets(o));
    ASSERT_TRUE(s.converged) << s.relative_residual;
    int checked = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      Vector2d centroid = Vector2d::Zero();
      for (int n : mesh.triangles[t]) {
        centroid += mesh.nodes_mm[n] / 3.0;
      }
      if (std::abs(centroid.x()) > 0.25 * L || centroid.y() < 0.35 * h || centroid.y() > 0.85 * h) {
        continue;
      }
      const double expected = material.weight_N_per_mm2 * (h - centroid.y());
      EXPECT_NEAR(s.triangles[t].tension_N_per_mm, expected, 0.01 * expected)
          << centroid.transpose();
      // Near the taut/wrinkled border (T_xx about 0) the direction is sensitive: within 6 degrees.
      EXPECT_GT(std::abs(s.triangles[t].direction.y()), std::cos(6.0 * std::numbers::pi / 180.0));
      ++checked;
    }
    EXPECT_GT(checked, 50);
    const double per_support = material.weight_N_per_mm2 * h * (L / nx);
    double lowest = 1e300;
    double highest = 0.0;
    for (std::size_t i = 0; i < o.supports.size(); ++i) {
      if (std::abs(o.supports[i].at_mm.x()) <= 0.25 * L) {
        const double share = -s.reactions_N[i].y() / per_support;
        lowest = std::min(lowest, share);
        highest = std::max(highest, share);
        if (nu == 0.0) {
          EXPECT_NEAR(share, 1.0, 0.01);
        }
      }
    }
    std::cout << "hung sheet, nu = " << nu << ": middle supports take " << lowest << " to "
              << highest << " of w h per unit length\n";
  }
}

Parameters default_parameters() {
  Parameters p;  // the Table 1 cloth: t = 0.25 mm, E = 165 MPa, w = 1.5e-6 N/mm², 1400 x 1400 mm
  p.hanging.height_mm = 1400.0;
  p.hanging.length_mm = 1400.0;
  p.hanging.support_displacement_mm = 100.0;
  return p;
}

// The flat area of each outline by hand, for its weight.
double outline_area_by_hand(const Parameters& p, OutlineKind kind) {
  const double h = p.hanging.height_mm;
  const double L = p.hanging.length_mm;
  switch (kind) {
    case OutlineKind::rectangular:
    case OutlineKind::inclined:
      return L * h;
    case OutlineKind::strip:
      return (p.shape.supports - 1) * L * h;
    case OutlineKind::cosine:
      return 2.0 * L * h / std::numbers::pi;  // (a_0 - a_n) times the integral of cos over L
    case OutlineKind::triangle:
    case OutlineKind::pennant:
      return 0.5 * L * h;
    case OutlineKind::wedge:
      return 0.5 * L * (h + 0.25 * h);  // a trapezoid: depth h at the left, h / 4 at the right
  }
  return 0.0;
}

// The hung cloth's centre of gravity across, x_g: each node carries a third of each flat triangle
// it is a corner of (w is uniform, so the weights' shares are the areas').
double hung_centre_of_gravity_x(const Mesh& mesh, const Solution& s) {
  double moment = 0.0;
  double total = 0.0;
  for (const auto& tri : mesh.triangles) {
    const Vector2d u = mesh.nodes_mm[tri[1]] - mesh.nodes_mm[tri[0]];
    const Vector2d v = mesh.nodes_mm[tri[2]] - mesh.nodes_mm[tri[0]];
    const double area = 0.5 * (u.x() * v.y() - u.y() * v.x());
    for (int n : tri) {
      moment += area / 3.0 * s.positions_mm[n].x();
    }
    total += area;
  }
  return moment / total;
}

TEST(FieldStatics, ReactionsCarryTheWeightForEveryOutline) {
  const Parameters p = default_parameters();
  const Material material = material_of(p.fabric);
  for (OutlineKind kind :
       {OutlineKind::rectangular, OutlineKind::cosine, OutlineKind::strip, OutlineKind::inclined,
        OutlineKind::triangle, OutlineKind::pennant, OutlineKind::wedge}) {
    SCOPED_TRACE(std::string(to_string(kind)));
    const Outline outline = make_outline(p, kind);
    const FieldReport r = solve_outline(outline, material, {16, 12, MeshSplit::union_jack});
    ASSERT_TRUE(r.solution.converged) << r.solution.relative_residual;
    const double weight = material.weight_N_per_mm2 * outline_area_by_hand(p, kind);
    // The cosine's edges are chords between 16 columns: the trapezoid rule's (pi/16)² / 12 = 0.32 %
    // below the cut's area.
    EXPECT_NEAR(r.solution.weight_N, weight, (kind == OutlineKind::cosine ? 4e-3 : 1e-12) * weight);
    Vector2d sum = Vector2d::Zero();
    for (const Vector2d& R : r.solution.reactions_N) {
      sum += R;
    }
    EXPECT_NEAR(sum.x(), 0.0, 1e-6 * r.solution.weight_N);
    EXPECT_NEAR(sum.y(), -r.solution.weight_N, 1e-6 * r.solution.weight_N);
  }
}

// Moments about the middle between supports at (-l/2, s) and (l/2, -s), s = (l/2) tan(theta):
// l (V_L - V_R) / 2 + 2 s H + x_g W = 0, with the reactions (-H, -V_L), (H, -V_R) and the hung
// cloth's centre of gravity at x_g. So V_R - V_L = 2 H tan(theta) + 2 x_g W / l: exactly
// Mansfield's 2 H tan(theta) when the cloth hangs with its weight midway.
TEST(FieldStatics, InclinedSupportsDifferByTwiceTheThrustTimesTheSlope) {
  Parameters p = default_parameters();
  p.shape.kind = ShapeKind::inclined;
  p.shape.incline_deg = 15.0;
  const Material material = material_of(p.fabric);
  const Outline outline = make_outline(p, OutlineKind::inclined);
  const Mesh mesh = make_mesh(outline, {20, 14, MeshSplit::union_jack});
  Solver solver(mesh);
  const Solution s = solver.solve(material, support_targets(outline));
  ASSERT_TRUE(s.converged);
  const double tan_theta = std::tan(15.0 * std::numbers::pi / 180.0);
  const double l = outline.supports[1].to_mm.x() - outline.supports[0].to_mm.x();
  const double x_g = hung_centre_of_gravity_x(mesh, s);
  const double H = 0.5 * (s.reactions_N[1].x() - s.reactions_N[0].x());
  const double V_L = -s.reactions_N[0].y();
  const double V_R = -s.reactions_N[1].y();
  EXPECT_NEAR(V_R - V_L, 2 * H * tan_theta + 2 * x_g * s.weight_N / l, 1e-6 * s.weight_N);
  std::cout << "inclined 15 deg: V_R - V_L = " << V_R - V_L << " N, 2 H tan = " << 2 * H * tan_theta
            << " N, x_g = " << x_g << " mm\n";
  EXPECT_GT(V_R, V_L);
}

// Mansfield's 2 H tan(theta) itself: where each support holds the corner it is sewn to (d = 0),
// the cloth hangs as cut but for its stretch, its centre of gravity stays midway but for a shift
// in proportion to the stretch, so V_R - V_L approaches 2 H tan(theta) as 1 / E. (With the
// supports moved together the cut swings and contracts across its rays, and the centre of
// gravity's shift stays whatever E is: the test above.)
TEST(FieldStatics, CornersHeldWhereTheyAreGiveTwiceTheThrustTimesTheSlopeAsTheClothStiffens) {
  Parameters p = default_parameters();
  p.shape.kind = ShapeKind::inclined;
  p.shape.incline_deg = 15.0;
  p.hanging.support_displacement_mm = 0.0;
  const Outline outline = make_outline(p, OutlineKind::inclined);
  const Mesh mesh = make_mesh(outline, {20, 14, MeshSplit::union_jack});
  Solver solver(mesh);
  const double tan_theta = std::tan(15.0 * std::numbers::pi / 180.0);
  std::vector<double> off;
  for (double stiffer : {1.0, 10.0, 100.0}) {
    Parameters q = p;
    q.fabric.youngs_modulus_MPa *= stiffer;
    const Solution s = solver.solve(material_of(q.fabric), support_targets(outline));
    ASSERT_TRUE(s.converged) << stiffer << ": " << s.relative_residual;
    const double H = 0.5 * (s.reactions_N[1].x() - s.reactions_N[0].x());
    const double difference = s.reactions_N[0].y() - s.reactions_N[1].y();  // V_R - V_L
    off.push_back(std::abs(difference / (2 * H * tan_theta) - 1.0));
    std::cout << "E x " << stiffer << ": V_R - V_L = " << difference
              << " N, 2 H tan = " << 2 * H * tan_theta << " N, off by " << off.back() << "\n";
  }
  EXPECT_LT(off[0], 1e-3);
  EXPECT_NEAR(off[0] / off[1], 10.0, 1.5);
  EXPECT_NEAR(off[1] / off[2], 10.0, 1.5);
}

// The wedge: its weight, w L (h + h/4) / 2 by hand, hangs nearer its thick (left) end. With the
// supports level at (-l/2, 0) and (l/2, 0) and reactions (-H, -V_L), (H, -V_R), moments about the
// middle between them give l (V_L - V_R) / 2 = -x_g W: the left support carries more, by exactly
// what the hung cloth's centre of gravity x_g (found here from the nodes) says.
TEST(FieldStatics, TheWedgeHangsMostlyFromItsThickEnd) {
  const Parameters p = default_parameters();
  const Material material = material_of(p.fabric);
  const Outline outline = make_outline(p, OutlineKind::wedge);
  const double h = p.hanging.height_mm;
  const double L = p.hanging.length_mm;
  EXPECT_NEAR(outline.area_mm2(), L * (h + h / 4) / 2, 1e-9 * L * h);
  const Mesh mesh = make_mesh(outline, {20, 14, MeshSplit::union_jack});
  Solver solver(mesh);
  const Solution s = solver.solve(material, support_targets(outline));
  ASSERT_TRUE(s.converged) << s.relative_residual;
  const double weight = material.weight_N_per_mm2 * L * (h + h / 4) / 2;
  EXPECT_NEAR(s.weight_N, weight, 1e-12 * weight);
  const Vector2d sum = s.reactions_N[0] + s.reactions_N[1];
  EXPECT_NEAR(sum.x(), 0.0, 1e-6 * weight);
  EXPECT_NEAR(sum.y(), -weight, 1e-6 * weight);
  const double x_g = hung_centre_of_gravity_x(mesh, s);
  const double l = outline.supports[1].to_mm.x() - outline.supports[0].to_mm.x();
  const double V_L = -s.reactions_N[0].y();
  const double V_R = -s.reactions_N[1].y();
  EXPECT_NEAR(V_L - V_R, -2.0 * x_g * weight / l, 1e-6 * weight);
  // The flat cut's centre of gravity, by hand: a trapezoid of parallel sides h and h/4 has it
  // L (h + 2 h/4) / (3 (h + h/4)) from the thick side, 0.4 L; the hung one is near it.
  EXPECT_LT(x_g, 0.0);
  EXPECT_GT(V_L, V_R);
  std::cout << "wedge: V_L = " << V_L << " N, V_R = " << V_R << " N, x_g = " << x_g
            << " mm (flat: " << 0.4 * L - 0.5 * L << " mm)\n";
}

// Folds from a uniform uniaxial field: a W x H rectangle pinned all round as x -> (1 + eps) x,
// y -> (1 - delta) y, no weight, is wrinkled everywhere with horizontal rays of tension
// T = Y e1 sqrt(1 + 2 e1), e1 = ((1 + eps)² - 1) / 2 (the patch test's). Its supports are every
// boundary node, so the span whose fibre is read is one column wide (the first, the widest being
// all equal), l = (1 + eps) W / 8, and the fibre is the column midway across it. By hand: the
// fibre keeps H (1 - nu T / Y) and lies (1 - delta) H in the plane, the difference is the width
// the folds take up; under Cerda and Mahadevan's law with T for w h,
// lambda = l (K E t³ / (T l²))^(1/4), so n = (1 - delta) H / lambda rounded, the folds evenly
// spaced, and
// n sqrt((dA)² + (2 z)²) = kept length gives z_max; under Conci's law the folds are spaced by
// the ratio Q7 of eq. 7 down to the depth floor and evenly at the floor's step above it.
TEST(FieldFolds, AUniformUniaxialFieldGivesTheHandCount) {
  const double W = 400.0;
  const double H = 300.0;
  const double eps = 0.01;
  const double delta = 0.02;
  const Outline outline = pinned_rectangle(W, H, 8, 6, [&](const Vector2d& q) {
    return Vector2d((1 + eps) * q.x(), (1 - delta) * q.y());
  });
  Parameters p;  // t = 0.25 mm, E = 165 MPa, nu = 0.3
  Material material = material_of(p.fabric);
  material.weight_N_per_mm2 = 0.0;
  const Mesh mesh = make_mesh(outline, {8, 6, MeshSplit::union_jack});
  Solver solver(mesh);
  SolveOptions tight;
  tight.relative_tolerance = 1e-12;
  const Solution s = solver.solve(material, support_targets(outline), tight);
  ASSERT_TRUE(s.converged) << s.relative_residual;

  const double nu = p.fabric.poisson_ratio;
  const double Y = p.fabric.youngs_modulus_MPa * p.fabric.thickness_mm;
  const double e1 = ((1 + eps) * (1 + eps) - 1) / 2;
  const double T = Y * e1 * std::sqrt(1 + 2 * e1);
  const double kept = H * (1 - nu * T / Y);
  const double in_plane = (1 - delta) * H;
  const double l = (1 + eps) * W / 8;
  const double Et3 = p.fabric.youngs_modulus_MPa * std::pow(p.fabric.thickness_mm, 3);

  p.model.law = WrinkleLawKind::cerda_mahadevan;
  p.model.load_constant_c = 4 * std::numbers::pi * std::numbers::pi / 3;
  p.model.stress_exponent_p = 1.0;
  p.model.int_rounding = IntRounding::nearest;
  const FieldFolds cm = field_folds(mesh, s, support_targets(outline), p);
  EXPECT_NEAR(cm.kept_length_mm, kept, 1e-9 * H);
  EXPECT_NEAR(cm.slack_width_mm, kept - in_plane, 1e-9 * H);
  EXPECT_NEAR(cm.mean_ray_tension_N_per_mm, T, 1e-9 * T);
  const double K_cm = 4 * std::numbers::pi * std::numbers::pi / 3 / (1 - nu * nu);
  const double lambda = l * std::pow(K_cm * Et3 / (T * l * l), 0.25);
  EXPECT_NEAR(cm.count_argument, in_plane / lambda, 1e-9 * in_plane / lambda);
  const int n = static_cast<int>(std::lround(in_plane / lambda));
  ASSERT_EQ(cm.n, n);
  ASSERT_EQ(cm.a_mm.size(), static_cast<std::size_t>(n + 1));
  for (int i = 0; i <= n; ++i) {
    EXPECT_NEAR(cm.a_mm[i], in_plane * (n - i) / n, 1e-6 * H) << i;
  }
  const double step = in_plane / n;
  EXPECT_NEAR(cm.z_max_mm, 0.5 * std::sqrt(std::pow(kept / n, 2) - step * step), 1e-6);
  std::cout << "uniform uniaxial field, Cerda-Mahadevan: lambda = " << lambda << " mm, n = " << n
            << ", z_max = " << cm.z_max_mm << " mm, slack width " << cm.slack_width_mm << " mm\n";

  p.model.law = WrinkleLawKind::conci;
  p.model.load_constant_c = kCalibratedLoadConstantC;
  const FieldFolds conci = field_folds(mesh, s, support_targets(outline), p);
  const double x = kCalibratedLoadConstantC / (1 - nu * nu) * Et3 / (T * l * l);
  // (1 - x) Q² - (2 + x) Q + 1 = 0, its root above 1.
  const double Q7 = ((2 + x) + std::sqrt((2 + x) * (2 + x) - 4 * (1 - x))) / (2 * (1 - x));
  const double floor = kFieldFoldsDepthFloorShare * kept;
  const double count = (1.0 + std::log(in_plane / floor)) / std::log(Q7);
  EXPECT_NEAR(conci.count_argument, count, 1e-4 * count);
  EXPECT_EQ(conci.n, static_cast<int>(std::lround(count)));
  EXPECT_NEAR(conci.Q, std::pow(in_plane / floor, 1.0 / conci.n), 1e-9);
  std::cout << "uniform uniaxial field, Conci: Q7 = " << Q7 << ", n = " << conci.n << "\n";
}

// A field stopped before it converged is drawn under a line that says so, with its residual, never
// as if it had converged; a converged one says that instead.
TEST(FieldSvg, AnUnconvergedFieldIsDrawnAsSuch) {
  const Parameters p = default_parameters();
  const Outline outline = make_outline(p, OutlineKind::rectangular);
  const Material material = material_of(p.fabric);
  const Mesh mesh = make_mesh(outline, {12, 8, MeshSplit::union_jack});
  Solver solver(mesh);
  SolveOptions two_steps;
  two_steps.max_iterations = 2;
  const FieldReport stopped = report_field(
      solver, solver.solve(material, support_targets(outline), two_steps), outline, material, 3);
  ASSERT_FALSE(stopped.solution.converged);
  const std::string drawn = field_to_svg(mesh, stopped, outline, "stopped");
  EXPECT_NE(drawn.find("NOT converged"), std::string::npos);
  char residual[32];
  std::snprintf(residual, sizeof residual, "%.2e", stopped.solution.relative_residual);
  EXPECT_NE(drawn.find(residual), std::string::npos) << residual;

  const FieldReport solved =
      report_field(solver, solver.solve(material, support_targets(outline)), outline, material, 3);
  ASSERT_TRUE(solved.solution.converged);
  const std::string good = field_to_svg(mesh, solved, outline, "solved");
  EXPECT_EQ(good.find("NOT converged"), std::string::npos);
  EXPECT_NE(good.find(">converged: "), std::string::npos);
}

// Refinement of Conci's set-up on nested meshes (each cell halved): a conforming refinement can
// only lower the minimum potential. A point support on an elastic membrane is singular: the
// fan of rays into it carries T ~ 1/r, so the stretch near it grows like ln(1/h) as the cells
// shrink, and the potential and the thrust H step by about the same amount at each halving
// (logarithmic, not a power of h) while the vertical reactions stay W/2 by statics.
TEST(FieldRefinement, PotentialFallsAndThePointSupportsStepLogarithmically) {
  const Parameters p = default_parameters();
  const Material material = material_of(p.fabric);
  const Outline outline = make_outline(p, OutlineKind::rectangular);
  std::vector<double> potential;
  std::vector<double> thrust;
  for (int n : {10, 20, 40}) {
    const FieldReport r =
        solve_outline(outline, material, {n, n * 7 / 10, MeshSplit::union_jack}, {}, 0);
    ASSERT_TRUE(r.solution.converged) << n;
    potential.push_back(r.solution.potential_Nmm);
    thrust.push_back(r.thrust_N);
    for (const Vector2d& R : r.solution.reactions_N) {
      EXPECT_NEAR(-R.y(), 0.5 * r.solution.weight_N, 1e-6 * r.solution.weight_N);
    }
    std::cout << "cells " << n << ": potential " << r.solution.potential_Nmm << " N mm, H "
              << r.thrust_N << " N, iterations " << r.solution.iterations << "\n";
  }
  EXPECT_LT(potential[1], potential[0]);
  EXPECT_LT(potential[2], potential[1]);
  const double potential_steps = (potential[1] - potential[2]) / (potential[0] - potential[1]);
  const double thrust_steps = (thrust[2] - thrust[1]) / (thrust[1] - thrust[0]);
  std::cout << "step ratios at each halving: potential " << potential_steps << ", H "
            << thrust_steps << " (1 is logarithmic, 1/2 first order, 1/4 second)\n";
  EXPECT_GT(potential_steps, 0.6);
  EXPECT_LT(potential_steps, 1.6);
  EXPECT_GT(thrust_steps, 0.6);
  EXPECT_LT(thrust_steps, 1.6);
}

// The stretch of a fibre hung from its top at depth Y below it, when nu = 0: the nominal tension
// lambda S = lambda Y_mod (lambda² - 1) / 2 carries the weight below, w (h - Y). The cubic's root
// above 1 by Newton's method from a start above it (the cubic is convex there).
double hung_fibre_stretch(double weight_below_N_per_mm, double stiffness_N_per_mm) {
  const double q = 2.0 * weight_below_N_per_mm / stiffness_N_per_mm;
  double lambda = 1.0 + q + 1.0;
  for (int i = 0; i < 100; ++i) {
    const double step = (lambda * lambda * lambda - lambda - q) / (3.0 * lambda * lambda - 1.0);
    lambda -= step;
    if (std::abs(step) < 1e-16) {
      break;
    }
  }
  return lambda;
}

// Without point supports the field converges as a smooth problem does. A sheet hung from its
// whole top edge with nu = 0 hangs as independent fibres, so its least potential per unit width
// is a one-dimensional integral, taken here by Simpson's rule on the fibre's stretch:
// Pi / L = integral over Y of Y_mod (lambda² - 1)² / 8 - w (h - Y) lambda (the weight's work,
// w times the integral of the hung depth, integrated by parts). Linear triangles on nested
// meshes approach it from above (a conforming refinement) as the cell size squared. The top
// supports' reactions approach w h times their share of the edge at first order: on a mesh the
// free lateral contraction of wrinkled triangles hands a little weight between columns.
TEST(FieldRefinement, WithoutPointSupportsThePotentialConvergesAsTheCellSizeSquared) {
  const double L = 600.0;
  const double h = 300.0;
  // Soft, so that the stretch (about 5 % at the top) is far from the linear theory's.
  const Material material{0.009, 0.0, 1.5e-6};
  constexpr int kIntervals = 20000;
  double per_width = 0.0;
  for (int k = 0; k <= kIntervals; ++k) {
    const double Y = h * k / kIntervals;
    const double lambda =
        hung_fibre_stretch(material.weight_N_per_mm2 * (h - Y), material.stiffness_N_per_mm);
    const double density = material.stiffness_N_per_mm * std::pow(lambda * lambda - 1.0, 2) / 8.0 -
                           material.weight_N_per_mm2 * (h - Y) * lambda;
    const double simpson = (k == 0 || k == kIntervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    per_width += simpson * density * (h / kIntervals) / 3.0;
  }
  const double exact_Nmm = L * per_width;
  std::vector<double> error;
  std::vector<double> middle_off;
  std::vector<double> corner_off;
  for (int nx : {8, 16, 32, 64}) {
    Outline o;
    o.top_mm = {{-0.5 * L, 0.0}, {0.5 * L, 0.0}};
    o.bottom_mm = {{-0.5 * L, h}, {0.5 * L, h}};
    for (int i = 0; i <= nx; ++i) {
      const Vector2d at(-0.5 * L + L * i / nx, 0.0);
      o.supports.push_back({at, at});
    }
    const Mesh mesh = make_mesh(o, {nx, nx / 2, MeshSplit::union_jack});
    Solver solver(mesh);
    const Solution s = solver.solve(material, support_targets(o));
    ASSERT_TRUE(s.converged) << nx << ": " << s.relative_residual;
    error.push_back(s.potential_Nmm - exact_Nmm);
    EXPECT_GT(error.back(), 0.0) << nx << " columns: below the least potential";
    // The middle half's supports and a corner, as shares of the column each would carry.
    const double per_column = material.weight_N_per_mm2 * h * (L / nx);
    double off = 0.0;
    for (std::size_t i = 0; i < o.supports.size(); ++i) {
      if (std::abs(o.supports[i].at_mm.x()) <= 0.25 * L) {
        off = std::max(off, std::abs(-s.reactions_N[i].y() / per_column - 1.0));
      }
    }
    middle_off.push_back(off);
    corner_off.push_back(std::abs(-s.reactions_N[0].y() / per_column - 0.5));
    std::cout << nx << " columns: middle supports within " << off << " of w h a column, a corner "
              << corner_off.back() << " off half of it\n";
    std::cout << nx << " x " << nx / 2 << " cells: potential " << s.potential_Nmm
              << " N mm, above the least by " << error.back() << " N mm\n";
  }
  for (std::size_t k = 1; k < error.size(); ++k) {
    const double order = std::log2(error[k - 1] / error[k]);
    const double middle_order = std::log2(middle_off[k - 1] / middle_off[k]);
    const double corner_order = std::log2(corner_off[k - 1] / corner_off[k]);
    std::cout << "orders at halving " << k << ": potential " << order << ", middle supports "
              << middle_order << ", corner " << corner_order << "\n";
    EXPECT_NEAR(order, 2.0, 0.1) << "halving " << k;
    EXPECT_NEAR(middle_order, 1.0, 0.25) << "halving " << k;
    EXPECT_NEAR(corner_order, 1.0, 0.25) << "halving " << k;
  }
}

// The Newton matrix's damping changes the path, not the field: halving its floor (both its cap
// and its share of the cloth's stretch) moves nothing.
TEST(FieldRegularisation, HalvingTheDampingFloorMovesNoFigure) {
  const Parameters p = default_parameters();
  const Material material = material_of(p.fabric);
  const Outline outline = make_outline(p, OutlineKind::rectangular);
  SolveOptions half;
  half.damping_floor *= 0.5;
  half.damping_floor_per_stretch *= 0.5;
  const FieldReport a = solve_outline(outline, material, {16, 12, MeshSplit::union_jack});
  const FieldReport b = solve_outline(outline, material, {16, 12, MeshSplit::union_jack}, half);
  ASSERT_TRUE(a.solution.converged);
  ASSERT_TRUE(b.solution.converged);
  EXPECT_NEAR(a.thrust_N, b.thrust_N, 1e-6 * a.thrust_N);
  EXPECT_NEAR(a.solution.energy_Nmm, b.solution.energy_Nmm, 1e-6 * a.solution.energy_Nmm);
  EXPECT_NEAR(a.solution.wrinkled_share, b.solution.wrinkled_share, 1e-9);
  EXPECT_NEAR(a.solution.slack_share, b.solution.slack_share, 1e-9);
}

// A budget spent on the first step of a stiff cloth's cold solve (a ladder of meshes, then Y
// raised tenfold at a time: six rungs here, each of which would take a step) ends it there: no
// later rung takes its own step, and what comes back is the real cloth's unconverged field, its
// residual the one a fresh look at the same positions finds.
TEST(FieldColdSolve, ASpentBudgetEndsTheLadder) {
  Parameters p = default_parameters();
  p.fabric.youngs_modulus_MPa = 2e4;
  const Material material = material_of(p.fabric);
  const MeshResolution resolution{32, 16, MeshSplit::union_jack};
  const Outline outline = make_outline(p, OutlineKind::rectangular);
  Solver solver(make_mesh(outline, resolution));
  SolveOptions options;
  options.time_budget_ms = 1e-6;
  const Solution spent = solve_cold(solver, outline, material, resolution, options);
  EXPECT_EQ(spent.iterations, 1);
  EXPECT_FALSE(spent.converged);
  Solver fresh(make_mesh(outline, resolution));
  SolveOptions look;
  look.max_iterations = 0;
  const Solution again = fresh.solve(material, support_targets(outline), look, &spent);
  EXPECT_EQ(spent.relative_residual, again.relative_residual);
  // Without a budget the same ladder takes more steps than it has rungs.
  Solver other(make_mesh(outline, resolution));
  const Solution whole = solve_cold(other, outline, material, resolution);
  EXPECT_TRUE(whole.converged) << whole.relative_residual << " " << whole.iterations;
  EXPECT_GT(whole.iterations, 8);
}

// A warm re-solve (from the field of d = 100 mm, after d moved 1 %) lands on the field a cold
// solve finds: the same thrust, energy and regions.
TEST(FieldWarmStart, ReachesTheColdField) {
  Parameters p = default_parameters();
  const Material material = material_of(p.fabric);
  const MeshResolution resolution{20, 14, MeshSplit::union_jack};
  const Outline before = make_outline(p, OutlineKind::rectangular);
  Solver solver(make_mesh(before, resolution));
  const Solution first = solve_cold(solver, before, material, resolution);
  p.hanging.support_displacement_mm *= 1.01;
  const Outline after = make_outline(p, OutlineKind::rectangular);
  const Solution warm = solver.solve(material, support_targets(after), {}, &first);
  const FieldReport cold = solve_outline(after, material, resolution, {}, 0);
  ASSERT_TRUE(warm.converged);
  ASSERT_TRUE(cold.solution.converged);
  EXPECT_LT(warm.iterations, cold.solution.iterations);
  EXPECT_NEAR(warm.reactions_N[1].x(), cold.thrust_N, 1e-6 * cold.thrust_N);
  EXPECT_NEAR(warm.energy_Nmm, cold.solution.energy_Nmm, 1e-6 * cold.solution.energy_Nmm);
  EXPECT_NEAR(warm.wrinkled_share, cold.solution.wrinkled_share, 1e-12);
}

// Mansfield's cosine outline hung from its ends (l = L): the pencil's thrust
// (w l² / pi²) ln(a_0 / a_n) beside the solver's, on refined meshes. Statics is asserted (each
// support carries half the weight); H, the taut share and the rays are reported.
TEST(FieldCosinePencil, ThrustBesideThePencilIsReported) {
  // The independent prototype's outline: l = 1130 mm, a_0 = 1610 mm, a_n = 37 mm.
  const double l = 1130.0;
  const double a0 = 1610.0;
  const double an = 37.0;
  const int segments = 256;
  Outline o;
  for (int i = 0; i <= segments; ++i) {
    const double x = -0.5 * l + l * i / segments;
    const double c = i == 0 || i == segments ? 0.0 : std::cos(std::numbers::pi * x / l);
    o.top_mm.emplace_back(x, an * c);
    o.bottom_mm.emplace_back(x, a0 * c);
  }
  o.supports = {{{-0.5 * l, 0.0}, {-0.5 * l, 0.0}}, {{0.5 * l, 0.0}, {0.5 * l, 0.0}}};
  const Material material{41.25, 0.3, 1.5e-6};
  const double pencil =
      material.weight_N_per_mm2 * l * l / (std::numbers::pi * std::numbers::pi) * std::log(a0 / an);
  for (int n : {16, 32, 48}) {
    const FieldReport r = solve_outline(o, material, {n, n, MeshSplit::union_jack});
    ASSERT_TRUE(r.solution.converged) << n;
    for (const Vector2d& R : r.solution.reactions_N) {
      EXPECT_NEAR(-R.y(), 0.5 * r.solution.weight_N, 1e-6 * r.solution.weight_N);
    }
    std::cout << "cosine " << n << " x " << n << ": H " << r.thrust_N << " N, pencil " << pencil
              << " N (" << 100.0 * (r.thrust_N / pencil - 1.0) << " %), taut "
              << r.solution.taut_share << ", wrinkled " << r.solution.wrinkled_share << ", slack "
              << r.solution.slack_share << "\n";
    for (const Ray& ray : r.rays) {
      std::cout << "  ray a = " << ray.depth_mm << " mm: fitted " << ray.fitted_amplitude_mm
                << " mm, rms " << ray.fit_rms_mm << " mm\n";
    }
  }
}

// The relaxed energy's table at three strains, and its stress as the derivative of its energy:
// S = dW/dE by central differences of the energy (a slow path beside the closed-form stress).
TEST(FieldRelaxedEnergy, StatesEnergiesAndStressFollowTheTable) {
  const Material m{40.0, 0.3, 0.0};
  const double c = m.stiffness_N_per_mm / (1.0 - m.poisson_ratio * m.poisson_ratio);
  struct Case {
    Eigen::Matrix2d E;
    State state;
    double energy;
  };
  Eigen::Matrix2d taut;
  taut << 0.02, 0.0, 0.0, 0.01;  // e2 = 0.01 > -nu e1
  Eigen::Matrix2d wrinkled;
  wrinkled << 0.02, 0.0, 0.0, -0.01;  // e2 = -0.01 <= -0.006
  Eigen::Matrix2d slack;
  slack << -0.01, 0.002, 0.002, -0.02;
  const Case cases[] = {
      {taut, State::taut, 0.5 * c * (0.02 * 0.02 + 0.01 * 0.01 + 2 * 0.3 * 0.02 * 0.01)},
      {wrinkled, State::wrinkled, 0.5 * 40.0 * 0.02 * 0.02},
      {slack, State::slack, 0.0},
  };
  for (const Case& k : cases) {
    // Rotated by 30 degrees, so that the principal directions are not the axes.
    const double a = std::numbers::pi / 6;
    Eigen::Matrix2d R;
    R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    const Eigen::Matrix2d E = R * k.E * R.transpose();
    const RelaxedStrain r = relax(E, m);
    EXPECT_EQ(r.state, k.state);
    EXPECT_NEAR(r.energy_N_per_mm, k.energy, 1e-15);
    const double step = 1e-7;
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        // A symmetric perturbation: dW = S : dE with dE symmetric.
        Eigen::Matrix2d dE = Eigen::Matrix2d::Zero();
        dE(i, j) += 0.5 * step;
        dE(j, i) += 0.5 * step;
        const double slope =
            (relax(E + dE, m).energy_N_per_mm - relax(E - dE, m).energy_N_per_mm) / (2 * step);
        EXPECT_NEAR(r.stress_N_per_mm(i, j), slope, 1e-6 * m.stiffness_N_per_mm) << i << j;
      }
    }
  }
}

// Why parse_outline_json refuses `text`, or empty when it does not.
std::string refused(const std::string& text) {
  try {
    parse_outline_json(text);
  } catch (const OutlineError& e) {
    return std::string(e.what());
  }
  return std::string();
}

TEST(FieldOutline, RefusesWhatCannotBeMeshed) {
  EXPECT_NE(refused(R"({"top": [[0,0],[10,0],[5,0]], "bottom": [[0,5],[10,5]],
                        "supports": [{"at": [0,0], "to": [0,0]}]})")
                .find("turns back"),
            std::string::npos);
  EXPECT_NE(refused(R"({"top": [[0,0],[10,0]], "bottom": [[0,5],[5,-1],[10,5]],
                        "supports": [{"at": [0,0], "to": [0,0]}]})")
                .find("cross"),
            std::string::npos);
  EXPECT_NE(refused(R"({"top": [[0,0],[10,0]], "bottom": [[0,5],[10,5]],
                        "supports": [{"at": [5,2], "to": [5,2]}]})")
                .find("off the outline"),
            std::string::npos);
  EXPECT_NE(refused(R"({"top": [[0,0],[10,0]], "bottom": [[0,5],[10,5]], "supports": []})")
                .find("at least one support"),
            std::string::npos);
  EXPECT_EQ(refused(R"({"top": [[0,0],[10,0]], "bottom": [[0,5],[10,5]],
                        "supports": [{"at": [0,0], "to": [1,0]}, {"at": [10,0], "to": [9,0]}]})"),
            "");
  Outline big = parse_outline_json(
      R"({"top": [[0,0],[10,0]], "bottom": [[0,5],[10,5]], "supports": [{"at": [0,0], "to": [0,0]}]})");
  EXPECT_THROW(make_mesh(big, {2000, 2000, MeshSplit::union_jack}), OutlineError);
}

// A strip hung from k supports on its top edge, each span of the default cloth (L = 1400 mm,
// moved in by d = 100 mm, so l = 1300 mm).
FieldReport solved_strip(int supports) {
  Parameters p = default_parameters();
  p.shape.supports = supports;
  const Outline outline = make_outline(p, OutlineKind::strip);
  return solve_outline(outline, material_of(p.fabric), {40, 28, MeshSplit::union_jack});
}

// With three supports the middle one is under the cut's centre line: every ray is traced from
// its own span's centre line, lies between that span's supports and runs from near one to near
// the other, and each span's thrust is of the order of Mansfield's pencil w l² / pi² ln(a_0 /
// a_n) across that span (the pencil is an equilibrium, not the elastic answer: within a factor
// 2, the ratio reported). The strip and its union-jack mesh are mirror images about the middle
// support, so the two spans' thrusts are equal.
TEST(FieldSpans, AStripOnThreeSupportsHasRaysAndAThrustInEachSpan) {
  const FieldReport r = solved_strip(3);
  ASSERT_TRUE(r.solution.converged) << r.solution.relative_residual;
  ASSERT_EQ(r.spans.size(), 2u);
  const Material material = material_of(default_parameters().fabric);
  for (std::size_t k = 0; k < r.spans.size(); ++k) {
    SCOPED_TRACE(k);
    const SpanReport& span = r.spans[k];
    EXPECT_EQ(span.left_support, static_cast<int>(k));
    EXPECT_EQ(span.right_support, static_cast<int>(k) + 1);
    EXPECT_DOUBLE_EQ(span.span_mm, 1300.0);
    const double left_mm = -1300.0 + 1300.0 * static_cast<double>(k);
    const double right_mm = left_mm + 1300.0;
    int rays = 0;
    for (const Ray& ray : r.rays) {
      if (ray.span != static_cast<int>(k)) {
        continue;
      }
      ++rays;
      ASSERT_FALSE(ray.points_mm.empty());
      double lo = ray.points_mm.front().x();
      double hi = lo;
      for (const Vector2d& q : ray.points_mm) {
        lo = std::min(lo, q.x());
        hi = std::max(hi, q.x());
      }
      // Within the span, and from within a tenth of it of one support to the other.
      EXPECT_GE(lo, left_mm - 1e-6) << ray.depth_mm;
      EXPECT_LE(hi, right_mm + 1e-6) << ray.depth_mm;
      EXPECT_LT(lo, left_mm + 130.0) << ray.depth_mm;
      EXPECT_GT(hi, right_mm - 130.0) << ray.depth_mm;
      EXPECT_GT(ray.fitted_points, 10);
      std::cout << "strip on 3, span " << k + 1 << ": ray a = " << ray.depth_mm << " mm, x " << lo
                << " .. " << hi << " mm, fitted a = " << ray.fitted_amplitude_mm << " mm, rms "
                << ray.fit_rms_mm << " mm\n";
    }
    EXPECT_GE(rays, 2);
    // The pencil by hand from the span's own centre-line depths.
    ASSERT_GT(span.centre_top_depth_mm, 0.0);
    ASSERT_GT(span.centre_bottom_depth_mm, span.centre_top_depth_mm);
    const double pencil = material.weight_N_per_mm2 * 1300.0 * 1300.0 /
                          (std::numbers::pi * std::numbers::pi) *
                          std::log(span.centre_bottom_depth_mm / span.centre_top_depth_mm);
    EXPECT_NEAR(span.pencil_thrust_N, pencil, 1e-12 * pencil);
    EXPECT_GT(span.thrust_N, 0.0);
    EXPECT_GT(span.thrust_N, 0.5 * pencil);
    EXPECT_LT(span.thrust_N, 2.0 * pencil);
    std::cout << "strip on 3, span " << k + 1 << ": H " << span.thrust_N << " N, pencil " << pencil
              << " N, H / pencil " << span.thrust_N / pencil << " (a_n " << span.centre_top_depth_mm
              << " mm, a_0 " << span.centre_bottom_depth_mm << " mm)\n";
  }
  EXPECT_EQ(static_cast<int>(r.rays.size()), kDefaultRayCount);
  EXPECT_NEAR(r.spans[0].thrust_N, r.spans[1].thrust_N, 1e-6 * r.spans[0].thrust_N);
  // The outermost supports alone carry the horizontal pull into either span's centre line.
  EXPECT_NEAR(r.spans[0].thrust_N, -r.solution.reactions_N[0].x(), 1e-6 * r.spans[0].thrust_N);
  // The report's figures are the widest span's: the first of the equal two.
  EXPECT_EQ(r.widest_span, 0);
  EXPECT_EQ(r.thrust_N, r.spans[0].thrust_N);
  EXPECT_EQ(r.pencil_thrust_N, r.spans[0].pencil_thrust_N);
  EXPECT_EQ(r.span_mm, 1300.0);
}

// The horizontal force across the flat column X = x_mm summed from the triangles' stresses: a
// triangle the column crosses over a flat length ds carries across it t (m . N) d ds per
// principal tension t (per flat width across it), m its flat direction, d its hung one, N the
// column's normal (1, 0); the smaller one's too where taut, at right angles on the flat cut.
double force_across_column_N(const Mesh& mesh, const Solution& solution, double x_mm) {
  double sum_N = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    // The column's length inside the triangle: between the crossings of its edges.
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (int e = 0; e < 3; ++e) {
      const Vector2d a = mesh.nodes_mm[tri[e]];
      const Vector2d b = mesh.nodes_mm[tri[(e + 1) % 3]];
      if ((a.x() - x_mm) * (b.x() - x_mm) < 0.0) {
        const double y = a.y() + (x_mm - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
        lo = std::min(lo, y);
        hi = std::max(hi, y);
      }
    }
    if (!(hi > lo)) {
      continue;
    }
    const TriangleResult& r = solution.triangles[t];
    const Vector2d m = r.flat_direction.normalized();
    sum_N += r.tension_N_per_mm * m.x() * r.direction.normalized().x() * (hi - lo);
    if (r.minor_tension_N_per_mm != 0.0) {
      // F from the flat edges to the hung ones.
      Eigen::Matrix2d flat;
      Eigen::Matrix2d hung;
      flat << mesh.nodes_mm[tri[1]] - mesh.nodes_mm[tri[0]],
          mesh.nodes_mm[tri[2]] - mesh.nodes_mm[tri[0]];
      hung << solution.positions_mm[tri[1]] - solution.positions_mm[tri[0]],
          solution.positions_mm[tri[2]] - solution.positions_mm[tri[0]];
      const Eigen::Matrix2d F = hung * flat.inverse();
      const Vector2d m2(-m.y(), m.x());
      sum_N += r.minor_tension_N_per_mm * m2.x() * (F * m2).normalized().x() * (hi - lo);
    }
  }
  return sum_N;
}

// Each span's thrust, from the supports' reactions, is the force the cloth carries across the
// span's centre line: summed from the stresses of the triangles the column crosses it agrees
// within the mesh's error, for two supports and for each span of three. Measured: 1.0 % apart
// on the cosine cut and 3.4 % on the strip at 40 x 28 cells, 0.1 % and 1.8 % at 80 x 56 (the
// constant stress of a linear triangle summed along a line, against the nodal balance).
TEST(FieldSpans, TheSpanThrustIsTheForceAcrossItsCentreLine) {
  const Parameters p = default_parameters();
  const Material material = material_of(p.fabric);
  for (OutlineKind kind : {OutlineKind::cosine, OutlineKind::strip}) {
    SCOPED_TRACE(std::string(to_string(kind)));
    const Outline outline = make_outline(p, kind);
    const MeshResolution resolution{40, 28, MeshSplit::union_jack};
    Solver solver(make_mesh(outline, resolution));
    const Solution solution = solve_cold(solver, outline, material, resolution);
    ASSERT_TRUE(solution.converged);
    const FieldReport r = report_field(solver, solution, outline, material, 0);
    const std::vector<SupportSpan> spans = top_spans(solver.mesh(), outline);
    ASSERT_EQ(spans.size(), r.spans.size());
    for (std::size_t k = 0; k < spans.size(); ++k) {
      // The centre line is a column of the mesh here: just left and just right of it.
      const double x = spans[k].flat_x_mm;
      const double across_N =
          0.5 * (std::abs(force_across_column_N(solver.mesh(), solution, x - 1e-3)) +
                 std::abs(force_across_column_N(solver.mesh(), solution, x + 1e-3)));
      std::cout << to_string(kind) << " span " << k + 1 << ": thrust " << r.spans[k].thrust_N
                << " N, summed across its centre line " << across_N << " N\n";
      EXPECT_NEAR(across_N, r.spans[k].thrust_N, 0.05 * r.spans[k].thrust_N);
    }
  }
}

// Four supports: three spans, each with its own rays (8 shared 3, 3, 2 or so, at least 2 each).
TEST(FieldSpans, AStripOnFourSupportsHasRaysInEverySpan) {
  const FieldReport r = solved_strip(4);
  ASSERT_TRUE(r.solution.converged) << r.solution.relative_residual;
  ASSERT_EQ(r.spans.size(), 3u);
  for (std::size_t k = 0; k < r.spans.size(); ++k) {
    SCOPED_TRACE(k);
    const double left_mm = r.spans[k].span_mm * (static_cast<double>(k) - 1.5);
    const double right_mm = left_mm + r.spans[k].span_mm;
    // A ray ending at a middle support comes to it from below, through cloth that hangs as far
    // as 1.5 mm beyond the support's x here: 1 % of l is allowed.
    const double beyond_mm = 0.01 * r.spans[k].span_mm;
    int rays = 0;
    double overshoot_mm = 0.0;
    for (const Ray& ray : r.rays) {
      if (ray.span == static_cast<int>(k)) {
        ++rays;
        for (const Vector2d& q : ray.points_mm) {
          EXPECT_GE(q.x(), left_mm - beyond_mm);
          EXPECT_LE(q.x(), right_mm + beyond_mm);
          overshoot_mm = std::max({overshoot_mm, left_mm - q.x(), q.x() - right_mm});
        }
      }
    }
    EXPECT_GE(rays, 2);
    const double ratio = r.spans[k].thrust_N / r.spans[k].pencil_thrust_N;
    EXPECT_GT(ratio, 0.5);
    EXPECT_LT(ratio, 2.0);
    std::cout << "strip on 4, span " << k + 1 << ": " << rays << " rays, at most " << overshoot_mm
              << " mm beyond its supports, H " << r.spans[k].thrust_N << " N, pencil "
              << r.spans[k].pencil_thrust_N << " N, H / pencil " << ratio << "\n";
  }
  EXPECT_EQ(static_cast<int>(r.rays.size()), kDefaultRayCount);
  EXPECT_NEAR(r.spans[0].thrust_N, r.spans[2].thrust_N, 1e-6 * r.spans[0].thrust_N);
}

// The two-support results kept: the default cut (Mansfield's cosine outline of the default cloth,
// 40 x 28 union-jack cells, 8 rays) gives the thrust, pencil and rays it gave before the rays
// were traced span by span (foldlab field --json of that version, printed to 17 digits).
TEST(FieldSpans, TheTwoSupportDefaultCutsFiguresAreKept) {
  const Parameters p = default_parameters();
  const FieldReport r = solve_outline(make_outline(p, OutlineKind::cosine), material_of(p.fabric),
                                      {40, 28, MeshSplit::union_jack});
  ASSERT_TRUE(r.solution.converged);
  const double thrust_N = 0.625295073202881;
  const double pencil_N = 0.4760251143171393;
  EXPECT_NEAR(r.thrust_N, thrust_N, 1e-9 * thrust_N);
  EXPECT_NEAR(r.pencil_thrust_N, pencil_N, 1e-9 * pencil_N);
  EXPECT_EQ(r.span_mm, 1300.0);
  // a, fitted a, rms, mm
  const double rays[8][3] = {{358.7696217497638, 361.9302545998116, 5.986831470413716},
                             {493.0120231492515, 506.04268725361175, 12.075643762320999},
                             {627.254424548739, 643.952067919619, 15.356687209021192},
                             {761.4968259482268, 774.0249433170549, 12.727638160156651},
                             {895.7392273477144, 915.4528047989515, 13.081019506363306},
                             {1029.981628747202, 1050.8823842028216, 12.207090362379216},
                             {1164.2240301466898, 1193.7027881388808, 21.81819473741451},
                             {1298.4664315461773, 1335.975420134498, 26.357414484701945}};
  ASSERT_EQ(r.rays.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_NEAR(r.rays[i].depth_mm, rays[i][0], 1e-9 * rays[i][0]);
    EXPECT_NEAR(r.rays[i].fitted_amplitude_mm, rays[i][1], 1e-9 * rays[i][1]);
    EXPECT_NEAR(r.rays[i].fit_rms_mm, rays[i][2], 1e-7 * rays[i][2]);
    EXPECT_EQ(r.rays[i].span, 0);
  }
  // Its one span is the cut's: the same figures.
  ASSERT_EQ(r.spans.size(), 1u);
  EXPECT_EQ(r.spans[0].thrust_N, r.thrust_N);
  EXPECT_EQ(r.spans[0].pencil_thrust_N, r.pencil_thrust_N);
}

// Spans are only between supports on the top edge: a support at a bottom corner, or at the
// foot of a side, is in none.
TEST(FieldSpans, SupportsOffTheTopEdgeAreInNoSpan) {
  Outline o;
  o.top_mm = {{0.0, 0.0}, {500.0, -100.0}, {1000.0, 0.0}};
  o.bottom_mm = {{0.0, 800.0}, {1000.0, 800.0}};
  o.supports = {{{1000.0, 800.0}, {950.0, 800.0}},  // bottom right corner
                {{250.0, -50.0}, {250.0, -50.0}},   // on the top edge between its vertices
                {{0.0, 0.0}, {50.0, 0.0}},          // top left corner
                {{1000.0, 0.0}, {950.0, 0.0}},      // top right corner
                {{0.0, 400.0}, {0.0, 400.0}}};      // halfway down the left side
  check_outline(o);
  const Mesh mesh = make_mesh(o, {10, 8, MeshSplit::union_jack});
  const std::vector<SupportSpan> spans = top_spans(mesh, o);
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0].left_support, 2);
  EXPECT_EQ(spans[0].right_support, 1);
  EXPECT_EQ(spans[1].left_support, 1);
  EXPECT_EQ(spans[1].right_support, 3);
  EXPECT_DOUBLE_EQ(spans[0].frame.span_mm(), 200.0);
  EXPECT_DOUBLE_EQ(spans[1].frame.span_mm(), 700.0);
  // Midway between the supports as cut.
  EXPECT_DOUBLE_EQ(spans[0].flat_x_mm, 125.0);
  EXPECT_DOUBLE_EQ(spans[1].flat_x_mm, 625.0);
  // One support on the top edge: no span.
  o.supports = {{{1000.0, 800.0}, {950.0, 800.0}}, {{0.0, 0.0}, {50.0, 0.0}}};
  EXPECT_TRUE(top_spans(make_mesh(o, {10, 8, MeshSplit::union_jack}), o).empty());
}

// A cloth hung from its two top corners and held at a bottom corner too: one span, its rays
// and figures; held at a top and a bottom corner only: the rays from the centre line as before.
TEST(FieldSpans, ASupportAtABottomCornerBreaksNothing) {
  const Parameters p = default_parameters();
  const Material material = material_of(p.fabric);
  Outline o = make_outline(p, OutlineKind::rectangular);
  const Vector2d corner = o.bottom_mm.front();
  o.supports.push_back({corner, corner + Vector2d(50.0, 0.0)});
  const FieldReport three = solve_outline(o, material, {16, 12, MeshSplit::union_jack});
  ASSERT_TRUE(three.solution.converged) << three.solution.relative_residual;
  ASSERT_EQ(three.spans.size(), 1u);
  EXPECT_EQ(three.spans[0].left_support, 0);
  EXPECT_EQ(three.spans[0].right_support, 1);
  EXPECT_EQ(three.rays.size(), static_cast<std::size_t>(kDefaultRayCount));
  EXPECT_EQ(three.thrust_N, three.spans[0].thrust_N);
  EXPECT_TRUE(std::isfinite(three.thrust_N) && std::isfinite(three.pencil_thrust_N));
  o.supports.erase(o.supports.begin() + 1);
  Solver solver(make_mesh(o, {16, 12, MeshSplit::union_jack}));
  const Solution solution = solve_cold(solver, o, material, {16, 12, MeshSplit::union_jack});
  ASSERT_TRUE(solution.converged);
  const FieldReport two = report_field(solver, solution, o, material);
  EXPECT_TRUE(two.spans.empty());
  const std::vector<Ray> centre = trace_rays(solver.mesh(), solution, support_targets(o), 8);
  ASSERT_EQ(two.rays.size(), centre.size());
  for (std::size_t i = 0; i < centre.size(); ++i) {
    EXPECT_EQ(two.rays[i].depth_mm, centre[i].depth_mm);
    EXPECT_EQ(two.rays[i].points_mm, centre[i].points_mm);
  }
}

// The rays shared by l, at least 2 a span.
TEST(FieldSpans, RaysAreSharedBySpanLength) {
  auto spans_of = [](std::vector<double> lengths_mm) {
    std::vector<SupportSpan> spans;
    double x = 0.0;
    for (double l : lengths_mm) {
      SupportSpan s;
      s.frame = SupportFrame{Vector2d(x, 0.0), Vector2d(x + l, 0.0)};
      x += l;
      spans.push_back(s);
    }
    return spans;
  };
  EXPECT_EQ(rays_per_span(spans_of({1300.0, 1300.0}), 8), (std::vector<int>{4, 4}));
  EXPECT_EQ(rays_per_span(spans_of({1000.0, 3000.0}), 8), (std::vector<int>{2, 6}));
  EXPECT_EQ(rays_per_span(spans_of({100.0, 3000.0}), 8), (std::vector<int>{2, 6}));
  EXPECT_EQ(rays_per_span(spans_of({1000.0, 1000.0, 1000.0}), 8), (std::vector<int>{3, 3, 2}));
  EXPECT_EQ(rays_per_span(spans_of({1000.0, 1000.0, 1000.0}), 3), (std::vector<int>{2, 2, 2}));
  EXPECT_EQ(rays_per_span(spans_of({1000.0, 1000.0}), 0), (std::vector<int>{0, 0}));
  EXPECT_EQ(rays_per_span(spans_of({1000.0}), 1), (std::vector<int>{1}));
}

// The rules a preset's outline and a file share: a key given twice or unknown, a pin too far,
// a step narrower than the mesh follows, a coordinate past 1e7 mm.
TEST(FieldOutline, RefusesKeysPinsStepsAndCoordinatesOutOfRule) {
  const std::string edges = R"("top": [[0,0],[10,0]], "bottom": [[0,5],[10,5]], )";
  EXPECT_NE(refused(R"({"top": [[0,0],[10,0]], )" + edges +
                    R"("supports": [{"at": [0,0], "to": [0,0]}]})")
                .find("\"top\" is given twice"),
            std::string::npos);
  EXPECT_NE(refused("{" + edges + R"("supports": [{"at": [0,0], "to": [0,0], "to": [1,0]}]})")
                .find("\"to\" is given twice"),
            std::string::npos);
  EXPECT_NE(refused("{" + edges + R"("supports": [{"at": [0,0], "to": [0,0]}], "x": 1})")
                .find("unknown key \"x\""),
            std::string::npos);
  // 10 times the cut's size (10 mm) from its place: 100 mm is the limit.
  EXPECT_EQ(refused("{" + edges + R"("supports": [{"at": [0,0], "to": [0,100]}]})"), "");
  EXPECT_NE(refused("{" + edges + R"("supports": [{"at": [0,0], "to": [0,100.01]}]})")
                .find("within 10 times"),
            std::string::npos);
  EXPECT_NE(refused(R"({"top": [[0,0],[5,0],[5.000001,1],[10,1]], "bottom": [[0,5],[10,5]],
                        "supports": [{"at": [0,0], "to": [0,0]}]})")
                .find("narrower than the mesh can follow"),
            std::string::npos);
  EXPECT_NE(refused(R"({"top": [[2e7,0],[2e7,0]], "bottom": [[0,5],[10,5]],
                        "supports": [{"at": [0,0], "to": [0,0]}]})")
                .find("out of range"),
            std::string::npos);
}

// Solved relative to solve_origin_mm: a cut about the origin is solved where it is; one shifted
// by 1e6 mm is moved back exactly (the origin a multiple of a power of two, 1024 here).
TEST(FieldOutline, SolveOriginIsExactAndZeroAboutTheOrigin) {
  Outline o;
  o.top_mm = {{-300, 0}, {300, 0}};
  o.bottom_mm = {{-300, 400}, {300, 400}};
  o.supports = {{{-300, 0}, {-270, 0}}, {{300, 0}, {270, 0}}};
  EXPECT_EQ(solve_origin_mm(o), Eigen::Vector2d(0, 0));
  const Outline far = translated(o, Eigen::Vector2d(1e6, 1e6));
  const Eigen::Vector2d origin = solve_origin_mm(far);
  EXPECT_EQ(origin, Eigen::Vector2d(977 * 1024.0, 977 * 1024.0));
  const Outline back = translated(far, -origin);
  EXPECT_EQ(back, translated(o, Eigen::Vector2d(1e6 - 977 * 1024.0, 1e6 - 977 * 1024.0)));
}

}  // namespace
}  // namespace foldlab::field
