// Text a frame drew that a reader cannot read whole: cut at the edge of a widget or a panel, or
// wrapped inside a word ("wrin" / "kled", "1." / "25"). Found once for every panel, menu and
// dialog from the glyph quads of ImGui's draw data (drawn_glyphs.hpp), so that no panel checks
// its own labels and a label added tomorrow is checked too.
#pragma once

#include <string>
#include <vector>

#include <imgui.h>

namespace foldlab::gui {

struct ClippedText {
  std::string panel;  // the panel's key ("parameters"), "menu_bar", or ImGui's window name
  std::string text;   // the line as drawn (its visible part); a wrap shows both lines
  std::string how;    // "cut" or "wrapped inside a word"
};

// Measured on the last frame's draw data (between ImGui::Render and the next NewFrame). Text cut
// at the left or right of its clip rectangle counts; text cut at the top or bottom does not:
// that is a panel's scrolling, and scrolling shows it. A label drawn wholly outside its clip
// rectangle leaves no glyph to find and is not counted. A wrap counts as inside a word when a
// number is broken after its point or comma, or when the line before the break is one word that
// reaches the window's wrapping edge (ImGui cuts a word wider than the line anywhere).
std::vector<ClippedText> clipped_text(const ImDrawData& data, const ImFont& font);

}  // namespace foldlab::gui
