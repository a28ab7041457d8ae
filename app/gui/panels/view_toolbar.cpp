#include "app/gui/panels/view_toolbar.hpp"

#include <imgui.h>
#include <imgui_internal.h>  // the window's title bar, where a presented view's button goes

namespace foldlab::gui {

bool ViewToolbar::begin(const char* label, float least_view_height_px, bool fold) {
  label_ = label;
  const ImVec2 available = ImGui::GetContentRegionAvail();
  const float font_px = ImGui::GetFontSize();
  // The window's width, not the content's, which a scrollbar coming and going would change.
  const float width_px = ImGui::GetWindowWidth();
  if (width_px != measured_width_px_ || font_px != measured_font_px_) {
    // A new width or text size rewraps the row: it is drawn in full once to be measured.
    measured_width_px_ = width_px;
    measured_font_px_ = font_px;
    folded_ = false;
    decided_height_px_ = -1.0f;
  } else if (available.y != decided_height_px_) {
    // Decided again only when the panel's size changes, never because a setting in the row made
    // it longer: a checkbox must not fold away under the pointer that ticked it.
    folded_ = available.y - full_height_px_ < least_view_height_px;
    decided_height_px_ = available.y;
  }
  if (fold) {
    folded_ = true;
    measured_width_px_ = -1.0f;  // measured afresh when it unfolds
  }
  in_popup_ = false;
  if (!folded_) {
    start_y_px_ = ImGui::GetCursorPosY();
    return true;
  }
  ImGuiWindow* window = ImGui::GetCurrentWindow();
  if (fold && (window->Flags & ImGuiWindowFlags_NoTitleBar) != 0) {
    if (open_requested_) {
      ImGui::OpenPopup(label);
      open_requested_ = false;
    }
    // Over the view's top left corner, under the read-out and the strip, rather than wherever
    // the menu that asked for it was (over the menu bar and the read-out). Every frame: a popup
    // is placed in the frame after it opens, once its size is known.
    ImGui::SetNextWindowPos(ImGui::GetCursorScreenPos());
    in_popup_ = ImGui::BeginPopup(label);
    return in_popup_;
  }
  open_requested_ = false;
  const ImVec2 cursor = ImGui::GetCursorScreenPos();
  const ImVec2 cursor_max = window->DC.CursorMaxPos;
  if (fold) {
    // In the title bar, after the title: the row it would take is the picture's. The button
    // sits above the content and must not widen what the window scrolls over.
    const ImRect title = window->TitleBarRect();
    const ImGuiStyle& style = ImGui::GetStyle();
    ImGui::PushClipRect(title.Min, title.Max, false);
    ImGui::SetCursorScreenPos(ImVec2(title.Min.x + style.FramePadding.x +
                                         ImGui::CalcTextSize(window->Name, nullptr, true).x +
                                         2.0f * style.ItemSpacing.x,
                                     title.Min.y));
  }
  if (ImGui::Button(label)) {
    ImGui::OpenPopup(label);
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(fold ? "The view's settings"
                           : "The view's settings (the panel is too small to show them beside it)");
  }
  if (fold) {
    ImGui::PopClipRect();
    ImGui::SetCursorScreenPos(cursor);
    window->DC.CursorMaxPos = cursor_max;
  }
  in_popup_ = ImGui::BeginPopup(label);
  return in_popup_;
}

void ViewToolbar::menu_item() {
  if (label_ != nullptr && ImGui::MenuItem(label_)) {
    open_requested_ = true;
  }
}

void ViewToolbar::end() {
  if (in_popup_) {
    ImGui::EndPopup();
    in_popup_ = false;
  } else if (!folded_) {
    full_height_px_ = ImGui::GetCursorPosY() - start_y_px_;
  }
}

}  // namespace foldlab::gui
