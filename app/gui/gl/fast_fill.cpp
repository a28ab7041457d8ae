#include "app/gui/gl/fast_fill.hpp"

#include "app/gui/gl/gl_api.hpp"

#include <cmath>
#include <deque>

#include <imgui_internal.h>

namespace foldlab::gui {
namespace {

struct Fill {
  ImVec2 min, max;
  ImVec4 colour;
  unsigned framebuffer;  // 0: a colour fill; else blit from this framebuffer
  FrameSize source;
};

// Stable addresses for the callbacks' data until the frame is drawn.
std::deque<Fill>& fills() {
  static std::deque<Fill> storage;
  return storage;
}

// ImGui's clip rectangles are in display coordinates with y down; GL's scissor has y up.
void scissor_to(const ImDrawList* list, const ImDrawCmd* cmd, ImVec2 min, ImVec2 max) {
  (void)list;
  const ImDrawData* data = ImGui::GetDrawData();
  const ImVec2 offset = data->DisplayPos;
  const ImVec2 scale = data->FramebufferScale;
  const float lo_x = std::max(min.x, cmd->ClipRect.x) - offset.x;
  const float lo_y = std::max(min.y, cmd->ClipRect.y) - offset.y;
  const float hi_x = std::min(max.x, cmd->ClipRect.z) - offset.x;
  const float hi_y = std::min(max.y, cmd->ClipRect.w) - offset.y;
  const int framebuffer_height = static_cast<int>(data->DisplaySize.y * scale.y);
  const int x = static_cast<int>(std::floor(lo_x * scale.x));
  const int y = framebuffer_height - static_cast<int>(std::ceil(hi_y * scale.y));
  const int w = std::max(0, static_cast<int>(std::ceil(hi_x * scale.x)) - x);
  const int h = std::max(0, static_cast<int>(std::ceil(hi_y * scale.y)) -
                                static_cast<int>(std::floor(lo_y * scale.y)));
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, w, h);
}

void run_fill(const ImDrawList* list, const ImDrawCmd* cmd) {
  const Fill& fill = *static_cast<const Fill*>(cmd->UserCallbackData);
  scissor_to(list, cmd, fill.min, fill.max);
  if (fill.framebuffer == 0) {
    glClearColor(fill.colour.x, fill.colour.y, fill.colour.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  GLint draw_framebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_framebuffer);
  const ImDrawData* data = ImGui::GetDrawData();
  const float height = data->DisplaySize.y * data->FramebufferScale.y;
  const ImVec2 scale = data->FramebufferScale;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fill.framebuffer);
  glBlitFramebuffer(
      0, 0, fill.source.width, fill.source.height, static_cast<GLint>(fill.min.x * scale.x),
      static_cast<GLint>(height - fill.max.y * scale.y), static_cast<GLint>(fill.max.x * scale.x),
      static_cast<GLint>(height - fill.min.y * scale.y), GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(draw_framebuffer));
}

}  // namespace

void begin_fast_fill_frame() {
  fills().clear();
}

void add_opaque_fill(ImDrawList* draw_list, ImVec2 min, ImVec2 max, ImVec4 colour) {
  fills().push_back(Fill{min, max, colour, 0, {}});
  draw_list->AddCallback(run_fill, &fills().back());
}

void add_framebuffer_blit(ImDrawList* draw_list, unsigned framebuffer, FrameSize source, ImVec2 min,
                          ImVec2 max) {
  fills().push_back(Fill{min, max, {}, framebuffer, source});
  draw_list->AddCallback(run_fill, &fills().back());
}

void fill_current_window_background() {
  ImGuiWindow* window = ImGui::GetCurrentWindow();
  const ImGuiStyle& style = ImGui::GetStyle();
  ImVec4 colour = style.Colors[ImGuiCol_WindowBg];
  colour.w = 1.0f;
  const float border = style.WindowBorderSize;
  const ImVec2 min(window->Pos.x + border, window->Pos.y + window->TitleBarHeight() + border);
  const ImVec2 max(window->Pos.x + window->Size.x - border,
                   window->Pos.y + window->Size.y - border);
  // The fill must come before anything the window draws itself: put it at the front of the list.
  ImDrawList* list = window->DrawList;
  add_opaque_fill(list, min, max, colour);
}

}  // namespace foldlab::gui
