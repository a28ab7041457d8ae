#include "app/gui/gl/gl_api.hpp"
// The GL header first: GLFW must not pull in one of its own.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <string>
#include <vector>

#include "app/gui/screen.hpp"
#include "app/gui/surface.hpp"
#include "backends/imgui_impl_glfw.h"

namespace foldlab::gui {
namespace {

// GLFW reports errors through a callback; the latest is kept for the exception's message.
std::string& last_glfw_error() {
  static std::string message = "no GLFW error reported";
  return message;
}

void report_glfw_error(int code, const char* description) {
  last_glfw_error() = "GLFW error " + std::to_string(code) + ": " + description;
}

class WindowSurface final : public Surface {
 public:
  explicit WindowSurface(const SurfaceOptions& options) {
    glfwSetErrorCallback(report_glfw_error);
    if (!glfwInit()) {
      throw SurfaceError("cannot open a window (" + last_glfw_error() +
                         "); is there a display? `foldlab render` draws without one");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(options.width, options.height, "FoldLab", nullptr, nullptr);
    if (window_ == nullptr) {
      glfwTerminate();
      throw SurfaceError("cannot create an OpenGL 3.3 core window (" + last_glfw_error() + ")");
    }
    // A window manager keeps the window at least this big; without one (Xvfb, xdotool) it may
    // still become smaller, down to one pixel, and every panel copes with that too.
    glfwSetWindowSizeLimits(window_, kMinFrameSize.width, kMinFrameSize.height, GLFW_DONT_CARE,
                            GLFW_DONT_CARE);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(options.vsync ? 1 : 0);
  }

  ~WindowSurface() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }

  void init_imgui_platform() override {
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    screen_shares_clipboard();
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, on_key);
    glfwSetMouseButtonCallback(window_, on_mouse_button);
  }
  void shutdown_imgui_platform() override { ImGui_ImplGlfw_Shutdown(); }
  bool open() const override { return !glfwWindowShouldClose(window_); }
  void keep_open() override { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

  void new_frame() override {
    presses_taken_.clear();
    glfwPollEvents();
    feed_keys();
    ImGui_ImplGlfw_NewFrame();
  }
  void new_frame_without_input() override {
    presses_taken_.clear();
    ImGui_ImplGlfw_NewFrame();
  }
  std::vector<std::chrono::steady_clock::time_point> key_presses_taken() const override {
    return presses_taken_;
  }
  void wait_events(double timeout_s) override {
    if (!keys_.empty()) {
      return;  // keys still to feed: the next frame is due now
    }
    glfwWaitEventsTimeout(timeout_s);
  }

  FrameSize framebuffer_size() const override {
    FrameSize size;
    glfwGetFramebufferSize(window_, &size.width, &size.height);
    return size;
  }

  void bind_framebuffer() override { glBindFramebuffer(GL_FRAMEBUFFER, 0); }
  void resize(FrameSize size) override { glfwSetWindowSize(window_, size.width, size.height); }
  void present() override { glfwSwapBuffers(window_); }
  void finish() override { glFinish(); }

 private:
  struct KeyEvent {
    int key;  // or the mouse button
    int scancode;
    int action;
    int mods;
    std::chrono::steady_clock::time_point at;  // when the callback had it
    bool mouse_button = false;
  };

  // ImGui 1.86 keeps only whether a key is down when a frame starts, so a key pressed and
  // released between two frames (a quick tap while the loop sleeps, or xdotool's) would never be
  // seen, and three quick Ctrl+Z would be one. The keys wait in order and each frame takes them
  // until one would change a key a second time, or would release a key after a press: every
  // press is seen by a frame of its own with the modifiers held around it (xdotool's Ctrl+S is
  // Ctrl down, S down, Ctrl up, S up). A mouse button waits in the same line: a click that
  // came after a key is read by the frame after the key's, since the key may close the window
  // under the pointer (Escape on the introduction) and the click is meant for what shows then.
  void feed_keys() {
    std::vector<int> changed;
    bool pressed = false;
    bool clicked = false;
    while (!keys_.empty()) {
      const KeyEvent& e = keys_.front();
      if (e.mouse_button) {
        if (pressed) {
          break;
        }
        ImGui_ImplGlfw_MouseButtonCallback(window_, e.key, e.action, e.mods);
        clicked = true;
        keys_.pop_front();
        continue;
      }
      // A key after a click waits for the next frame, so that the click is read with the keys
      // held around it (the page's long press is Ctrl down, click, Ctrl up, in one go).
      if (clicked || std::find(changed.begin(), changed.end(), e.key) != changed.end() ||
          (pressed && e.action == GLFW_RELEASE)) {
        break;
      }
      changed.push_back(e.key);
      pressed |= e.action == GLFW_PRESS;
      ImGui_ImplGlfw_KeyCallback(window_, e.key, e.scancode, e.action, e.mods);
      if (e.action != GLFW_RELEASE) {
        presses_taken_.push_back(e.at);
      }
      keys_.pop_front();
    }
  }

  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
    auto* self = static_cast<WindowSurface*>(glfwGetWindowUserPointer(window));
    self->keys_.push_back({key, scancode, action, mods, std::chrono::steady_clock::now()});
  }

  static void on_mouse_button(GLFWwindow* window, int button, int action, int mods) {
    auto* self = static_cast<WindowSurface*>(glfwGetWindowUserPointer(window));
    self->keys_.push_back({button, 0, action, mods, std::chrono::steady_clock::now(), true});
  }

  GLFWwindow* window_ = nullptr;
  std::deque<KeyEvent> keys_;  // keys and mouse buttons, in the order they came
  std::vector<std::chrono::steady_clock::time_point> presses_taken_;
};

}  // namespace

std::unique_ptr<Surface> make_window_surface(const SurfaceOptions& options) {
  return std::make_unique<WindowSurface>(options);
}

}  // namespace foldlab::gui
