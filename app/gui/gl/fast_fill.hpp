// llvmpipe, the GL this program mostly meets, pays for every blended, textured pixel: an opaque
// window background drawn the ImGui way costs as much as the rest of the frame. These draw-list
// callbacks fill rectangles with a scissored glClear and copy the 3D view with glBlitFramebuffer
// instead, which llvmpipe does at memory speed. They run in the draw lists' order, so windows
// still cover each other correctly.
#pragma once

#include <imgui.h>

#include "app/gui/renderer.hpp"

namespace foldlab::gui {

// Call once per frame before any window is built: releases the previous frame's callback data.
void begin_fast_fill_frame();

// Fills [min, max) (screen pixels) with an opaque colour, at this point of the draw list.
void add_opaque_fill(ImDrawList* draw_list, ImVec2 min, ImVec2 max, ImVec4 colour);

// Copies a framebuffer's colour (size `source`) into [min, max), at this point of the draw list.
// The first row of the framebuffer lands at the bottom, as GL has it.
void add_framebuffer_blit(ImDrawList* draw_list, unsigned framebuffer, FrameSize source, ImVec2 min,
                          ImVec2 max);

// Fills the content area of the current window (below its title bar, inside its border) with the
// style's window background colour. Use with a transparent ImGuiCol_WindowBg.
void fill_current_window_background();

}  // namespace foldlab::gui
