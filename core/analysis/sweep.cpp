#include "core/analysis/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/io/export_budget.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {

double SweepAxis::value(int i) const {
  // The ends are the values given, not recomputed: exp(log(50)) is 50.000000000000014, which the
  // input's range would refuse.
  if (i <= 0 || steps <= 1) {
    return from;
  }
  if (i >= steps - 1) {
    return to;
  }
  const double f = static_cast<double>(i) / (steps - 1);
  // A log axis steps in log space: to / from overflows for ends far apart (1e-320 to 0.01).
  const double value = logarithmic ? std::exp(std::log(from) + (std::log(to) - std::log(from)) * f)
                                   : from + (to - from) * f;
  return std::clamp(value, std::min(from, to), std::max(from, to));
}

// The cloth, its hanging and eq. 7's K: the inputs a sweep or the regime map can vary.
const std::vector<std::string>& sweepable_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> out;
    for (const InputSpec& spec : input_table()) {
      if (spec.preset.starts_with("/fabric/") || spec.preset.starts_with("/hanging/") ||
          spec.kind == InputKind::stiffness_K) {
        out.emplace_back(spec.key);
      }
    }
    return out;
  }();
  return keys;
}

bool natural_log_scale(const std::string& key) {
  const InputSpec* spec = find_input(key);
  return spec != nullptr && spec->scale == InputScale::logarithmic;
}

std::string sweepable_keys_on_scale(bool logarithmic) {
  std::vector<std::string> keys;
  for (const std::string& key : sweepable_keys()) {
    if (natural_log_scale(key) == logarithmic) {
      keys.push_back(key);
    }
  }
  return detail::join(keys, ", ");
}

// The sweepable keys only; the key -> field table itself lives in settings.cpp.
bool set_number(Parameters& p, const std::string& key, double value) {
  const std::vector<std::string>& keys = sweepable_keys();
  return std::find(keys.begin(), keys.end(), key) != keys.end() && !set_input(p, key, value);
}

double get_number(const Parameters& p, const std::string& key) {
  return numeric_setting(p, key).value_or(0.0);
}

namespace {

// Where an end of a sweep over `key` may lie: the input table's range, for K the range of c
// divided by 1 - nu² over the permitted nu (K = c / (1 - nu²)).
InputInterval sweep_range(const InputSpec& spec) {
  if (spec.kind != InputKind::stiffness_K) {
    return spec.valid;
  }
  const InputInterval c = find_input("c")->valid;
  const InputInterval nu = find_input("nu")->valid;
  return {c.lo, c.hi / (1.0 - nu.hi * nu.hi), c.lo_open, nu.hi_open || c.hi_open};
}

}  // namespace

std::optional<std::string> check_axis(const SweepAxis& axis) {
  Parameters probe;
  if (!set_number(probe, axis.key, 1.0)) {
    return "'" + axis.key + "' cannot be swept (one of: " + detail::join(sweepable_keys(), ", ") +
           ")";
  }
  if (!std::isfinite(axis.from) || !std::isfinite(axis.to)) {
    return "the range of " + axis.key + " must be finite";
  }
  if (axis.steps < 2 || axis.steps > kMaxSweepSteps) {
    return "steps = " + std::to_string(axis.steps) + " must be in [2, " +
           std::to_string(kMaxSweepSteps) +
           "]: a sweep needs its two ends, and more steps would take too long";
  }
  if (axis.logarithmic && !(axis.from > 0.0 && axis.to > 0.0)) {
    return "a logarithmic range of " + axis.key + " needs positive ends";
  }
  const InputSpec& spec = *find_input(axis.key);
  const InputInterval range = sweep_range(spec);
  for (const double end : {axis.from, axis.to}) {
    if (end != 0.0 && std::abs(end) < std::numeric_limits<double>::min()) {
      return "the sweep's end: " + input_title(spec) + " = " + shown_quantity(spec, end) +
             " is subnormal: no cloth is described by it";
    }
    if (!range.contains(end)) {
      const std::string why =
          spec.why.empty() ? "c / (1 − ν²) with c and ν in their ranges" : std::string(spec.why);
      return "the sweep's end: " + refusal_sentence(range_refusal(spec, end, range, why));
    }
  }
  return std::nullopt;
}

