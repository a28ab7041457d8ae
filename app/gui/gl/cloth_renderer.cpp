#include "app/gui/gl/cloth_renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace foldlab::gui {
namespace {

// Model coordinates have y pointing down (gravity); the view's world has +Y up. z may be drawn
// exaggerated; a normal then scales by the inverse (the inverse transpose of the stretch).
Eigen::Vector3f to_world(const Eigen::Vector3f& model, float z_scale = 1.0f) {
  return {model.x(), -model.y(), z_scale * model.z()};
}
Eigen::Vector3f normal_to_world(const Eigen::Vector3f& normal, float z_scale) {
  return Eigen::Vector3f(normal.x(), -normal.y(), normal.z() / z_scale).normalized();
}

// foldlab::breeze_offset (core/src/geometry.cpp) on the GPU, in world coordinates (y up): both
// vertex shaders prepend it so that the fold lines move with the cloth.
constexpr const char* kBreezeGlsl = R"(#version 330 core
uniform float breeze_amplitude_mm;
uniform float breeze_depth_mm;
uniform float time_s;
uniform float z_scale;
vec3 breeze(vec3 world) {
  const float omega = 2.0 * 3.14159265 * 0.4;
  float down = max(0.0, -world.y) / max(breeze_depth_mm, 1.0);
  float weight = breeze_amplitude_mm * down * down;
  return vec3(0.25 * weight * sin(0.7 * omega * time_s + 1.3), 0.0,
              z_scale * weight * sin(omega * time_s - 2.5 * 3.14159265 * down));
}
)";

constexpr const char* kMeshVertex = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 material;
uniform mat4 view_projection;
out vec3 world_normal;
out vec3 world_position;
out vec2 material_mm;
void main() {
  world_normal = normal;
  world_position = position + breeze(position);
  material_mm = material;
  gl_Position = view_projection * vec4(world_position, 1.0);
}
)";

// Cloth has two faces: the back face is lit with the flipped normal and has its own colour.
// A print follows the material coordinates (X, Y on the flat cloth, mm), so it folds with it.
constexpr const char* kMeshFragment = R"(#version 330 core
in vec3 world_normal;
in vec3 world_position;
in vec2 material_mm;
uniform vec3 eye;
uniform vec3 front_colour;
uniform vec3 back_colour;
uniform int print_kind;  // 0 plain, 1 woven checks, 2 stripes
uniform float print_mm;
out vec4 colour;
vec3 print(vec3 base) {
  if (print_kind == 1) {
    vec2 cell = floor(material_mm / print_mm);
    float dark = mod(cell.x + cell.y, 2.0);
    vec2 thread = abs(fract(material_mm / (print_mm / 8.0)) - 0.5);
    float weave = 0.92 + 0.08 * step(0.35, max(thread.x, thread.y));
    return base * mix(1.0, 0.62, dark) * weave;
  }
  if (print_kind == 2) {
    float band = mod(floor(material_mm.x / print_mm), 2.0);
    return mix(base, vec3(0.20, 0.35, 0.62), 0.75 * band);
  }
  return base;
}
void main() {
  vec3 n = normalize(world_normal);
  vec3 base = print(front_colour);
  if (!gl_FrontFacing) { n = -n; base = back_colour; }
  vec3 to_eye = normalize(eye - world_position);
  vec3 key = normalize(vec3(0.4, 0.8, 0.6));
  float diffuse = 0.65 * max(dot(n, key), 0.0) + 0.35 * max(dot(n, to_eye), 0.0);
  vec3 h = normalize(key + to_eye);
  float specular = 0.12 * pow(max(dot(n, h), 0.0), 24.0);
  colour = vec4(base * (0.35 + 0.65 * diffuse) + vec3(specular), 1.0);
}
)";

constexpr const char* kLineVertex = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 vertex_colour;
uniform mat4 view_projection;
uniform float point_size;
out vec3 line_colour;
void main() {
  line_colour = vertex_colour;
  gl_Position = view_projection * vec4(position + breeze(position), 1.0);
  gl_PointSize = point_size;
}
)";

constexpr const char* kLineFragment = R"(#version 330 core
in vec3 line_colour;
uniform vec4 override_colour;
out vec4 colour;
void main() {
  colour = override_colour.a > 0.0 ? override_colour : vec4(line_colour, 1.0);
}
)";

