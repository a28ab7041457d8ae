#include "app/gui/presentation_bar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include <imgui.h>

#include "app/gui/panels/cloth_view_panel.hpp"
#include "app/gui/panels/parameters_panel.hpp"
#include "app/gui/panels/presets_panel.hpp"
#include "app/gui/panels/results_panel.hpp"
#include "app/gui/panels/widgets.hpp"

namespace foldlab::gui {
namespace {

// The read-out's lines at one scale: as large as the width allows, up to two and a half times the
// text, as it is read from the back of a room (a hair short of the width, so that rounding never
// wraps it). Only a line too long at the text's own size (scale 1) wraps: between n, Q and z_max
// (headline()), never after a number's '.' as ImGui's wrapping would.
struct Headlines {
  std::vector<std::pair<std::string, ImVec4>> lines;
  float scale = 1.0f;
  float height = 0.0f;
};

Headlines fit_headlines(std::vector<std::pair<std::string, ImVec4>> lines, float available,
                        float largest_scale) {
  constexpr float kLargestScale = 2.5f;
  float text_width = 1.0f;
  for (const auto& [line, colour] : lines) {
    text_width = std::max(text_width, ImGui::CalcTextSize(line.c_str()).x);
  }
  Headlines fitted;
  // A phone is read at arm's length, and held sideways it has few lines to give: the picture
  // keeps them.
  constexpr float kLargestPhoneScale = 1.5f;
  const float largest = shows_one_view() ? kLargestPhoneScale : kLargestScale;
  fitted.scale = std::clamp(0.98f * available / text_width, 1.0f, std::min(largest, largest_scale));
  for (auto& [line, colour] : lines) {
    line = wrap_at_spaces(line, available);
    fitted.height += fitted.scale * ImGui::CalcTextSize(line.c_str()).y;
  }
  fitted.height += static_cast<float>(lines.size() - 1) * ImGui::GetStyle().ItemSpacing.y;
  fitted.lines = std::move(lines);
  return fitted;
}

void draw_headlines(const Headlines& headlines) {
  ImGui::SetWindowFontScale(headlines.scale);
  for (const auto& [line, colour] : headlines.lines) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextUnformatted(line.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::SetWindowFontScale(1.0f);
}

// The views to switch between on a phone, named short enough for a third of its width.
const char* short_view_name(const Panel& panel) {
  const std::string_view key = panel.key();
  return key == "parameters"  ? "Inputs"
         : key == "fold_plot" ? "2D"
         : key == "cloth"     ? "3D"
                              : panel.name();
}

// As many of the views' buttons to a row as fit `available` with their names whole: all six on a
// phone held sideways, three upright (a third of its width each).
int views_per_row(const PanelContext& context, float available) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  float widest = 0.0f;
  int views = 0;
  for (const std::unique_ptr<Panel>& panel : context.panels) {
    if (Layout::tiled(*panel)) {
      widest = std::max(widest, button_width(short_view_name(*panel)));
      ++views;
    }
  }
  for (int per_row = views; per_row > 1; --per_row) {
    if (static_cast<float>(per_row) * widest + static_cast<float>(per_row - 1) * spacing <=
        available) {
      // Rows of equal length: six are two rows of three, not five and one.
      const int rows = (views + per_row - 1) / per_row;
      return (views + rows - 1) / rows;
    }
  }
  return 1;
}

// The views' buttons, in rows as wide as `available`: the presented one disabled. Where each was
// drawn goes into `drawn`, by its panel's key.
void view_switch(PanelContext& context, Layout& layout, float available,
                 std::map<std::string, PanelRect>& drawn) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const int per_row = views_per_row(context, available);
  const float width =
      (available - static_cast<float>(per_row - 1) * spacing) / static_cast<float>(per_row);
  int shown = 0;
  for (const std::unique_ptr<Panel>& panel : context.panels) {
    if (!Layout::tiled(*panel)) {
      continue;
    }
    if (shown % per_row != 0) {
      ImGui::SameLine();
    }
    ++shown;
    ImGui::BeginDisabled(layout.presented() == panel.get());
    if (ImGui::Button(short_view_name(*panel), ImVec2(width, 0.0f))) {
      layout.request_present(panel.get());
    }
    drawn[panel->key()] = PanelRect{ImGui::GetItemRectMin(), ImGui::GetItemRectSize()};
    ImGui::EndDisabled();
  }
}

int view_switch_rows(const PanelContext& context, float available) {
  const auto views = std::count_if(context.panels.begin(), context.panels.end(),
                                   [](const auto& panel) { return Layout::tiled(*panel); });
  const int per_row = views_per_row(context, available);
  return static_cast<int>((views + per_row - 1) / per_row);
}

// The play/pause button's words: what it does to which input ("play h", "pause h").
std::string play_label(const ParametersPanel& parameters, bool playing) {
  return std::string(playing ? ParametersPanel::kPauseLabel : ParametersPanel::kPlayLabel) + " " +
         parameters.animated_key();
}

float play_button_width(const ParametersPanel& parameters) {
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::CalcTextSize(play_label(parameters, true).c_str()).x + 2.0f * style.FramePadding.x;
}

// As tall as the read-out's line beside it, so that the button costs the picture nothing: a
// frame's padding is for a finger only.
float play_button_height() {
  return finger_pointer() ? ImGui::GetFrameHeight() : ImGui::GetTextLineHeight() + 2.0f;
}

// At the right of the read-out's first line, so that it costs the picture no row: plays the input
// the Parameters panel's "animate" chose through its range, or pauses it where it is.
void play_pause(PanelContext& context, ParametersPanel& parameters, float width,
                double presented_since_s) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const bool playing = parameters.animating();
  const ImVec2 cursor = ImGui::GetCursorScreenPos();
  ImGui::SetCursorScreenPos(ImVec2(
      ImGui::GetWindowPos().x + width - style.WindowPadding.x - play_button_width(parameters),
      cursor.y));
  const std::string label = play_label(parameters, playing) + "###present play";
  // The label in the middle of a button shorter than a frame.
  ImGui::PushStyleVar(
      ImGuiStyleVar_FramePadding,
      ImVec2(style.FramePadding.x,
             std::min(style.FramePadding.y, 0.5f * (play_button_height() - ImGui::GetFontSize()))));
  const bool clicked =
      ImGui::Button(label.c_str(), ImVec2(play_button_width(parameters), play_button_height()));
  ImGui::PopStyleVar();
  // The button sits where a tile's present button was: the second click of a double click on
  // that one, landing here, would start the input playing.
  const bool just_presented =
      ImGui::GetTime() - presented_since_s < ImGui::GetIO().MouseDoubleClickTime;
  if (clicked && !just_presented) {
    parameters.toggle_play(context.document, context.status);
  }
  if (ImGui::IsItemHovered()) {
    const std::string& problem = parameters.animation_problem();
    // Wrapped: one line the window's width would hide the strip while the pointer waits here.
    wrapped_tooltip("%s", problem.empty() ? "Runs the input chosen under \"animate\" in the "
                                            "Parameters panel from the low end of its slider to "
                                            "the high end and back; pause leaves it where it is."
                                          : problem.c_str());
  }
  ImGui::SetCursorScreenPos(cursor);
}

}  // namespace

