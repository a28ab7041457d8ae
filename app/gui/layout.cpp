#include "app/gui/layout.hpp"

#include <nlohmann/json.hpp>

#include "app/gui/input_words.hpp"
#include "app/gui/panels/widgets.hpp"
#include "core/model/text_format.hpp"

#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <imgui_internal.h>  // FindWindowByName: where the user moved a panel

namespace foldlab::gui {
namespace {

// A tiled panel's place in the arrays indexed by tile.
std::size_t tile_of(const Panel& panel) {
  return static_cast<std::size_t>(*tile_index(panel.key()));
}

}  // namespace

void Layout::begin_frame(float menu_height_px) {
  if (presented_ != nullptr && !presented_->is_open()) {
    present(nullptr);  // the presented window was closed
  }
  if (present_request_) {
    present(*present_request_);
    present_request_.reset();
  }
  menu_height_px_ = menu_height_px;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  tiles_ = tiled_layout(display, menu_height_px_, ImGui::GetFontSize(), splits_);
  if (follow_user_edits()) {
    tiles_ = tiled_layout(display, menu_height_px_, ImGui::GetFontSize(), splits_);
  }
}

void Layout::set_presented_top(float top_px) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  presented_rect_ =
      PanelRect{ImVec2(0.0f, top_px),
                ImVec2(std::floor(display.x), std::max(std::floor(display.y - top_px), 1.0f))};
}

bool Layout::shows(const Panel& panel) const {
  return !presentable(panel) || presented_ == nullptr || presented_ == &panel;
}

void Layout::forget_places() {
  for (bool& valid : placed_valid_) {
    valid = false;
  }
}

void Layout::reset() {
  automatic_ = true;
  splits_ = LayoutSplits{};
  forget_places();
}

void Layout::view_settings(ViewSettings& settings) {
  for (int split = 0; split < kSplitCount; ++split) {
    // negative: where the tiles put it
    settings.add_number(split_key(split), &splits_.fraction[static_cast<std::size_t>(split)],
                        ViewRange<float>{-1.0f, 1.0f, ""}, kRemembered);
  }
  settings.add_switch("automatic_layout", &automatic_, kRemembered);
  settings.add_switch("present_inputs", &presents_inputs_, kRemembered);
  settings.add_action(
      "present",
      [this](std::string_view value) -> std::optional<std::string> {
        if (value == "none") {
          present(nullptr);
          return std::nullopt;
        }
        if (const Panel* shown = presentable_panel(value)) {
          present(shown);
          return std::nullopt;
        }
        std::string known = "none";
        for (const std::unique_ptr<Panel>& panel : panels_) {
          if (presentable(*panel)) {
            known += std::string(", ") + panel->key();
          }
        }
        return "present = '" + detail::cut(value) + "' is not one of: " + known;
      },
      [this] {
        return presented_ != nullptr ? nlohmann::json(presented_->key()) : nlohmann::json(nullptr);
      });
}

PanelRect Layout::rect_of(const Panel& panel) const {
  for (const auto& [key, rect] : panel_rects()) {
    if (key == panel.key()) {
      return rect;
    }
  }
  return {};
}

Panel* Layout::presentable_panel(std::string_view key) const {
  for (const std::unique_ptr<Panel>& panel : panels_) {
    if (presentable(*panel) && key == panel->key()) {
      return panel.get();
    }
  }
  return nullptr;
}

void Layout::present(const Panel* panel) {
  if (presented_ == panel) {
    return;
  }
  if (panel != nullptr && (!automatic_ || !tiled(*panel))) {
    if (const ImGuiWindow* window = ImGui::FindWindowByName(panel->window_label().c_str())) {
      const PanelRect was{window->Pos, window->SizeFull};
      if (tiled(*panel)) {
        restore_[tile_of(*panel)] = was;
      } else if (window->Active) {
        window_restore_ = was;
      }
    }
  }
  if (presented_ != nullptr && !tiled(*presented_)) {
    window_to_restore_ = presented_;
  }
  if (panel != nullptr) {
    // A window presented from the menu or a script opens, as the one it replaces would show.
    if (Panel* shown = presentable_panel(panel->key()); shown != nullptr && shown->open_flag()) {
      *shown->open_flag() = true;
    }
  }
  presented_ = panel;
  presented_since_s_ = ImGui::GetTime();
  forget_places();
}

