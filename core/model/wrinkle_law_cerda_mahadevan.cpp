// Cerda and Mahadevan's law: a sheet stretched along its length L with strain gamma wrinkles
// across it with the wavelength that balances bending against the tension's stiffness,
// lambda = (2 pi L t)^(1/2) / (3 (1 - nu²) gamma)^(1/4)
// (E. Cerda and L. Mahadevan, "Geometry and physics of wrinkling", Phys. Rev. Lett. 90, 074302
// (2003); E. Cerda, K. Ravi-Chandar and L. Mahadevan, Nature 419, 579 (2002)).
//
// FoldLab's reading for a hung cloth: the tension rays run between the supports, so L is the span
// l, and the strain is the weight's stress over the modulus, gamma = w h / (E t), the stress eq. 7
// of Conci balances too. Then lambda = l (K E t³ / (w h l²))^(1/4) with K = 4 pi² / (3 (1 - nu²)),
// i.e. c = 4 pi² / 3 in FoldLab's K = c / (1 - nu²): the same strength s as Conci's law, so that
// the calibration's s -> s^p serves both (lambda = l x^(1/4), x = s^p). The count is as many
// folds as fit lambda apart down the centre fibre, n = Int[(a_0 - a_n) / lambda]; the shared
// geometry then lays them out in eq. 5's progression, as under every law.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/model/wrinkle_law.hpp"

namespace foldlab {
namespace {

class CerdaMahadevanLaw final : public WrinkleLaw {
 public:
  WrinkleLawKind kind() const override { return WrinkleLawKind::cerda_mahadevan; }
  std::string_view key() const override { return "cerda-mahadevan"; }
  std::string_view title() const override { return "Cerda-Mahadevan (wavelength)"; }
  std::string_view count_formula() const override { return "Int[(a_0 - a_n) / lambda]"; }
  double published_load_constant_c() const override {
    return 4.0 * std::numbers::pi * std::numbers::pi / 3.0;
  }

  std::optional<FoldCountRule> count_rule(double strength, double span_mm) const override {
    return FoldCountRule{FoldSpacing::even, span_mm * std::pow(strength, 0.25)};
  }

  // Once lambda >= a_0, (a_0 - a_n) / lambda < 1 for every a_n: one fold.
  double log_strength_ceiling(double a0_mm, double span_mm) const override {
    return std::max(0.0, 4.0 * std::log(a0_mm / span_mm));
  }
};

}  // namespace

const WrinkleLaw& cerda_mahadevan_wrinkle_law() {
  static const CerdaMahadevanLaw law;
  return law;
}

}  // namespace foldlab
