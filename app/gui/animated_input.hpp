// One input moved back and forth across its slider's range, evenly on the slider's scale: for
// `--animate KEY` (one way in 60 frames) and the Parameters panel's play button (one way in a few
// seconds), which share this code path.
#pragma once

#include <string>

#include "core/model/parameters.hpp"
#include "core/model/settings.hpp"

namespace foldlab::gui {

// The input goes from its slider's low end to its high end and back (the input table's typical
// range and scale), within the part of that range where the other inputs as they are accept it.
class AnimatedInput {
 public:
  static constexpr int kFramesPerWay = 60;  // --animate: one way in 60 frames

  // Throws app::InputError for a key that has no slider or no valid value on it.
  AnimatedInput(const std::string& key, const Parameters& base,
                SliderReach reach = SliderReach::expert);
  // The value at a frame of --animate.
  double value(int frame) const { return at(static_cast<double>(frame) / kFramesPerWay); }
  // The value after `ways` one-way sweeps: lo at 0, hi at 1, lo again at 2, ...
  double at(double ways) const;
  // Narrows the sweep to [lo, hi] (in the input's unit), kept inside the valid range; a range
  // with lo > hi is turned round.
  void set_range(double lo, double hi);
  const std::string& key() const { return key_; }
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  // The valid range found at the start, which set_range keeps within.
  double valid_lo() const { return valid_lo_; }
  double valid_hi() const { return valid_hi_; }

 private:
  std::string key_;
  double lo_ = 0.0;
  double hi_ = 0.0;
  double valid_lo_ = 0.0;
  double valid_hi_ = 0.0;
  bool logarithmic_ = false;
};

}  // namespace foldlab::gui