void Layout::present_button(const Panel& panel) {
  const std::string label = panel.window_label();
  ImGuiWindow* window = ImGui::FindWindowByName(label.c_str());
  if (window == nullptr || !window->Active) {
    return;
  }
  ImGui::Begin(label.c_str());  // appends to the panel's window, whose title bar holds the button
  const bool presented = presented_ == &panel;
  const ImRect title = window->TitleBarRect();
  const float side = title.GetHeight();
  // Left of a window's close button, when it has one.
  const float right = title.Max.x - (window->HasCloseButton ? side : 0.0f);
  // The button sits above the content: it must not widen what the window scrolls over.
  const ImVec2 cursor = ImGui::GetCursorScreenPos();
  const ImVec2 cursor_max = window->DC.CursorMaxPos;
  ImGui::PushClipRect(title.Min, title.Max, false);
  ImGui::SetCursorScreenPos(ImVec2(right - side, title.Min.y));
  const bool clicked = ImGui::InvisibleButton("##present", ImVec2(side, side));
  const bool hovered = ImGui::IsItemHovered();
  // A square outline (fill the window), or two overlapping ones (back to the tiles).
  ImDrawList* draw = window->DrawList;
  const ImU32 colour = ImGui::GetColorU32(hovered ? ImGuiCol_Text : ImGuiCol_TextDisabled);
  const float thickness = std::max(1.0f, std::round(ImGui::GetFontSize() / 12.0f));
  const float inset = std::round(0.28f * side);
  const ImVec2 a(right - side + inset, title.Min.y + inset);
  const ImVec2 b(right - inset, title.Max.y - inset);
  if (presented) {
    const float shift = std::round(0.15f * side);
    draw->AddRect(ImVec2(a.x + shift, a.y), ImVec2(b.x, b.y - shift), colour, 0.0f, 0, thickness);
    draw->AddRectFilled(ImVec2(a.x, a.y + shift), ImVec2(b.x - shift, b.y),
                        ImGui::GetColorU32(ImGuiCol_TitleBgActive));
    draw->AddRect(ImVec2(a.x, a.y + shift), ImVec2(b.x - shift, b.y), colour, 0.0f, 0, thickness);
  } else {
    draw->AddRect(a, b, colour, 0.0f, 0, thickness);
    draw->AddLine(ImVec2(a.x, a.y + thickness), ImVec2(b.x, a.y + thickness), colour, thickness);
  }
  ImGui::PopClipRect();
  ImGui::SetCursorScreenPos(cursor);
  window->DC.CursorMaxPos = cursor_max;
  if (hovered) {
    ImGui::SetTooltip("%s", presented ? "Back to the tiles (Esc)" : hint_words(Hint::present_view));
  }
  // As ImGui tells a double-click on a title from one on an item in it.
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  const bool title_double_clicked =
      !hovered && g.HoveredWindow == window && g.HoveredIdPreviousFrame == 0 &&
      ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && title.Contains(ImGui::GetIO().MousePos);
  if (clicked || title_double_clicked) {
    present_request_ = presented ? nullptr : &panel;
  }
  if (presented) {
    // Never written to imgui.ini: the user's arrangement keeps this panel's own place.
    window->Flags |= ImGuiWindowFlags_NoSavedSettings;
  }
  ImGui::End();
}

