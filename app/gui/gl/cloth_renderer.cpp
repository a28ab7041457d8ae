#include "app/gui/gl/cloth_renderer.hpp"

#include "app/gui/gl/gl_api.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/gui/cloth_uploads.hpp"
#include "app/gui/colour_map.hpp"
#include "app/gui/gl/gl_handles.hpp"
#include "app/gui/gl/mipmapped_texture.hpp"
#include "core/geometry/fold_occlusion.hpp"
#include "core/geometry/level_of_detail.hpp"

namespace foldlab::gui {
namespace {

// World coordinates (cloth_uploads.hpp: y up, z maybe exaggerated); a normal scales by the inverse
// of the stretch (its inverse transpose).
Eigen::Vector3f to_world(const Eigen::Vector3f& model, float z_scale = 1.0f) {
  return model.cwiseProduct(world_scale(z_scale));
}
Eigen::Vector3f normal_to_world(const Eigen::Vector3f& normal, float z_scale) {
  return normal.cwiseQuotient(world_scale(z_scale)).normalized();
}

// foldlab::breeze_offset (core/src/geometry.cpp) on the GPU, in world coordinates (y up): both
// vertex shaders prepend it so that the fold lines move with the cloth.
constexpr const char* kBreezeGlsl = R"(
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
layout(location = 3) in vec2 occlusion;
uniform mat4 view_projection;
out vec3 world_normal;
out vec3 world_position;
out vec2 material_mm;
out vec2 sky_hidden;
out float model_z_mm;
void main() {
  world_normal = normal;
  world_position = position + breeze(position);
  material_mm = material;
  sky_hidden = occlusion;
  model_z_mm = position.z / max(z_scale, 1e-6);
  gl_Position = view_projection * vec4(world_position, 1.0);
}
)";

// Cloth has two faces: the back face is lit with the flipped normal and has its own colour.
// A print follows the material coordinates (X, Y on the flat cloth, mm), so it folds with it.
// The light set-up reads pleats: a key light grazing the cloth from above (across the folds, which
// run sideways), so that a pleat's upper face is lit and its lower face is not; a soft fill from
// the front-left and a sky/ground ambient, both dimmed by the fold occlusion, so that the inside
// of a fold stays darker than its crest under any light; a faint sheen at grazing view, as fibres
// catch the light. Lighting is done on linear colours and the result encoded back for display.
// One program per surface colouring (the fabric plain, the fabric printed, by z, by fold sign):
// llvmpipe runs both sides of a branch on every pixel, so the texture lookup and the colour map
// are compiled only into the variants that show them. Gamma 2 (a square and a square root) stands
// for the display's 2.2: the pow() calls were about a quarter of the cloth's cost on llvmpipe.
constexpr const char* kMeshFragment = R"(
in vec3 world_normal;
in vec3 world_position;
in vec2 material_mm;
in vec2 sky_hidden;
in float model_z_mm;
uniform vec3 eye;
uniform vec3 front_colour;
uniform vec3 back_colour;
uniform float print_period_mm;
uniform sampler2D print_texture;
uniform float z_range_mm;
uniform vec3 colour_map[9];
uniform vec3 positive_colour;
uniform vec3 negative_colour;
uniform vec3 key_direction;
uniform vec3 fill_direction;
out vec4 colour;
vec3 surface_colour(bool front) {
#if COLOUR_BY == 1
  float x = clamp(0.5 + 0.5 * model_z_mm / z_range_mm, 0.0, 1.0) * 8.0;
  int i = min(int(x), 7);
  return mix(colour_map[i], colour_map[i + 1], x - float(i));
#elif COLOUR_BY == 2
  return mix(negative_colour, positive_colour, smoothstep(-0.05, 0.05, model_z_mm / z_range_mm));
#elif PRINTED
  return front ? texture(print_texture, material_mm / print_period_mm).rgb : back_colour;
#else
  return front ? front_colour : back_colour;
#endif
}
void main() {
  vec3 n = normalize(world_normal);
  float hidden = sky_hidden.x;
  if (!gl_FrontFacing) { n = -n; hidden = sky_hidden.y; }
  vec3 base = surface_colour(gl_FrontFacing);
  base *= base;
  vec3 to_eye = normalize(eye - world_position);
  float open_sky = clamp(1.0 - 2.5 * hidden, 0.1, 1.0);
  float key = max(dot(n, key_direction), 0.0);
  float fill = 0.5 + 0.5 * dot(n, fill_direction);
  float sky = 0.5 + 0.5 * n.y;
  vec3 light = vec3(1.00, 0.96, 0.90) * 1.9 * key * mix(0.5, 1.0, open_sky)
             + vec3(0.80, 0.86, 1.00) * 0.22 * fill * open_sky
             + mix(vec3(0.06, 0.05, 0.05), vec3(0.14, 0.15, 0.18), sky) * open_sky;
  float grazing = 1.0 - max(dot(n, to_eye), 0.0);
  grazing *= grazing;
  float sheen = 0.10 * grazing * grazing * open_sky;
  colour = vec4(sqrt(base * light + vec3(sheen)), 1.0);
}
)";

