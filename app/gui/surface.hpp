// Where a frame is drawn: a GL 3.3 core context plus a framebuffer. Two backends share one frame
// loop, in the manner of Polyscope's render engines: a GLFW window (the explorer, and scripted
// window runs under Xvfb) and an EGL surfaceless context with an off-screen framebuffer (headless
// rendering with no display and no X server).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "app/common/inputs.hpp"
#include "app/gui/renderer.hpp"

namespace foldlab::gui {

class SurfaceError : public app::EnvironmentError {
 public:
  using app::EnvironmentError::EnvironmentError;
};

class Surface {
 public:
  virtual ~Surface() = default;
  // Initialises ImGui's platform side for this backend (the renderer side is shared).
  virtual void init_imgui_platform() = 0;
  virtual void shutdown_imgui_platform() = 0;
  // False once the user asked to close the window.
  virtual bool open() const = 0;
  // Undoes a close request (the user chose to stay when asked about unsaved edits).
  virtual void keep_open() {}
  // Polls input and starts ImGui's platform frame: display size, time step, mouse, keys.
  virtual void new_frame() = 0;
  // The same, reading no new input (the events wait for the next new_frame): a frame drawn again
  // at once because the one before changed the layout.
  virtual void new_frame_without_input() { new_frame(); }
  // When each key press (or repeat) the last new_frame() gave ImGui came from the window system:
  // for `gui --report`'s key latency. Empty where no key events arrive (headless).
  virtual std::vector<std::chrono::steady_clock::time_point> key_presses_taken() const {
    return {};
  }
  // Sleeps until an input event arrives or `timeout_s` passes (a window); returns at once
  // headless, where nothing arrives.
  virtual void wait_events(double timeout_s) = 0;
  virtual FrameSize framebuffer_size() const = 0;
  // Asks for a new size (input playback); a window may take a frame or two to follow.
  virtual void resize(FrameSize size) = 0;
  // Makes the frame's own framebuffer current (0 for a window, the off-screen one headless).
  virtual void bind_framebuffer() = 0;
  virtual void present() = 0;
  // Blocks until the frame is on the screen or in the buffer: for timing and screenshots.
  virtual void finish() = 0;
};

// The sizes a window or picture may be given (--size, a played resize; the window's own lower
// limit): below 200 x 150 nothing of a panel can be read, above 8192 GL's textures may not follow.
inline constexpr FrameSize kMinFrameSize{200, 150};
inline constexpr FrameSize kMaxFrameSize{8192, 8192};
// "WxH" within those limits; nullopt otherwise.
std::optional<FrameSize> parse_frame_size(std::string_view text);
// What parse_frame_size() takes, for messages: "WxH with 200 <= W <= 8192, 150 <= H <= 8192".
std::string frame_size_rule();

struct SurfaceOptions {
  int width = 1280;
  int height = 800;
  bool vsync = true;  // window only
};

std::unique_ptr<Surface> make_window_surface(const SurfaceOptions& options);
std::unique_ptr<Surface> make_headless_surface(const SurfaceOptions& options);

// Writes RGBA pixels (top row first) as PNG. Throws SurfaceError naming the path on failure.
void write_png(const char* path, FrameSize size, const std::vector<std::uint8_t>& rgba);
// Keeps the part of RGBA pixels (top row first) `width` x `height` from (x, y), cut to the frame,
// in place; returns its size (a nothing rectangle keeps one pixel, so that a PNG can be written).
FrameSize crop_pixels(std::vector<std::uint8_t>& rgba, FrameSize size, int x, int y, int width,
                      int height);

}  // namespace foldlab::gui
