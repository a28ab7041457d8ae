#include "core/model/parameters.hpp"

#include <cmath>

#include "core/model/named_enum.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {

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

double bending_stiffness_Nmm(const Fabric& f) {
  const double t = f.thickness_mm;
  const double nu = f.poisson_ratio;
  return f.youngs_modulus_MPa * t * t * t / (12.0 * (1.0 - nu * nu));
}

double bending_length_mm(const Fabric& f) {
  return std::cbrt(bending_stiffness_Nmm(f) / f.weight_N_per_mm2);
}

std::vector<ValidationIssue> validate(const Parameters& p) {
  std::vector<ValidationIssue> issues;
  for (const InputRefusal& refusal : input_refusals(p)) {
    issues.push_back({std::string(refusal.spec->field), refusal.value, refusal_sentence(refusal)});
  }
  // c is what K is stored as: whoever set K reads it by that name too.
  if (!issues.empty() && issues.back().field == "c") {
    issues.back().message +=
        " (K = c / (1 − ν²) = " + detail::message_number(stiffness_constant_K(p)) + ")";
  }
  const ModelSettings& m = p.model;
  if (m.simpson_intervals % 2 != 0 && m.length_quadrature == LengthQuadrature::simpson) {
    issues.push_back({"simpson_intervals", static_cast<double>(m.simpson_intervals),
                      input_title(*find_input("simpson_intervals")) + " = " +
                          std::to_string(m.simpson_intervals) +
                          " must be even: composite Simpson pairs its intervals"});
  }
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