// The ground's shadow: a soft elliptical blob under the cloth's footprint (its extent seen from
// above, narrowed across where a hanging cloth comes near the ground only at its middle), darkest
// at the centre and gone `soft_mm` beyond the footprint.
constexpr const char* kShadowVertex = R"(
layout(location = 0) in vec3 position;
uniform mat4 view_projection;
out vec2 ground_mm;
void main() {
  ground_mm = position.xz;
  gl_Position = view_projection * vec4(position, 1.0);
}
)";

constexpr const char* kShadowFragment = R"(
in vec2 ground_mm;
uniform vec2 footprint_centre_mm;
uniform vec2 footprint_half_mm;
uniform float soft_mm;
uniform float darkness;
out vec4 colour;
void main() {
  vec2 reach = footprint_half_mm + vec2(soft_mm);
  float d = length((ground_mm - footprint_centre_mm) / reach);
  float fade = 1.0 - smoothstep(0.0, 1.0, d);
  colour = vec4(0.0, 0.0, 0.0, darkness * fade);
}
)";

constexpr const char* kLineVertex = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 vertex_colour;
uniform mat4 view_projection;
uniform float point_size;
uniform vec2 offset_ndc;
out vec3 line_colour;
void main() {
  line_colour = vertex_colour;
  gl_Position = view_projection * vec4(position + breeze(position), 1.0);
  gl_Position.xy += offset_ndc * gl_Position.w;
  gl_PointSize = point_size;
}
)";

constexpr const char* kLineFragment = R"(
in vec3 line_colour;
uniform vec4 override_colour;
out vec4 colour;
void main() {
  colour = override_colour.a > 0.0 ? override_colour : vec4(line_colour, 1.0);
}
)";

// The dialect's prologue (gl_api.hpp), then `prefix` (may be null: the shared breeze function or
// a variant's defines), then `source`.
GlShader compile(GLenum type, const char* prefix, const char* source) {
  GlShader shader(glCreateShader(type));
  const char* parts[] = {gl::kGlslPrologue, prefix != nullptr ? prefix : "", source};
  glShaderSource(shader.get(), 3, parts, nullptr);
  glCompileShader(shader.get());
  GLint ok = 0;
  glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetShaderInfoLog(shader.get(), sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader compilation failed: ") + log);
  }
  return shader;
}

// A failed compilation or link throws; whatever was made by then is deleted.
GlProgram link(const char* vertex, const char* fragment, const char* vertex_prefix = kBreezeGlsl,
               const char* fragment_prefix = nullptr) {
  GlProgram program = GlProgram::make();
  {
    // Attached shaders live on with the program; deleting them here only drops their names.
    const GlShader vs = compile(GL_VERTEX_SHADER, vertex_prefix, vertex);
    const GlShader fs = compile(GL_FRAGMENT_SHADER, fragment_prefix, fragment);
    glAttachShader(program.get(), vs.get());
    glAttachShader(program.get(), fs.get());
    glLinkProgram(program.get());
  }
  GLint ok = 0;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetProgramInfoLog(program.get(), sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader link failed: ") + log);
  }
  return program;
}

