// The one place where the two GL dialects FoldLab draws with differ: OpenGL 3.3 core through
// libepoxy on the desktop, OpenGL ES 3.0 (WebGL2) in the browser build. Every file in gl/ includes
// this header instead of a GL header, writes its shaders after kGlslPrologue, and calls the few
// desktop-only features through the helpers below.
#pragma once

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
// The extensions' names after the core ones, whose types they use.
#include <GLES2/gl2ext.h>
#include <emscripten/html5_webgl.h>
#else
#include <epoxy/gl.h>
#endif

namespace foldlab::gui::gl {

#ifdef __EMSCRIPTEN__
// ES shaders need a default precision for floats in fragment shaders; highp everywhere keeps the
// breeze and the lighting as precise as on the desktop.
inline constexpr const char* kGlslPrologue = "#version 300 es\nprecision highp float;\n";
// What ImGui's OpenGL3 backend is given.
inline constexpr const char* kImGuiGlslVersion = "#version 300 es";
#else
inline constexpr const char* kGlslPrologue = "#version 330 core\n";
inline constexpr const char* kImGuiGlslVersion = "#version 330 core";
#endif

// Whether the context offers the anisotropic filtering extension (either of its names). WebGL
// offers it only once asked for, which this does.
inline bool has_anisotropic_filtering() {
#ifdef __EMSCRIPTEN__
  return emscripten_webgl_enable_extension(emscripten_webgl_get_current_context(),
                                           "EXT_texture_filter_anisotropic") != 0;
#else
  return epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") ||
         epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic");
#endif
}

// Triangles drawn as their edges; WebGL has no polygon mode, so there the wireframe is not drawn
// (false: the caller skips the draw).
inline bool set_polygon_lines(bool lines) {
#ifdef __EMSCRIPTEN__
  (void)lines;
  return false;
#else
  glPolygonMode(GL_FRONT_AND_BACK, lines ? GL_LINE : GL_FILL);
  return true;
#endif
}

// gl_PointSize takes effect: a switch on the desktop, always so in ES.
inline void set_program_point_size(bool on) {
#ifdef __EMSCRIPTEN__
  (void)on;
#else
  if (on) {
    glEnable(GL_PROGRAM_POINT_SIZE);
  } else {
    glDisable(GL_PROGRAM_POINT_SIZE);
  }
#endif
}

// glMultiDrawArrays, which ES 3.0 lacks: one draw each there.
inline void multi_draw_arrays(GLenum mode, const GLint* firsts, const GLsizei* counts,
                              GLsizei draws) {
#ifdef __EMSCRIPTEN__
  for (GLsizei i = 0; i < draws; ++i) {
    glDrawArrays(mode, firsts[i], counts[i]);
  }
#else
  glMultiDrawArrays(mode, firsts, counts, draws);
#endif
}

}  // namespace foldlab::gui::gl
