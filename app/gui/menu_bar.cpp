#include "app/gui/menu_bar.hpp"

#include <array>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/common/version.hpp"
#include "app/gui/appearance.hpp"
#include "app/gui/panels/cloth_view_panel.hpp"
#include "app/gui/panels/compare_table.hpp"
#include "app/gui/panels/intro_window.hpp"
#include "app/gui/panels/parameters_panel.hpp"
#include "app/gui/panels/stats_overlay.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/presentation_bar.hpp"
#include "app/gui/view_settings.hpp"

namespace foldlab::gui {

bool MenuBar::bar_item(const char* label) {
  const bool chosen = ImGui::MenuItem(label);
  item_rects_[label] = PanelRect{ImGui::GetItemRectMin(), ImGui::GetItemRectSize()};
  return chosen;
}

float MenuBar::draw(PanelContext& context) {
  export_.new_frame();
  item_rects_.clear();
  float height = 0.0f;
  // A menu's rows are its text and the item spacing tall: for a finger, as tall as a target
  // (touch_style has made the frames so, and the menu bar is one).
  begin_touch_rows();
  if (ImGui::BeginMainMenuBar()) {
    height = ImGui::GetWindowHeight();
    if (ImGui::BeginMenu("View")) {
      view_menu(context);
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Compare")) {
      compare_menu(context.document, context.status);
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Export")) {
      export_items(context);
      ImGui::EndMenu();
    }
    if (bar_item(IntroWindow::kTitle)) {
      context.panel<IntroWindow>().open();
    }
    // One click from the menu bar while the user's own arrangement is shown.
    if ((!layout_.automatic() || layout_.splits().any()) && layout_.presented() == nullptr &&
        bar_item("Reset layout")) {
      layout_.reset();
    }
    if (layout_.cramped() && !shows_one_view()) {
      cramped_notice(context);
    }
    // On a phone the views are switched under the read-out: there are no tiles to go back to.
    if (layout_.presented() != nullptr && !shows_one_view()) {
      presenting_items(context);
    }
    ImGui::EndMainMenuBar();
  }
  end_touch_rows();
  return height;
}

void MenuBar::cramped_notice(PanelContext& context) {
  // Six tiles at this text size each hold a sliver: one view over the window holds it all. The
  // tiles stay as they are (a smaller text size, or a larger window, brings them back in full).
  const ImGuiStyle& style = ImGui::GetStyle();
  const float menu_width = ImGui::CalcTextSize(kPresentOneViewLabel).x + 2.0f * style.ItemSpacing.x;
  const float room = ImGui::GetWindowWidth() - style.WindowPadding.x - ImGui::GetCursorPosX();
  // The longest words that leave the menu whole; none when only the menu fits (its tooltip
  // says why).
  const auto fits = [&](const char* text) {
    return ImGui::CalcTextSize(text).x + style.ItemSpacing.x + menu_width <= room;
  };
  const char* words = fits(kCrampedNotice)        ? kCrampedNotice
                      : fits(kCrampedShortNotice) ? kCrampedShortNotice
                                                  : nullptr;
  if (words != nullptr) {
    ImGui::PushStyleColor(ImGuiCol_Text, static_cast<ImVec4>(kNoteText));
    ImGui::TextUnformatted(words);
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s", kCrampedTooltip);
    }
  }
  const bool opened = ImGui::BeginMenu(kPresentOneViewLabel);
  if (words == nullptr && ImGui::IsItemHovered() && !opened) {
    ImGui::SetTooltip("%s", kCrampedTooltip);
  }
  if (opened) {
    for (const std::unique_ptr<Panel>& panel : context.panels) {
      if (Layout::presentable(*panel) && ImGui::MenuItem(panel->name())) {
        layout_.request_present(panel.get());
      }
    }
    ImGui::EndMenu();
  }
}

void MenuBar::presenting_items(PanelContext& context) {
  const bool strip_item = layout_.presented() != &context.panel<ParametersPanel>();
  const char* strip_label = layout_.presents_inputs() ? kHideInputsLabel : kShowInputsLabel;
  // At a large text size in a small window the long label would push the last item off the bar.
  // A menu bar item takes its text and twice the item spacing.
  const ImGuiStyle& style = ImGui::GetStyle();
  const auto item_width = [&style](const char* label) {
    return ImGui::CalcTextSize(label).x + 2.0f * style.ItemSpacing.x;
  };
  Panel* shown = layout_.presentable_panel(layout_.presented()->key());
  // The view's menu and the strip's item first; "Back to the tiles" in as many words as leave
  // them on the bar, or none (it is in the view's menu, and Esc).
  const float room = ImGui::GetWindowWidth() - style.WindowPadding.x - ImGui::GetCursorPosX() -
                     (strip_item ? item_width(strip_label) : 0.0f) -
                     (shown != nullptr ? item_width(shown->name()) : 0.0f);
  const char* back = item_width(kBackToTilesLabel) <= room        ? kBackToTilesLabel
                     : item_width(kBackToTilesShortLabel) <= room ? kBackToTilesShortLabel
                                                                  : nullptr;
  // The presented view's title bar, folded into the bar above it: its row is the picture's.
  if (shown != nullptr && ImGui::BeginMenu(shown->name())) {
    shown->presented_menu_items(context);
    ImGui::Separator();
    if (ImGui::MenuItem("Back to the tiles", "Esc")) {
      layout_.request_present(nullptr);
    }
    ImGui::EndMenu();
  }
  if (back != nullptr && bar_item(back)) {
    layout_.request_present(nullptr);
  }
  if (strip_item && bar_item(strip_label)) {
    layout_.set_presents_inputs(!layout_.presents_inputs());
  }
}

