#include "app/gui/panels/axis_inputs.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/gui/panels/widgets.hpp"

#include "core/analysis/sweep.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

std::string axis_label(const std::string& key) {
  const InputSpec* spec = find_input(key);
  return spec != nullptr ? readable(shown_label(*spec)) : key;
}

double to_shown(const std::string& key, double stored) {
  const InputSpec* spec = find_input(key);
  return spec != nullptr ? to_shown_unit(*spec, stored) : stored;
}

double from_shown(const std::string& key, double shown) {
  const InputSpec* spec = find_input(key);
  return spec != nullptr ? from_shown_unit(*spec, shown) : shown;
}

namespace {

std::string key_symbol(const std::string& key) {
  const InputSpec* spec = find_input(key);
  return spec != nullptr ? readable(input_symbol(*spec)) : key;
}

}  // namespace

std::string shown_value(const std::string& key, double stored) {
  const InputSpec* spec = find_input(key);
  if (spec == nullptr) {
    return key + " = " + detail::printf_string("%.4g", stored);
  }
  const std::string_view unit = shown_unit(*spec).symbol;
  return readable(std::string(input_symbol(*spec)) + " = " +
                  detail::printf_string("%.4g", to_shown_unit(*spec, stored)) +
                  (unit.empty() ? "" : " " + std::string(unit)));
}

bool key_combo(const char* label, std::string& key) {
  bool changed = false;
  std::vector<std::string> symbols;
  for (const std::string& option : sweepable_keys()) {
    symbols.push_back(key_symbol(option));
  }
  ImGui::SetNextItemWidth(combo_width(symbols));
  if (begin_combo(label, key_symbol(key).c_str())) {
    for (const std::string& option : sweepable_keys()) {
      ImGui::PushID(option.c_str());
      const bool chosen = ImGui::Selectable(key_symbol(option).c_str(), option == key);
      ImGui::PopID();
      if (chosen) {
        changed = option != key;
        key = option;
      }
    }
    end_combo();
  }
  return changed;
}

void default_range(const std::string& key, double current, double& from, double& to) {
  const InputSpec* spec = find_input(key);
  if (natural_log_scale(key)) {
    from = current / 10.0;
    to = current * 10.0;
  } else if (spec != nullptr && spec->axis_over_typical) {
    from = spec->typical_lo;
    to = spec->typical_hi;
  } else {
    from = std::max(current * 0.3, 1.0);
    to = current * 3.0;
  }
}

namespace {

constexpr float kRangeFieldEms = 6.5f;

}  // namespace

float range_inputs_width() {
  return 2.0f * ems(kRangeFieldEms) + ImGui::CalcTextSize("to").x +
         2.0f * ImGui::GetStyle().ItemSpacing.x;
}

bool range_inputs(const char* id, const std::string& key, double& from, double& to) {
  ImGui::PushID(id);
  bool changed = false;
  // Each value with its unit ("500 mm"); a number typed alone is read in that unit.
  const InputSpec* spec = find_input(key);
  const std::string unit = spec != nullptr ? std::string(shown_unit(*spec).symbol) : "";
  const std::string format = "%.4g" + (unit.empty() ? "" : " " + readable(unit));
  // Only a value typed and entered goes back to the stored unit, so that showing the range
  // never moves it by a rounding.
  const auto field = [&](const char* label, double& stored) {
    double shown = to_shown(key, stored);
    ImGui::SetNextItemWidth(ems(kRangeFieldEms));
    if (ImGui::InputDouble(label, &shown, 0.0, 0.0, format.c_str(),
                           ImGuiInputTextFlags_EnterReturnsTrue)) {
      stored = from_shown(key, shown);
      changed = true;
    }
  };
  field("##from", from);
  // In a narrow panel "to ..." goes under "from" rather than past the panel's edge.
  same_line_if_fits(range_inputs_width() - ems(kRangeFieldEms) - ImGui::GetStyle().ItemSpacing.x);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("to");
  ImGui::SameLine();
  field("##to", to);
  ImGui::PopID();
  return changed;
}

}  // namespace foldlab::gui
