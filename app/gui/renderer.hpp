// The renderer layer: the only place that talks to the GPU. Panels and the frame loop ask it for
// what they need (the 3D view of the cloth, an image for ImGui::Image, opaque window backgrounds,
// the frame's pixels) and never call GL themselves. GlRenderer (app/gui/gl/) draws with OpenGL
// 3.3; NullRenderer draws nothing, so that the explorer runs in a test process with no context.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <imgui.h>
#include <Eigen/Core>

#include "app/gui/camera.hpp"
#include "app/gui/cloth_uploads.hpp"
#include "app/gui/print_image.hpp"

namespace foldlab::gui {

struct FrameSize {
  int width = 0;
  int height = 0;
  bool operator==(const FrameSize&) const = default;
};

struct ClothStyle {
  bool wireframe = false;  // shows the grid as it is, every vertex drawn
  // Draws the grid's rows and columns a few pixels apart on screen rather than every vertex
  // (core/geometry/level_of_detail.hpp); off draws them all, as the wireframe does.
  bool level_of_detail = true;
  bool fold_lines = true;
  bool ground = true;
  float z_exaggeration = 1.0f;  // draws z (out of plane) this many times deeper; a view aid only
  // A photo is tiled every print_mm on the flat cloth; checks and stripes are drawn from tiles made
  // on the CPU. All three are mip-mapped textures, so fine folds show no moire.
  enum class Print { plain, checks, stripes, photo } print = Print::plain;
  float print_mm = 60.0f;  // size of a check, the width of a stripe, or the side of the photo
  std::shared_ptr<const PrintImage> photo;  // print == photo; nothing else sets it
  // Colours the cloth by its out-of-plane depth z (a diverging map over +-z_max, the colour bar
  // beside the view) or by the sign of the fold a point belongs to; none shows the fabric.
  enum class ColourBy { none, z, fold_sign } colour_by = ColourBy::none;
  bool breeze = false;  // foldlab::breeze_offset on top of the wrinkles
  float breeze_mm = 60.0f;
  float time_s = 0.0f;
  Eigen::Vector3f front_colour{0.93f, 0.86f, 0.74f};  // the fabric's two faces
  Eigen::Vector3f back_colour{0.72f, 0.78f, 0.92f};
  Eigen::Vector3f positive_fold_colour{0.12f, 0.23f, 0.58f};
  Eigen::Vector3f negative_fold_colour{0.84f, 0.15f, 0.16f};
  Eigen::Vector3f background{0.16f, 0.17f, 0.20f};
  Eigen::Vector3f support_colour{0.95f, 0.85f, 0.25f};  // the supports' markers
  // 0 leaves the picture transparent around the cloth (a picture with a transparent background).
  float background_alpha = 1.0f;
  // The fold lines' and the ground's width and the supports' scale, in pixels at 1: wider in a
  // large picture, where one pixel would all but vanish.
  float line_width_px = 1.0f;
  // Every field takes part: the 3D view's picture is kept only while its style is unchanged.
  bool operator==(const ClothStyle&) const = default;
};

// What reached the GPU: buffers are uploaded only when what they are made from changed
// (ClothUploadRule), and the 3D view's picture is drawn again only when what it shows changed
// (ClothViewCache).
struct RenderCounters {
  std::uint64_t mesh_uploads = 0;
  std::uint64_t fold_line_uploads = 0;
  std::uint64_t frames = 0;           // frames that showed the 3D view
  std::uint64_t view_renders = 0;     // of which the picture was drawn
  std::uint64_t view_cache_hits = 0;  // and the last picture was shown again
  std::uint64_t drawn_columns = 0;    // the grid's columns and rows the 3D view drew last
  std::uint64_t drawn_rows = 0;
};

// Whether the 3D view's picture must be drawn again. On a software GL (llvmpipe) drawing the
// cloth is most of a frame, yet most frames show the same picture: a hover, a tooltip, a plot
// zoomed, a frame woken by the idle timeout. The picture depends on the versions of the buffers it
// shows, the camera, the view's size and the style, and on nothing else; while all of them are
// unchanged the renderer keeps the last picture and only copies it to the screen.
class ClothViewCache {
 public:
  // True when the picture drawn last shows exactly this; otherwise remembers this as the picture
  // about to be drawn. Counts either outcome in `counters`.
  bool reuse(const ClothBuffers& buffers, const OrbitCamera& camera, FrameSize size,
             const ClothStyle& style, RenderCounters& counters);
  // The kept picture is gone (its framebuffer was lost or re-made): the next call draws.
  void forget() { drawn_.reset(); }

 private:
  struct Key {
    std::uint64_t normals_version = 0;
    std::uint64_t fold_lines_version = 0;  // 0 when the style hides the fold lines
    std::uint64_t grid_version = 0;
    OrbitCamera camera;
    FrameSize size;
    ClothStyle style;
    bool operator==(const Key&) const = default;
  };
  std::optional<Key> drawn_;
};

// A cloth the renderer keeps buffers and a picture for (create_cloth_view). A panel showing two
// cloths side by side asks for two, so that each uploads only what changed in it, and the second
// costs nothing until it is first drawn.
using ClothView = int;
inline constexpr ClothView kNoClothView = -1;

class Renderer {
 public:
  virtual ~Renderer() = default;

