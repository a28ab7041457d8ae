#include "core/model/wrinkle_law.hpp"

#include <array>
#include <cmath>

#include "core/model/equations.hpp"

namespace foldlab {

const WrinkleLaw& conci_wrinkle_law();
const WrinkleLaw& cerda_mahadevan_wrinkle_law();

double FoldCountRule::separation(double a0_mm, double an_mm) const {
  return spacing == FoldSpacing::geometric ? std::log(a0_mm / an_mm) : a0_mm - an_mm;
}

int FoldCountRule::count(double a0_mm, double an_mm, bool round_to_nearest) const {
  return wrinkle_count_from_logs(separation(a0_mm, an_mm), step, round_to_nearest);
}

double FoldCountRule::amplitude_at(double a0_mm, double x) const {
  return spacing == FoldSpacing::geometric ? a0_mm * std::exp(-x * step) : a0_mm - x * step;
}

std::span<const WrinkleLaw* const> wrinkle_laws() {
  static const auto laws =
      std::to_array<const WrinkleLaw*>({&conci_wrinkle_law(), &cerda_mahadevan_wrinkle_law()});
  return laws;
}

const WrinkleLaw& wrinkle_law(WrinkleLawKind kind) {
  for (const WrinkleLaw* law : wrinkle_laws()) {
    if (law->kind() == kind) {
      return *law;
    }
  }
  return conci_wrinkle_law();
}

std::string_view to_string(WrinkleLawKind kind) {
  return wrinkle_law(kind).key();
}

bool parse_wrinkle_law(std::string_view s, WrinkleLawKind& out) {
  for (const WrinkleLaw* law : wrinkle_laws()) {
    if (law->key() == s) {
      out = law->kind();
      return true;
    }
  }
  return false;
}

}  // namespace foldlab
