// When the window may rest: after an input event ImGui needs a few frames to settle (hover, focus,
// a window's new size, a new font's layout, a child window's scrollbar, which it knows only from
// the frame before). The frame loop draws those frames and then sleeps until the next event.
#pragma once

#include <imgui.h>

namespace foldlab::gui {

// Whether the frame just built saw input: the mouse moved, a button or key went down or up, the
// wheel turned or text was typed. Call between ImGui::NewFrame and the next one.
inline bool frame_saw_input(const ImGuiIO& io) {
  if (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f ||
      io.MouseWheelH != 0.0f || !io.InputQueueCharacters.empty()) {
    return true;
  }
  for (int b = 0; b < IM_ARRAYSIZE(io.MouseDown); ++b) {
    if (io.MouseClicked[b] || io.MouseReleased[b]) {
      return true;
    }
  }
  for (int k = 0; k < IM_ARRAYSIZE(io.KeysDown); ++k) {
    const bool pressed = io.KeysDownDuration[k] == 0.0f;
    const bool released = io.KeysDownDurationPrev[k] >= 0.0f && io.KeysDownDuration[k] < 0.0f;
    if (pressed || released) {
      return true;
    }
  }
  return false;
}

// The frames after input. Input that arrives while those frames are being drawn starts them
// again: a key pressed in the last of them (Ctrl+0 asking for a smaller font, which the next frame
// builds) or a window opened there (its scrollbar comes a frame later) would otherwise leave the
// screen showing a frame the next click does not land on.
class FramesAfterInput {
 public:
  static constexpr int kFrames = 3;
  // Woken by input (true) or by a timeout (false) after a rest: all the frames, or one.
  void woken(bool by_input) { drawn_ = by_input ? 0 : kFrames - 1; }
  // After each frame: whether it saw input (frame_saw_input).
  void frame_drawn(bool saw_input) { drawn_ = saw_input ? 0 : drawn_ + 1; }
  bool settled() const { return drawn_ >= kFrames; }

 private:
  int drawn_ = 0;
};

}  // namespace foldlab::gui
