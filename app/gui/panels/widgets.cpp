#include "app/gui/panels/widgets.hpp"

namespace foldlab::gui {

ImVec4 message_colour(MessageKind kind) {
  switch (kind) {
    case MessageKind::info:
      return kDimText;
    case MessageKind::success:
      return kOkText;
    case MessageKind::warning:
      return kNoteText;
    case MessageKind::error:
      return kErrorText;
  }
  return kDimText;
}

// In the title bar, so that the mark takes no room from the view and moves nothing.
void stale_mark(const Document& document) {
  if (document.issues().empty()) {
    return;
  }
  const char* text = "stale: last valid inputs";
  const ImVec2 pos = ImGui::GetWindowPos();
  const float width = ImGui::GetWindowWidth();
  const ImGuiStyle& style = ImGui::GetStyle();
  const float title_height = ImGui::GetFontSize() + 2.0f * style.FramePadding.y;
  const float text_width = ImGui::CalcTextSize(text).x;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(pos, ImVec2(pos.x + width, pos.y + title_height), false);
  draw->AddText(ImVec2(pos.x + width - text_width - 2.0f * style.FramePadding.x - title_height,
                       pos.y + style.FramePadding.y),
                ImGui::GetColorU32(kNoteText), text);
  draw->PopClipRect();
}

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
