#include "app/gui/panels/widgets.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

float marker_item_width();

}  // namespace

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

namespace {
bool g_next_without_title_bar = false;
}  // namespace

void next_panel_without_title_bar() {
  g_next_without_title_bar = true;
}

bool begin_panel(const char* title, Renderer& renderer, bool* open) {
  // A double-click on the title presents the panel (see Explorer) rather than folding it away,
  // which would leave a hole in the tiles.
  const bool presented = g_next_without_title_bar;
  g_next_without_title_bar = false;
  const ImGuiWindowFlags flags =
      ImGuiWindowFlags_NoCollapse | (presented ? ImGuiWindowFlags_NoTitleBar : 0);
  // Presented, the window is the screen's: its margin is the spacing between two items, not a
  // frame round a tile.
  if (presented) {
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(spacing, spacing));
  }
  const bool shown = ImGui::Begin(title, open, flags);
  if (presented) {
    ImGui::PopStyleVar();
  }
  if (!shown) {
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

bool notched_slider(const std::function<bool()>& slider, const std::function<double()>& fraction) {
  const ImVec2 frame_min = ImGui::GetCursorScreenPos();
  const float frame_width = ImGui::CalcItemWidth();
  ImGui::PushStyleColor(ImGuiCol_SliderGrab, IM_COL32(0, 0, 0, 0));
  ImGui::PushStyleColor(ImGuiCol_SliderGrabActive, IM_COL32(0, 0, 0, 0));
  const bool changed = slider();
  ImGui::PopStyleColor(2);
  const bool active = ImGui::IsItemActive();
  const ImGuiStyle& style = ImGui::GetStyle();
  // Where ImGui 1.86 centres its own handle: the frame less 2 px each side and half a handle.
  constexpr float kGrabPaddingPx = 2.0f;
  const float usable = frame_width - 2.0f * kGrabPaddingPx - style.GrabMinSize;
  const double at = std::clamp(fraction(), 0.0, 1.0);
  float centre = frame_min.x + kGrabPaddingPx + 0.5f * style.GrabMinSize +
                 static_cast<float>(std::isnan(at) ? 0.0 : at) * std::max(usable, 0.0f);
  // Wide enough to find from the back of a room, in the padding that the text does not use.
  const float half =
      std::min(std::max(style.GrabMinSize, 0.3f * ImGui::GetFontSize()), 0.5f * frame_width);
  // Kept within the frame at the ends of the scale.
  centre = std::clamp(centre, frame_min.x + half, frame_min.x + frame_width - half);
  const float frame_bottom = frame_min.y + ImGui::GetFrameHeight();
  // Opaque: a notch is small, and no text lies under it.
  ImVec4 opaque = style.Colors[active ? ImGuiCol_SliderGrabActive : ImGuiCol_SliderGrab];
  opaque.w = 1.0f;
  const ImU32 colour = ImGui::GetColorU32(opaque);
  ImDrawList& drawn = *ImGui::GetWindowDrawList();
  drawn.AddRectFilled(ImVec2(centre - half, frame_min.y),
                      ImVec2(centre + half, frame_min.y + style.FramePadding.y), colour);
  drawn.AddRectFilled(ImVec2(centre - half, frame_bottom - style.FramePadding.y),
                      ImVec2(centre + half, frame_bottom), colour);
  return changed;
}

bool notched_slider_int(const char* label, int& value, int lo, int hi, const char* format) {
  return notched_slider(
      [&] { return ImGui::SliderInt(label, &value, lo, hi, format, ImGuiSliderFlags_AlwaysClamp); },
      [&] { return hi > lo ? double(value - lo) / double(hi - lo) : 0.0; });
}

bool small_button(const char* label) {
  if (finger_pointer()) {
    const bool pressed = ImGui::Button(label);
    note_target(label);
    return pressed;
  }
  return ImGui::SmallButton(label);
}

bool finger_pointer() {
  return (ImGui::GetIO().ConfigFlags & ImGuiConfigFlags_IsTouchScreen) != 0;
}

namespace {

// The rows begin_touch_rows() pushed a spacing for, innermost last.
std::vector<bool> touch_rows_pushed;

SmallestTarget tally_now;

}  // namespace

void begin_touch_rows() {
  const bool push = finger_pointer();
  if (push) {
    ImGui::PushStyleVar(
        ImGuiStyleVar_ItemSpacing,
        ImVec2(ImGui::GetStyle().ItemSpacing.x, ImGui::GetFrameHeight() - ImGui::GetFontSize()));
  }
  touch_rows_pushed.push_back(push);
  if (push) {
    note_target_height(ImGui::GetTextLineHeight() + ImGui::GetStyle().ItemSpacing.y,
                       "rows of lists, combos and menus");
  }
}

void end_touch_rows() {
  if (!touch_rows_pushed.empty()) {
    if (touch_rows_pushed.back()) {
      ImGui::PopStyleVar();
    }
    touch_rows_pushed.pop_back();
  }
}

bool begin_combo(const char* label, const char* preview, ImGuiComboFlags flags) {
  if (!ImGui::BeginCombo(label, preview, flags)) {
    return false;
  }
  begin_touch_rows();
  return true;
}

void end_combo() {
  end_touch_rows();
  ImGui::EndCombo();
}

bool combo(const char* label, int* current, const char* items_zero_separated) {
  std::vector<const char*> items;
  for (const char* item = items_zero_separated; *item != '\0'; item += std::strlen(item) + 1) {
    items.push_back(item);
  }
  const bool valid = *current >= 0 && *current < static_cast<int>(items.size());
  bool changed = false;
  if (begin_combo(label, valid ? items[static_cast<std::size_t>(*current)] : "")) {
    for (int i = 0; i < static_cast<int>(items.size()); ++i) {
      ImGui::PushID(i);
      if (ImGui::Selectable(items[static_cast<std::size_t>(i)], i == *current) && i != *current) {
        *current = i;
        changed = true;
      }
      note_target(items[static_cast<std::size_t>(i)]);
      ImGui::PopID();
    }
    end_combo();
  }
  return changed;
}

float combo_width(const char* items_zero_separated) {
  float widest_px = 0.0f;
  for (const char* item = items_zero_separated; *item != '\0'; item += std::strlen(item) + 1) {
    widest_px = std::max(widest_px, ImGui::CalcTextSize(item).x);
  }
  return widest_px + 2.0f * ImGui::GetStyle().FramePadding.x + ImGui::GetFrameHeight();
}

float combo_width(std::span<const std::string> choices) {
  float widest_px = 0.0f;
  for (const std::string& choice : choices) {
    widest_px = std::max(widest_px, ImGui::CalcTextSize(choice.c_str()).x);
  }
  return widest_px + 2.0f * ImGui::GetStyle().FramePadding.x + ImGui::GetFrameHeight();
}

void begin_target_tally() {
  tally_now = {};
  // Every frame a slider, button, checkbox, combo, field or tab draws is this tall.
  note_target_height(ImGui::GetFrameHeight(), "frames (sliders, buttons, checkboxes, combos)");
}

void note_target_height(float height_px, std::string_view what) {
  if (tally_now.what.empty() || height_px < tally_now.height_px) {
    tally_now = {height_px, std::string(what)};
  }
}

void note_target(std::string_view what) {
  // A selectable's box as ImGui hit-tests it: its row and the spacing it extends over.
  note_target_height(ImGui::GetItemRectSize().y, what);
}

const SmallestTarget& smallest_target() {
  return tally_now;
}

void hint_after(const char* text) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float right_edge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  const float text_width = ImGui::CalcTextSize(text).x;
  if (ImGui::GetItemRectMax().x + spacing + text_width <= right_edge) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", text);
  } else if (ImGui::GetWindowPos().x + ImGui::GetCursorPosX() + text_width <= right_edge) {
    ImGui::TextDisabled("%s", text);  // a line of its own
  } else {
    // Lines of a wrapped hint would take the height from the view under them: the hint waits
    // behind a marker instead.
    help_marker(text);
  }
}