GLint uniform(const GlProgram& program, const char* name) {
  return glGetUniformLocation(program.get(), name);
}

// Each program with its uniforms' locations, looked up once when it is linked. A uniform that the
// compiler left out (unused in a variant) is at -1, which glUniform* ignores.
struct BreezeUniforms {
  GLint amplitude_mm, depth_mm, time_s, z_scale;
  explicit BreezeUniforms(const GlProgram& p)
      : amplitude_mm(uniform(p, "breeze_amplitude_mm")),
        depth_mm(uniform(p, "breeze_depth_mm")),
        time_s(uniform(p, "time_s")),
        z_scale(uniform(p, "z_scale")) {}
};

struct MeshProgram {
  GlProgram program;
  GLint view_projection, eye, front_colour, back_colour, print_period_mm, print_texture, z_range_mm,
      colour_map, positive_colour, negative_colour, key_direction, fill_direction;
  BreezeUniforms breeze;
  explicit MeshProgram(GlProgram linked)
      : program(std::move(linked)),
        view_projection(uniform(program, "view_projection")),
        eye(uniform(program, "eye")),
        front_colour(uniform(program, "front_colour")),
        back_colour(uniform(program, "back_colour")),
        print_period_mm(uniform(program, "print_period_mm")),
        print_texture(uniform(program, "print_texture")),
        z_range_mm(uniform(program, "z_range_mm")),
        colour_map(uniform(program, "colour_map")),
        positive_colour(uniform(program, "positive_colour")),
        negative_colour(uniform(program, "negative_colour")),
        key_direction(uniform(program, "key_direction")),
        fill_direction(uniform(program, "fill_direction")),
        breeze(program) {}
};

struct LineProgram {
  GlProgram program;
  GLint view_projection, point_size, offset_ndc, override_colour;
  BreezeUniforms breeze;
  explicit LineProgram(GlProgram linked)
      : program(std::move(linked)),
        view_projection(uniform(program, "view_projection")),
        point_size(uniform(program, "point_size")),
        offset_ndc(uniform(program, "offset_ndc")),
        override_colour(uniform(program, "override_colour")),
        breeze(program) {}
};

struct ShadowProgram {
  GlProgram program;
  GLint view_projection, footprint_centre_mm, footprint_half_mm, soft_mm, darkness;
  explicit ShadowProgram(GlProgram linked)
      : program(std::move(linked)),
        view_projection(uniform(program, "view_projection")),
        footprint_centre_mm(uniform(program, "footprint_centre_mm")),
        footprint_half_mm(uniform(program, "footprint_half_mm")),
        soft_mm(uniform(program, "soft_mm")),
        darkness(uniform(program, "darkness")) {}
};

void set_breeze_uniforms(const BreezeUniforms& u, const ClothBuffers& buffers,
                         const ClothStyle& style) {
  glUniform1f(u.amplitude_mm, style.breeze ? style.breeze_mm : 0.0f);
  glUniform1f(u.depth_mm, buffers.lowest_point_mm);
  glUniform1f(u.time_s, style.time_s);
  glUniform1f(u.z_scale, style.z_exaggeration);
}

// Position + colour (or normal) pairs, the layout every buffer here uses.
struct Vertex {
  Eigen::Vector3f position;
  Eigen::Vector3f attribute;
};
static_assert(sizeof(Vertex) == 6 * sizeof(float));

// The cloth's vertices also carry their material coordinates, for prints,
// and how much of the sky each face sees (fold_occlusion.hpp).
struct MeshVertex {
  Eigen::Vector3f position;
  Eigen::Vector3f normal;
  Eigen::Vector2f material;
  Eigen::Vector2f occlusion;  // front, back
};
static_assert(sizeof(MeshVertex) == 10 * sizeof(float));

