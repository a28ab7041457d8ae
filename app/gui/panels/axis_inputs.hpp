// The widgets the sweep and the regime map share for choosing an input and its range. Inputs are
// named by key, never by their place in the input table, which may change.
#pragma once

#include <string>

namespace foldlab::gui {

// "h (mm)": the key with its unit from the input table.
std::string axis_label(const std::string& key);
// A combo of the sweepable inputs' keys; true when the user chose another.
bool key_combo(const char* label, std::string& key);
// A range for a key around the current value: a decade each way on log scales, x0.3..x3 else.
void default_range(const std::string& key, double current, double& from, double& to);
// "from ... to ..." inputs, applied on Enter; true when one was applied.
bool range_inputs(const char* id, double& from, double& to);

}  // namespace foldlab::gui
