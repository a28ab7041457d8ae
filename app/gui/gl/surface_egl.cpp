#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <string>

#include <imgui.h>

#include "app/gui/surface.hpp"

namespace foldlab::gui {
namespace {

std::string egl_error_text() {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  return std::string("EGL error ") + code;
}

// Mesa's surfaceless platform: a GL context with no window system at all, drawing into an
// off-screen framebuffer. Input is absent, and the time step is a fixed 1/60 s so that frames,
// and therefore pictures, are reproducible.
class HeadlessSurface final : public Surface {
 public:
  explicit HeadlessSurface(const SurfaceOptions& options) : size_{options.width, options.height} {
    display_ =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0;
    EGLint minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
      throw SurfaceError("cannot open Mesa's surfaceless EGL display (" + egl_error_text() +
                         "); is libegl-mesa0 installed?");
    }
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
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glGenRenderbuffers(2, renderbuffers_);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size_.width, size_.height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              renderbuffers_[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, size_.width, size_.height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              renderbuffers_[1]);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw SurfaceError("the off-screen framebuffer is incomplete");
    }
  }

  ~HeadlessSurface() override {
    glDeleteRenderbuffers(2, renderbuffers_);
    glDeleteFramebuffers(1, &framebuffer_);
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
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
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size_.width, size_.height);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, size_.width, size_.height);
    ImGui::GetIO().DisplaySize =
        ImVec2(static_cast<float>(size_.width), static_cast<float>(size_.height));
  }
  void bind_framebuffer() override { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_); }
  void wait_events(double) override {}
  void present() override {}
  void finish() override { glFinish(); }

 private:
  FrameSize size_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  GLuint framebuffer_ = 0;
  GLuint renderbuffers_[2] = {0, 0};
};

}  // namespace

std::unique_ptr<Surface> make_headless_surface(const SurfaceOptions& options) {
  return std::make_unique<HeadlessSurface>(options);
}

}  // namespace foldlab::gui
