// Small pieces every panel uses: the colours of messages, the first-use layout, a panel window
// with its opaque background, section titles and help markers.
#pragma once

#include <imgui.h>

#include "app/gui/document.hpp"
#include "app/gui/renderer.hpp"

namespace foldlab::gui {

inline const ImVec4 kErrorText(1.0f, 0.45f, 0.40f, 1.0f);
inline const ImVec4 kOkText(0.55f, 0.85f, 0.55f, 1.0f);
inline const ImVec4 kNoteText(1.0f, 0.78f, 0.35f, 1.0f);
inline const ImVec4 kDimText(0.65f, 0.65f, 0.70f, 1.0f);

// Information reads dim, success green, a warning amber, an error red.
ImVec4 message_colour(MessageKind kind);

// A line at the top of a view while an input is refused: what it shows is the last valid state.
void stale_mark(const Document& document);

// First-use layout, in fractions of the display: parameters and presets on the left, the two
// views on top, numbers below.
void place_window(float x, float y, float w, float h);

// ImGui::Begin for the tiled panels, with the background filled by the renderer. Call
// ImGui::End() whatever it returns.
bool begin_panel(const char* title, Renderer& renderer);

// ImGui 1.86 has no SeparatorText.
void section(const char* title);

// A "(?)" after the last item that shows `text` when hovered.
void help_marker(const char* text);

}  // namespace foldlab::gui