bool shows_one_view() {
  // A phone upright is narrower than 40 lines (600 CSS px at 100 %), held sideways lower than 30
  // (450 CSS px): either way six tiles leave each a sliver. A tablet (768 CSS px or more each
  // way) keeps its tiles.
  constexpr float kLeastTilesWidthLines = 40.0f;
  constexpr float kLeastTilesHeightLines = 30.0f;
  const ImGuiIO& io = ImGui::GetIO();
  return (io.ConfigFlags & ImGuiConfigFlags_IsTouchScreen) != 0 &&
         (io.DisplaySize.x < kLeastTilesWidthLines * ImGui::GetFontSize() ||
          io.DisplaySize.y < kLeastTilesHeightLines * ImGui::GetFontSize());
}

// The status line under the read-out and the strip (a copied link, a refused file): the Presets
// panel that shows it is out of sight unless it is the one presented. Under the strip, so that a
// message coming and going never moves the strip's sliders; not when the strip already says it
// (the reason typed text was no value, under its slider).
std::string PresentationBar::message_for_presented(PanelContext& context, bool strip) const {
  if (layout_.presented() == &context.panel<PresetsPanel>()) {
    return "";
  }
  const std::string& message = context.status.message();
  // (std::any_of, not std::ranges: the page's libc++ has no ranges algorithms.)
  const std::map<std::string, std::string> reasons =
      context.panel<ParametersPanel>().unread_reasons();
  if (strip && std::any_of(reasons.begin(), reasons.end(),
                           [&](const auto& entry) { return entry.second == message; })) {
    return "";
  }
  return message;
}

