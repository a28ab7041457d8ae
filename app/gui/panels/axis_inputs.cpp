#include "app/gui/panels/axis_inputs.hpp"

#include <algorithm>

#include <imgui.h>

#include "app/gui/panels/widgets.hpp"

#include "core/analysis/sweep.hpp"
#include "core/model/settings.hpp"

namespace foldlab::gui {

std::string axis_label(const std::string& key) {
  const InputSpec* spec = find_input(key);
  return spec != nullptr ? input_label(*spec) : key;
}

bool key_combo(const char* label, std::string& key) {
  bool changed = false;
  ImGui::SetNextItemWidth(ems(5.0f));
  if (ImGui::BeginCombo(label, key.c_str())) {
    for (const std::string& option : sweepable_keys()) {
      if (ImGui::Selectable(option.c_str(), option == key)) {
        changed = option != key;
        key = option;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

void default_range(const std::string& key, double current, double& from, double& to) {
  if (natural_log_scale(key)) {
    from = current / 10.0;
    to = current * 10.0;
  } else if (key == "nu") {
    from = 0.0;
    to = 0.49;
  } else {
    from = std::max(current * 0.3, 1.0);
    to = current * 3.0;
  }
}

bool range_inputs(const char* id, double& from, double& to) {
  ImGui::PushID(id);
  bool changed = false;
  ImGui::SetNextItemWidth(ems(6.5f));
  changed |=
      ImGui::InputDouble("##from", &from, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  ImGui::TextUnformatted("to");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ems(6.5f));
  changed |=
      ImGui::InputDouble("##to", &to, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::PopID();
  return changed;
}

}  // namespace foldlab::gui
