// The area of a cut as an outline file or a preset's "outline" gives it, by the shoelace formula
// over its vertices: round the top edge left to right, back along the bottom edge right to left.
// Independent of the solver's mesh, so that tests can set the field's weight against it.
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace foldlab::testing {

inline double shoelace_area_mm2(const nlohmann::json& outline) {
  std::vector<std::pair<double, double>> ring;
  for (const nlohmann::json& v : outline.at("top")) {
    ring.emplace_back(v[0].get<double>(), v[1].get<double>());
  }
  const nlohmann::json& bottom = outline.at("bottom");
  for (std::size_t i = bottom.size(); i-- > 0;) {
    ring.emplace_back(bottom[i][0].get<double>(), bottom[i][1].get<double>());
  }
  double twice = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto& [x0, y0] = ring[i];
    const auto& [x1, y1] = ring[(i + 1) % ring.size()];
    twice += x0 * y1 - x1 * y0;
  }
  return 0.5 * std::abs(twice);
}

}  // namespace foldlab::testing