// A print's repeating tile, top row first: checks and stripes are made here from the front colour
// (the tile holds two checks or two stripes a side), a photo is used as it is.
struct Tile {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

std::uint8_t to_byte(float value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

void put(Tile& tile, int x, int y, const Eigen::Vector3f& c) {
  const auto at = (static_cast<std::size_t>(y) * tile.width + x) * 4;
  tile.rgba[at] = to_byte(c.x());
  tile.rgba[at + 1] = to_byte(c.y());
  tile.rgba[at + 2] = to_byte(c.z());
  tile.rgba[at + 3] = 255;
}

// Woven checks: dark and light cells, each crossed by 8 threads whose gaps show a shade darker.
Tile checks_tile(const Eigen::Vector3f& base) {
  constexpr int kCellPx = 128;
  Tile tile{2 * kCellPx, 2 * kCellPx, {}};
  tile.rgba.resize(static_cast<std::size_t>(tile.width) * tile.height * 4);
  for (int y = 0; y < tile.height; ++y) {
    for (int x = 0; x < tile.width; ++x) {
      const float cx = (static_cast<float>(x) + 0.5f) / kCellPx;
      const float cy = (static_cast<float>(y) + 0.5f) / kCellPx;
      const bool dark = (static_cast<int>(cx) + static_cast<int>(cy)) % 2 == 1;
      const float tx = std::abs(cx * 8.0f - std::floor(cx * 8.0f) - 0.5f);
      const float ty = std::abs(cy * 8.0f - std::floor(cy * 8.0f) - 0.5f);
      const float weave = std::max(tx, ty) >= 0.35f ? 1.0f : 0.92f;
      put(tile, x, y, base * (dark ? 0.62f : 1.0f) * weave);
    }
  }
  return tile;
}

Tile stripes_tile(const Eigen::Vector3f& base) {
  constexpr int kStripePx = 64;
  Tile tile{2 * kStripePx, 4, {}};
  tile.rgba.resize(static_cast<std::size_t>(tile.width) * tile.height * 4);
  const Eigen::Vector3f blue(0.20f, 0.35f, 0.62f);
  for (int y = 0; y < tile.height; ++y) {
    for (int x = 0; x < tile.width; ++x) {
      put(tile, x, y, x < kStripePx ? base : Eigen::Vector3f(base + 0.75f * (blue - base)));
    }
  }
  return tile;
}

void describe_vertex_layout() {
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(3 * sizeof(float)));
}

}  // namespace

// Every GL object the view uses, each owned by a handle: made in this order, deleted in reverse,
// and nothing left behind if a shader fails part-way.
struct ClothRenderer::Gl {
  LineProgram line_program{link(kLineVertex, kLineFragment)};
  ShadowProgram shadow_program{link(kShadowVertex, kShadowFragment, nullptr)};
  // By colouring: the fabric plain, printed, by z, by fold sign; made when first needed.
  std::array<std::optional<MeshProgram>, 4> mesh_programs;
  const MeshProgram* mesh_program = nullptr;  // the variant in use, one of mesh_programs
  GlVertexArray shadow_vao = GlVertexArray::make();
  GlBuffer shadow_vbo = GlBuffer::make();
  GlTexture print_texture = GlTexture::make();
  GlVertexArray mesh_vao = GlVertexArray::make(), lines_vao = GlVertexArray::make(),
                decor_vao = GlVertexArray::make();
  GlBuffer mesh_vbo = GlBuffer::make(), mesh_ebo = GlBuffer::make(), lines_vbo = GlBuffer::make(),
           decor_vbo = GlBuffer::make();
  GlFramebuffer framebuffer = GlFramebuffer::make();
  GlTexture colour_texture = GlTexture::make();
  GlRenderbuffer depth_buffer = GlRenderbuffer::make();
  GLsizei mesh_index_count = 0;
  std::vector<GLint> line_firsts;
  std::vector<GLsizei> line_counts;
  GLsizei ground_vertex_count = 0;  // GL_LINES, from 0
  GLsizei support_first = 0;        // GL_POINTS, support_count of them
  GLsizei support_count = 0;
  float ground_y_mm = 0.0f;                // world y of the ground plane
  Eigen::Vector2f footprint_min_mm{0, 0};  // the cloth's extent in world (x, z), as uploaded
  Eigen::Vector2f footprint_max_mm{0, 0};
};

