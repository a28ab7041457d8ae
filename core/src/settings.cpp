#include "foldlab/settings.hpp"

#include <charconv>
#include <cmath>

namespace foldlab {

const std::vector<SettingKey>& setting_keys() {
  static const std::vector<SettingKey> keys = {
      {"t", "mm", "fabric thickness"},
      {"E", "MPa", "Young's modulus"},
      {"w", "N/mm²", "weight per area (1.5e-6 N/mm² = 150 g/m²)"},
      {"nu", "", "Poisson's ratio"},
      {"h", "mm", "height of the cloth at the centre"},
      {"L", "mm", "length of the upper edge (width)"},
      {"d", "mm", "inward displacement of each support"},
      {"K", "", "c/(1-nu²) of eq. 7 (sets c at the current nu)"},
      {"c", "", "load-condition constant of eq. 7"},
      {"method", "", "paper | exact"},
      {"span_rule", "", "L-d | L-2d: how the span l follows from L and d"},
      {"int_rounding", "", "nearest | floor: Int[] of eq. 10"},
      {"simpson_intervals", "", "paper method: Simpson intervals for eq. 8 (even)"},
      {"length_tolerance", "", "paper method: stop when |L'/L - 1| <= this"},
      {"max_iterations", "", "paper method: iteration cap"},
  };
  return keys;
}

std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::string> apply_setting(Parameters& p, std::string_view key,
                                         std::string_view value) {
  const std::string quoted = "'" + std::string(value) + "'";
  auto named = [&](auto parse, auto& field, const char* allowed) -> std::optional<std::string> {
    if (parse(value, field)) {
      return std::nullopt;
    }
    return std::string(key) + " = " + quoted + " is not one of: " + allowed;
  };
  if (key == "method") {
    return named(parse_method, p.model.method, "paper, exact");
  }
  if (key == "span_rule") {
    return named(parse_span_rule, p.model.span_rule, "L-d, L-2d");
  }
  if (key == "int_rounding") {
    return named(parse_int_rounding, p.model.int_rounding, "nearest, floor");
  }
  const std::optional<double> number = parse_number(value);
  double* target = nullptr;
  if (key == "t") target = &p.fabric.thickness_mm;
  else if (key == "E") target = &p.fabric.youngs_modulus_MPa;
  else if (key == "w") target = &p.fabric.weight_N_per_mm2;
  else if (key == "nu") target = &p.fabric.poisson_ratio;
  else if (key == "h") target = &p.hanging.height_mm;
  else if (key == "L") target = &p.hanging.length_mm;
  else if (key == "d") target = &p.hanging.support_displacement_mm;
  else if (key == "c") target = &p.model.load_constant_c;
  else if (key == "length_tolerance") target = &p.model.length_tolerance;
  const bool integer_key = key == "simpson_intervals" || key == "max_iterations";
  if (target == nullptr && !integer_key && key != "K") {
    std::string known;
    for (const SettingKey& k : setting_keys()) {
      known += (known.empty() ? "" : ", ") + std::string(k.key);
    }
    return "unknown key '" + std::string(key) + "' (known: " + known + ")";
  }
  if (!number) {
    return std::string(key) + " = " + quoted + " is not a number";
  }
  if (key == "K") {
    set_stiffness_constant_K(p, *number);
  } else if (integer_key) {
    if (*number != std::floor(*number) || std::abs(*number) > 1e9) {
      return std::string(key) + " = " + quoted + " must be a whole number";
    }
    (key == "simpson_intervals" ? p.model.simpson_intervals : p.model.max_iterations) =
        static_cast<int>(*number);
  } else {
    *target = *number;
  }
  return std::nullopt;
}

std::vector<std::string> apply_assignments(Parameters& p, const std::vector<std::string>& assignments) {
  std::vector<std::string> errors;
  std::vector<std::pair<std::string, std::string>> deferred;
  for (const std::string& assignment : assignments) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
      errors.push_back("'" + assignment + "' is not KEY=VALUE");
      continue;
    }
    std::string key = assignment.substr(0, eq);
    std::string value = assignment.substr(eq + 1);
    if (key == "K") {
      deferred.emplace_back(std::move(key), std::move(value));
      continue;
    }
    if (auto error = apply_setting(p, key, value)) {
      errors.push_back(*error);
    }
  }
  for (const auto& [key, value] : deferred) {
    if (auto error = apply_setting(p, key, value)) {
      errors.push_back(*error);
    }
  }
  return errors;
}

}  // namespace foldlab
