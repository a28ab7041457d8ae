// Sweeps and regime maps are solves at the swept values; the breeze leaves the supports alone.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "core/analysis/sweep.hpp"
#include "core/geometry/geometry.hpp"
#include "core/io/preset.hpp"

namespace foldlab {
namespace {

// Table 1's cloth by the exact method (eq. 7 as printed, c = 26.9), swept over h in 50 mm steps:
// the points at Table 1's three heights are its rows as docs/calibration.md tabulates them (the
// long-double reference solutions of test_benchmark_cases agree): n = 5, 8, 14; z_max = 56.6,
// 43.0, 29.5 mm; Q = 1.317, 1.253, 1.180.
Parameters table1_exact() {
  Parameters p =
      load_preset(std::filesystem::path(FOLDLAB_PRESETS_DIR) / "paper-table1-h900.json").parameters;
  p.model.method = Method::exact;
  return p;
}

TEST(Sweep, EachPointIsTheSolveAtThatValue) {
  const SweepAxis axis{"h", 900.0, 2350.0, 30, false};  // (2350 - 900) / 29 = 50 mm a step
  const std::vector<SweepPoint> points = sweep(table1_exact(), axis);
  ASSERT_EQ(points.size(), 30u);
  EXPECT_DOUBLE_EQ(points.front().value, 900.0);
  EXPECT_DOUBLE_EQ(points.back().value, 2350.0);
  for (const SweepPoint& point : points) {
    ASSERT_TRUE(point.valid) << point.value;
    EXPECT_EQ(point.regime, Regime::wrinkled) << point.value;
  }
  struct Row {
    std::size_t index;
    double h_mm;
    int n;
    double z_max_mm;
    double Q;
  };
  for (const Row& row : {Row{0, 900.0, 5, 56.6, 1.317}, Row{10, 1400.0, 8, 43.0, 1.253},
                         Row{29, 2350.0, 14, 29.5, 1.180}}) {
    const SweepPoint& point = points[row.index];
    SCOPED_TRACE(row.h_mm);
    EXPECT_NEAR(point.value, row.h_mm, 1e-9);
    EXPECT_EQ(point.n, row.n);
    EXPECT_NEAR(point.z_max_mm, row.z_max_mm, 0.05);
    EXPECT_NEAR(point.Q, row.Q, 0.0005);
  }
  // The paper's trend: n grows with h (Table 1 printed 5, 7, 8 at 900, 1400, 2350 mm).
  for (std::size_t i = 1; i < points.size(); ++i) {
    EXPECT_GE(points[i].n, points[i - 1].n) << points[i].value;
  }
}

TEST(Sweep, LogarithmicAxisAndKAtTheCurrentNu) {
  const SweepAxis axis{"K", 10.0, 1000.0, 3, true};
  EXPECT_NEAR(axis.value(1), 100.0, 1e-9);
  Parameters p;
  ASSERT_TRUE(set_number(p, "K", 40.0));
  EXPECT_NEAR(stiffness_constant_K(p), 40.0, 1e-12);
  EXPECT_NEAR(get_number(p, "K"), 40.0, 1e-12);
}

TEST(Sweep, InvalidValuesAreMarkedNotSolved) {
  Parameters base;
  const std::vector<SweepPoint> points = sweep(base, SweepAxis{"d", 0.0, 800.0, 9, false});
  EXPECT_TRUE(points.front().valid);  // d = 0: no slack, a valid answer
  EXPECT_EQ(points.front().regime, Regime::no_slack);
  EXPECT_FALSE(points.back().valid);  // d = 800 >= L/2 = 700
}

TEST(Sweep, AxisChecksSayWhatIsWrong) {
  EXPECT_NE(check_axis({"q", 1, 2, 10, false})->find("cannot be swept"), std::string::npos);
  EXPECT_NE(check_axis({"E", -1, 2, 10, true})->find("positive"), std::string::npos);
  EXPECT_NE(check_axis({"E", 1, 2, 1, false})->find("steps"), std::string::npos);
  EXPECT_FALSE(check_axis({"w", 1e-7, 1e-5, 64, true}).has_value());
}

TEST(Sweep, LogarithmicEndsFarApartStayFinite) {
  // from * pow(to / from, f) overflowed here: 0.01 / 1e-300 is above DBL_MAX.
  const SweepAxis axis{"w", 1e-300, 1e10, 1001, true};
  for (const int i : {1, 500, 999}) {
    // Evenly spaced in log10 between -300 and 10.
    const double expected_log10 = -300.0 + 310.0 * i / 1000.0;
    EXPECT_NEAR(std::log10(axis.value(i)), expected_log10, 1e-9) << i;
  }
  EXPECT_NEAR(axis.value(1000), 1e10, 1e-3);
}

// The ends are the numbers given: recomputed through exp(log(x)) they came out a few ulps past
// them (50.000000000000014), and the input's own range refused the last row.
TEST(Sweep, TheEndsAreExactlyTheValuesGiven) {
  for (const auto& [from, to] :
       {std::pair{1e-3, 50.0}, std::pair{1e-2, 1e-9}, std::pair{0.1, 0.3}, std::pair{3.0, 7.0}}) {
    for (const bool logarithmic : {true, false}) {
      for (const int steps : {2, 3, 10000}) {
        SweepAxis axis;
        axis.from = from;
        axis.to = to;
        axis.steps = steps;
        axis.logarithmic = logarithmic;
        EXPECT_EQ(axis.value(0), from);
        EXPECT_EQ(axis.value(steps - 1), to) << from << " " << to << " " << steps;
        for (int i = 0; i < steps; i += 997) {
          EXPECT_GE(axis.value(i), std::min(from, to));
          EXPECT_LE(axis.value(i), std::max(from, to));
        }
      }
    }
  }
  SweepAxis t;
  t.key = "t";
  t.from = 1e-3;
  t.to = 50.0;
  t.steps = 10000;
  t.logarithmic = true;
  const std::vector<SweepPoint> points = sweep(Parameters{}, t);
  EXPECT_TRUE(points.back().valid) << points.back().value;
  EXPECT_EQ(points.back().value, 50.0);
}

TEST(Sweep, EndsOutsideTheInputTableAreRefusedWithTheRange) {
  // Subnormal, below the table's range, and K far beyond c's range divided by 1 - nu^2.
  const std::optional<std::string> subnormal = check_axis({"w", 1e-320, 0.01, 2000, true});
  ASSERT_TRUE(subnormal.has_value());
  EXPECT_NE(subnormal->find("subnormal"), std::string::npos) << *subnormal;
  const std::optional<std::string> thin = check_axis({"t", 1e-300, 1.0, 50, true});
  ASSERT_TRUE(thin.has_value());
  EXPECT_NE(thin->find("thickness t = 1e-300 mm must be between 0.001 and 50 mm"),
            std::string::npos)
      << *thin;
  const std::optional<std::string> stiff = check_axis({"K", 1e-300, 1e300, 50, true});
  ASSERT_TRUE(stiff.has_value());
  EXPECT_NE(stiff->find("K = 1e-300"), std::string::npos) << *stiff;
  EXPECT_TRUE(check_axis({"K", 1.0, 1e300, 50, true}).has_value());
  // c's upper end 1e4 over 1 - 0.5^2 (nu below 0.5): K up to 13333 can still be reached.
  EXPECT_FALSE(check_axis({"K", 1.0, 13000.0, 50, true}).has_value());
  EXPECT_TRUE(check_axis({"K", 1.0, 13400.0, 50, true}).has_value());
  EXPECT_FALSE(check_axis({"h", 900.0, 2350.0, 10000, false}).has_value());
  EXPECT_TRUE(check_axis({"h", 900.0, 2350.0, 10001, false}).has_value());
}

// Table 1's cloth over h (x, as the sweep above) and d (y: 100, 50 and 0 mm), in two halves as two
// threads compute them. The first row is Table 1's d = 100 mm: its cells at Table 1's heights are
// the rows docs/calibration.md tabulates. The last, d = 0, leaves the upper edge no slack (l = L):
// a flat cloth, n = 0, at every h. Between them, l = 1350 mm: the edge's sag A, from
// L/l - 1 = (pi A / 2 l)² = 0.037, is about 165 mm, well below every h, so the cloth folds.
TEST(RegimeMap, RowsAreSolvesAtTheGridValues) {
  const SweepAxis x{"h", 900.0, 2350.0, 30, false};
  const SweepAxis y{"d", 100.0, 0.0, 3, false};
  std::vector<MapCell> cells(30 * 3);
  map_rows(table1_exact(), x, y, 0, 1, std::span<MapCell>(cells).first(30));
  map_rows(table1_exact(), x, y, 1, 3, std::span<MapCell>(cells).subspan(30));
  const auto cell = [&](int i, int j) { return cells[static_cast<std::size_t>(j * 30 + i)]; };
  for (const auto& [i, n, z_max_mm] :
       {std::tuple{0, 5, 56.6}, std::tuple{10, 8, 43.0}, std::tuple{29, 14, 29.5}}) {
    ASSERT_TRUE(cell(i, 0).valid) << i;
    EXPECT_EQ(cell(i, 0).n, n) << i;
    EXPECT_NEAR(cell(i, 0).z_max_mm, z_max_mm, 0.05) << i;
  }
  for (int i = 0; i < 30; ++i) {
    ASSERT_TRUE(cell(i, 1).valid) << i;
    EXPECT_EQ(cell(i, 1).regime, Regime::wrinkled) << i;
    EXPECT_GE(cell(i, 1).n, 1) << i;
    ASSERT_TRUE(cell(i, 2).valid) << i;
    EXPECT_EQ(cell(i, 2).regime, Regime::no_slack) << i;
    EXPECT_EQ(cell(i, 2).n, 0) << i;
  }
}

TEST(Breeze, SupportsStayAndTheOffsetIsBounded) {
  for (float t : {0.0f, 0.7f, 2.5f}) {
    EXPECT_EQ(breeze_offset({-650.0f, 0.0f, 0.0f}, 1414.0f, 80.0f, t), Eigen::Vector3f::Zero());
    const Eigen::Vector3f bottom = breeze_offset({0.0f, 1414.0f, 40.0f}, 1414.0f, 80.0f, t);
    EXPECT_LE(std::abs(bottom.z()), 80.0f + 1e-4f);
    EXPECT_LE(std::abs(bottom.x()), 20.0f + 1e-4f);
    EXPECT_EQ(bottom.y(), 0.0f);
  }
  // It moves: two instants give two offsets.
  EXPECT_NE(breeze_offset({0, 1000, 0}, 1414, 80, 0.0f),
            breeze_offset({0, 1000, 0}, 1414, 80, 0.3f));
}

// Thicker cloth on Table 1's case turns stiff where s = K E t³ / (w h l²) reaches 1, i.e. at
// t = (w h l² / (K E))^(1/3) = (1.5e-6 × 1400 × 1300² / (29.56 × 165))^(1/3) = 0.901 mm (by hand,
// K = 26.9 / (1 - 0.3²)). Before it, eq. 10 already gives one fold. A single fold's Q is
// a_0/a_1 ~ 100 (the paper's guess a_0/a_n = 101): both stretches are bands, not a Q spike.
TEST(Sweep, AStiffStretchIsABandAndNoSpikeInTheCurves) {
  Parameters base =
      load_preset(std::filesystem::path(FOLDLAB_PRESETS_DIR) / "paper-table1-h1400.json")
          .parameters;
  const SweepAxis axis{"t", 0.1, 1.5, 141, false};  // 0.01 mm apart
  const std::vector<SweepPoint> points = sweep(base, axis);
  double wrinkled_max_Q = 0.0;  // over the points with a progression of folds (n >= 2)
  double single_fold_max_Q = 0.0;
  for (const SweepPoint& p : points) {
    ASSERT_TRUE(p.valid);
    double& max_Q = p.regime == Regime::wrinkled && p.n >= 2 ? wrinkled_max_Q : single_fold_max_Q;
    max_Q = std::max(max_Q, p.Q);
  }
  ASSERT_GT(single_fold_max_Q, 10.0 * wrinkled_max_Q) << "the spike the curves used to show";

  const std::vector<RegimeBand> bands = regime_bands(points, false);
  ASSERT_EQ(bands.size(), 2u);
  EXPECT_EQ(bands[0].name, "one fold");
  EXPECT_FALSE(bands[0].breaks_curve) << "n = 1 and its z_max stay on the curve";
  EXPECT_DOUBLE_EQ(bands[0].to, bands[1].from);
  EXPECT_EQ(bands[1].regime, Regime::stiff);
  EXPECT_EQ(bands[1].name, "stiff");
  EXPECT_TRUE(bands[1].breaks_curve);
  EXPECT_NEAR(bands[1].from, 0.901, 0.01);
  EXPECT_DOUBLE_EQ(bands[1].to, 1.5);

  const SweepCurves curves = sweep_curves(points);
  ASSERT_EQ(curves.Q.size(), points.size());
  int gaps = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (std::isnan(curves.Q[i])) {
      ++gaps;
      EXPECT_GE(points[i].value, bands[0].from);
      EXPECT_EQ(std::isnan(curves.n[i]), points[i].value > bands[1].from);
    } else {
      EXPECT_LE(curves.Q[i], wrinkled_max_Q);
      EXPECT_LT(points[i].value, bands[0].from);
    }
  }
  EXPECT_GT(gaps, static_cast<int>(std::round((1.5 - 0.901) / 0.01)));
}

TEST(Sweep, RefusedAndOtherRegimesMakeTheirOwnBands) {
  Parameters base;
  base.hanging.length_mm = 1400.0;
  // d from 0 (no slack) through wrinkled to d >= L/2 (refused); half-way edges between points.
  const std::vector<SweepPoint> points = sweep(base, SweepAxis{"d", 0.0, 800.0, 9, false});
  const std::vector<RegimeBand> bands = regime_bands(points, false);
  ASSERT_EQ(bands.size(), 2u);
  EXPECT_EQ(bands[0].name, "no slack");
  EXPECT_DOUBLE_EQ(bands[0].from, 0.0);
  EXPECT_DOUBLE_EQ(bands[0].to, 50.0);
  EXPECT_EQ(bands[1].name, "refused");
  EXPECT_FALSE(bands[1].valid);
  EXPECT_DOUBLE_EQ(bands[1].from, 650.0);
  EXPECT_DOUBLE_EQ(bands[1].to, 800.0);
}

}  // namespace
}  // namespace foldlab
