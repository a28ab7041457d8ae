// The solution as the CLI's JSON object and as a readable table with units.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

// The predictions at the ends of the constants that fit the calibration data as well as the ones
// in force (and of the fits that left one row out): what the data allow, not an error bar.
// A prediction interval: each of n, z_max and Q with the ends that the leave-one-out residuals of
// the data behind the constants allow at `level` (core/analysis/uncertainty.hpp).
struct PredictionRange {
  double level = 0.0;  // the interval's stated level, e.g. 0.714 for six residuals
  int n_min = 0;
  int n_max = 0;
  double z_max_min_mm = 0.0;
  double z_max_max_mm = 0.0;
  double Q_min = 1.0;
  double Q_max = 1.0;
};

// Which form of eq. 7 a solution used and how far the data behind it pin it down; filled by
// core/analysis/uncertainty.hpp.
struct ModelStanding {
  std::string form;   // "calibrated" (s -> s^p, p != 1) or "printed" (the paper's form, p = 1)
  std::string label;  // e.g. "calibrated on Conci's Tables 1–2 (K = 1.686, p = 0.5216)"
  std::optional<PredictionRange> range;
  std::string range_basis;  // what the range spans, or why there is none
};

// " (lo–hi)", each end printed with `format`: a range after the value it brackets.
std::string range_text(double lo, double hi, const char* format);

// Keys: method, law, regime, message, n, Q, Q7 (null when eq. 7 has no root or under another
// law), fold_spacing_mm (the law's lambda for evenly spaced folds, else null), s, z_max_mm, a_mm,
// l_mm, A_mm, iterations, hit_iteration_cap, n_capped, n_cycle, residual_length, residual_height,
// B_Nmm (bending stiffness), c_b_mm (bending length), "rounded_folds" (rounded, radius_mm per fold,
// depth_scale, z_fold_mm, length_kept; see FoldRounding), stopped_at_first_iterate, and the inputs
// under "inputs" (same units, same names as presets). With a standing: form, form_label, n_range,
// z_max_range_mm, Q_range ([lo, hi], null without a range) and range_basis.
nlohmann::json solution_to_json(const Solution& s, const Parameters& p,
                                const ModelStanding* standing = nullptr);

// With a standing, n, Q and z_max carry their range, e.g. "7 (6–8)", and the form is named.
std::string solution_table(const Solution& s, const Parameters& p, const std::string& preset_name,
                           const ModelStanding* standing = nullptr);

}  // namespace foldlab
