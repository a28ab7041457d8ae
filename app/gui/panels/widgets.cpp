#include "app/gui/panels/widgets.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

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

float ems(float ems) {
  return std::round(ems * ImGui::GetFontSize());
}

TiledLayout tiled_layout(ImVec2 display, float top_px, float font_px) {
  const float width = std::max(std::floor(display.x), 1.0f);
  const float height = std::max(std::floor(display.y - top_px), 1.0f);
  const float top = std::floor(top_px);
  // 25 font sizes hold a slider's label, the slider and its unit at any scale; 40 keep the
  // sliders short enough that a pixel of drag stays a small step on a wide screen. Never more
  // than 45 % of the width, so that the views keep the rest.
  const float left = std::floor(
      std::min(std::clamp(0.30f * width, 25.0f * font_px, 40.0f * font_px), 0.45f * width));
  const float middle = std::floor((width - left) / 2.0f);
  const float right = width - left - middle;
  const float parameters_h = std::floor(0.62f * height);
  const float views_h = std::floor(0.56f * height);
  TiledLayout l;
  const auto set = [&l](Tile tile, float x, float y, float w, float h) {
    l.rects[static_cast<int>(tile)] = PanelRect{ImVec2(x, y), ImVec2(w, h)};
  };
  set(Tile::parameters, 0, top, left, parameters_h);
  set(Tile::presets, 0, top + parameters_h, left, height - parameters_h);
  set(Tile::fold_plot, left, top, middle, views_h);
  set(Tile::results, left, top + views_h, middle, height - views_h);
  set(Tile::cloth, left + middle, top, right, views_h);
  set(Tile::analysis, left + middle, top + views_h, right, height - views_h);
  return l;
}

bool begin_panel(const char* title, Renderer& renderer) {
  if (!ImGui::Begin(title)) {
    return false;
  }
  renderer.fill_window_background();
  return true;
}

void same_line_if_fits(float width) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float right_edge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetItemRectMax().x + spacing + width <= right_edge) {
    ImGui::SameLine();
  }
}

float checkbox_width(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::GetFrameHeight() + style.ItemInnerSpacing.x +
         ImGui::CalcTextSize(label, nullptr, true).x;
}

float button_width(const char* label) {
  return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

float labelled_width(float item_width, const char* label) {
  const float text = ImGui::CalcTextSize(label, nullptr, true).x;
  return item_width + (text > 0.0f ? ImGui::GetStyle().ItemInnerSpacing.x + text : 0.0f);
}

void hint_after(const char* text) {
  same_line_if_fits(ImGui::CalcTextSize(text).x);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%s", text);
  ImGui::PopStyleColor();
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::TextColored(kSectionText, "%s", title);
  ImGui::Separator();
}

namespace {

struct AsciiSpelling {
  ImWchar codepoint;
  const char* ascii;
};
constexpr AsciiSpelling kAsciiSpellings[] = {
    {0x03BD, "nu"},    {0x03C3, "sigma"}, {0x03BB, "lambda"}, {0x03C0, "pi"}, {0x03A3, "Sum"},
    {0x03B8, "theta"}, {0x222B, "Int"},   {0x2212, "-"},      {0x2032, "'"},  {0x2264, "<="},
    {0x2265, ">="},    {0x2026, "..."},   {0x2192, "->"},     {0x2190, "<-"}, {0x221A, "sqrt"},
};

// The code point at `at` in UTF-8 and its length in bytes; a malformed byte stands for itself.
std::pair<unsigned, std::size_t> decode(std::string_view s, std::size_t at) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[at + k]); };
  const unsigned first = byte(0);
  if (first >= 0xE0 && at + 2 < s.size()) {
    return {((first & 0x0Fu) << 12) | ((byte(1) & 0x3Fu) << 6) | (byte(2) & 0x3Fu), 3};
  }
  if (first >= 0xC0 && at + 1 < s.size()) {
    return {((first & 0x1Fu) << 6) | (byte(1) & 0x3Fu), 2};
  }
  return {first, 1};
}

}  // namespace

std::string readable(std::string_view utf8) {
  const ImFont* font = ImGui::GetFont();
  std::string out;
  out.reserve(utf8.size());
  for (std::size_t at = 0; at < utf8.size();) {
    const auto [codepoint, length] = decode(utf8, at);
    const char* ascii = nullptr;
    if (codepoint >= 0x100 && font != nullptr &&
        font->FindGlyphNoFallback(static_cast<ImWchar>(codepoint)) == nullptr) {
      for (const AsciiSpelling& spelling : kAsciiSpellings) {
        if (spelling.codepoint == codepoint) {
          ascii = spelling.ascii;
        }
      }
    }
    if (ascii != nullptr) {
      out += ascii;
    } else {
      out.append(utf8.substr(at, length));
    }
    at += length;
  }
  return out;
}

void help_marker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(readable(text).c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

}  // namespace foldlab::gui