// `prefix` (may be null) is prepended to `source`: the shared breeze function.
GLuint compile(GLenum type, const char* prefix, const char* source) {
  const GLuint shader = glCreateShader(type);
  const char* parts[] = {prefix, source};
  if (prefix != nullptr) {
    glShaderSource(shader, 2, parts, nullptr);
  } else {
    glShaderSource(shader, 1, &source, nullptr);
  }
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader compilation failed: ") + log);
  }
  return shader;
}

GLuint link(const char* vertex, const char* fragment) {
  const GLuint program = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, kBreezeGlsl, vertex);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, nullptr, fragment);
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader link failed: ") + log);
  }
  return program;
}

// Position + colour (or normal) pairs, the layout every buffer here uses.
struct Vertex {
  Eigen::Vector3f position;
  Eigen::Vector3f attribute;
};
static_assert(sizeof(Vertex) == 6 * sizeof(float));

// The cloth's vertices also carry their material coordinates, for prints.
struct MeshVertex {
  Eigen::Vector3f position;
  Eigen::Vector3f normal;
  Eigen::Vector2f material;
};
static_assert(sizeof(MeshVertex) == 8 * sizeof(float));

void describe_vertex_layout() {
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(3 * sizeof(float)));
}

}  // namespace

struct ClothRenderer::Gl {
  GLuint mesh_program = 0;
  GLuint line_program = 0;
  GLuint mesh_vao = 0, mesh_vbo = 0, mesh_ebo = 0;
  GLsizei mesh_index_count = 0;
  GLuint lines_vao = 0, lines_vbo = 0;
  std::vector<GLint> line_firsts;
  std::vector<GLsizei> line_counts;
  GLuint decor_vao = 0, decor_vbo = 0;
  GLsizei ground_vertex_count = 0;  // GL_LINES, from 0
  GLsizei support_first = 0;        // GL_POINTS, support_count of them
  GLsizei support_count = 0;
  GLuint framebuffer = 0, colour_texture = 0, depth_buffer = 0;
};

ClothRenderer::ClothRenderer() : gl_(new Gl) {
  gl_->mesh_program = link(kMeshVertex, kMeshFragment);
  gl_->line_program = link(kLineVertex, kLineFragment);
  GLuint vaos[3];
  GLuint buffers[4];
  glGenVertexArrays(3, vaos);
  glGenBuffers(4, buffers);
  gl_->mesh_vao = vaos[0];
  gl_->lines_vao = vaos[1];
  gl_->decor_vao = vaos[2];
  gl_->mesh_vbo = buffers[0];
  gl_->mesh_ebo = buffers[1];
  gl_->lines_vbo = buffers[2];
  gl_->decor_vbo = buffers[3];
  for (auto [vao, vbo] :
       {std::pair{gl_->lines_vao, gl_->lines_vbo}, std::pair{gl_->decor_vao, gl_->decor_vbo}}) {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    describe_vertex_layout();
  }
  glBindVertexArray(gl_->mesh_vao);
  glBindBuffer(GL_ARRAY_BUFFER, gl_->mesh_vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                        reinterpret_cast<const void*>(6 * sizeof(float)));
  glBindVertexArray(gl_->mesh_vao);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gl_->mesh_ebo);
  glBindVertexArray(0);
  glGenFramebuffers(1, &gl_->framebuffer);
  glGenTextures(1, &gl_->colour_texture);
  glGenRenderbuffers(1, &gl_->depth_buffer);
}

ClothRenderer::~ClothRenderer() {
  const GLuint vaos[] = {gl_->mesh_vao, gl_->lines_vao, gl_->decor_vao};
  const GLuint buffers[] = {gl_->mesh_vbo, gl_->mesh_ebo, gl_->lines_vbo, gl_->decor_vbo};
  glDeleteVertexArrays(3, vaos);
  glDeleteBuffers(4, buffers);
  glDeleteProgram(gl_->mesh_program);
  glDeleteProgram(gl_->line_program);
  glDeleteFramebuffers(1, &gl_->framebuffer);
  glDeleteTextures(1, &gl_->colour_texture);
  glDeleteRenderbuffers(1, &gl_->depth_buffer);
  delete gl_;
}

unsigned ClothRenderer::framebuffer() const {
  return gl_->framebuffer;
}

