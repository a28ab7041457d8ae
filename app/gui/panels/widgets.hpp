// Small pieces every panel uses: the colours of messages, the first-use layout, a panel window
// with its opaque background, section titles and help markers.
#pragma once

#include <string>
#include <string_view>

#include <imgui.h>

#include "app/gui/appearance.hpp"
#include "app/gui/document.hpp"
#include "app/gui/renderer.hpp"

namespace foldlab::gui {

// Information reads dim, success green, a warning amber, an error red.
ImVec4 message_colour(MessageKind kind);

// A line at the top of a view while an input is refused: what it shows is the last valid state.
void stale_mark(const Document& document);

// A width or height that scales with the UI scale: `ems` times the current font size.
float ems(float ems);

// A panel's place on the display, in whole pixels (ImGui floors what it is given).
struct PanelRect {
  ImVec2 pos{0, 0};
  ImVec2 size{0, 0};
};
// The tiled panels' places, in the order of TiledLayout::rects (each panel names its own with
// Panel::tile()).
enum class Tile { parameters, presets, fold_plot, cloth, results, analysis };
inline constexpr int kTileCount = 6;

// Where the user dragged the tiles' shared edges, each as a fraction of what it divides; a
// negative fraction leaves that edge where the automatic layout puts it.
struct LayoutSplits {
  float left_column = -1.0f;  // the parameters column's width, of the window's width
  float parameters = -1.0f;   // the parameters panel's height, of the height below the menu bar
  float views = -1.0f;        // the views' (fold plot and cloth) height, of the same
  float fold_plot = -1.0f;    // the fold plot's width, of the width right of the column
  float results = -1.0f;      // the results' width, of the width right of the column
  bool any() const {
    return left_column >= 0.0f || parameters >= 0.0f || views >= 0.0f || fold_plot >= 0.0f ||
           results >= 0.0f;
  }
};

// The automatic layout: the display below `top_px` (the menu bar) tiled edge to edge with no gap.
// Parameters and presets on the left, the 2D plot over the results in the middle and the 3D view
// over the analysis on the right. The column is wide enough for a slider with its label (in
// font sizes, so that it follows the UI scale) but never more than a third of the width, and the
// views' row grows with the font by the height of their toolbars: as the UI scale grows the plots
// keep their share and the text panels wrap or scroll. `splits` moves the edges the user dragged;
// every panel keeps at least a few font sizes either way.
struct TiledLayout {
  PanelRect rects[kTileCount];
  const PanelRect& operator[](Tile tile) const { return rects[static_cast<int>(tile)]; }
};
TiledLayout tiled_layout(ImVec2 display, float top_px, float font_px,
                         const LayoutSplits& splits = {});

// A tile's edge that a user dragged to `to_px` (screen coordinates): the split it moves, as a
// fraction of what it divides. False when that edge is the window's border, which stays.
enum class Edge { left, right, top, bottom };
bool drag_split(Tile tile, Edge edge, float to_px, ImVec2 display, float top_px,
                const TiledLayout& layout, LayoutSplits& splits);

// ImGui::Begin for the tiled panels, with the background filled by the renderer. Call
// ImGui::End() whatever it returns.
bool begin_panel(const char* title, Renderer& renderer);

// ImGui::SameLine() when an item `width` pixels wide still fits on the current line; otherwise
// the item starts a new line, so that a narrow panel wraps a row of controls instead of cutting
// it off.
void same_line_if_fits(float width);
// The width of a checkbox, button or small button with this label.
float checkbox_width(const char* label);
float button_width(const char* label);
// The width of a `item_width` wide slider, combo or field followed by its label (none for "##").
float labelled_width(float item_width, const char* label);

// A dim hint after the last item: on its line when it fits there, else on a line of its own, else
// as a "(?)" that shows it when hovered.
void hint_after(const char* text);

// ImGui 1.86 has no SeparatorText.
void section(const char* title);

// `utf8` as the current font can draw it: each of the paper's symbols the font lacks (ν, σ, λ, π,
// Σ, ∫, −, θ, ≤, ≥, …) spelt in ASCII ("nu", "sigma", "-", "<="), so that ImGui's built-in font,
// which has no Greek, shows "nu" rather than "?". Everything else is kept.
std::string readable(std::string_view utf8);

// `text` with line breaks put in at spaces only, each line at most `width_px` wide (a word
// wider than that stays whole on its own line). ImGui's own wrapping also breaks after a '.'
// or ',', which cuts a number in two ("p = 0." / "5216").
std::string wrap_at_spaces(std::string_view text, float width_px);
// ImGui::TextWrapped that wraps at spaces only (see wrap_at_spaces), with a checked format.
[[gnu::format(printf, 1, 2)]] void wrapped_text(const char* format, ...);

// An equation with today's numbers as lines at most `width_px` wide: broken before a relation
// ("=", "->", "vs") where it can be, else before an arithmetic operator ("×", "/", "+", "-"),
// else at a space (wrap_at_spaces), so that no number is cut. A line after a break is indented by
// `indent`.
std::string wrap_equation(std::string_view text, float width_px, std::string_view indent = "    ");
// ImGui::TextUnformatted of wrap_equation at the width left on the line, in `colour` when given.
[[gnu::format(printf, 2, 3)]] void equation_text(const ImVec4* colour, const char* format, ...);

// A "(?)" after the last item that shows `text` when hovered.
void help_marker(const char* text);

}  // namespace foldlab::gui