ClothRenderer::ClothRenderer() : gl_(std::make_unique<Gl>()) {
  glBindVertexArray(gl_->shadow_vao.get());
  glBindBuffer(GL_ARRAY_BUFFER, gl_->shadow_vbo.get());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  for (auto [vao, vbo] : {std::pair{gl_->lines_vao.get(), gl_->lines_vbo.get()},
                          std::pair{gl_->decor_vao.get(), gl_->decor_vbo.get()}}) {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    describe_vertex_layout();
  }
  glBindVertexArray(gl_->mesh_vao.get());
  glBindBuffer(GL_ARRAY_BUFFER, gl_->mesh_vbo.get());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                        reinterpret_cast<const void*>(6 * sizeof(float)));
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                        reinterpret_cast<const void*>(8 * sizeof(float)));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gl_->mesh_ebo.get());
  glBindVertexArray(0);
}

ClothRenderer::~ClothRenderer() = default;

unsigned ClothRenderer::framebuffer() const {
  return gl_->framebuffer.get();
}

void ClothRenderer::resize(FrameSize size) {
  if (size.width == size_.width && size.height == size_.height) {
    return;
  }
  size_ = size;
  glBindTexture(GL_TEXTURE_2D, gl_->colour_texture.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.width, size.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindRenderbuffer(GL_RENDERBUFFER, gl_->depth_buffer.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.width, size.height);
  glBindFramebuffer(GL_FRAMEBUFFER, gl_->framebuffer.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                         gl_->colour_texture.get(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            gl_->depth_buffer.get());
}

void ClothRenderer::upload_mesh(const ClothBuffers& buffers, float z_scale,
                                const DrawnLattice& lattice, bool indices_too) {
  const std::vector<Eigen::Vector3f>& normals = *buffers.normals;
  const DeformedGrid& grid = *buffers.grid;
  const int columns = static_cast<int>(lattice.columns.size());
  const int rows = static_cast<int>(lattice.rows.size());
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> world_normals;
  std::vector<Eigen::Vector2f> material;
  positions.reserve(static_cast<std::size_t>(columns) * rows);
  world_normals.reserve(positions.capacity());
  material.reserve(positions.capacity());
  Eigen::Vector2f low(std::numeric_limits<float>::max(), std::numeric_limits<float>::max());
  Eigen::Vector2f high = -low;
  for (int j : lattice.rows) {
    for (int i : lattice.columns) {
      const std::size_t k = static_cast<std::size_t>(j) * grid.nx + i;
      positions.push_back(to_world(grid.positions_mm[k], z_scale));
      world_normals.push_back(normal_to_world(normals[k], z_scale));
      material.push_back(grid.material_mm[k]);
      const Eigen::Vector2f ground(positions.back().x(), positions.back().z());
      low = low.cwiseMin(ground);
      high = high.cwiseMax(ground);
    }
  }
  gl_->footprint_min_mm = positions.empty() ? Eigen::Vector2f::Zero() : low;
  gl_->footprint_max_mm = positions.empty() ? Eigen::Vector2f::Zero() : high;
  const FoldOcclusion hidden =
      fold_occlusion(positions, world_normals, columns, rows, buffers.occlusion_reach_mm);
  std::vector<MeshVertex> vertices(positions.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    vertices[i] = {positions[i], world_normals[i], material[i], {hidden.front[i], hidden.back[i]}};
  }
  glBindVertexArray(gl_->mesh_vao.get());
  glBindBuffer(GL_ARRAY_BUFFER, gl_->mesh_vbo.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(MeshVertex)),
               vertices.data(), GL_DYNAMIC_DRAW);
  if (indices_too) {
    const std::vector<std::uint32_t> indices = lattice_triangles(columns, rows);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    gl_->mesh_index_count = static_cast<GLsizei>(indices.size());
  }
  glBindVertexArray(0);
  counters_.drawn_columns = static_cast<std::uint64_t>(columns);
  counters_.drawn_rows = static_cast<std::uint64_t>(rows);
  ++counters_.mesh_uploads;
}

void ClothRenderer::upload_fold_lines(const FoldLines& lines, const ClothStyle& style) {
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
  glBindBuffer(GL_ARRAY_BUFFER, gl_->lines_vbo.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_DYNAMIC_DRAW);
  ++counters_.fold_line_uploads;
}

// The ground grid below the cloth and the supports; they follow the solution (span, depth).
void ClothRenderer::upload_decorations(const ClothBuffers& buffers) {
  const float depth = buffers.ground_depth_mm;
  const float extent = buffers.ground_extent_mm;
  const float spacing = buffers.ground_spacing_mm;
  gl_->ground_y_mm = -depth;
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
  for (const Eigen::Vector3f& support : buffers.supports_mm) {
    vertices.push_back(
        {to_world(support), Eigen::Vector3f::Zero()});  // drawn in the style's colour
  }
  gl_->support_count = static_cast<GLsizei>(vertices.size()) - gl_->support_first;
  glBindBuffer(GL_ARRAY_BUFFER, gl_->decor_vbo.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_DYNAMIC_DRAW);
}

void ClothRenderer::update_print(const ClothStyle& style) {
  const bool photo = style.print == ClothStyle::Print::photo && style.photo != nullptr;
  const int kind =
      photo ? 3
            : static_cast<int>(style.print == ClothStyle::Print::photo ? ClothStyle::Print::plain
                                                                       : style.print);
  if (kind == print_kind_ && style.front_colour == print_colour_ &&
      (!photo || style.photo.get() == print_photo_)) {
    return;
  }
  print_kind_ = kind;
  print_colour_ = style.front_colour;
  print_photo_ = photo ? style.photo.get() : nullptr;
  if (photo) {
    upload_mipmapped(gl_->print_texture.get(), style.photo->width, style.photo->height,
                     style.photo->rgba.data(), true);
  } else if (kind == 1 || kind == 2) {
    const Tile tile =
        kind == 1 ? checks_tile(style.front_colour) : stripes_tile(style.front_colour);
    upload_mipmapped(gl_->print_texture.get(), tile.width, tile.height, tile.rgba.data(), true);
  }
}

void ClothRenderer::select_mesh_program(const ClothStyle& style) {
  static constexpr const char* kVariants[] = {
      "#define COLOUR_BY 0\n#define PRINTED 0\n",
      "#define COLOUR_BY 0\n#define PRINTED 1\n",
      "#define COLOUR_BY 1\n#define PRINTED 0\n",
      "#define COLOUR_BY 2\n#define PRINTED 0\n",
  };
  const std::size_t variant = style.colour_by == ClothStyle::ColourBy::z           ? 2
                              : style.colour_by == ClothStyle::ColourBy::fold_sign ? 3
                              : print_kind_ != 0                                   ? 1
                                                                                   : 0;
  std::optional<MeshProgram>& program = gl_->mesh_programs[variant];
  if (!program) {
    program.emplace(link(kMeshVertex, kMeshFragment, kBreezeGlsl, kVariants[variant]));
  }
  gl_->mesh_program = &*program;
}

void ClothRenderer::set_mesh_colour_uniforms(const ClothBuffers& buffers, const ClothStyle& style) {
  const MeshProgram& program = *gl_->mesh_program;
  glUniform3fv(program.front_colour, 1, style.front_colour.data());
  glUniform3fv(program.back_colour, 1, style.back_colour.data());
  // The checks' and stripes' tiles hold two of them a side; a photo is one swatch.
  glUniform1f(program.print_period_mm,
              (print_kind_ == 3 ? 1.0f : 2.0f) * std::max(style.print_mm, 1.0f));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, gl_->print_texture.get());
  glUniform1i(program.print_texture, 0);
  glUniform1f(program.z_range_mm, std::max(buffers.z_max_mm, 1e-3f));
  glUniform3fv(program.colour_map, static_cast<GLsizei>(kDivergingMap.size()),
               kDivergingMap.front().data());
  glUniform3fv(program.positive_colour, 1, style.positive_fold_colour.data());
  glUniform3fv(program.negative_colour, 1, style.negative_fold_colour.data());
  // About 17 degrees above the cloth's plane, from above and a little to the left.
  const Eigen::Vector3f key = Eigen::Vector3f(-0.3f, 1.0f, 0.32f).normalized();
  const Eigen::Vector3f fill = Eigen::Vector3f(0.6f, 0.15f, 1.0f).normalized();
  glUniform3fv(program.key_direction, 1, key.data());
  glUniform3fv(program.fill_direction, 1, fill.data());
}

