// Folds measured on a real cloth: from the fold depths at the centre (or points clicked on a
// photo) to the n and Q of eqs. 5 and 10, and a row that `foldlab calibrate` reads.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/measurements.hpp"
#include "core/model/parameters.hpp"

namespace foldlab {

// Measured input that cannot describe folds; the message names the input ("depths", "supports",
// "folds") and the problem.
class FoldMeasurementError : public std::invalid_argument {
 public:
  FoldMeasurementError(std::string input, const std::string& message)
      : std::invalid_argument(message), input_(std::move(input)) {}
  const std::string& input() const { return input_; }

 private:
  std::string input_;
};

struct FoldMeasurement {
  int n = 0;                 // folds between the lower boundary and the upper edge
  double Q = 1.0;            // exp(-slope) of the least-squares line through (i, ln a_i)
  std::vector<double> a_mm;  // the measured depths, a_0 (lowest) .. a_n
  // Root mean square of ln a_i about that line: the folds' relative departure from eq. 5's
  // geometric progression (0 for two folds, or for a perfect progression).
  double fit_residual = 0.0;
};

// Depths below the supports' line at the centre, lowest first: at least two, each > 0, strictly
// decreasing. Throws FoldMeasurementError("depths", ...).
FoldMeasurement measure_folds(const std::vector<double>& depths_mm);

// Two points in image pixels, y growing downward.
struct PixelPoint {
  double x = 0.0;
  double y = 0.0;
};

// The depths of folds clicked on a photo: the supports set rotation and scale (their distance is
// the span l), and each fold is taken where the centre line (perpendicular to the supports' line
// through its middle) reaches the clicked pixel row. Throws FoldMeasurementError naming
// "supports" (coincident, or a line steeper than 45°) or "folds" (a fold above the supports).
std::vector<double> depths_from_pixels(const PixelPoint& support_1, const PixelPoint& support_2,
                                       const std::vector<double>& fold_rows_px, double span_mm);

// The measurement as a fit row of a measurements file: `p`'s fabric and hanging, the measured n
// and Q, and z_max when given.
Measurement measurement_row(const Parameters& p, const FoldMeasurement& folds,
                            std::optional<double> z_max_mm, std::string name);

}  // namespace foldlab
