#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <string>

#include <imgui.h>

#include "app/gui/gl/gl_handles.hpp"
#include "app/gui/surface.hpp"

namespace foldlab::gui {
namespace {

std::string egl_error_text() {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  return std::string("EGL error ") + code;
}

// Mesa's surfaceless display with a desktop OpenGL 3.3 core context made current; released in
// reverse, also when making it fails part-way.
class EglContext {
 public:
  EglContext() {
    try {
      make();
    } catch (...) {
      release();
      throw;
    }
  }
  ~EglContext() { release(); }
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

 private:
  void make() {
    display_ =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0;
    EGLint minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
      throw SurfaceError("cannot open Mesa's surfaceless EGL display (" + egl_error_text() +
                         "); is libegl-mesa0 installed?");
    }
    initialized_ = true;
    if (!eglBindAPI(EGL_OPENGL_API)) {
      throw SurfaceError("EGL has no desktop OpenGL (" + egl_error_text() + ")");
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT ||
        !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw SurfaceError("cannot create a surfaceless OpenGL 3.3 core context (" +
                         egl_error_text() + ")");
    }
  }
  void release() {
    if (context_ != EGL_NO_CONTEXT) {
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display_, context_);
      context_ = EGL_NO_CONTEXT;
    }
    if (initialized_) {
      eglTerminate(display_);
      initialized_ = false;
    }
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  bool initialized_ = false;
  EGLContext context_ = EGL_NO_CONTEXT;
};

// Mesa's surfaceless platform: a GL context with no window system at all, drawing into an
// off-screen framebuffer. Input is absent, and the time step is a fixed 1/60 s so that frames,
// and therefore pictures, are reproducible.
class HeadlessSurface final : public Surface {
 public:
  explicit HeadlessSurface(const SurfaceOptions& options) : size_{options.width, options.height} {
    target_ = make_offscreen_target(size_.width, size_.height);
    if (!target_.complete) {
      throw SurfaceError("the off-screen framebuffer is incomplete");
    }
  }

  void init_imgui_platform() override { ImGui::GetIO().BackendPlatformName = "foldlab_headless"; }
  void shutdown_imgui_platform() override {}
  bool open() const override { return true; }

  void new_frame() override {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(size_.width), static_cast<float>(size_.height));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
  }

  FrameSize framebuffer_size() const override { return size_; }
  void resize(FrameSize size) override {
    size_ = size;
    target_ = make_offscreen_target(size_.width, size_.height);
    ImGui::GetIO().DisplaySize =
        ImVec2(static_cast<float>(size_.width), static_cast<float>(size_.height));
  }
  void bind_framebuffer() override { glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer.get()); }
  void wait_events(double) override {}
  void present() override {}
  void finish() override { glFinish(); }

 private:
  FrameSize size_;
  // The context first: members go in reverse, so the GL objects are deleted while it is current.
  EglContext egl_;
  OffscreenTarget target_;
};

}  // namespace

std::unique_ptr<Surface> make_headless_surface(const SurfaceOptions& options) {
  return std::make_unique<HeadlessSurface>(options);
}

}  // namespace foldlab::gui
