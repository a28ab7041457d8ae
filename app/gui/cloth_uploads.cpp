#include "app/gui/cloth_uploads.hpp"

#include <algorithm>
#include <cmath>

#include "app/gui/renderer.hpp"
#include "core/geometry/geometry.hpp"
#include "core/geometry/scene.hpp"

namespace foldlab::gui {

Eigen::Vector3f world_scale(float z_scale) {
  return {1.0f, -1.0f, z_scale};
}

ClothUploads ClothUploadRule::next(const ClothBufferSources& wanted) {
  ClothUploads uploads;
  uploads.mesh = wanted.normals_version != mesh_version_ || wanted.z_scale != mesh_z_scale_ ||
                 wanted.lattice.columns != mesh_lattice_.columns ||
                 wanted.lattice.rows != mesh_lattice_.rows;
  if (uploads.mesh) {
    uploads.mesh_indices = wanted.lattice.columns.size() != mesh_lattice_.columns.size() ||
                           wanted.lattice.rows.size() != mesh_lattice_.rows.size();
    mesh_version_ = wanted.normals_version;
    mesh_z_scale_ = wanted.z_scale;
    mesh_lattice_ = wanted.lattice;
  }
  if (wanted.fold_lines_shown) {
    uploads.fold_lines = wanted.fold_lines_version != fold_line_version_ ||
                         wanted.positive_fold_colour != positive_fold_colour_ ||
                         wanted.z_scale != lines_z_scale_ ||
                         wanted.negative_fold_colour != negative_fold_colour_;
    if (uploads.fold_lines) {
      fold_line_version_ = wanted.fold_lines_version;
      lines_z_scale_ = wanted.z_scale;
      positive_fold_colour_ = wanted.positive_fold_colour;
      negative_fold_colour_ = wanted.negative_fold_colour;
    }
  }
  uploads.decorations = wanted.grid_version != decoration_version_;
  decoration_version_ = wanted.grid_version;
  return uploads;
}

void update_cloth_buffers(Scene& scene, const ClothStyle& style, ClothBuffers& b) {
  b.normals = &scene.normals();
  b.grid = &scene.grid();
  b.fold_lines = style.fold_lines ? &scene.fold_lines() : nullptr;
  b.fold_lines_version = style.fold_lines ? scene.version(Stage::fold_lines) : 0;
  b.normals_version = scene.version(Stage::normals);
  const std::uint64_t grid_version = scene.version(Stage::grid);
  if (grid_version == b.grid_version && grid_version != 0) {
    return;  // the numbers below follow the solution and the shape, which re-make the grid
  }
  b.grid_version = grid_version;
  const Solution& s = scene.solution();
  const Parameters& p = scene.parameters();
  b.fold_count = s.n;
  b.height_mm = static_cast<float>(p.hanging.height_mm);
  b.occlusion_reach_mm = static_cast<float>(p.hanging.height_mm / std::max(1, s.n + 1));
  b.lowest_point_mm = static_cast<float>(lowest_point_mm(s, p.hanging.height_mm));
  b.z_max_mm = static_cast<float>(s.z_max_mm);
  b.ground_depth_mm =
      static_cast<float>(lowest_point_mm(s, p.hanging.height_mm) + 0.05 * p.hanging.height_mm);
  // Wide enough for every span of a strip, with a span's margin beyond the outer supports.
  double widest_mm = 0.0;
  b.supports_mm.clear();
  for (const Eigen::Vector3d& support : support_points(s.span_mm, p.shape)) {
    widest_mm = std::max(widest_mm, std::abs(support.x()));
    b.supports_mm.push_back(support.cast<float>());
  }
  const float one_span =
      static_cast<float>(0.75 * std::max(p.hanging.length_mm, p.hanging.height_mm));
  b.ground_extent_mm = std::max(one_span, static_cast<float>(widest_mm + 0.5 * s.span_mm));
  b.ground_spacing_mm = std::pow(10.0f, std::floor(std::log10(one_span / 2.0f)));
  while (b.ground_extent_mm / b.ground_spacing_mm > 50.0f) {
    b.ground_spacing_mm *= 10.0f;  // a long strip: no more than a hundred lines each way
  }
}

ClothBuffers cloth_buffers(Scene& scene, const ClothStyle& style) {
  ClothBuffers b;
  update_cloth_buffers(scene, style, b);
  return b;
}

ClothBufferSources cloth_buffer_sources(const ClothBuffers& buffers, const OrbitCamera& camera,
                                        FrameSize size, const ClothStyle& style) {
  ClothBufferSources sources;
  const DeformedGrid& grid = *buffers.grid;
  if (style.wireframe || !style.level_of_detail) {
    sources.lattice = full_lattice(grid);
  } else {
    const float aspect =
        static_cast<float>(size.width) / static_cast<float>(std::max(size.height, 1));
    const Eigen::Matrix4f view_projection = camera.projection(aspect) * camera.view();
    const Eigen::Vector3f scale = world_scale(style.z_exaggeration);
    const Eigen::Matrix4f model_to_clip =
        view_projection *
        Eigen::Vector4f(scale.x(), scale.y(), scale.z(), 1.0f).asDiagonal().toDenseMatrix();
    sources.lattice = drawn_lattice(grid,
                                    screen_spacing(grid, model_to_clip,
                                                   Eigen::Vector2f(static_cast<float>(size.width),
                                                                   static_cast<float>(size.height)),
                                                   scale),
                                    buffers.fold_count);
  }
  sources.normals_version = buffers.normals_version;
  sources.fold_lines_version = buffers.fold_lines_version;
  sources.grid_version = buffers.grid_version;
  sources.fold_lines_shown = style.fold_lines;
  sources.z_scale = style.z_exaggeration;
  sources.positive_fold_colour = style.positive_fold_colour;
  sources.negative_fold_colour = style.negative_fold_colour;
  return sources;
}

}  // namespace foldlab::gui
