// Pictures for a mood board or a slide: the 3D cloth, the fold plot, the sweep's plots or A and B
// side by side, alone, with no interface, at any size, over white, dark or nothing (alpha 0),
// optionally with a caption of the fabric, its results and its inputs. `foldlab picture` and the
// Export menu's picture dialog draw them through this one path, in an ImGui context of the
// picture's own size (Renderer::render_picture).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/gui/camera.hpp"
#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/sweep_panel.hpp"
#include "app/gui/renderer.hpp"

namespace foldlab::gui {

enum class PictureBackground { white, transparent, dark };

struct PictureSpec {
  PictureView view = PictureView::cloth;
  FrameSize size{1920, 1080};
  PictureBackground background = PictureBackground::white;
  bool caption = false;  // a strip at the bottom: the fabric, n, Q, z_max and the inputs
  bool legend = false;   // the fold plot's legend
};

// The backgrounds by the names the command line takes: "white", "transparent", "dark"; nullopt
// for any other. (The views' names are their panels' offers: panel_list.hpp.)
std::optional<PictureBackground> parse_picture_background(std::string_view name);
inline constexpr const char* kPictureBackgroundNames = "white, transparent, dark";

// A picture's sides are those of a window (kMinFrameSize..kMaxFrameSize) and its pixels at most
// this many: 8192 x 4096 (33.5 megapixels), 128 MB of RGBA, drawn twice over (the cloth's
// framebuffer and the picture's).
inline constexpr std::int64_t kMaxPicturePixels = std::int64_t{8192} * 4096;
// Why `size` cannot be a picture's (nullopt when it can).
std::optional<std::string> picture_size_problem(FrameSize size);
// The two sides typed in the picture dialog's custom size: the size, or why there is none,
// saying the ranges in words ("The width must be from 200 to 8192 pixels, not 99999."). The text
// is read whole, digits alone, so that a long number is too large rather than wrapped around.
struct TypedPictureSize {
  std::optional<FrameSize> size;
  std::string problem;  // empty when `size` is set
};
TypedPictureSize read_typed_picture_size(std::string_view width, std::string_view height);
// The digits a side's field keeps: enough for the largest side and one more, so that one typed
// too many is seen and said rather than cut off.
inline constexpr std::size_t kPictureSideDigits = 5;

// "WxH" as a picture's size; the problem otherwise.
std::optional<FrameSize> parse_picture_size(std::string_view text, std::string& problem);

// The text of a picture, in pixels: proportional to the picture, so that a caption is read
// alike at 1920x1080 and 3000x2000, never below the window's own size.
float picture_text_px(FrameSize size);

// The 3D view's lines and supports in a picture of `size`, in pixels: as wide as in the window
// at the window's text size, and in proportion to the picture's text beyond it.
float picture_line_width_px(FrameSize size);

// The caption's lines: the fabric's name with n, Q and z_max (with the ranges Results shows),
// then the inputs in the units the explorer shows them (t mm, E MPa, w g/m², h, L, d mm). With
// `with_b` (B pinned), A's lines and then B's, each name after its letter.
// `drawn`: the solution A's cloth was drawn with when not the closed form's (the tension field's
// folds), said in `drawn_words` after its n, Q and z_max.
std::vector<std::string> picture_caption(Document& document, bool with_b = false,
                                         const Solution* drawn = nullptr,
                                         std::string_view drawn_words = {});

// What a picture is drawn from: the explorer's document and its 3D view.
struct PictureSource {
  Document& document;
  ClothStyle style;  // the 3D view's; the background is the picture's
  // The 3D view's camera; nullopt frames the cloth as the 3D view does at first.
  std::optional<OrbitCamera> camera;
  ClothView cloth_view = kNoClothView;  // the renderer's view kept for pictures
  std::filesystem::path font_file;      // empty: ImGui's built-in font
  // The Sweep tab, whose axis, curves and paper points a sweep picture shows.
  SweepPanel* sweep = nullptr;
  ClothView compare_cloth_view = kNoClothView;  // B's, for a compare picture
  // The explorer's panels: a view whose panel draws its own pictures is drawn by it.
  std::span<const std::unique_ptr<Panel>> panels = {};
  // The scene the 3D view drew A's cloth from when it was not the document's (the tension
  // field's folds), so that its picture shows the same cloth; null: the document's.
  Scene* cloth_scene = nullptr;
  // Whose folds cloth_scene has, for the caption: "folds from the tension field".
  std::string cloth_scene_words;
};

// The caption `spec` asks for (none without spec.caption): a cloth picture drawn from the field's
// folds (source.cloth_scene) gives their n, Q and z_max and says whose they are.
std::vector<std::string> picture_caption(const PictureSource& source, const PictureSpec& spec);

// The source the explorer's panels give: the 3D view's style and camera once it has framed the
// cloth (until then, framed as it would be), and the Sweep tab.
PictureSource picture_source(Document& document, std::span<const std::unique_ptr<Panel>> panels,
                             ClothView cloth_view, ClothView compare_cloth_view,
                             const std::filesystem::path& font_file);

// Why `spec` cannot be drawn from `source` as it is (a compare picture with no B pinned, a sweep
// whose axis is refused); nullopt when it can.
std::optional<std::string> picture_problem(const PictureSource& source, const PictureSpec& spec);

// The picture's pixels, spec.size, top row first, with alpha.
std::vector<std::uint8_t> draw_picture(Renderer& renderer, const PictureSource& source,
                                       const PictureSpec& spec);

}  // namespace foldlab::gui
