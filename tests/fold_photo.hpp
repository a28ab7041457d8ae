// A "photo" of a hanging cloth that FoldLab draws itself: the solution's fold lines as dark dots
// on a light background, rotated by 3° and scaled by 0.4 px/mm, so that a test which clicks the
// supports and the folds on it knows which n and Q it must get back. Used by the `foldlab
// measure` test and by the explorer's photo test.
#pragma once

#include <stb_image_write.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/analysis/fold_measurement.hpp"
#include "core/geometry/geometry.hpp"
#include "core/model/solver.hpp"

namespace foldlab::testing {

struct FoldPhoto {
  int width_px = 700;
  int height_px = 700;
  double px_per_mm = 0.4;
  double angle_rad = 3.0 * std::numbers::pi / 180.0;
  PixelPoint left_support;
  PixelPoint right_support;
  std::vector<PixelPoint> folds;  // where each fold crosses the centre line, lowest first

  // Plot millimetres (x right, y down from the supports' line at the centre) to photo pixels.
  PixelPoint to_px(double x_mm, double y_mm) const {
    return {350.0 + px_per_mm * (x_mm * std::cos(angle_rad) - y_mm * std::sin(angle_rad)),
            60.0 + px_per_mm * (x_mm * std::sin(angle_rad) + y_mm * std::cos(angle_rad))};
  }
};

// Draws `s`'s fold lines into a PNG at `path`. Throws std::runtime_error when it cannot write.
inline FoldPhoto write_fold_photo(const Solution& s, const Parameters& p,
                                  const std::filesystem::path& path) {
  FoldPhoto photo;
  const int width = photo.width_px;
  const int height = photo.height_px;
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width * height * 3), 235);
  auto dot = [&](PixelPoint q) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = static_cast<int>(std::lround(q.x)) + dx;
        const int y = static_cast<int>(std::lround(q.y)) + dy;
        if (x >= 0 && x < width && y >= 0 && y < height) {
          for (int c = 0; c < 3; ++c) {
            rgb[static_cast<std::size_t>((y * width + x) * 3 + c)] = 20;
          }
        }
      }
    }
  };
  const FoldLines lines = fold_lines(s, p, 401);
  for (const FoldLine& line : lines.lines) {
    for (std::size_t k = 0; k + 1 < line.points_mm.size(); ++k) {
      for (int t = 0; t <= 8; ++t) {
        const Eigen::Vector3d q =
            line.points_mm[k] + (line.points_mm[k + 1] - line.points_mm[k]) * (t / 8.0);
        dot(photo.to_px(q.x(), q.y()));
      }
    }
  }
  if (stbi_write_png(path.string().c_str(), width, height, 3, rgb.data(), width * 3) == 0) {
    throw std::runtime_error(path.string() + ": cannot write the PNG");
  }
  photo.left_support = photo.to_px(-s.span_mm / 2, 0.0);
  photo.right_support = photo.to_px(s.span_mm / 2, 0.0);
  for (double a : s.a_mm) {
    photo.folds.push_back(photo.to_px(0.0, a));
  }
  return photo;
}

}  // namespace foldlab::testing
