// The solution as the CLI's JSON object and as a readable table with units.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

// Keys: method, regime, message, n, Q, Q7 (null when eq. 7 has no root), s, z_max_mm, a_mm,
// l_mm, A_mm, iterations, hit_iteration_cap, n_capped, n_cycle, residual_length, residual_height,
// B_Nmm (bending stiffness), c_b_mm (bending length), "rounded_folds" (rounded, radius_mm per fold,
// depth_scale, z_fold_mm, length_kept; see FoldRounding) and the inputs under "inputs" (same units,
// same names as presets).
nlohmann::json solution_to_json(const Solution& s, const Parameters& p);

std::string solution_table(const Solution& s, const Parameters& p, const std::string& preset_name);

}  // namespace foldlab
