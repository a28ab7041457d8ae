#include "app/gui/panels/widgets.hpp"

namespace foldlab::gui {

void place_window(float x, float y, float w, float h) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(x * display.x, y * display.y), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(w * display.x, h * display.y), ImGuiCond_FirstUseEver);
}

bool begin_panel(const char* title, Renderer& renderer) {
  if (!ImGui::Begin(title)) {
    return false;
  }
  renderer.fill_window_background();
  return true;
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", title);
  ImGui::Separator();
}

void help_marker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

}  // namespace foldlab::gui
