#include "foldlab/settings.hpp"

#include <charconv>
#include <cmath>

namespace foldlab {
namespace {

enum class Kind {
  number,
  whole_number,
  stiffness_K,
  method,
  span_rule,
  int_rounding,
  length_quadrature,
  shape
};

// The one table of keys: help texts, parsing and the field each key sets all come from here.
struct Binding {
  SettingKey key;
  Kind kind;
  double& (*number)(Parameters&) = nullptr;     // for Kind::number
  int& (*whole_number)(Parameters&) = nullptr;  // for Kind::whole_number
};

const std::vector<Binding>& bindings() {
  static const std::vector<Binding> table = {
      {{"t", "mm", "fabric thickness"},
       Kind::number,
       [](Parameters& p) -> double& { return p.fabric.thickness_mm; }},
      {{"E", "MPa", "Young's modulus"},
       Kind::number,
       [](Parameters& p) -> double& { return p.fabric.youngs_modulus_MPa; }},
      {{"w", "N/mm²", "weight per area (1.5e-6 N/mm² = 150 g/m²)"},
       Kind::number,
       [](Parameters& p) -> double& { return p.fabric.weight_N_per_mm2; }},
      {{"nu", "", "Poisson's ratio"},
       Kind::number,
       [](Parameters& p) -> double& { return p.fabric.poisson_ratio; }},
      {{"h", "mm", "height of the cloth at the centre"},
       Kind::number,
       [](Parameters& p) -> double& { return p.hanging.height_mm; }},
      {{"L", "mm", "length of the upper edge (width)"},
       Kind::number,
       [](Parameters& p) -> double& { return p.hanging.length_mm; }},
      {{"d", "mm", "inward displacement of each support"},
       Kind::number,
       [](Parameters& p) -> double& { return p.hanging.support_displacement_mm; }},
      {{"K", "", "c/(1-nu²) of eq. 7 (sets c at the current nu)"}, Kind::stiffness_K},
      {{"c", "", "load-condition constant of eq. 7"},
       Kind::number,
       [](Parameters& p) -> double& { return p.model.load_constant_c; }},
      {{"p", "", "exponent on eq. 7's stress ratio, s -> s^p (1 = the paper; foldlab calibrate)"},
       Kind::number,
       [](Parameters& p) -> double& { return p.model.stress_exponent_p; }},
      {{"method", "", "paper | exact"}, Kind::method},
      {{"span_rule", "", "L-d | L-2d: how the span l follows from L and d"}, Kind::span_rule},
      {{"int_rounding", "", "nearest | floor: Int[] of eq. 10"}, Kind::int_rounding},
      {{"simpson_intervals", "", "paper method: Simpson intervals for eq. 8 (even)"},
       Kind::whole_number,
       nullptr,
       [](Parameters& p) -> int& { return p.model.simpson_intervals; }},
      {{"length_tolerance", "", "paper method: stop when |L'/L - 1| <= this"},
       Kind::number,
       [](Parameters& p) -> double& { return p.model.length_tolerance; }},
      {{"max_iterations", "", "paper method: iteration cap"},
       Kind::whole_number,
       nullptr,
       [](Parameters& p) -> int& { return p.model.max_iterations; }},
      {{"length_quadrature", "",
        "simpson | trapezoid: paper method's rule for eq. 8 (simpson_intervals intervals)"},
       Kind::length_quadrature},
      {{"shape", "", "cosine | rectangular | strip | inclined: the cloth the pattern is laid on"},
       Kind::shape},
      {{"supports", "", "strip: number of equally spaced supports (k - 1 spans)"},
       Kind::whole_number,
       nullptr,
       [](Parameters& p) -> int& { return p.shape.supports; }},
      {{"incline_deg", "deg", "inclined: angle of the line through the supports"},
       Kind::number,
       [](Parameters& p) -> double& { return p.shape.incline_deg; }},
  };
  return table;
}

template <class Enum>
std::optional<std::string> set_named(std::string_view key, std::string_view value, Enum& field,
                                     bool (*parse)(std::string_view, Enum&), const char* allowed) {
  if (parse(value, field)) {
    return std::nullopt;
  }
  return std::string(key) + " = '" + std::string(value) + "' is not one of: " + allowed;
}

}  // namespace

const std::vector<SettingKey>& setting_keys() {
  static const std::vector<SettingKey> keys = [] {
    std::vector<SettingKey> out;
    for (const Binding& b : bindings()) {
      out.push_back(b.key);
    }
    return out;
  }();
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

static const Binding* find_binding(std::string_view key) {
  for (const Binding& b : bindings()) {
    if (b.key.key == key) {
      return &b;
    }
  }
  return nullptr;
}

bool set_numeric_setting(Parameters& p, std::string_view key, double value) {
  const Binding* binding = find_binding(key);
  if (binding != nullptr && binding->kind == Kind::number) {
    binding->number(p) = value;
    return true;
  }
  if (binding != nullptr && binding->kind == Kind::stiffness_K) {
    set_stiffness_constant_K(p, value);
    return true;
  }
  return false;
}

std::optional<double> numeric_setting(const Parameters& p, std::string_view key) {
  const Binding* binding = find_binding(key);
  if (binding != nullptr && binding->kind == Kind::number) {
    // The table's accessors take a mutable Parameters; this one only reads.
    return binding->number(const_cast<Parameters&>(p));
  }
  if (binding != nullptr && binding->kind == Kind::stiffness_K) {
    return stiffness_constant_K(p);
  }
  return std::nullopt;
}

std::optional<std::string> apply_setting(Parameters& p, std::string_view key,
                                         std::string_view value) {
  const Binding* binding = find_binding(key);
  if (binding == nullptr) {
    std::string known;
    for (const SettingKey& k : setting_keys()) {
      known += (known.empty() ? "" : ", ") + std::string(k.key);
    }
    return "unknown key '" + std::string(key) + "' (known: " + known + ")";
  }
  switch (binding->kind) {
    case Kind::method:
      return set_named(key, value, p.model.method, parse_method, "paper, exact");
    case Kind::span_rule:
      return set_named(key, value, p.model.span_rule, parse_span_rule, "L-d, L-2d");
    case Kind::int_rounding:
      return set_named(key, value, p.model.int_rounding, parse_int_rounding, "nearest, floor");
    case Kind::length_quadrature:
      return set_named(key, value, p.model.length_quadrature, parse_length_quadrature,
                       "simpson, trapezoid");
    case Kind::shape:
      return set_named(key, value, p.shape.kind, parse_shape_kind,
                       "cosine, rectangular, strip, inclined");
    default:
      break;
  }
  const std::optional<double> number = parse_number(value);
  if (!number) {
    return std::string(key) + " = '" + std::string(value) + "' is not a number";
  }
  switch (binding->kind) {
    case Kind::stiffness_K:
      set_stiffness_constant_K(p, *number);
      break;
    case Kind::whole_number:
      if (*number != std::floor(*number) || std::abs(*number) > 1e9) {
        return std::string(key) + " = '" + std::string(value) + "' must be a whole number";
      }
      binding->whole_number(p) = static_cast<int>(*number);
      break;
    default:
      binding->number(p) = *number;
  }
  return std::nullopt;
}

std::vector<std::string> apply_assignments(Parameters& p,
                                           const std::vector<std::string>& assignments) {
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