void help_marker_and_hint(const char* help, const char* hint) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float right_edge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  const float hint_width = ImGui::CalcTextSize(hint).x;
  const float marker_end = ImGui::GetItemRectMax().x + spacing + marker_item_width();
  const float line_start = ImGui::GetWindowPos().x + ImGui::GetStyle().WindowPadding.x;
  if (marker_end + spacing + hint_width <= right_edge || line_start + hint_width <= right_edge) {
    help_marker(help);
    hint_after(hint);
  } else {
    // Two markers side by side read as a stutter: one holds both.
    help_marker((std::string(help) + "\n\n" + hint).c_str());
  }
}

void section(const char* title) {
  ImGui::Spacing();
  // Wrapped in a narrow panel rather than cut ("eq. 7: critical stress gives Q7").
  ImGui::PushStyleColor(ImGuiCol_Text, static_cast<ImVec4>(kSectionText));
  wrapped_text("%s", title);
  ImGui::PopStyleColor();
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

std::string unbroken(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    out += c == ' ' ? std::string_view("\u00A0") : std::string_view(&c, 1);
  }
  return out;
}

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

std::string wrap_at_spaces(std::string_view text, float width_px) {
  const auto width_of = [](std::string_view s) {
    return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x;
  };
  std::string out;
  std::string line;
  // A panel squeezed to nothing still gets a width: every character then stands on a line of its
  // own instead of the cut below finding no character that fits.
  width_px = std::max(width_px, 1.0f);
  const auto char_end = [](std::string_view s, std::size_t at) {
    std::size_t next = at + 1;
    while (next < s.size() && (static_cast<unsigned char>(s[next]) & 0xC0) == 0x80) {
      ++next;
    }
    return next;
  };
  // Starts a line with `word`; a word wider than a whole line is cut where it must be, as ImGui
  // does, between UTF-8 characters, with at least one character on each line.
  const auto start_line = [&](std::string_view word) {
    while (width_of(word) > width_px) {
      std::size_t cut = char_end(word, 0);
      if (cut >= word.size()) {
        break;  // one character wider than the line: it stands alone
      }
      for (std::size_t next = char_end(word, cut);
           next <= word.size() && width_of(word.substr(0, next)) <= width_px;
           next = char_end(word, cut)) {
        cut = next;
      }
      // A path breaks after a folder's '/' rather than inside a name ("….js" over "on").
      if (const std::size_t slash = word.substr(0, cut).rfind('/');
          slash != std::string_view::npos && slash > 0 && cut < word.size()) {
        cut = slash + 1;
      }
      out += std::string(word.substr(0, cut)) + "\n";
      word.remove_prefix(cut);
    }
    line = word;
  };
  bool started = false;  // a line may begin with spaces: its empty first words are kept
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t end = std::min(text.find_first_of(" \n", at), text.size());
    const std::string_view word = text.substr(at, end - at);
    if (!started) {
      start_line(word);
      started = true;
    } else if (const std::string longer = line + " " + std::string(word);
               !word.empty() && width_of(longer) > width_px) {
      out += line + "\n";
      start_line(word);
    } else {
      line = longer;
    }
    if (end < text.size() && text[end] == '\n') {
      out += line + "\n";
      line.clear();
      started = false;
    }
    at = end + 1;
  }
  return out + line;
}

