#include "app/gui/gl/gl_api.hpp"
// The GL header first: GLFW must not pull in one of its own.
#include <GLFW/glfw3.h>

#include <string>
#include <vector>

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
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, on_key);
  }
  void shutdown_imgui_platform() override { ImGui_ImplGlfw_Shutdown(); }
  bool open() const override { return !glfwWindowShouldClose(window_); }
  void keep_open() override { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

  void new_frame() override {
    release_keys_seen_down();
    glfwPollEvents();
    ImGui_ImplGlfw_NewFrame();
    // The frame about to start sees these keys down; their releases go out before the next
    // batch of events.
    releases_due_ = std::move(deferred_releases_);
    deferred_releases_.clear();
    pressed_since_frame_ = false;
  }
  void new_frame_without_input() override { ImGui_ImplGlfw_NewFrame(); }
  void wait_events(double timeout_s) override {
    release_keys_seen_down();
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
    int key;
    int scancode;
    int mods;
  };

  void release_keys_seen_down() {
    for (const KeyEvent& release : releases_due_) {
      ImGui_ImplGlfw_KeyCallback(window_, release.key, release.scancode, GLFW_RELEASE,
                                 release.mods);
    }
    releases_due_.clear();
  }

  // ImGui 1.86 keeps only whether a key is down when a frame starts, so a chord pressed and
  // released between two frames (a quick tap while the loop sleeps, or xdotool's) would never be
  // seen: after a press, releases wait for the next frame, in order. A modifier held from an
  // earlier frame counts too (Ctrl down, then = down, Ctrl up, = up in one batch).
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
    auto* self = static_cast<WindowSurface*>(glfwGetWindowUserPointer(window));
    if (action == GLFW_PRESS) {
      self->pressed_since_frame_ = true;
    } else if (action == GLFW_RELEASE && self->pressed_since_frame_) {
      self->deferred_releases_.push_back({key, scancode, mods});
      return;
    }
    ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
  }

  GLFWwindow* window_ = nullptr;
  bool pressed_since_frame_ = false;
  std::vector<KeyEvent> deferred_releases_;
  std::vector<KeyEvent> releases_due_;
};

}  // namespace

std::unique_ptr<Surface> make_window_surface(const SurfaceOptions& options) {
  return std::make_unique<WindowSurface>(options);
}

}  // namespace foldlab::gui