float PresentationBar::draw(PanelContext& context, float top) {
  ParametersPanel& parameters = context.panel<ParametersPanel>();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = std::floor(display.x);
  const float available = width - 2.0f * style.WindowPadding.x;
  // Above and below its rows no more than between them: the rows are the picture's.
  const float padding_y = style.ItemSpacing.y;
  // The inputs under the read-out, for a "what if" without leaving the view; not over the
  // Parameters panel itself, whose own play button is in sight.
  const bool presents_parameters = layout_.presented() == &parameters;
  const bool play = !presents_parameters;
  const float play_room = play ? play_button_width(parameters) + style.ItemSpacing.x : 0.0f;
  // The presented 3D view drawn with the field's folds is read out with them: its scene for this
  // frame, the field brought up to date first.
  const Solution* drawn = nullptr;
  std::string drawn_words;
  ClothViewPanel& cloth = context.panel<ClothViewPanel>();
  if (layout_.presented() == &cloth) {
    Scene& scene = cloth.scene_to_draw(context);
    if (&scene != &context.document.scene()) {
      drawn = &scene.solution();
      drawn_words = cloth.drawn_folds_words();
    }
  }
  if (available != scale_cap_width_ || ImGui::GetFontSize() != scale_cap_font_ ||
      layout_.presented() != scale_cap_view_) {
    scale_cap_ = std::numeric_limits<float>::infinity();
    scale_cap_width_ = available;
    scale_cap_font_ = ImGui::GetFontSize();
    scale_cap_view_ = layout_.presented();
  }
  const Headlines headlines =
      fit_headlines(context.panel<ResultsPanel>().headlines(context.document, drawn, drawn_words),
                    available - play_room, scale_cap_);
  scale_cap_ = headlines.scale;
  const bool strip = layout_.presents_inputs() && !presents_parameters;
  message_ = message_for_presented(context, strip);
  float text_height = std::max(headlines.height, play ? play_button_height() : 0.0f);
  if (!message_.empty()) {
    text_height +=
        style.ItemSpacing.y + ImGui::CalcTextSize(message_.c_str(), nullptr, false, available).y;
  }
  if (strip) {
    text_height += style.ItemSpacing.y + parameters.strip_height(context.document, available);
  } else if (!presents_parameters) {
    parameters.forget_slider_places();
  }
  const bool one_view = shows_one_view();
  if (one_view) {
    const int rows = view_switch_rows(context, available);
    text_height += static_cast<float>(rows) * (ImGui::GetFrameHeight() + style.ItemSpacing.y);
  }
  const float height = std::ceil(text_height + 2.0f * padding_y);
  ImGui::SetNextWindowPos(ImVec2(0.0f, top), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar |
                                 ImGuiWindowFlags_NoScrollWithMouse;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(style.WindowPadding.x, padding_y));
  const bool shown = ImGui::Begin(kWindow, nullptr, flags);
  ImGui::PopStyleVar();
  if (shown) {
    context.renderer.fill_window_background();
    ImGui::PushTextWrapPos(0.0f);
    if (one_view) {
      view_switch(context, layout_, available, view_buttons_);
    }
    const float headlines_top = ImGui::GetCursorScreenPos().y;
    if (play) {
      // Play and pause, for a lesson that runs an input through its range while the class
      // watches the presented view.
      play_pause(context, parameters, width, layout_.presented_since_s());
    }
    draw_headlines(headlines);
    // A button a finger's height is taller than a line of the read-out: what comes under them
    // starts under the button, not over its foot.
    const float gap = headlines_top + play_button_height() - ImGui::GetCursorScreenPos().y;
    if (play && gap > 0.0f) {
      ImGui::Dummy(ImVec2(0.0f, gap));
    }
    if (strip) {
      parameters.draw_strip(context.document, context.status, available);
    }
    if (!message_.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, message_colour(context.status.message_kind()));
      ImGui::TextUnformatted(message_.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
  return top + height;
}

}  // namespace foldlab::gui
