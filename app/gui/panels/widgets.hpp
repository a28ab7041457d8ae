// Small pieces every panel uses: the colours of messages, the first-use layout, a panel window
// with its opaque background, section titles and help markers.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <imgui.h>

#include "app/gui/appearance.hpp"
#include "app/gui/document.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/tiles.hpp"

namespace foldlab::gui {

// Information reads dim, success green, a warning amber, an error red.
ImVec4 message_colour(MessageKind kind);

// A line at the top of a view while an input is refused: what it shows is the last valid state.
void stale_mark(const Document& document);

// A width or height that scales with the UI scale: `ems` times the current font size.
float ems(float ems);

// ImGui::Begin for the tiled panels, with the background filled by the renderer. Call
// ImGui::End() whatever it returns.
// `open`: a window the user may close (its title bar's cross clears it).
bool begin_panel(const char* title, Renderer& renderer, bool* open = nullptr);
// The next begin_panel's window has no title bar: a view presented to a room, whose title and
// buttons stand in the menu bar, so that their row is the picture's. Like ImGui's SetNextWindow*,
// it holds for one window.
void next_panel_without_title_bar();

// ImGui::SameLine() when an item `width` pixels wide still fits on the current line; otherwise
// the item starts a new line, so that a narrow panel wraps a row of controls instead of cutting
// it off.
void same_line_if_fits(float width);
// The width of a checkbox, button or small button with this label.
float checkbox_width(const char* label);
float button_width(const char* label);
// The width of a `item_width` wide slider, combo or field followed by its label (none for "##").
float labelled_width(float item_width, const char* label);

// Runs `slider` (one ImGui slider call, drawn at the cursor `CalcItemWidth()` wide) with ImGui's
// handle hidden, then marks where the value lies on the scale (`fraction` of the way, read after
// the call) by two notches in the frame's top and bottom padding: the handle no longer crosses
// the value's text ("24|00 mm"), which stays whole wherever the value is. Returns the slider's.
bool notched_slider(const std::function<bool()>& slider, const std::function<double()>& fraction);
// ImGui's SliderInt, kept within [lo, hi], notched.
bool notched_slider_int(const char* label, int& value, int lo, int hi, const char* format);

// ImGui's small button (a line of text tall, no padding above or below it), or for a finger
// (ImGuiConfigFlags_IsTouchScreen) a whole button, as tall as a target (touch_style).
bool small_button(const char* label);

// A dim hint after the last item: on its line when it fits there, else on a line of its own, else
// as a "(?)" that shows it when hovered.
void hint_after(const char* text);
// A help marker after the last item, then hint_after(hint); when the hint would only fit behind
// a marker of its own, the one marker says both.
void help_marker_and_hint(const char* help, const char* hint);

// ImGui 1.86 has no SeparatorText.
void section(const char* title);

// `utf8` as the current font can draw it: each of the paper's symbols the font lacks (ν, σ, λ, π,
// Σ, ∫, −, θ, ≤, ≥, …) spelt in ASCII ("nu", "sigma", "-", "<="), so that ImGui's built-in font,
// which has no Greek, shows "nu" rather than "?". Everything else is kept.
std::string readable(std::string_view utf8);

// `text` with each space a no-break space (U+00A0), which ImGui's wrapping does not break at:
// "z_max = 48.96 (30.5–78.6) mm" moves to the next line whole, not its "mm" alone.
std::string unbroken(std::string_view text);

// `text` with line breaks put in at spaces only, each line at most `width_px` wide (a word
// wider than that stays whole on its own line). ImGui's own wrapping also breaks after a '.'
// or ',', which cuts a number in two ("p = 0." / "5216").
std::string wrap_at_spaces(std::string_view text, float width_px);
// ImGui::SetTooltip with its text wrapped at spaces to a readable width that fits the window.
[[gnu::format(printf, 1, 2)]] void wrapped_tooltip(const char* format, ...);
// ImGui::TextWrapped that wraps at spaces only (see wrap_at_spaces), with a checked format.
[[gnu::format(printf, 1, 2)]] void wrapped_text(const char* format, ...);

// An equation with today's numbers as lines at most `width_px` wide: broken before a relation
// ("=", "->", "vs") where it can be, else before an arithmetic operator ("×", "/", "+", "-"),
// else at a space (wrap_at_spaces), so that no number is cut. A line after a break is indented by
// `indent`.
std::string wrap_equation(std::string_view text, float width_px, std::string_view indent = "    ");
// ImGui::TextUnformatted of wrap_equation at the width left on the line, in `colour` when given.
[[gnu::format(printf, 2, 3)]] void equation_text(const ImVec4* colour, const char* format, ...);

// A "(?)" after the last item that shows `text` when hovered (for a finger: tapped, and as tall
// as a target, a button of the frames' height).
void help_marker(const char* text);
// The room a help marker takes after its item: the spacing before it and its width.
float help_marker_width();

// Whether the explorer is worked with fingers now (ImGuiConfigFlags_IsTouchScreen).
bool finger_pointer();
// For a finger, the rows of a list, combo or menu stand a target's height apart: ImGui extends a
// selectable's and a menu item's box over the spacing between rows, so that a row's target is the
// text and the spacing tall. Call end_touch_rows() after the rows. Nothing for a mouse.
void begin_touch_rows();
void end_touch_rows();
// ImGui::BeginCombo whose open list has rows a target tall for a finger; end_combo() closes it.
bool begin_combo(const char* label, const char* preview, ImGuiComboFlags flags = 0);
void end_combo();
// ImGui::Combo over "a\0b\0c\0" items, through begin_combo.
bool combo(const char* label, int* current, const char* items_zero_separated);
// The width a combo needs to show the widest of its choices whole beside its arrow, a frame's
// height square (a target wide for a finger): from the text, never a fixed width.
float combo_width(const char* items_zero_separated);
float combo_width(std::span<const std::string> choices);

// The smallest target a finger was given in the frame drawn last (read between frames) (a frame's
// height for every slider, button, checkbox and combo; the rows of lists, combos and menus; the
// help markers; a tile edge's grip across the edge): its height in the screen's pixels and what it
// was. note_target() counts the last item.
struct SmallestTarget {
  float height_px = 0.0f;
  std::string what;
};
// Called as a frame begins (Explorer::frame).
void begin_target_tally();
void note_target(std::string_view what);
void note_target_height(float height_px, std::string_view what);
const SmallestTarget& smallest_target();

}  // namespace foldlab::gui
