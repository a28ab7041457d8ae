// Conci's law: the folds stop where the weight's stress across a fold reaches the critical
// stress of a plate strip, eq. 7 of A. Conci, "After buckling behavior of thin membranes and
// textiles based on tension field theory and experiments": w h (Q-1)² / (t Q (Q+1)) =
// c E t² / (l² (1 - nu²)), i.e. (Q-1)² = s Q (Q+1) with s = K E t³ / (w h l²). Its root Q7 spaces
// the folds in a geometric progression (eq. 5), and eq. 10 counts them: n = Int[ln(a_0/a_n) / ln
// Q7].
#include <cmath>

#include "core/model/equations.hpp"
#include "core/model/parameters.hpp"
#include "core/model/wrinkle_law.hpp"

namespace foldlab {
namespace {

class ConciLaw final : public WrinkleLaw {
 public:
  WrinkleLawKind kind() const override { return WrinkleLawKind::conci; }
  std::string_view key() const override { return "conci"; }
  std::string_view title() const override { return "Conci (critical stress, eq. 7)"; }
  std::string_view count_formula() const override { return "Int[log(a_0/a_n) / log Q7]"; }
  // The paper prints no c; FoldLab's calibration of the printed form on Tables 1-2
  // (docs/calibration.md) stands in for it.
  double published_load_constant_c() const override { return kCalibratedLoadConstantC; }

  std::optional<FoldCountRule> count_rule(double strength, double /*span_mm*/) const override {
    const std::optional<double> Q7 = wrinkle_ratio_from_stress_ratio(strength);
    if (!Q7) {
      return std::nullopt;  // s^p >= 1: the stiff regime
    }
    return FoldCountRule{FoldSpacing::geometric, std::log(*Q7), *Q7};
  }

  // At x >= 0 (s^p >= 1) eq. 7 has no root: one fold whatever the geometry.
  double log_strength_ceiling(double /*a0_mm*/, double /*span_mm*/) const override { return 0.0; }
};

}  // namespace

const WrinkleLaw& conci_wrinkle_law() {
  static const ConciLaw law;
  return law;
}

}  // namespace foldlab
