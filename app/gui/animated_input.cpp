#include "app/gui/animated_input.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "app/common/inputs.hpp"
#include "core/analysis/sweep.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

// A point of [lo, hi] at fraction f, evenly on the input's scale.
double along(double lo, double hi, bool logarithmic, double f) {
  return logarithmic ? lo * std::pow(hi / lo, f) : lo + (hi - lo) * f;
}

}  // namespace

AnimatedInput::AnimatedInput(const std::string& key, const Parameters& base, SliderReach reach)
    : key_(key) {
  const std::vector<std::string>& keys = sweepable_keys();
  if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
    throw app::InputError("--animate " + key + ": not one of " + detail::join_comma(keys));
  }
  const InputSpec& spec = *find_input(key);
  // The slider's own ends: a beginner's animation stays among the fabrics one buys.
  const InputInterval ends = slider_ends(spec, reach);
  logarithmic_ = spec.scale == InputScale::logarithmic;
  // d must stay below L/2, for one: keep to the values the model accepts with the rest as is.
  constexpr int kProbes = 200;
  std::optional<double> first;
  double last = 0.0;
  for (int i = 0; i <= kProbes; ++i) {
    const double v = along(ends.lo, ends.hi, logarithmic_, static_cast<double>(i) / kProbes);
    Parameters p = base;
    if (!set_input(p, key, v) && validate(p).empty()) {
      first = first.value_or(v);
      last = v;
    }
  }
  if (!first) {
    throw app::InputError("--animate " + key +
                          ": no value of its slider is valid with the other inputs");
  }
  lo_ = valid_lo_ = *first;
  hi_ = valid_hi_ = last;
}

double AnimatedInput::at(double ways) const {
  const double phase = std::abs(std::fmod(ways, 2.0) - 1.0);  // 1 -> 0 -> 1
  return along(lo_, hi_, logarithmic_, 1.0 - phase);
}

void AnimatedInput::set_range(double lo, double hi) {
  if (lo > hi) {
    std::swap(lo, hi);
  }
  lo_ = std::clamp(lo, valid_lo_, valid_hi_);
  hi_ = std::clamp(hi, valid_lo_, valid_hi_);
}

}  // namespace foldlab::gui
