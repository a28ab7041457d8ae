// Inputs of the wrinkle model: the fabric, its hanging geometry and the model's settings.
// Units (mm, MPa = N/mm², N/mm²) are part of every name; docs/model.md explains each input.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/model/shape.hpp"
#include "core/model/wrinkle_law.hpp"

namespace foldlab {

// c of eq. 7 as printed (p = 1), calibrated on Tables 1-2 of the paper with nu = 0.3, so
// K = c / (1 - nu²) = 29.56: the middle (geometric mean) of the widest band of c that gets the most
// rows' n exactly (docs/calibration.md). The solver's neutral default and the paper presets'
// constant; the default preset uses the calibrated form s -> s^p (docs/default-model.md).
inline constexpr double kCalibratedLoadConstantC = 26.9;
inline constexpr double kDefaultPoissonRatio = 0.3;

struct Fabric {
  double thickness_mm = 0.25;
  double youngs_modulus_MPa = 165.0;
  double weight_N_per_mm2 = 15e-7;
  double poisson_ratio = kDefaultPoissonRatio;

  bool operator==(const Fabric&) const = default;
};

struct Hanging {
  double height_mm = 1400.0;               // h: vertical extent at the centre
  double length_mm = 1400.0;               // L: initial length of the upper edge
  double support_displacement_mm = 100.0;  // d: inward displacement of each support

  bool operator==(const Hanging&) const = default;
};

enum class Method { paper, exact };
// How the span l between the supports follows from L and d. The paper's text says L - 2d, its
// printed tables fit L - d (docs/model.md), so both are offered.
enum class SpanRule { L_minus_d, L_minus_2d };
// Int[·] of eq. 10: the paper does not say whether it rounds down or to the nearest.
enum class IntRounding { floor, nearest };
// The paper method's quadrature of eq. 8: the paper's composite Simpson, or the trapezoid rule,
// which converges exponentially on this smooth periodic integrand.
enum class LengthQuadrature { simpson, trapezoid };

struct ModelSettings {
  Method method = Method::paper;
  // Which law counts the folds (core/model/wrinkle_law.hpp); c and p are its constants.
  WrinkleLawKind law = WrinkleLawKind::conci;
  // c of eq. 7, the load-condition constant; eq. 7 uses K = c / (1 - nu²). Calibrated on Tables 1-2
  // (docs/calibration.md).
  double load_constant_c = kCalibratedLoadConstantC;
  SpanRule span_rule = SpanRule::L_minus_d;
  IntRounding int_rounding = IntRounding::nearest;
  int simpson_intervals = 20;      // paper method: intervals of the eq. 8 quadrature
  double length_tolerance = 0.05;  // paper method: stop when |L'/L - 1| <= this
  int max_iterations = 200;        // paper method: iteration cap
  LengthQuadrature length_quadrature = LengthQuadrature::simpson;  // paper method: rule for eq. 8
  // The calibrated variant of eq. 7: its stress ratio s enters as s^p. p = 1 is the paper's form
  // (docs/calibration.md: the printed tables make n depend on w, t, E and h less than eq. 7 does).
  double stress_exponent_p = 1.0;

  bool operator==(const ModelSettings&) const = default;
};

struct Parameters {
  Fabric fabric;
  Hanging hanging;
  ModelSettings model;
  Shape shape;  // how the solution is laid out; never an input of the solver

  bool operator==(const Parameters&) const = default;
};

// The constants of eq. 7 as a calibration sees them: K = c / (1 - nu²) and the exponent p.
struct Eq7Constants {
  double K = 0.0;
  double p = 1.0;

  bool operator==(const Eq7Constants&) const = default;
};

// K = c / (1 - nu²): the only combination of c and nu that eq. 7 sees.
double stiffness_constant_K(const Parameters& p);
// Sets c so that K takes the given value at the current Poisson ratio.
void set_stiffness_constant_K(Parameters& p, double K);
// The span l between the supports, by the chosen span rule.
double span_mm(const Parameters& p);

// The fabric's plate bending stiffness per unit width, B = E t³ / (12 (1 - nu²)), in N mm
// (N mm² per mm of width): the moment per unit width that bends it to unit curvature.
double bending_stiffness_Nmm(const Fabric& f);
// Peirce's bending length c_b = (B / w)^(1/3), mm: the length over which the fabric's own weight
// bends it as much as its stiffness resists, the radius its folds take (docs/rounded-folds.md).
double bending_length_mm(const Fabric& f);

// One problem with one input: which field (the paper's symbol with its unit), its value, and a
// sentence with the allowed range and the reason.
struct ValidationIssue {
  std::string field;
  double value = 0.0;
  std::string message;
};

// Every problem at once; empty when the parameters can be solved.
std::vector<ValidationIssue> validate(const Parameters& p);
std::string format_issues(const std::vector<ValidationIssue>& issues);

std::string_view to_string(Method m);
std::string_view to_string(SpanRule r);
std::string_view to_string(IntRounding r);
std::string_view to_string(LengthQuadrature q);
// Parse the names above; return false (and leave `out` alone) for anything else.
bool parse_method(std::string_view s, Method& out);
bool parse_span_rule(std::string_view s, SpanRule& out);
bool parse_int_rounding(std::string_view s, IntRounding& out);
bool parse_length_quadrature(std::string_view s, LengthQuadrature& out);

}  // namespace foldlab
