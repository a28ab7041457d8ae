// What every SVG writer of the project shares: the document's opening (size, font and a white
// page, so that a viewer with a dark background still shows the drawing) and a "nice" step for
// an axis' ticks. In the lowest layer, so that the field's drawing (beside io) and the
// exports and the benchmark's chart (above it) use one copy.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "core/model/text_format.hpp"

namespace foldlab::detail {

// <svg ...> with its viewBox in pixels, and the white page under everything drawn after it.
inline std::string svg_open(double width_px, double height_px, int font_size_px) {
  return printf_string(
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
             "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"%d\">\n",
             width_px, height_px, width_px, height_px, font_size_px) +
         "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

// A "nice" tick step (1, 2 or 5 times a power of ten) giving about `target` ticks over `range`.
inline double tick_step(double range, int target) {
  const double raw = range / std::max(1, target);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * power >= raw) {
      return m * power;
    }
  }
  return 10.0 * power;
}

}  // namespace foldlab::detail
