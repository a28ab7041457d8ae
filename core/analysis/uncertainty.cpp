#include "core/analysis/uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

using detail::printf_string;

bool close(double a, double b) {
  return std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b));
}

// K = 29.56 at p = 1: the constant FoldLab reads eq. 7 as printed with (c = 26.9 at nu = 0.3), to
// the four digits a user types.
bool is_printed_constant(const Parameters& p) {
  const double printed_K =
      kCalibratedLoadConstantC / (1.0 - kDefaultPoissonRatio * kDefaultPoissonRatio);
  return p.model.stress_exponent_p == 1.0 &&
         std::abs(stiffness_constant_K(p) / printed_K - 1.0) < 2e-4;
}

}  // namespace

PredictionRange prediction_range(const Parameters& p, const std::vector<Eq7Constants>& constants) {
  const Solution own = solve(p);
  PredictionRange r{own.n, own.n, own.z_max_mm, own.z_max_mm, own.Q, own.Q};
  for (const Eq7Constants& k : constants) {
    const Solution s = solve(with_constants(p, k.K, k.p));
    r.n_min = std::min(r.n_min, s.n);
    r.n_max = std::max(r.n_max, s.n);
    r.z_max_min_mm = std::min(r.z_max_min_mm, s.z_max_mm);
    r.z_max_max_mm = std::max(r.z_max_max_mm, s.z_max_mm);
    r.Q_min = std::min(r.Q_min, s.Q);
    r.Q_max = std::max(r.Q_max, s.Q);
  }
  return r;
}

bool record_applies(const Parameters& p, const CalibrationRecord& record) {
  return p.model.method == record.method && close(stiffness_constant_K(p), record.fitted.K) &&
         close(p.model.stress_exponent_p, record.fitted.p);
}

ModelStanding model_standing(const Parameters& p, const std::optional<CalibrationRecord>& record) {
  ModelStanding out;
  const double K = stiffness_constant_K(p);
  const double exponent = p.model.stress_exponent_p;
  const std::string constants = printf_string("K = %.4g, p = %.4g", K, exponent);
  out.form = exponent == 1.0 ? "printed" : "calibrated";
  const bool applies = record && record_applies(p, *record);
  if (applies) {
    out.label = "calibrated on " + record->calibrated_on + " (" + constants + ", " +
                std::to_string(record->fit_rows) + " rows, " +
                std::string(to_string(record->method)) + " method)";
  } else if (is_printed_constant(p)) {
    out.label = "Conci's eq. 7 as printed (" + constants + ")";
  } else if (exponent == 1.0) {
    out.label = "eq. 7 as printed with another constant (" + constants + ")";
  } else {
    out.label = "eq. 7 with s -> s^p (" + constants + "), not a stored calibration";
  }
  if (!applies) {
    out.range_basis =
        record ? "none: these constants or this method differ from the preset's calibration"
               : "none: the preset carries no calibration";
    return out;
  }
  std::vector<Eq7Constants> constants_list = record->equally_good;
  constants_list.insert(constants_list.end(), record->leave_one_out.begin(),
                        record->leave_one_out.end());
  out.range = prediction_range(p, constants_list);
  out.range_basis = "over the " + std::to_string(record->equally_good.size()) +
                    " ends of the constants that fit " + record->calibrated_on +
                    " equally well and the " + std::to_string(record->leave_one_out.size()) +
                    " leave-one-out fits";
  return out;
}

CalibrationRecord calibration_record(const CalibrationReport& report, std::string calibrated_on) {
  CalibrationRecord record;
  record.calibrated_on = std::move(calibrated_on);
  record.method = report.base.model.method;
  record.fitted = {report.fitted.K, report.fitted.p};
  record.fit_rows = report.fit_row_count;
  record.equally_good = report.fitted.equally_good_ends;
  for (const CalibrationRow& row : report.rows) {
    if (row.measurement.role == MeasurementRole::fit && row.held_out) {
      record.leave_one_out.push_back({row.held_out_K, row.held_out_p});
    }
  }
  return record;
}

}  // namespace foldlab
