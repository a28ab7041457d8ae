// The widgets the sweep and the regime map share for choosing an input and its range. Inputs are
// named by key, never by their place in the input table, which may change. Values are stored in
// the input table's unit and shown, typed and plotted in the unit the input's slider shows
// (shown_unit: w in g/m²).
#pragma once

#include <string>

namespace foldlab::gui {

// "w (g/m²)", "ν": the symbol with the unit its slider shows, as the font can draw it.
std::string axis_label(const std::string& key);
// A stored value of `key` in the unit its slider shows, and back.
double to_shown(const std::string& key, double stored);
double from_shown(const std::string& key, double shown);
// "w = 153 g/m²": a stored value of `key` in the unit its slider shows.
std::string shown_value(const std::string& key, double stored);
// A combo of the sweepable inputs; true when the user chose another.
bool key_combo(const char* label, std::string& key);
// A range for a key around the current value: a decade each way on log scales, x0.3..x3 else;
// the typical range for a row that asks for it (axis_over_typical: ν).
void default_range(const std::string& key, double current, double& from, double& to);
// "from ... to ..." inputs for `key`'s stored range, shown with and typed in its slider's unit
// and applied on Enter; true when one was applied.
bool range_inputs(const char* id, const std::string& key, double& from, double& to);
// The width range_inputs takes on one line.
float range_inputs_width();

}  // namespace foldlab::gui
