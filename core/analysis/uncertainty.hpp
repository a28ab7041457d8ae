// How far the data behind a model's constants pin its predictions down. A calibration leaves a set
// of eq. 7 constants that fit its rows equally well (the loss is piecewise constant, and K and p
// trade off along a valley), and a set of leave-one-out fits; the predictions at those constants
// are the range the data allow. A preset stores them (CalibrationRecord), so a solve evaluates a
// few stored constants instead of calibrating again.
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

// The range of n, z_max and Q over `p` solved with each of `constants` and with its own.
// Precondition: validate(p) is empty.
PredictionRange prediction_range(const Parameters& p, const std::vector<Eq7Constants>& constants);

// True when `p` solves with the record's method and constants (to 1e-6 relative), so that the
// record's ranges describe it.
bool record_applies(const Parameters& p, const CalibrationRecord& record);

// The form of eq. 7 in force, its label, and the range when `record` applies to `p`.
// Precondition: validate(p) is empty.
ModelStanding model_standing(const Parameters& p, const std::optional<CalibrationRecord>& record);

// What a preset stores of a calibration: the fitted constants, the ends of the equally good set
// and the leave-one-out fits. The report must come from calibrate() with held_out on for the
// leave-one-out part.
CalibrationRecord calibration_record(const CalibrationReport& report, std::string calibrated_on);

}  // namespace foldlab