void MenuBar::export_items(PanelContext& context) {
  export_.menu(context.document, context.status, context.panel<ClothViewPanel>().style(),
               context.files, context.panels);
  ImGui::Separator();
  if (ImGui::MenuItem("Copy link")) {
    copy_link_();
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "The fabric (and B, when pinned) as an address: open it in the page, or in an installed "
        "FoldLab");
  }
  ImGui::MenuItem("Link sets my theme and text size", nullptr, &link_choices_.carries_look);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Off: whoever opens the link keeps their own theme and text size (a phone's, a "
        "projector's)");
  }
  if (link_choices_.page_knows_address) {
    return;
  }
  // Set once, remembered: where the page is served, so that a link opens in any browser.
  ImGui::TextUnformatted("Page address");
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 22.0f);
  std::array<char, ViewSettings::kMaxTextBytes + 1> typed{};
  std::snprintf(typed.data(), typed.size(), "%s", link_choices_.page_address.c_str());
  if (ImGui::InputTextWithHint("##page_address", "https://.../foldlab/index.html", typed.data(),
                               typed.size())) {
    link_choices_.page_address = typed.data();
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Where the FoldLab page is served: Copy link then gives a web address anyone can open. "
        "Empty: a foldlab: link, which opens in an installed FoldLab.");
  }
}

// The UI scale and theme, for a projector, beside the shortcuts that do the same. For a finger
// no submenu: where there is no room beside this menu (a phone) one opens over it, under the
// finger that opened it, whose lift then picks whatever lies there (a quick tap presented the
// Parameters). The text sizes are a row of buttons and the views to present rows of this menu.
void MenuBar::view_menu(PanelContext& context) {
  const bool finger = (ImGui::GetIO().ConfigFlags & ImGuiConfigFlags_IsTouchScreen) != 0;
  int percent = appearance_.scale_percent();
  bool light = appearance_.light_theme();
  ImGui::Text("UI scale %d %%", percent);
  // The sizes a room needs, in one move rather than ten presses of Ctrl +.
  constexpr int kTextSizes[] = {100, 125, 150, 200};
  if (finger) {
    for (const int choice : kTextSizes) {
      ImGui::SameLine();
      ImGui::BeginDisabled(percent == choice);
      if (ImGui::Button((std::to_string(choice) + " %").c_str())) {
        percent = choice;
      }
      ImGui::EndDisabled();
    }
  } else {
    if (ImGui::MenuItem("Larger text", "Ctrl +", false, percent < kMaxUiScalePercent)) {
      percent += kUiScaleStepPercent;
    }
    if (ImGui::MenuItem("Smaller text", "Ctrl -", false, percent > kMinUiScalePercent)) {
      percent -= kUiScaleStepPercent;
    }
    if (ImGui::MenuItem("Default size", "Ctrl 0", false, percent != kMinUiScalePercent)) {
      percent = kMinUiScalePercent;
    }
    if (ImGui::BeginMenu("Text size")) {
      for (const int choice : kTextSizes) {
        if (ImGui::MenuItem((std::to_string(choice) + " %").c_str(), nullptr, percent == choice)) {
          percent = choice;
        }
      }
      ImGui::EndMenu();
    }
  }
  ImGui::MenuItem("Light theme", nullptr, &light);
  appearance_.request(percent, light);
  ImGui::Separator();
  ImGui::MenuItem("Pipeline stats", nullptr, &show_stats_);
  // The windows that open and close (the tension field), each ticked while it is open. One
  // opened while a view is presented is presented in its place: behind it, it would not be seen;
  // one opened while the tiles are too small for the text is presented too: as a window it would
  // be mostly its legend.
  for (const std::unique_ptr<Panel>& panel : context.panels) {
    if (bool* open = panel->open_flag()) {
      if (ImGui::MenuItem(panel->name(), nullptr, open) && *open &&
          (layout_.presented() || (layout_.cramped() && !shows_one_view())) &&
          Layout::presentable(*panel)) {
        layout_.request_present(panel.get());
      }
    }
  }
  // The one presented is ticked.
  const auto present_items = [&] {
    for (const std::unique_ptr<Panel>& panel : context.panels) {
      if (Layout::presentable(*panel) &&
          ImGui::MenuItem(panel->name(), nullptr, layout_.presented() == panel.get())) {
        layout_.request_present(panel.get());
      }
    }
  };
  // On a phone the views are the buttons under the read-out, and there are no tiles. A view
  // presented is switched for another from here, without the tiles in between.
  if (layout_.presented() && !shows_one_view() &&
      ImGui::MenuItem("Back to the tiles", finger ? nullptr : "Esc")) {
    layout_.request_present(nullptr);
  }
  if (!shows_one_view() && finger) {
    ImGui::TextDisabled("Present (fill the screen):");
    ImGui::Indent();
    present_items();
    ImGui::Unindent();
  } else if (!shows_one_view() && ImGui::BeginMenu("Present (fill the window)")) {
    present_items();
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem(IntroWindow::kTitle)) {
    context.panel<IntroWindow>().open();
  }
  if (ImGui::MenuItem("Reset layout", nullptr, false,
                      !layout_.automatic() || layout_.splits().any())) {
    layout_.reset();
  }
  ImGui::Separator();
  ImGui::TextDisabled("About FoldLab: %s", app::version_line().c_str());
}

void MenuBar::draw_after_panels(PanelContext& context) {
  const ClothViewPanel& cloth = context.panel<ClothViewPanel>();
  stats_overlay(show_stats_, context.document.scene(),
                context.renderer.cloth_counters(cloth.a_view()));
  export_.draw_picture_dialog(context.status, context.files);
}

}  // namespace foldlab::gui
