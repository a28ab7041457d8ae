#include <epoxy/gl.h>
// epoxy first: GLFW must not pull in a GL header of its own.
#include <GLFW/glfw3.h>

#include <string>

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
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(options.vsync ? 1 : 0);
  }

  ~WindowSurface() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }

  void init_imgui_platform() override { ImGui_ImplGlfw_InitForOpenGL(window_, true); }
  void shutdown_imgui_platform() override { ImGui_ImplGlfw_Shutdown(); }
  bool open() const override { return !glfwWindowShouldClose(window_); }
  void keep_open() override { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

  void new_frame() override {
    glfwPollEvents();
    ImGui_ImplGlfw_NewFrame();
  }

  void wait_events(double timeout_s) override { glfwWaitEventsTimeout(timeout_s); }

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
  GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Surface> make_window_surface(const SurfaceOptions& options) {
  return std::make_unique<WindowSurface>(options);
}

}  // namespace foldlab::gui
