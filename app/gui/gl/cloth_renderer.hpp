// The 3D view: the deformed cloth with two-sided lighting that reads pleats (a grazing key light, a
// fill, occlusion from the fold geometry, a soft ground shadow), prints as mip-mapped textures, an
// optional wireframe, the fold lines on its surface, the supports and a ground grid, drawn with
// OpenGL 3.3 core into a texture that an ImGui window shows. GPU buffers are re-uploaded only when
// the scene's stage versions change.
#pragma once

#include <memory>

#include <Eigen/Core>

#include "app/gui/camera.hpp"
#include "app/gui/cloth_uploads.hpp"
#include "app/gui/renderer.hpp"
#include "core/geometry/level_of_detail.hpp"

namespace foldlab::gui {

class ClothRenderer {
 public:
  ClothRenderer();
  ~ClothRenderer();
  ClothRenderer(const ClothRenderer&) = delete;
  ClothRenderer& operator=(const ClothRenderer&) = delete;

  // Draws the cloth into the renderer's own framebuffer and returns its colour texture (GL name).
  // Leaves the framebuffer binding at 0 and the viewport as it found it.
  unsigned render(const ClothBuffers& buffers, const OrbitCamera& camera, FrameSize size,
                  const ClothStyle& style);

  const RenderCounters& counters() const { return counters_; }
  // The framebuffer render() drew into (GL name), for copying it to the screen.
  unsigned framebuffer() const;

 private:
  struct Gl;
  void resize(FrameSize size);
  // `indices_too`: the lattice's size changed, so its triangles are uploaded as well.
  void upload_mesh(const ClothBuffers& buffers, float z_scale, const DrawnLattice& lattice,
                   bool indices_too);
  void upload_fold_lines(const FoldLines& lines, const ClothStyle& style);
  void upload_decorations(const ClothBuffers& buffers);
  void update_print(const ClothStyle& style);
  void select_mesh_program(const ClothStyle& style);
  void set_mesh_colour_uniforms(const ClothBuffers& buffers, const ClothStyle& style);
  void draw_shadow(const ClothBuffers& buffers, const Eigen::Matrix4f& view_projection);
  // The steps of render(), in order.
  void upload_stale(const ClothBuffers& buffers, const OrbitCamera& camera, FrameSize size,
                    const ClothStyle& style);
  void begin_drawing(FrameSize size, const ClothStyle& style);
  void draw_cloth_surface(const ClothBuffers& buffers, const ClothStyle& style,
                          const Eigen::Matrix4f& view_projection, const Eigen::Vector3f& eye);
  void draw_lines(const ClothBuffers& buffers, const ClothStyle& style,
                  const Eigen::Matrix4f& view_projection, FrameSize size);
  void draw_decorations(const ClothStyle& style);

  // The GL objects, each owned by a handle; kept out of the header so that it needs no GL include.
  std::unique_ptr<Gl> gl_;
  FrameSize size_{};
  ClothUploadRule upload_rule_;  // what the buffers were last made from
  RenderCounters counters_;
  // The print texture's contents: 0 none, 1 checks, 2 stripes (both from print_colour_), 3 photo.
  int print_kind_ = -1;
  Eigen::Vector3f print_colour_{-1, -1, -1};
  const PrintImage* print_photo_ = nullptr;
};

}  // namespace foldlab::gui
