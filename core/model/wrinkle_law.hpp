// A wrinkle law decides how many folds the hanging cloth forms: given the fold amplitudes a_0 at
// the lower boundary and a_n at the upper edge, and the fabric, it says where eq. 10's Int[] falls.
// Everything else (the fold lines of eqs. 4-6, the inextensible upper edge of eq. 8 and fibre of
// eq. 9) is geometry that every law shares, so the solver, its iteration trace, the calibration
// and the uncertainty ranges work through this interface alone (docs/model.md#wrinkle-laws).
//
// Each law is driven by one strength x = s^p with s = K E t³ / (w h l²), K = c / (1 - nu²): the
// dimensionless ratio of the fabric's bending stiffness to the weight it carries over the span.
// Conci's critical stress and Cerda and Mahadevan's wavelength both reduce to it, so a fit of K
// and p (core/analysis/calibration) serves every law unchanged.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace foldlab {

enum class WrinkleLawKind { conci, cerda_mahadevan };

// How a law counts the folds between a_0 and a_n: in equal steps of ln a (a ratio between
// neighbours) or of a itself (a wavelength). Only the count: the fold lines follow eq. 5 either
// way.
enum class FoldSpacing { geometric, even };

// A law's count for one parameter set: n = Int[(f(a_0) - f(a_n)) / step], f = ln (geometric) or
// the identity (even).
struct FoldCountRule {
  FoldSpacing spacing = FoldSpacing::geometric;
  double step = 1.0;   // ln Q of the law (geometric), or the fold spacing lambda in mm (even); > 0
  double ratio = 0.0;  // geometric: the law's Q itself (e^step, as computed); even: 0

  // f(a_0) - f(a_n).
  double separation(double a0_mm, double an_mm) const;
  // The argument of eq. 10's Int[].
  double argument(double a0_mm, double an_mm) const { return separation(a0_mm, an_mm) / step; }
  // Int[argument], at least 1 (floor with eq. 10's guard, or nearest).
  int count(double a0_mm, double an_mm, bool round_to_nearest) const;
  // The a_n at which the argument equals x: the inverse of argument() for a given a_0.
  double amplitude_at(double a0_mm, double x) const;
};

class WrinkleLaw {
 public:
  virtual ~WrinkleLaw() = default;
  virtual WrinkleLawKind kind() const = 0;
  // The name typed after --set law= and stored in presets: "conci".
  virtual std::string_view key() const = 0;
  // A short name for menus: "Conci (critical stress)".
  virtual std::string_view title() const = 0;
  // Eq. 10 as this law writes it, for the explorer's equations and iteration views.
  virtual std::string_view count_formula() const = 0;
  // The law's constant c as its authors print it (K = c / (1 - nu²)), with p = 1.
  virtual double published_load_constant_c() const = 0;
  // The count rule at strength x = s^p over a span l; nullopt when the law allows one fold at
  // most whatever a_n is (Conci: eq. 7 has no root, the stiff regime).
  virtual std::optional<FoldCountRule> count_rule(double strength, double span_mm) const = 0;
  // ln x above which the count no longer changes for a_0 over a span l (every a_n gives n = 1):
  // where a calibration starts its scan of a row.
  virtual double log_strength_ceiling(double a0_mm, double span_mm) const = 0;
};

const WrinkleLaw& wrinkle_law(WrinkleLawKind kind);
// Every law, in the order menus list them.
std::span<const WrinkleLaw* const> wrinkle_laws();

std::string_view to_string(WrinkleLawKind kind);
// False (and `out` unchanged) for a name that is no law's key.
bool parse_wrinkle_law(std::string_view s, WrinkleLawKind& out);

}  // namespace foldlab
