// The diverging colour map of the 3D view's colour-by-z (warm to cool through a light grey, after
// Moreland's), shared by the shader and the colour bar so that the bar shows what the cloth shows.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include <Eigen/Core>

namespace foldlab::gui {

// Display (sRGB) colours at t = 0, 1/8, ..., 1: warm at t = 0 (-z_max), cool at t = 1 (+z_max),
// so that +z is blue here as a positive fold (z > 0) is blue in the fold lines and the 3D view's
// fold colours: one meaning per colour across the views.
inline constexpr std::array<std::array<float, 3>, 9> kDivergingMap{{
    {0.706f, 0.016f, 0.150f},
    {0.902f, 0.484f, 0.382f},
    {0.969f, 0.658f, 0.537f},
    {0.957f, 0.769f, 0.678f},
    {0.865f, 0.865f, 0.865f},
    {0.667f, 0.779f, 0.993f},
    {0.468f, 0.606f, 0.969f},
    {0.340f, 0.456f, 0.882f},
    {0.230f, 0.299f, 0.754f},
}};

// The map at t (clamped to [0, 1]), linear between its stops; the shader does the same.
inline Eigen::Vector3f diverging_colour(float t) {
  const float x = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(kDivergingMap.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(x), kDivergingMap.size() - 2);
  const float f = x - static_cast<float>(i);
  const auto& a = kDivergingMap[i];
  const auto& b = kDivergingMap[i + 1];
  return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
}

}  // namespace foldlab::gui