std::vector<SweepPoint> sweep(const Parameters& base, const SweepAxis& axis) {
  std::vector<SweepPoint> points(static_cast<std::size_t>(std::max(axis.steps, 0)));
  Parameters p = base;
  for (int i = 0; i < axis.steps; ++i) {
    SweepPoint& point = points[static_cast<std::size_t>(i)];
    point.value = axis.value(i);
    set_number(p, axis.key, point.value);
    if (!validate(p).empty()) {
      continue;
    }
    static_cast<FoldSummary&>(point) = fold_summary(solve(p));
    point.valid = true;
  }
  return points;
}

namespace {

// n and z_max join the curve wherever there are folds to count; Q only where there are two or
// more: a single fold's "ratio" is a_0/a_1, ~100 at the paper's initial guess, no progression.
bool on_curve(const SweepPoint& p) {
  return p.valid && regime_info(p.regime).has_folds;
}
bool Q_on_curve(const SweepPoint& p) {
  return on_curve(p) && p.n >= 2;
}

bool plain(const SweepPoint& p) {
  return p.valid && regime_info(p.regime).unremarkable && p.n >= 2;
}

const char* band_name(const SweepPoint& p) {
  if (!p.valid) {
    return "refused";
  }
  if (regime_info(p.regime).unremarkable) {
    return p.n < 2 ? "one fold" : "";
  }
  return regime_info(p.regime).label.data();
}

double between(double a, double b, bool logarithmic) {
  return logarithmic && a > 0.0 && b > 0.0 ? std::sqrt(a * b) : 0.5 * (a + b);
}

}  // namespace

std::vector<RegimeBand> regime_bands(std::span<const SweepPoint> points, bool logarithmic) {
  std::vector<RegimeBand> bands;
  const std::size_t count = points.size();
  for (std::size_t i = 0; i < count;) {
    const SweepPoint& first = points[i];
    if (plain(first)) {
      ++i;
      continue;
    }
    const std::string_view name = band_name(first);
    std::size_t end = i + 1;
    while (end < count && !plain(points[end]) && band_name(points[end]) == name) {
      ++end;
    }
    RegimeBand band;
    band.from = i == 0 ? first.value : between(points[i - 1].value, first.value, logarithmic);
    band.to = end == count ? points[end - 1].value
                           : between(points[end - 1].value, points[end].value, logarithmic);
    band.valid = first.valid;
    band.regime = first.regime;
    band.breaks_curve = !on_curve(first);
    band.name = name;
    bands.push_back(std::move(band));
    i = end;
  }
  return bands;
}

SweepCurves sweep_curves(std::span<const SweepPoint> points) {
  SweepCurves out;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const SweepPoint& p : points) {
    const bool shown = on_curve(p);
    out.x.push_back(p.value);
    out.n.push_back(shown ? p.n : nan);
    out.Q.push_back(Q_on_curve(p) ? p.Q : nan);
    out.z_max_mm.push_back(shown ? p.z_max_mm : nan);
  }
  return out;
}

void map_rows(const Parameters& base, const SweepAxis& x, const SweepAxis& y, int row_begin,
              int row_end, std::span<MapCell> out) {
  Parameters p = base;
  std::size_t k = 0;
  for (int j = row_begin; j < row_end; ++j) {
    set_number(p, y.key, y.value(j));
    for (int i = 0; i < x.steps && k < out.size(); ++i, ++k) {
      set_number(p, x.key, x.value(i));
      MapCell& cell = out[k];
      cell = MapCell{};
      if (!validate(p).empty()) {
        continue;
      }
      cell = MapCell::solved(fold_summary(solve(p)));
    }
  }
}

}  // namespace foldlab