// Blended over the ground, under the cloth (which is drawn first and hides it), before the ground
// lines so that they stay crisp on top.
void ClothRenderer::draw_shadow(const ClothBuffers& buffers,
                                const Eigen::Matrix4f& view_projection) {
  const float soft_mm = 0.12f * buffers.height_mm;
  const Eigen::Vector2f low = gl_->footprint_min_mm - Eigen::Vector2f::Constant(soft_mm);
  const Eigen::Vector2f high = gl_->footprint_max_mm + Eigen::Vector2f::Constant(soft_mm);
  const float y = gl_->ground_y_mm;
  const float quad[] = {low.x(), y, low.y(),  high.x(), y, low.y(),
                        low.x(), y, high.y(), high.x(), y, high.y()};
  const ShadowProgram& shadow = gl_->shadow_program;
  glBindVertexArray(gl_->shadow_vao.get());
  glBindBuffer(GL_ARRAY_BUFFER, gl_->shadow_vbo.get());
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_DYNAMIC_DRAW);
  glUseProgram(shadow.program.get());
  glUniformMatrix4fv(shadow.view_projection, 1, GL_FALSE, view_projection.data());
  const Eigen::Vector2f centre = 0.5f * (gl_->footprint_min_mm + gl_->footprint_max_mm);
  const Eigen::Vector2f half =
      0.5f *
      (gl_->footprint_max_mm - gl_->footprint_min_mm).cwiseProduct(Eigen::Vector2f(0.5f, 1.0f));
  glUniform2fv(shadow.footprint_centre_mm, 1, centre.data());
  glUniform2fv(shadow.footprint_half_mm, 1, half.data());
  glUniform1f(shadow.soft_mm, soft_mm);
  glUniform1f(shadow.darkness, 0.45f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void ClothRenderer::upload_stale(const ClothBuffers& buffers, const OrbitCamera& camera,
                                 FrameSize size, const ClothStyle& style) {
  // Upload only what changed (cloth_uploads.hpp). The wireframe shows the grid as it is;
  // otherwise the cells are a few pixels (level_of_detail.hpp).
  const ClothBufferSources sources = cloth_buffer_sources(buffers, camera, size, style);
  const ClothUploads uploads = upload_rule_.next(sources);
  if (uploads.mesh) {
    upload_mesh(buffers, style.z_exaggeration, sources.lattice, uploads.mesh_indices);
  }
  if (uploads.fold_lines) {
    upload_fold_lines(*buffers.fold_lines, style);
  }
  if (uploads.decorations) {
    upload_decorations(buffers);
  }
}

void ClothRenderer::begin_drawing(FrameSize size, const ClothStyle& style) {
  glBindFramebuffer(GL_FRAMEBUFFER, gl_->framebuffer.get());
  glViewport(0, 0, size.width, size.height);
  glClearColor(style.background.x(), style.background.y(), style.background.z(),
               style.background_alpha);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
}

void ClothRenderer::draw_cloth_surface(const ClothBuffers& buffers, const ClothStyle& style,
                                       const Eigen::Matrix4f& view_projection,
                                       const Eigen::Vector3f& eye) {
  // Pushed back a little so that lines on its surface win the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  select_mesh_program(style);
  const MeshProgram& mesh = *gl_->mesh_program;
  glUseProgram(mesh.program.get());
  glUniformMatrix4fv(mesh.view_projection, 1, GL_FALSE, view_projection.data());
  glUniform3fv(mesh.eye, 1, eye.data());
  set_mesh_colour_uniforms(buffers, style);
  set_breeze_uniforms(mesh.breeze, buffers, style);
  glBindVertexArray(gl_->mesh_vao.get());
  glDrawElements(GL_TRIANGLES, gl_->mesh_index_count, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void ClothRenderer::draw_lines(const ClothBuffers& buffers, const ClothStyle& style,
                               const Eigen::Matrix4f& view_projection, FrameSize size) {
  const LineProgram& line = gl_->line_program;
  glUseProgram(line.program.get());
  glUniformMatrix4fv(line.view_projection, 1, GL_FALSE, view_projection.data());
  glUniform1f(line.point_size, 1.0f);
  set_breeze_uniforms(line.breeze, buffers, style);
  if (style.wireframe && gl::set_polygon_lines(true)) {
    glUniform4f(line.override_colour, 0.1f, 0.1f, 0.1f, 1.0f);
    glDrawElements(GL_TRIANGLES, gl_->mesh_index_count, GL_UNSIGNED_INT, nullptr);
    gl::set_polygon_lines(false);
  }
  glUniform4f(line.override_colour, 0.0f, 0.0f, 0.0f, 0.0f);
  if (style.ground) {
    draw_shadow(buffers, view_projection);
    glUseProgram(line.program.get());
  }
  // A line wider than a pixel is drawn again shifted by whole pixels across its width: core GL
  // and WebGL draw lines one pixel wide only.
  const int passes = std::max(1, static_cast<int>(std::lround(style.line_width_px)));
  const float middle = 0.5f * static_cast<float>(passes - 1);
  for (int i = 0; i < passes; ++i) {
    for (int j = 0; j < passes; ++j) {
      const float dx = static_cast<float>(i) - middle;
      const float dy = static_cast<float>(j) - middle;
      if (dx * dx + dy * dy > (middle + 0.5f) * (middle + 0.5f)) {
        continue;  // a round pen: the corners of the square left out
      }
      glUniform2f(line.offset_ndc, 2.0f * dx / static_cast<float>(size.width),
                  2.0f * dy / static_cast<float>(size.height));
      if (style.fold_lines && !gl_->line_counts.empty()) {
        glBindVertexArray(gl_->lines_vao.get());
        gl::multi_draw_arrays(GL_LINE_STRIP, gl_->line_firsts.data(), gl_->line_counts.data(),
                              static_cast<GLsizei>(gl_->line_counts.size()));
      }
      if (style.ground) {
        glBindVertexArray(gl_->decor_vao.get());
        glDrawArrays(GL_LINES, 0, gl_->ground_vertex_count);
      }
    }
  }
  glUniform2f(line.offset_ndc, 0.0f, 0.0f);
}

// The supports, with the line program in use (the ground's grid is drawn with the lines).
void ClothRenderer::draw_decorations(const ClothStyle& style) {
  const LineProgram& line = gl_->line_program;
  glBindVertexArray(gl_->decor_vao.get());
  gl::set_program_point_size(true);
  glUniform1f(line.point_size, 12.0f * std::max(1.0f, style.line_width_px));
  // The supports' colour follows the theme (the backdrop does), so it is a uniform, not baked in.
  glUniform4f(line.override_colour, style.support_colour.x(), style.support_colour.y(),
              style.support_colour.z(), 1.0f);
  glDisable(GL_DEPTH_TEST);  // the supports are always visible
  glDrawArrays(GL_POINTS, gl_->support_first, gl_->support_count);
  gl::set_program_point_size(false);
}

unsigned ClothRenderer::render(const ClothBuffers& buffers, const OrbitCamera& camera,
                               FrameSize size, const ClothStyle& style) {
  GLint previous_viewport[4];
  glGetIntegerv(GL_VIEWPORT, previous_viewport);
  resize(size);
  update_print(style);
  const float aspect =
      static_cast<float>(size.width) / static_cast<float>(std::max(size.height, 1));
  const Eigen::Matrix4f view_projection = camera.projection(aspect) * camera.view();
  upload_stale(buffers, camera, size, style);
  begin_drawing(size, style);
  draw_cloth_surface(buffers, style, view_projection, camera.eye());
  draw_lines(buffers, style, view_projection, size);
  draw_decorations(style);
  glBindVertexArray(0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2],
             previous_viewport[3]);
  ++counters_.frames;
  return gl_->colour_texture.get();
}

}  // namespace foldlab::gui