  // Once per frame, before ImGui::NewFrame.
  virtual void new_frame() = 0;
  // The font atlas was rebuilt (a new UI scale): its texture must be made again.
  virtual void fonts_changed() = 0;
  // Fills the current window's content area with the style's (opaque) window background, behind
  // everything the window draws. The style's own WindowBg is transparent.
  virtual void fill_window_background() = 0;
  virtual ClothView create_cloth_view() = 0;
  // Draws `view`'s cloth as a `size` picture into [min, min + size) of `draw_list`, uploading only
  // the buffers that changed; while nothing the picture shows has changed, shows the last one
  // again instead of drawing it.
  virtual void draw_cloth(ClothView view, ImDrawList* draw_list, ImVec2 min,
                          const ClothBuffers& buffers, const OrbitCamera& camera, FrameSize size,
                          const ClothStyle& style) = 0;
  // All zero for kNoClothView.
  virtual const RenderCounters& cloth_counters(ClothView view) const = 0;
  // The time spent so far in the 3D views' uploads and draw calls (ms, on this thread; the GPU
  // may finish them later): a part of `gui --report`'s key latency.
  virtual double cloth_render_ms_total() const { return 0.0; }

  // An RGBA image for ImGui::Image, kept by the renderer until it is destroyed. The first row of
  // `rgba` is the image's first (GL: bottom) row.
  virtual int create_image() = 0;
  virtual void update_image(int image, int width, int height, const std::uint32_t* rgba) = 0;
  virtual ImTextureID texture(int image) const = 0;
  // The same for a photo, which is drawn scaled down and rotated: sampled smoothly (mipmaps), so
  // that thin lines in it do not break up. `rgba` is top row first, for uv (0, 0) at the top left.
  virtual void update_photo(int image, int width, int height, const std::uint32_t* rgba) = 0;

  // Draws ImGui's draw data onto the frame's framebuffer (bound by the surface), cleared first.
  virtual void render_draw_data(FrameSize size) = 0;
  // The frame's pixels, top row first, opaque: for screenshots.
  virtual std::vector<std::uint8_t> read_pixels(FrameSize size) = 0;

  // A picture of exactly `size` drawn off-screen, apart from the window and of any size the GL
  // takes: `build` runs in frames of the current ImGui context, which the caller made for the
  // picture (display size `size`, no input), and the last is drawn over `clear`. Returns its
  // pixels, top row first, with their alpha. The window's framebuffer is bound again afterwards.
  virtual std::vector<std::uint8_t> render_picture(FrameSize size, ImVec4 clear,
                                                   const std::function<void()>& build) = 0;
};

// Draws nothing and reads nothing, but pulls the scene's stages and counts uploads by the GL
// renderer's own rule (cloth_uploads.hpp), so that what a frame computes and uploads is the same
// with and without a GPU. Images are never sampled.
class NullRenderer final : public Renderer {
 public:
  void new_frame() override {}
  // Builds the atlas's pixels, as a backend would before uploading them.
  void fonts_changed() override;
  void fill_window_background() override {}
  ClothView create_cloth_view() override;
  void draw_cloth(ClothView view, ImDrawList* draw_list, ImVec2 min, const ClothBuffers& buffers,
                  const OrbitCamera& camera, FrameSize size, const ClothStyle& style) override;
  const RenderCounters& cloth_counters(ClothView view) const override;
  int create_image() override { return image_count_++; }
  void update_image(int image, int width, int height, const std::uint32_t* rgba) override;
  ImTextureID texture(int image) const override;
  void update_photo(int image, int width, int height, const std::uint32_t* rgba) override {
    update_image(image, width, height, rgba);
  }
  void render_draw_data(FrameSize) override {}
  std::vector<std::uint8_t> read_pixels(FrameSize size) override;
  // Builds the picture's frames (what they compute is computed) and returns transparent pixels.
  std::vector<std::uint8_t> render_picture(FrameSize size, ImVec4 clear,
                                           const std::function<void()>& build) override;

  // How many times update_image sent pixels (the GL renderer would upload each).
  std::uint64_t image_updates() const { return image_updates_; }

 private:
  struct View {
    RenderCounters counters;
    ClothViewCache cache;
    ClothUploadRule upload_rule;
  };
  std::vector<View> views_;  // by ClothView
  int image_count_ = 0;
  std::uint64_t image_updates_ = 0;
};

// The GL renderer; needs a current GL 3.3 context and an ImGui context (it initialises ImGui's
// OpenGL3 backend and shuts it down when destroyed).
std::unique_ptr<Renderer> make_gl_renderer();

}  // namespace foldlab::gui
