#include "app/gui/cloth_uploads.hpp"

#include <algorithm>

#include "app/gui/renderer.hpp"

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

ClothBufferSources cloth_buffer_sources(Scene& scene, const OrbitCamera& camera, FrameSize size,
                                        const ClothStyle& style) {
  ClothBufferSources sources;
  scene.normals();
  const DeformedGrid& grid = scene.grid();
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
                                    scene.solution().n);
  }
  if (style.fold_lines) {
    scene.fold_lines();
  }
  sources.normals_version = scene.version(Stage::normals);
  sources.fold_lines_version = scene.version(Stage::fold_lines);
  sources.grid_version = scene.version(Stage::grid);
  sources.fold_lines_shown = style.fold_lines;
  sources.z_scale = style.z_exaggeration;
  sources.positive_fold_colour = style.positive_fold_colour;
  sources.negative_fold_colour = style.negative_fold_colour;
  return sources;
}

}  // namespace foldlab::gui