void Layout::tile_handles(bool coarse_pointer, float target_px) {
  handle_rects_.clear();
  if (!coarse_pointer || presented_ != nullptr || !automatic_) {
    return;
  }
  constexpr ImGuiWindowFlags kGripFlags =
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
      ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus |
      ImGuiWindowFlags_NoNav;
  const ImGuiIO& io = ImGui::GetIO();
  std::vector<ImGuiWindow*> grips;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1.0f, 1.0f));
  for (int split = 0; split < kSplitCount; ++split) {
    const std::size_t s = static_cast<std::size_t>(split);
    const PanelRect grip = tile_handle(split, tiles_, target_px, 2.0f * target_px);
    if (grip.size.x < 1.0f || grip.size.y < 1.0f) {
      continue;
    }
    const bool vertical = kSplits[split].side_by_side;
    const std::string name = std::string("##tile_handle_") + split_key(split);
    ImGui::SetNextWindowPos(grip.pos, ImGuiCond_Always);
    ImGui::SetNextWindowSize(grip.size, ImGuiCond_Always);
    ImGui::Begin(name.c_str(), nullptr, kGripFlags);
    ImGui::SetCursorScreenPos(grip.pos);
    ImGui::InvisibleButton("grip", grip.size);
    const float finger_px = vertical ? io.MousePos.x : io.MousePos.y;
    if (ImGui::IsItemActivated()) {
      handle_grab_px_ = finger_px - tiles_.edge_px[s];
    }
    const bool held = ImGui::IsItemActive();
    // A tap that does not move leaves the edge where the tiles put it.
    if (held && (vertical ? io.MouseDelta.x : io.MouseDelta.y) != 0.0f) {
      move_split(split, finger_px - handle_grab_px_, tiles_, splits_);
      tiles_ = tiled_layout(io.DisplaySize, menu_height_px_, ImGui::GetFontSize(), splits_);
    }
    // A rounded bar along the edge with three ridges across it, in the scrollbar's colours (drawn
    // to be seen over any panel), the whole edge lit while it is dragged.
    const ImGuiCol fill = held                     ? ImGuiCol_ScrollbarGrabActive
                          : ImGui::IsItemHovered() ? ImGuiCol_ScrollbarGrabHovered
                                                   : ImGuiCol_ScrollbarGrab;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 centre(grip.pos.x + 0.5f * grip.size.x, grip.pos.y + 0.5f * grip.size.y);
    const float thick = std::round(0.3f * target_px);
    const float length = std::round(0.75f * (vertical ? grip.size.y : grip.size.x));
    const ImVec2 half =
        vertical ? ImVec2(0.5f * thick, 0.5f * length) : ImVec2(0.5f * length, 0.5f * thick);
    const ImVec2 a(centre.x - half.x, centre.y - half.y);
    const ImVec2 b(centre.x + half.x, centre.y + half.y);
    const float line = std::max(1.0f, std::round(target_px / 44.0f));
    draw->AddRectFilled(a, b, ImGui::GetColorU32(fill), 0.5f * thick);
    draw->AddRect(a, b, ImGui::GetColorU32(ImGuiCol_Border), 0.5f * thick, 0, line);
    for (int ridge = -1; ridge <= 1; ++ridge) {
      const float at = static_cast<float>(ridge) * 0.25f * thick;
      const float inset = 0.25f * thick;
      if (vertical) {
        draw->AddLine(ImVec2(a.x + inset, centre.y + at), ImVec2(b.x - inset, centre.y + at),
                      ImGui::GetColorU32(ImGuiCol_Text), line);
      } else {
        draw->AddLine(ImVec2(centre.x + at, a.y + inset), ImVec2(centre.x + at, b.y - inset),
                      ImGui::GetColorU32(ImGuiCol_Text), line);
      }
    }
    if (held) {
      const PanelRect& area = tiles_.splits[s];
      const float edge = tiles_.edge_px[s];
      ImGui::GetForegroundDrawList()->AddLine(
          vertical ? ImVec2(edge, area.pos.y) : ImVec2(area.pos.x, edge),
          vertical ? ImVec2(edge, area.pos.y + area.size.y)
                   : ImVec2(area.pos.x + area.size.x, edge),
          ImGui::GetColorU32(ImGuiCol_SeparatorActive), 2.0f * line);
    }
    note_target_height(std::min(grip.size.x, grip.size.y), "tile handles");
    handle_rects_.emplace_back(split_key(split), grip);
    grips.push_back(ImGui::GetCurrentWindow());
    ImGui::End();
  }
  ImGui::PopStyleVar(3);
  // The grips lie just over the topmost tile (a tile comes to the front when touched), under any
  // window or menu that floats over the tiles. ImGui keeps a window's children after it.
  ImGuiContext& g = *ImGui::GetCurrentContext();
  ImGuiWindow* below = nullptr;
  for (const std::unique_ptr<Panel>& panel : panels_) {
    ImGuiWindow* window =
        tiled(*panel) ? ImGui::FindWindowByName(panel->window_label().c_str()) : nullptr;
    if (window != nullptr && window->Active &&
        (below == nullptr ||
         ImGui::FindWindowDisplayIndex(window) > ImGui::FindWindowDisplayIndex(below))) {
      below = window;
    }
  }
  if (below == nullptr) {
    return;
  }
  for (ImGuiWindow* grip : grips) {
    ImGuiWindow* next = nullptr;
    for (int i = ImGui::FindWindowDisplayIndex(below) + 1; i < g.Windows.Size; ++i) {
      if ((g.Windows[i]->Flags & ImGuiWindowFlags_ChildWindow) == 0) {
        next = g.Windows[i];
        break;
      }
    }
    if (next == nullptr) {
      ImGui::BringWindowToDisplayFront(grip);
    } else if (next != grip) {
      ImGui::BringWindowToDisplayBehind(grip, next);
    }
    below = grip;
  }
}

