#include "core/analysis/sweep.hpp"

#include <algorithm>
#include <cmath>

#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {

double SweepAxis::value(int i) const {
  const double f = steps > 1 ? static_cast<double>(i) / (steps - 1) : 0.0;
  return logarithmic ? from * std::pow(to / from, f) : from + (to - from) * f;
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

// The sweepable keys only; the key -> field table itself lives in settings.cpp.
bool set_number(Parameters& p, const std::string& key, double value) {
  const std::vector<std::string>& keys = sweepable_keys();
  return std::find(keys.begin(), keys.end(), key) != keys.end() &&
         set_numeric_setting(p, key, value);
}

double get_number(const Parameters& p, const std::string& key) {
  return numeric_setting(p, key).value_or(0.0);
}

std::optional<std::string> check_axis(const SweepAxis& axis) {
  Parameters probe;
  if (!set_number(probe, axis.key, 1.0)) {
    return "'" + axis.key + "' cannot be swept (one of: " + detail::join(sweepable_keys(), ", ") +
           ")";
  }
  if (!std::isfinite(axis.from) || !std::isfinite(axis.to)) {
    return "the range of " + axis.key + " must be finite";
  }
  if (axis.steps < 2 || axis.steps > 100000) {
    return "steps = " + std::to_string(axis.steps) + " must be in [2, 100000]";
  }
  if (axis.logarithmic && !(axis.from > 0.0 && axis.to > 0.0)) {
    return "a logarithmic range of " + axis.key + " needs positive ends";
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
    const Solution s = solve(p);
    point.valid = true;
    point.n = s.n;
    point.Q = s.Q;
    point.z_max_mm = s.z_max_mm;
    point.regime = s.regime;
  }
  return points;
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
      const Solution s = solve(p);
      cell.valid = true;
      cell.n = s.n;
      cell.z_max_mm = static_cast<float>(s.z_max_mm);
      cell.regime = s.regime;
    }
  }
}

}  // namespace foldlab
