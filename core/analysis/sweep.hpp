// One input swept over a range (the sweep plots and `foldlab sweep`), and two inputs over a grid
// (the regime map). Pure functions of the base parameters: safe to run on several threads.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

struct SweepAxis {
  std::string key;  // a --set key that takes a number: t, E, w, h, L, d, K, nu, c, p ...
  double from = 0.0;
  double to = 1.0;
  int steps = 100;  // points, >= 2
  bool logarithmic = false;

  double value(int i) const;  // the i-th of `steps` values, from `from` to `to`
};

// The keys a sweep or a map can run over, and whether their natural scale is logarithmic.
const std::vector<std::string>& sweepable_keys();
bool natural_log_scale(const std::string& key);
// The sweepable keys whose natural scale is logarithmic ("t, E, w, K"), or linear: for help texts.
std::string sweepable_keys_on_scale(bool logarithmic);

// Checks the axis: a known numeric key, finite ends, steps in [2, 100000], positive ends on a log
// scale. Returns the problem as a sentence, or nullopt.
std::optional<std::string> check_axis(const SweepAxis& axis);

// Sets a numeric input by its key (K at the current nu, as --set does). False for unknown keys.
bool set_number(Parameters& p, const std::string& key, double value);
double get_number(const Parameters& p, const std::string& key);

// The solution at one value of the axis (FoldSummary's defaults where nothing was solved).
struct SweepPoint : FoldSummary {
  double value = 0.0;
  bool valid = false;  // false where the parameters do not validate (e.g. d >= L/2): no solve
};

std::vector<SweepPoint> sweep(const Parameters& base, const SweepAxis& axis);

// A run of sweep points outside the plain wrinkled regime with two or more folds, shown as a
// shaded band along the x axis. Its Q says nothing a curve should join: with one fold (stiff, or
// n = 1) Q is that fold's a_0/a_1, ~100, and would flatten every wrinkled value.
struct RegimeBand {
  double from = 0.0;  // half-way to the neighbouring points (geometric on a log axis)
  double to = 0.0;
  bool valid = true;  // false: the inputs are refused (validate fails), nothing was solved
  Regime regime = Regime::no_slack;
  // n and z_max break here; "one fold" and "n cycles" keep them (Q breaks wherever n < 2).
  bool breaks_curve = true;
  std::string name;  // short, for the band's label: "stiff", "one fold", "refused", ...
};
std::vector<RegimeBand> regime_bands(std::span<const SweepPoint> points, bool logarithmic);

// n, Q and z_max per point for the curves, NaN (a gap) where a band breaks the curve and Q's
// gap wherever n < 2.
struct SweepCurves {
  std::vector<double> x, n, Q, z_max_mm;
};
SweepCurves sweep_curves(std::span<const SweepPoint> points);

// A FoldSummary narrowed for maps of many cells: no Q, z_max in single precision.
struct MapCell {
  bool valid = false;
  int n = 0;
  float z_max_mm = 0.0f;
  Regime regime = Regime::no_slack;
  bool n_capped = false;  // n is kMaxWrinkles, the cap, not eq. 10's count

  static MapCell solved(const FoldSummary& s) {
    return {true, s.n, static_cast<float>(s.z_max_mm), s.regime, s.n_capped};
  }
};

// Rows [row_begin, row_end) of a map over two axes, row-major (x fastest): out has x.steps cells
// per row. Each cell is one solve at the base parameters with the two inputs set.
void map_rows(const Parameters& base, const SweepAxis& x, const SweepAxis& y, int row_begin,
              int row_end, std::span<MapCell> out);

}  // namespace foldlab