void ClothRenderer::resize(FrameSize size) {
  if (size.width == size_.width && size.height == size_.height) {
    return;
  }
  size_ = size;
  glBindTexture(GL_TEXTURE_2D, gl_->colour_texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.width, size.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindRenderbuffer(GL_RENDERBUFFER, gl_->depth_buffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.width, size.height);
  glBindFramebuffer(GL_FRAMEBUFFER, gl_->framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, gl_->colour_texture,
                         0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            gl_->depth_buffer);
}

void ClothRenderer::upload_mesh(Scene& scene, float z_scale) {
  const std::vector<Eigen::Vector3f>& normals = scene.normals();
  const DeformedGrid& grid = scene.grid();
  std::vector<MeshVertex> vertices(grid.positions_mm.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    vertices[i] = {to_world(grid.positions_mm[i], z_scale), normal_to_world(normals[i], z_scale),
                   grid.material_mm[i]};
  }
  glBindVertexArray(gl_->mesh_vao);
  glBindBuffer(GL_ARRAY_BUFFER, gl_->mesh_vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(MeshVertex)),
               vertices.data(), GL_DYNAMIC_DRAW);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(grid.triangle_indices.size() * sizeof(std::uint32_t)),
               grid.triangle_indices.data(), GL_DYNAMIC_DRAW);
  glBindVertexArray(0);
  gl_->mesh_index_count = static_cast<GLsizei>(grid.triangle_indices.size());
  mesh_z_scale_ = z_scale;
  ++counters_.mesh_uploads;
}

