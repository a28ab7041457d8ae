// When the 3D view's GPU buffers must be made again. The GL cloth renderer (app/gui/gl/) uploads
// what this rule asks for, and the NullRenderer runs the same rule with no GPU, so that the upload
// counts a test reads through the NullRenderer are the real renderer's. No GL here.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "app/gui/camera.hpp"
#include "core/geometry/geometry.hpp"
#include "core/geometry/level_of_detail.hpp"

namespace foldlab {
class Scene;
}

namespace foldlab::gui {

struct FrameSize;  // renderer.hpp, which includes this header
struct ClothStyle;

// What the 3D view draws, made from a scene by the panel that shows it (cloth_buffers): the
// renderer draws these and never sees the model. The pointers are into the scene's stages and stay
// valid until the scene changes; each part carries the version it was made from, so that a
// renderer uploads only what changed.
struct ClothBuffers {
  const DeformedGrid* grid = nullptr;
  const std::vector<Eigen::Vector3f>* normals = nullptr;  // per vertex of the grid
  const FoldLines* fold_lines = nullptr;                  // null while the style hides them
  std::uint64_t normals_version = 0;
  std::uint64_t fold_lines_version = 0;  // 0 while hidden
  std::uint64_t grid_version = 0;
  int fold_count = 0;  // n: the level of detail keeps a row in every fold
  // The occlusion looks as far as a fold's spacing: the walls of the fold a point sits in, not
  // the far side of the cloth.
  float occlusion_reach_mm = 0.0f;
  float height_mm = 0.0f;        // the shadow's softness follows the cloth's height
  float lowest_point_mm = 0.0f;  // where the breeze sways most
  float z_max_mm = 0.0f;         // the colour map's range when colouring by z
  // The ground grid below the cloth (its depth, half-width and line spacing) and the supports, in
  // model coordinates; they follow the grid's version.
  float ground_depth_mm = 0.0f;
  float ground_extent_mm = 0.0f;
  float ground_spacing_mm = 0.0f;
  std::vector<Eigen::Vector3f> supports_mm;
};

// Brings the stages the view shows up to date (lazily: the fold lines only when the style shows
// them) and points at them. `kept`, the buffers made last frame for the same view, keeps the
// numbers that follow the solution (the ground, the supports, ...) until the grid is made again.
void update_cloth_buffers(Scene& scene, const ClothStyle& style, ClothBuffers& kept);
ClothBuffers cloth_buffers(Scene& scene, const ClothStyle& style);

// Model coordinates have y pointing down (gravity); the view's world has +Y up. z may be drawn
// exaggerated: a position scales by this, a normal by its inverse.
Eigen::Vector3f world_scale(float z_scale);

// What the cloth's buffers are made from: the scene's stage versions, the parts of the style baked
// into vertices (the z exaggeration, the fold lines' colours) and the grid's rows and columns
// drawn.
struct ClothBufferSources {
  std::uint64_t normals_version = 0;
  std::uint64_t fold_lines_version = 0;
  std::uint64_t grid_version = 0;
  bool fold_lines_shown = true;
  float z_scale = 1.0f;
  Eigen::Vector3f positive_fold_colour{0, 0, 0};
  Eigen::Vector3f negative_fold_colour{0, 0, 0};
  DrawnLattice lattice;
};

// The buffers to make again.
struct ClothUploads {
  bool mesh = false;          // the drawn lattice's vertices
  bool mesh_indices = false;  // and its triangles: the lattice's number of rows or columns changed
  bool fold_lines = false;
  bool decorations = false;  // the ground and the supports
  bool operator==(const ClothUploads&) const = default;
};

// Remembers what the buffers were last made from. The mesh is made again when the normals, the z
// exaggeration or the drawn lattice change; the fold lines, while shown, when they, their colours
// or the z exaggeration change; the ground and the supports when the grid is made again (they
// follow the solution and the shape, and both re-make the grid). The first call makes everything.
class ClothUploadRule {
 public:
  // What must be uploaded to show `wanted`; from then on `wanted` counts as uploaded.
  ClothUploads next(const ClothBufferSources& wanted);

 private:
  // None of the versions is ever ~0 and no exaggeration or colour is -1: the first call uploads.
  std::uint64_t mesh_version_ = ~std::uint64_t{0};
  float mesh_z_scale_ = -1.0f;
  DrawnLattice mesh_lattice_;
  std::uint64_t fold_line_version_ = ~std::uint64_t{0};
  float lines_z_scale_ = -1.0f;
  Eigen::Vector3f positive_fold_colour_{-1, -1, -1};
  Eigen::Vector3f negative_fold_colour_{-1, -1, -1};
  std::uint64_t decoration_version_ = ~std::uint64_t{0};
};

// The sources of a frame's buffers: picks the lattice for the view's size and camera
// (level_of_detail.hpp), or every vertex for the wireframe or with the level of detail off.
ClothBufferSources cloth_buffer_sources(const ClothBuffers& buffers, const OrbitCamera& camera,
                                        FrameSize size, const ClothStyle& style);

}  // namespace foldlab::gui
