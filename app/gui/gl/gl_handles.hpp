// Owning handles for GL object names: each deletes its object when it goes, so that an exception
// part-way through making a renderer (a shader that fails to compile or link) leaks nothing. Move
// only; a handle holding 0 owns nothing. Destroy them while their context is current.
#pragma once

#include "app/gui/gl/gl_api.hpp"

#include <utility>

namespace foldlab::gui {

template <class Kind>
class GlHandle {
 public:
  GlHandle() = default;
  explicit GlHandle(GLuint name) : name_(name) {}
  ~GlHandle() { reset(); }
  GlHandle(GlHandle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;

  // A new object of this kind (glGen*, glCreate*).
  static GlHandle make() { return GlHandle(Kind::make()); }

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  void reset() {
    if (name_ != 0) {
      Kind::destroy(name_);
      name_ = 0;
    }
  }

 private:
  GLuint name_ = 0;
};

namespace gl_kind {

struct Program {
  static GLuint make() { return glCreateProgram(); }
  static void destroy(GLuint name) { glDeleteProgram(name); }
};
struct Shader {  // made with a type: GlShader(glCreateShader(type))
  static void destroy(GLuint name) { glDeleteShader(name); }
};
struct Buffer {
  static GLuint make() {
    GLuint name = 0;
    glGenBuffers(1, &name);
    return name;
  }
  static void destroy(GLuint name) { glDeleteBuffers(1, &name); }
};
struct VertexArray {
  static GLuint make() {
    GLuint name = 0;
    glGenVertexArrays(1, &name);
    return name;
  }
  static void destroy(GLuint name) { glDeleteVertexArrays(1, &name); }
};
struct Texture {
  static GLuint make() {
    GLuint name = 0;
    glGenTextures(1, &name);
    return name;
  }
  static void destroy(GLuint name) { glDeleteTextures(1, &name); }
};
struct Framebuffer {
  static GLuint make() {
    GLuint name = 0;
    glGenFramebuffers(1, &name);
    return name;
  }
  static void destroy(GLuint name) { glDeleteFramebuffers(1, &name); }
};
struct Renderbuffer {
  static GLuint make() {
    GLuint name = 0;
    glGenRenderbuffers(1, &name);
    return name;
  }
  static void destroy(GLuint name) { glDeleteRenderbuffers(1, &name); }
};

}  // namespace gl_kind

using GlProgram = GlHandle<gl_kind::Program>;
using GlShader = GlHandle<gl_kind::Shader>;
using GlBuffer = GlHandle<gl_kind::Buffer>;
using GlVertexArray = GlHandle<gl_kind::VertexArray>;
using GlTexture = GlHandle<gl_kind::Texture>;
using GlFramebuffer = GlHandle<gl_kind::Framebuffer>;
using GlRenderbuffer = GlHandle<gl_kind::Renderbuffer>;

// A framebuffer drawn into with no window: RGBA8 colour and a depth-stencil buffer, each a
// renderbuffer. Made bound; `complete` says whether the GL can draw into it at this size.
struct OffscreenTarget {
  GlFramebuffer framebuffer;
  GlRenderbuffer colour;
  GlRenderbuffer depth;
  bool complete = false;
};
inline OffscreenTarget make_offscreen_target(int width, int height) {
  OffscreenTarget t{GlFramebuffer::make(), GlRenderbuffer::make(), GlRenderbuffer::make()};
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.get());
  glBindRenderbuffer(GL_RENDERBUFFER, t.colour.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.colour.get());
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                            t.depth.get());
  t.complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  return t;
}

}  // namespace foldlab::gui