void ClothRenderer::upload_fold_lines(Scene& scene, const ClothStyle& style) {
  const FoldLines& lines = scene.fold_lines();
  std::vector<Vertex> vertices;
  gl_->line_firsts.clear();
  gl_->line_counts.clear();
  for (const FoldLine& line : lines.lines) {
    gl_->line_firsts.push_back(static_cast<GLint>(vertices.size()));
    gl_->line_counts.push_back(static_cast<GLsizei>(line.points_mm.size()));
    const Eigen::Vector3f& colour =
        line.sign < 0 ? style.negative_fold_colour : style.positive_fold_colour;
    for (const Eigen::Vector3d& p : line.points_mm) {
      vertices.push_back({to_world(p.cast<float>(), style.z_exaggeration), colour});
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, gl_->lines_vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_DYNAMIC_DRAW);
  uploaded_positive_ = style.positive_fold_colour;
  lines_z_scale_ = style.z_exaggeration;
  uploaded_negative_ = style.negative_fold_colour;
  ++counters_.fold_line_uploads;
}

// The ground grid below the cloth and the two supports; they follow the solution (span, depth).
void ClothRenderer::upload_decorations(Scene& scene) {
  const Solution& s = scene.solution();
  const Parameters& p = scene.parameters();
  const float depth =
      static_cast<float>(lowest_point_mm(s, p.hanging.height_mm) + 0.05 * p.hanging.height_mm);
  const float extent =
      static_cast<float>(0.75 * std::max(p.hanging.length_mm, p.hanging.height_mm));
  const float spacing = std::pow(10.0f, std::floor(std::log10(extent / 2.0f)));
  const Eigen::Vector3f grey(0.36f, 0.38f, 0.42f);
  std::vector<Vertex> vertices;
  for (float v = -std::floor(extent / spacing) * spacing; v <= extent; v += spacing) {
    vertices.push_back({{v, -depth, -extent}, grey});
    vertices.push_back({{v, -depth, extent}, grey});
    vertices.push_back({{-extent, -depth, v}, grey});
    vertices.push_back({{extent, -depth, v}, grey});
  }
  gl_->ground_vertex_count = static_cast<GLsizei>(vertices.size());
  gl_->support_first = static_cast<GLsizei>(vertices.size());
  const Eigen::Vector3f support_colour(0.95f, 0.85f, 0.25f);
  for (const Eigen::Vector3d& support : support_points(s.span_mm, p.shape)) {
    vertices.push_back({to_world(support.cast<float>()), support_colour});
  }
  gl_->support_count = static_cast<GLsizei>(vertices.size()) - gl_->support_first;
  glBindBuffer(GL_ARRAY_BUFFER, gl_->decor_vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_DYNAMIC_DRAW);
}

void ClothRenderer::set_breeze_uniforms(unsigned program, Scene& scene, const ClothStyle& style) {
  const float depth =
      static_cast<float>(lowest_point_mm(scene.solution(), scene.parameters().hanging.height_mm));
  glUniform1f(glGetUniformLocation(program, "breeze_amplitude_mm"),
              style.breeze ? style.breeze_mm : 0.0f);
  glUniform1f(glGetUniformLocation(program, "breeze_depth_mm"), depth);
  glUniform1f(glGetUniformLocation(program, "time_s"), style.time_s);
  glUniform1f(glGetUniformLocation(program, "z_scale"), style.z_exaggeration);
}

unsigned ClothRenderer::render(Scene& scene, const OrbitCamera& camera, FrameSize size,
                               const ClothStyle& style) {
  GLint previous_viewport[4];
  glGetIntegerv(GL_VIEWPORT, previous_viewport);
  resize(size);
  // Bring the stages this view needs up to date (lazily), then upload only what changed.
  scene.normals();
  if (scene.version(Stage::normals) != mesh_version_ || mesh_z_scale_ != style.z_exaggeration) {
    upload_mesh(scene, style.z_exaggeration);
    mesh_version_ = scene.version(Stage::normals);
  }
  if (style.fold_lines) {
    scene.fold_lines();
    if (scene.version(Stage::fold_lines) != fold_line_version_ ||
        uploaded_positive_ != style.positive_fold_colour ||
        lines_z_scale_ != style.z_exaggeration ||
        uploaded_negative_ != style.negative_fold_colour) {
      upload_fold_lines(scene, style);
      fold_line_version_ = scene.version(Stage::fold_lines);
    }
  }
  // The supports and the ground follow the solution and the shape: both re-make the grid.
  if (scene.version(Stage::grid) != decoration_version_) {
    upload_decorations(scene);
    decoration_version_ = scene.version(Stage::grid);
  }

  glBindFramebuffer(GL_FRAMEBUFFER, gl_->framebuffer);
  glViewport(0, 0, size.width, size.height);
  glClearColor(style.background.x(), style.background.y(), style.background.z(), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);

  const float aspect =
      static_cast<float>(size.width) / static_cast<float>(std::max(size.height, 1));
  const Eigen::Matrix4f view_projection = camera.projection(aspect) * camera.view();
  const Eigen::Vector3f eye = camera.eye();

  // The cloth, pushed back a little so that lines on its surface win the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  glUseProgram(gl_->mesh_program);
  glUniformMatrix4fv(glGetUniformLocation(gl_->mesh_program, "view_projection"), 1, GL_FALSE,
                     view_projection.data());
  glUniform3fv(glGetUniformLocation(gl_->mesh_program, "eye"), 1, eye.data());
  glUniform3fv(glGetUniformLocation(gl_->mesh_program, "front_colour"), 1,
               style.front_colour.data());
  glUniform3fv(glGetUniformLocation(gl_->mesh_program, "back_colour"), 1, style.back_colour.data());
  glUniform1i(glGetUniformLocation(gl_->mesh_program, "print_kind"), static_cast<int>(style.print));
  glUniform1f(glGetUniformLocation(gl_->mesh_program, "print_mm"), style.print_mm);
  set_breeze_uniforms(gl_->mesh_program, scene, style);
  glBindVertexArray(gl_->mesh_vao);
  glDrawElements(GL_TRIANGLES, gl_->mesh_index_count, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_POLYGON_OFFSET_FILL);

  glUseProgram(gl_->line_program);
  glUniformMatrix4fv(glGetUniformLocation(gl_->line_program, "view_projection"), 1, GL_FALSE,
                     view_projection.data());
  const GLint override_colour = glGetUniformLocation(gl_->line_program, "override_colour");
  glUniform1f(glGetUniformLocation(gl_->line_program, "point_size"), 1.0f);
  set_breeze_uniforms(gl_->line_program, scene, style);
  if (style.wireframe) {
    glUniform4f(override_colour, 0.1f, 0.1f, 0.1f, 1.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDrawElements(GL_TRIANGLES, gl_->mesh_index_count, GL_UNSIGNED_INT, nullptr);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
  glUniform4f(override_colour, 0.0f, 0.0f, 0.0f, 0.0f);
  if (style.fold_lines && !gl_->line_counts.empty()) {
    glBindVertexArray(gl_->lines_vao);
    glMultiDrawArrays(GL_LINE_STRIP, gl_->line_firsts.data(), gl_->line_counts.data(),
                      static_cast<GLsizei>(gl_->line_counts.size()));
  }
  glBindVertexArray(gl_->decor_vao);
  if (style.ground) {
    glDrawArrays(GL_LINES, 0, gl_->ground_vertex_count);
  }
  glEnable(GL_PROGRAM_POINT_SIZE);
  glUniform1f(glGetUniformLocation(gl_->line_program, "point_size"), 12.0f);
  glDisable(GL_DEPTH_TEST);  // the supports are always visible
  glDrawArrays(GL_POINTS, gl_->support_first, gl_->support_count);
  glDisable(GL_PROGRAM_POINT_SIZE);

  glBindVertexArray(0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2],
             previous_viewport[3]);
  ++counters_.frames;
  return gl_->colour_texture;
}

}  // namespace foldlab::gui