void wrapped_text(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  const std::string text = detail::vprintf_string(format, args);
  va_end(args);
  ImGui::TextUnformatted(wrap_at_spaces(text, ImGui::GetContentRegionAvail().x).c_str());
}

namespace {

// The words an equation breaks before, the stronger first.
constexpr std::string_view kRelations[] = {"=", "->", "→", "vs", "≈", "<", ">", "≤", "≥"};
constexpr std::string_view kArithmetic[] = {"×", "/", "+", "-", "−", "·"};

// `text` as pieces that each start at an operator of `operators` (the first piece at the start),
// split at the space before the operator.
std::vector<std::string_view> split_before(std::string_view text,
                                           std::span<const std::string_view> operators) {
  std::vector<std::string_view> pieces;
  std::size_t piece_start = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t space = text.find(' ', at);
    if (space == std::string_view::npos) {
      break;
    }
    std::size_t word_start = space;
    while (word_start < text.size() && text[word_start] == ' ') {
      ++word_start;
    }
    const std::size_t word_end = std::min(text.find(' ', word_start), text.size());
    const std::string_view word = text.substr(word_start, word_end - word_start);
    const bool before_operator =
        std::find(operators.begin(), operators.end(), word) != operators.end();
    // Not at a line's own leading spaces ("  = value"): those stay with their operator.
    if (before_operator && text.find_first_not_of(' ', piece_start) < space) {
      pieces.push_back(text.substr(piece_start, space - piece_start));
      piece_start = space;
    }
    at = word_start;
  }
  pieces.push_back(text.substr(piece_start));
  return pieces;
}

