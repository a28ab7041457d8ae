#include "core/analysis/fold_measurement.hpp"

#include <cmath>
#include <utility>

#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {

using detail::shortest_number;

FoldMeasurement measure_folds(const std::vector<double>& depths_mm) {
  const double min_depth_mm = find_input("t")->valid.lo;
  const double max_depth_mm = find_input("h")->valid.hi;
  if (depths_mm.size() < 2) {
    throw FoldMeasurementError(
        "depths", "need at least two fold depths (the lower boundary and the upper edge), got " +
                      std::to_string(depths_mm.size()));
  }
  // The limit a measurements file holds an observed n to, so that what is measured can be kept.
  if (depths_mm.size() > static_cast<std::size_t>(kMaxObservedFolds)) {
    throw FoldMeasurementError("depths", std::to_string(depths_mm.size()) + " depths: at most " +
                                             std::to_string(kMaxObservedFolds) +
                                             " folds can be measured on one cloth");
  }
  for (std::size_t i = 0; i < depths_mm.size(); ++i) {
    const double a = depths_mm[i];
    if (!(std::isfinite(a) && a > 0.0)) {
      throw FoldMeasurementError("depths", "depth " + std::to_string(i) + " = " +
                                               shortest_number(a) +
                                               " mm: every fold lies below the supports (> 0)");
    }
    // The thinnest cloth's thickness to the tallest cloth's height: outside, Q overflows.
    if (!(a >= min_depth_mm && a <= max_depth_mm)) {
      throw FoldMeasurementError(
          "depths", "depth " + std::to_string(i) + " = " + shortest_number(a) + " mm must be in [" +
                        shortest_number(min_depth_mm) + ", " + shortest_number(max_depth_mm) +
                        "] mm (the thinnest cloth to the tallest)");
    }
    if (i > 0 && !(a < depths_mm[i - 1])) {
      throw FoldMeasurementError(
          "depths",
          "the depths must be listed deepest first, each shallower than the one "
          "before, but depth " +
              std::to_string(i) + " = " + shortest_number(a) + " mm is not shallower than depth " +
              std::to_string(i - 1) + " = " + shortest_number(depths_mm[i - 1]) + " mm");
    }
  }
  // Least squares of ln a_i = ln a_0 - i ln Q (eq. 5) over i = 0..n.
  const auto count = static_cast<double>(depths_mm.size());
  double mean_i = 0.0;
  double mean_log = 0.0;
  for (std::size_t i = 0; i < depths_mm.size(); ++i) {
    mean_i += static_cast<double>(i) / count;
    mean_log += std::log(depths_mm[i]) / count;
  }
  double s_il = 0.0;
  double s_ii = 0.0;
  for (std::size_t i = 0; i < depths_mm.size(); ++i) {
    const double di = static_cast<double>(i) - mean_i;
    s_il += di * (std::log(depths_mm[i]) - mean_log);
    s_ii += di * di;
  }
  const double slope = s_il / s_ii;
  double squares = 0.0;
  for (std::size_t i = 0; i < depths_mm.size(); ++i) {
    const double predicted = mean_log + slope * (static_cast<double>(i) - mean_i);
    squares += std::pow(std::log(depths_mm[i]) - predicted, 2);
  }
  FoldMeasurement out;
  out.n = static_cast<int>(depths_mm.size()) - 1;
  out.Q = std::exp(-slope);
  out.a_mm = depths_mm;
  out.fit_residual = std::sqrt(squares / count);
  return out;
}

std::vector<double> depths_from_pixels(const PixelPoint& support_1, const PixelPoint& support_2,
                                       const std::vector<double>& fold_rows_px, double span_mm) {
  const double dx = support_2.x - support_1.x;
  const double dy = support_2.y - support_1.y;
  const double distance_px = std::hypot(dx, dy);
  if (!(distance_px > 0.0) || !std::isfinite(distance_px)) {
    throw FoldMeasurementError("supports", "the two supports are the same pixel");
  }
  // The vertical part of the centre line's downward unit direction (-dy, dx) / distance, up to
  // sign; a supports' line steeper than 45° would make a pixel row a poor stand-in for a point on
  // the centre line.
  const double ny = std::abs(dx) / distance_px;
  if (ny < std::sqrt(0.5)) {
    throw FoldMeasurementError("supports",
                               "the supports' line is steeper than 45°: click the two upper "
                               "corners where the cloth hangs from");
  }
  const double mm_per_px = span_mm / distance_px;
  const double centre_y = 0.5 * (support_1.y + support_2.y);
  std::vector<double> depths;
  for (std::size_t i = 0; i < fold_rows_px.size(); ++i) {
    const double below_px = (fold_rows_px[i] - centre_y) / ny;
    if (!(below_px > 0.0)) {
      throw FoldMeasurementError(
          "folds", "fold " + std::to_string(i) + " at y = " + shortest_number(fold_rows_px[i]) +
                       " px is not below the supports' line (y = " + shortest_number(centre_y) +
                       " px at the centre; y grows downward)");
    }
    depths.push_back(below_px * mm_per_px);
  }
  return depths;
}

Measurement measurement_row(const Parameters& p, const FoldMeasurement& folds,
                            std::optional<double> z_max_mm, std::string name) {
  Measurement m;
  m.name = std::move(name);
  m.role = MeasurementRole::fit;
  m.inputs = p;
  m.shape = std::string(to_string(p.shape.kind));
  m.observed.n = folds.n;
  m.observed.Q = folds.Q;
  m.observed.z_max_mm = z_max_mm;
  return m;
}

}  // namespace foldlab
