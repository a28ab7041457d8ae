#include "foldlab/parameters.hpp"

#include <cmath>
#include <initializer_list>
#include <sstream>

namespace foldlab {
namespace {

std::string format_number(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

// Adds an issue unless lo <= value <= hi (with the inclusivity given) and value is finite.
void check_range(std::vector<ValidationIssue>& issues, const char* field, double value, double lo,
                 double hi, bool lo_inclusive, bool hi_inclusive, const char* why) {
  const bool above_lo = lo_inclusive ? value >= lo : value > lo;
  const bool below_hi = hi_inclusive ? value <= hi : value < hi;
  if (std::isfinite(value) && above_lo && below_hi) {
    return;
  }
  std::string message = std::string(field) + " = " + format_number(value) + " must be ";
  message += lo_inclusive ? "in [" : "in (";
  message += format_number(lo) + ", " + format_number(hi);
  message += hi_inclusive ? "]" : ")";
  message += std::string(": ") + why;
  issues.push_back({field, value, std::move(message)});
}

template <class Enum>
bool parse_named(std::string_view s, Enum& out, std::initializer_list<Enum> values) {
  for (Enum v : values) {
    if (s == to_string(v)) {
      out = v;
      return true;
    }
  }
  return false;
}

}  // namespace

double stiffness_constant_K(const Parameters& p) {
  const double nu = p.fabric.poisson_ratio;
  return p.model.load_constant_c / (1.0 - nu * nu);
}

void set_stiffness_constant_K(Parameters& p, double K) {
  const double nu = p.fabric.poisson_ratio;
  p.model.load_constant_c = K * (1.0 - nu * nu);
}

double span_mm(const Parameters& p) {
  const double L = p.hanging.length_mm;
  const double d = p.hanging.support_displacement_mm;
  return p.model.span_rule == SpanRule::L_minus_d ? L - d : L - 2.0 * d;
}

std::vector<ValidationIssue> validate(const Parameters& p) {
  std::vector<ValidationIssue> issues;
  const Fabric& f = p.fabric;
  const Hanging& g = p.hanging;
  const ModelSettings& m = p.model;
  check_range(issues, "t_mm", f.thickness_mm, 0.0, 50.0, false, true,
              "a fabric or membrane thickness, above 0 and at most 50 mm");
  check_range(issues, "E_MPa", f.youngs_modulus_MPa, 0.0, 1e6, false, true,
              "Young's modulus, above 0 and at most 1e6 MPa (stiffer than steel)");
  check_range(issues, "w_N_per_mm2", f.weight_N_per_mm2, 0.0, 1e-2, false, true,
              "weight per area, above 0 and at most 1e-2 N/mm² (a 1 m² sheet of 1 t)");
  check_range(issues, "nu", f.poisson_ratio, 0.0, 0.5, true, false,
              "Poisson's ratio of an isotropic material, 0 <= nu < 0.5");
  check_range(issues, "h_mm", g.height_mm, 0.0, 1e5, false, true,
              "the cloth's height, above 0 and at most 100 m");
  check_range(issues, "L_mm", g.length_mm, 0.0, 1e5, false, true,
              "the upper edge's length, above 0 and at most 100 m");
  if (std::isfinite(g.length_mm) && g.length_mm > 0.0) {
    const double half = 0.5 * g.length_mm;
    check_range(issues, "d_mm", g.support_displacement_mm, 0.0, half, true, false,
                ("each support moves inward by d, so d must stay below L/2 = " +
                 format_number(half) + " where the supports would meet")
                    .c_str());
  }
  check_range(issues, "c", m.load_constant_c, 0.0, 1e6, false, true,
              "the load-condition constant of eq. 7 is positive");
  check_range(issues, "p", m.stress_exponent_p, 0.0, 5.0, false, true,
              "the exponent on eq. 7's stress ratio (1 = the paper); above 0 so that stiffer "
              "fabric still gives fewer folds, at most 5 (the calibration's search range)");
  check_range(issues, "simpson_intervals", m.simpson_intervals, 2.0, 1e6, true, true,
              "composite Simpson needs at least 2 intervals");
  if (m.simpson_intervals % 2 != 0 && m.length_quadrature == LengthQuadrature::simpson) {
    issues.push_back({"simpson_intervals", static_cast<double>(m.simpson_intervals),
                      "simpson_intervals = " + std::to_string(m.simpson_intervals) +
                          " must be even: composite Simpson pairs its intervals"});
  }
  check_range(issues, "length_tolerance", m.length_tolerance, 0.0, 1.0, false, false,
              "the paper method's relative tolerance on L, e.g. 0.05 for the paper's 5%");
  check_range(issues, "max_iterations", m.max_iterations, 1.0, 1e6, true, true,
              "the paper method needs at least one iteration");
  check_range(issues, "supports", p.shape.supports, 2.0, 64.0, true, true,
              "a strip hangs from 2 to 64 equally spaced supports");
  check_range(issues, "incline_deg", p.shape.incline_deg, -80.0, 80.0, false, false,
              "the line through inclined supports is steeper than vertical beyond +-80 deg");
  return issues;
}

std::string format_issues(const std::vector<ValidationIssue>& issues) {
  std::string out;
  for (const ValidationIssue& issue : issues) {
    out += issue.message;
    out += '\n';
  }
  return out;
}

std::string_view to_string(Method m) {
  return m == Method::paper ? "paper" : "exact";
}
std::string_view to_string(SpanRule r) {
  return r == SpanRule::L_minus_d ? "L-d" : "L-2d";
}
std::string_view to_string(IntRounding r) {
  return r == IntRounding::floor ? "floor" : "nearest";
}
std::string_view to_string(LengthQuadrature q) {
  return q == LengthQuadrature::simpson ? "simpson" : "trapezoid";
}

bool parse_method(std::string_view s, Method& out) {
  return parse_named(s, out, {Method::paper, Method::exact});
}
bool parse_span_rule(std::string_view s, SpanRule& out) {
  return parse_named(s, out, {SpanRule::L_minus_d, SpanRule::L_minus_2d});
}
bool parse_int_rounding(std::string_view s, IntRounding& out) {
  return parse_named(s, out, {IntRounding::floor, IntRounding::nearest});
}
bool parse_length_quadrature(std::string_view s, LengthQuadrature& out) {
  return parse_named(s, out, {LengthQuadrature::simpson, LengthQuadrature::trapezoid});
}

}  // namespace foldlab