// Lines of `text` at most `width_px` wide, continuation lines starting with `indent`; `level` 0
// breaks at relations, 1 at arithmetic, 2 at any space.
void wrap_equation_lines(std::string_view text, float width_px, std::string_view indent, int level,
                         std::vector<std::string>& lines) {
  // A line after the first: the indent, then the text without its own leading spaces.
  const auto shown = [&](std::string_view line) {
    if (lines.empty()) {
      return std::string(line);
    }
    line.remove_prefix(std::min(line.find_first_not_of(' '), line.size()));
    return std::string(indent) + std::string(line);
  };
  const auto fits = [&](std::string_view line) {
    const std::string s = shown(line);
    return ImGui::CalcTextSize(s.c_str()).x <= width_px;
  };
  if (level < 2 && fits(text)) {
    lines.push_back(shown(text));
    return;
  }
  if (level >= 2) {
    // Any space, as wrap_at_spaces breaks, with room for the indent on every line.
    const std::string first = shown(text);
    const std::string_view rest =
        lines.empty() ? text : std::string_view(first).substr(indent.size());
    const std::string wrapped =
        wrap_at_spaces(rest, width_px - ImGui::CalcTextSize(std::string(indent).c_str()).x);
    for (std::size_t start = 0; start <= wrapped.size();) {
      const std::size_t end = std::min(wrapped.find('\n', start), wrapped.size());
      lines.push_back(shown(std::string_view(wrapped).substr(start, end - start)));
      start = end + 1;
    }
    return;
  }
  const std::vector<std::string_view> pieces =
      split_before(text, level == 0 ? std::span<const std::string_view>(kRelations)
                                    : std::span<const std::string_view>(kArithmetic));
  // Pieces [first, end) as one line of the original text.
  const auto joined = [&](std::size_t first, std::size_t end) {
    const char* from = pieces[first].data();
    const char* to = pieces[end - 1].data() + pieces[end - 1].size();
    return std::string_view(from, static_cast<std::size_t>(to - from));
  };
  // Greedy: as many pieces on a line as fit; a piece too wide alone breaks at the next level.
  for (std::size_t first = 0; first < pieces.size();) {
    std::size_t end = first + 1;
    while (end < pieces.size() && fits(joined(first, end + 1))) {
      ++end;
    }
    if (fits(joined(first, end))) {
      lines.push_back(shown(joined(first, end)));
    } else {
      wrap_equation_lines(joined(first, end), width_px, indent, level + 1, lines);
    }
    first = end;
  }
}

}  // namespace

std::string wrap_equation(std::string_view text, float width_px, std::string_view indent) {
  std::vector<std::string> lines;
  wrap_equation_lines(text, std::max(width_px, 1.0f), indent, 0, lines);
  std::string out;
  for (const std::string& line : lines) {
    out += (out.empty() ? "" : "\n") + line;
  }
  return out;
}

void equation_text(const ImVec4* colour, const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  const std::string text = detail::vprintf_string(format, args);
  va_end(args);
  const std::string wrapped = wrap_equation(text, ImGui::GetContentRegionAvail().x);
  if (colour != nullptr) {
    ImGui::PushStyleColor(ImGuiCol_Text, *colour);
  }
  ImGui::TextUnformatted(wrapped.c_str());
  if (colour != nullptr) {
    ImGui::PopStyleColor();
  }
}

namespace {

// The marker itself: its text for a mouse, a button around it for a finger.
float marker_item_width() {
  const float text = ImGui::CalcTextSize("(?)").x;
  return finger_pointer() ? text + 2.0f * ImGui::GetStyle().FramePadding.x : text;
}

}  // namespace

float help_marker_width() {
  // For a mouse as it always was: a space and the text.
  return finger_pointer() ? ImGui::GetStyle().ItemSpacing.x + marker_item_width()
                          : ImGui::CalcTextSize(" (?)").x;
}

void help_marker(const char* text) {
  same_line_if_fits(marker_item_width());  // under its item rather than cut in half
  if (finger_pointer()) {
    // A target a finger finds; one id per text, since many share the label.
    ImGui::PushID(text);
    ImGui::Button("(?)");
    ImGui::PopID();
    note_target("(?)");
  } else {
    ImGui::TextDisabled("(?)");
  }
  if (ImGui::IsItemHovered()) {
    wrapped_tooltip("%s", readable(text).c_str());
  }
}

void wrapped_tooltip(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  const std::string text = detail::vprintf_string(format, args);
  va_end(args);
  // Thirty font sizes, or the window's width less a margin when that is narrower (a large text
  // size in a small window).
  const float width = std::min(ImGui::GetFontSize() * 30.0f,
                               ImGui::GetIO().DisplaySize.x - 4.0f * ImGui::GetFontSize());
  ImGui::BeginTooltip();
  ImGui::TextUnformatted(wrap_at_spaces(text, width).c_str());
  ImGui::EndTooltip();
}

}  // namespace foldlab::gui
