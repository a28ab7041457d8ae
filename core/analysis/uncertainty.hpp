// How far a prediction can be trusted: prediction intervals from the calibration's own held-out
// errors. A calibration on m rows leaves m leave-one-out fits and each one's residual R_i on the
// row it left out; at a new cloth, each fit's prediction plus or minus |R_i| bounds the plausible
// values (the jackknife+ of R. F. Barber, E. J. Candès, A. Ramdas and R. J. Tibshirani, "Predictive
// inference with the jackknife+", Ann. Statist. 49(1), 486-507, 2021), and the smallest and
// largest of the m bound the interval. For exchangeable rows a new value falls between the
// extremes of m others with probability (m - 1)/(m + 1): the interval's stated level, 71 % for six
// rows. Whether that holds on these data is measured, not assumed: cross_validated_coverage()
// counts how often such intervals, built without a row, contained it. A preset stores the fits,
// the residuals and that count (CalibrationRecord), so a solve evaluates a few stored constants
// instead of calibrating again.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/analysis/calibration.hpp"
#include "core/io/preset.hpp"
#include "core/io/report.hpp"
#include "core/model/parameters.hpp"

namespace foldlab {

// What presets and reports call the data of the paper's Tables 1-2.
inline constexpr const char* kConciTables12 = "Conci's Tables 1–2";

// The stated level of an interval from m residuals: (m - 1)/(m + 1); 0 below two.
double interval_level(int residuals);

// The prediction interval of n, z_max and Q at `p` from leave-one-out fits and their residuals
// (same order and length). nullopt with fewer than two usable residuals for n. Precondition:
// validate(p) is empty.
std::optional<PredictionRange> prediction_interval(const Parameters& p,
                                                   const std::vector<Eq7Constants>& fits,
                                                   const std::vector<HeldOutResidual>& residuals);

// Widens `range` to hold the prediction it is shown beside (the constants in force, not the
// leave-one-out fits the jackknife+ is made of): far from the data the fits can all land to one
// side of it. Only for showing: the coverage checks judge the jackknife+ alone, whose rows must
// not reach the interval through the constants fitted on all of them; widening never lowers
// coverage.
void hold_prediction(PredictionRange& range, const Solution& predicted);

// One fit row's residual under the fit that left it out: observed minus predicted.
HeldOutResidual held_out_residual(const PublishedResult& observed, const Solution& predicted);

// How often intervals built without some rows contained those rows, per quantity.
struct QuantityCoverage {
  int covered = 0;
  int total = 0;
  double level = 0.0;  // the stated level of those intervals (they stand on fewer rows)
};
struct CoverageCheck {
  std::string name;  // "leave-one-out", "fit on one group, test on another"
  QuantityCoverage n, z_max, Q;
};
// The most fit rows a coverage check takes. It refits about m² times, each fit on m rows, so its
// time grows about as m³ (K and p) : measured on a shared 2-core VM (docs/performance.md), 24 rows
// of K and p take 13-20 s and 32 rows 38 s, while K alone takes 1.2 s for 64 rows, the most a
// preset stores.
inline constexpr int kMaxCoverageRowsK = 64;
inline constexpr int kMaxCoverageRowsKandP = 32;
int max_coverage_rows(FitConstants fit);

// Leave-one-out over the fit rows (each row's interval from fits and residuals on the others
// alone, nested) and, when the rows come in groups, each group's rows from the others. Refits
// about m² times: a fraction of a second for the paper's six rows. nullopt when cancelled. Throws
// CalibrationError as calibrate() does, and for more fit rows than max_coverage_rows().
std::optional<std::vector<CoverageCheck>> cross_validated_coverage(
    const MeasurementSet& data, const Parameters& base, const CalibrationOptions& options,
    const CalibrationProgress& progress = {});
// "leave-one-out n 5/6, z_max 4/6, Q 4/6 at a stated 67 %; ..."
std::string describe_coverage(const std::vector<CoverageCheck>& checks);

// True when `p` solves with the record's method and constants (to 1e-6 relative), so that the
// record's ranges describe it.
bool record_applies(const Parameters& p, const CalibrationRecord& record);

// The form of eq. 7 in force, its label, and the range when `record` applies to `p`, widened to
// hold `predicted`, solve(p), which the caller has already (hold_prediction).
// Precondition: validate(p) is empty.
ModelStanding model_standing(const Parameters& p, const std::optional<CalibrationRecord>& record,
                             const Solution& predicted);
// The same, solving `p` for the prediction.
ModelStanding model_standing(const Parameters& p, const std::optional<CalibrationRecord>& record);

// What a preset stores of a calibration: the fitted constants, the ends of the equally good set,
// the leave-one-out fits with their residuals, and `coverage` (describe_coverage(), or empty).
// The report must come from calibrate() with held_out on for the leave-one-out part.
CalibrationRecord calibration_record(const CalibrationReport& report, std::string calibrated_on,
                                     std::string coverage = {});

}  // namespace foldlab