bool Layout::follow_user_edits() {
  if (!automatic_) {
    return false;
  }
  bool moved = false;
  for (const std::unique_ptr<Panel>& panel : panels_) {
    if (!tiled(*panel) || !placed_valid_[tile_of(*panel)]) {
      continue;
    }
    const ImGuiWindow* window = ImGui::FindWindowByName(panel->window_label().c_str());
    const PanelRect& last = placed_[tile_of(*panel)];
    if (window == nullptr ||
        (window->Pos.x == last.pos.x && window->Pos.y == last.pos.y &&
         window->SizeFull.x == last.size.x && window->SizeFull.y == last.size.y)) {
      continue;
    }
    if (window->SizeFull.x == last.size.x && window->SizeFull.y == last.size.y) {
      automatic_ = false;  // moved by its title: the user's arrangement stays until reset
      return false;
    }
    const float before[] = {last.pos.x, last.pos.x + last.size.x, last.pos.y,
                            last.pos.y + last.size.y};
    const float now[] = {window->Pos.x, window->Pos.x + window->SizeFull.x, window->Pos.y,
                         window->Pos.y + window->SizeFull.y};
    for (int edge = 0; edge < 4; ++edge) {
      if (now[edge] != before[edge]) {
        moved |= drag_split(static_cast<int>(tile_of(*panel)), static_cast<Edge>(edge), now[edge],
                            tiles_, splits_);
      }
    }
  }
  return moved;
}

void Layout::place(const Panel& panel) {
  if (!tiled(panel)) {
    if (presented_ == &panel) {
      ImGui::SetNextWindowPos(presented_rect_.pos, ImGuiCond_Always);
      ImGui::SetNextWindowSize(presented_rect_.size, ImGuiCond_Always);
    } else if (window_to_restore_ == &panel) {
      // Where it was, or, presented before it was ever open, its first place: not the whole
      // window it filled while presented.
      const PanelRect back =
          window_restore_.value_or(first_window_place(ImGui::GetIO().DisplaySize, menu_height_px_));
      ImGui::SetNextWindowPos(back.pos, ImGuiCond_Always);
      ImGui::SetNextWindowSize(back.size, ImGuiCond_Always);
      ImGui::SetNextWindowFocus();  // back over the tiles it was presented from
      window_to_restore_ = nullptr;
      window_restore_.reset();
    }
    return;
  }
  const std::size_t i = tile_of(panel);
  PanelRect rect = tiles_.tiles[i];
  ImGuiCond when = automatic_ ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
  if (presented_ == &panel) {
    rect = presented_rect_;
    when = ImGuiCond_Always;
  } else if (restore_[i]) {
    rect = *restore_[i];
    when = ImGuiCond_Always;
    restore_[i].reset();
  }
  ImGui::SetNextWindowPos(rect.pos, when);
  ImGui::SetNextWindowSize(rect.size, when);
  placed_[i] = rect;
  placed_valid_[i] = automatic_ && presented_ == nullptr;
}

std::vector<std::pair<std::string, PanelRect>> Layout::panel_rects() const {
  std::vector<std::pair<std::string, PanelRect>> out;
  for (const std::unique_ptr<Panel>& panel : panels_) {
    if (!tiled(*panel)) {
      continue;
    }
    const ImGuiWindow* window = ImGui::FindWindowByName(panel->window_label().c_str());
    if (window != nullptr && window->Active) {  // not one hidden behind a presented panel
      out.emplace_back(panel->key(), PanelRect{window->Pos, window->SizeFull});
    }
  }
  return out;
}

bool Layout::cramped() const {
  if (presented_ != nullptr || !automatic_) {
    return false;
  }
  const float font_px = ImGui::GetFontSize();
  return std::any_of(tiles_.tiles.begin(), tiles_.tiles.end(), [font_px](const PanelRect& tile) {
    return tile.size.x < kLeastTileWidthEms * font_px ||
           tile.size.y < kLeastTileHeightEms * font_px;
  });
}

bool Layout::fills_window() const {
  const auto rects = panel_rects();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  double area = 0.0;
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const PanelRect& a = rects[i].second;
    if (a.pos.x < 0.0f || a.pos.y < menu_height_px_ || a.pos.x + a.size.x > display.x ||
        a.pos.y + a.size.y > display.y) {
      return false;
    }
    area += static_cast<double>(a.size.x) * a.size.y;
    for (std::size_t j = i + 1; j < rects.size(); ++j) {
      const PanelRect& b = rects[j].second;
      if (a.pos.x < b.pos.x + b.size.x && b.pos.x < a.pos.x + a.size.x &&
          a.pos.y < b.pos.y + b.size.y && b.pos.y < a.pos.y + a.size.y) {
        return false;
      }
    }
  }
  return rects.size() == kTileCount &&
         area ==
             static_cast<double>(display.x) * (static_cast<double>(display.y) - menu_height_px_);
}

}  // namespace foldlab::gui
