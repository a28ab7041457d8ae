// The "Cloth (3D)" panel: the view's settings (wireframe, fold lines, ground, z exaggeration,
// print, breeze) and the orbit camera, with the picture drawn by the renderer. Until the user
// moves the camera it follows the cloth, so a slider never drags the cloth out of view.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <imgui.h>

#include "app/gui/camera.hpp"
#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/view_toolbar.hpp"

namespace foldlab::gui {

// `style` with the cloth's front in the fabric's own colour, or in the style's default colour
// (ClothStyle's) for a fabric with none: each of A and B is drawn in its own.
ClothStyle in_fabric_colour(ClothStyle style, const foldlab::Appearance& appearance);

// Whose folds the 3D cloth is drawn with: the closed form's (the model's solution) or those read
// from the tension field (core/field/field_folds.hpp), through the same geometry.
enum class FoldSource { closed_form, field };

class ClothViewPanel : public Panel {
 public:
  const char* name() const override { return "Cloth (3D)"; }
  const char* introduction() const override {
    return "the same folds on the cloth itself; drag to turn it, the z exaggeration "
           "deepens the folds to see them.";
  }
  const char* key() const override { return "cloth"; }
  void draw(PanelContext& context) override;
  void presented_menu_items(PanelContext& /*context*/) override { toolbar_row_.menu_item(); }
  // The print and its file, colour, breeze, z exaggeration, switches and `full`.
  void view_settings(ViewSettings& settings, Document& document) override;
  // Asks the tension field panel to solve the field while the folds come from it.
  void begin_frame(PanelContext& context) override;
  // "camera", the renderer's counters of A's and B's cloth ("renderer") and "fold_source": the
  // source chosen, the one drawn ("closed_form", "field", "previous_field"), the drawn n, Q, z_max
  // and a_i, what the view says of it, the frames drawn by each while the field's folds are
  // chosen ("frames") and the colour bar's title and z_max ("colour_bar", null when not shown).
  void report(nlohmann::json& state, PanelContext& context) const override;
  // The cloth, and A and B side by side.
  static constexpr PictureOffer kPictures[] = {
      {PictureView::cloth, "cloth", "Export 3D view picture", "3D view picture (.png)...",
       "3D view picture, any size (.png)...",
       "The 3D view's cloth alone, as the view shows it now.", "3d-view"},
      {PictureView::compare, "compare", "Export A and B picture", nullptr,
       "A and B picture, any size (.png)...",
       "A and B side by side, as the 3D view shows them now.", "a-and-b"}};
  std::span<const PictureOffer> pictures() const override { return kPictures; }
  std::optional<std::string> picture_unavailable(PictureView view, const Document& document,
                                                 bool as_drawn) const override;
  std::optional<PanelRect> picture_rect(PictureView /*view*/) const override { return view_rect_; }
  // "cloth": the 3D viewport (the colour bar beside it left out).
  void drawing_areas(DrawingAreas& areas) const override {
    if (const std::optional<PanelRect> rect = drawn_.recent()) {
      areas.emplace_back(key(), *rect);
    }
  }
  // The swatch file last asked for as the print.
  std::vector<app::NamedPath> files_in_use() const override {
    return {{"the 3D view's print file", photo_path_}};
  }

  static constexpr const char* kBrowseLabel = "browse...";
  ClothStyle& style() { return style_; }
  const OrbitCamera& camera() const { return camera_; }
  // False until the view first framed the cloth (it has not been drawn yet).
  bool camera_framed() const { return camera_framed_; }
  // The renderer's views of A's cloth (the one being edited) and of B's (pinned beside it);
  // kNoClothView until first drawn.
  ClothView a_view() const { return views_[0]; }
  ClothView b_view() const { return views_[1]; }
  const ClothStyle& style() const { return style_; }
  // True while the breeze plays: every frame shows a new instant.
  bool animating() const override { return style_.breeze && breeze_playing_; }
  // Where the view's picture was drawn last (display pixels), for a picture of the view alone.
  const PanelRect& view_rect() const { return view_rect_; }
  FoldSource fold_source() const { return fold_source_; }
  // The field's folds A's cloth was drawn with at the last frame; none when it was drawn with the
  // closed form's (chosen, or standing in while the field is solved).
  const std::optional<FoldOverride>& drawn_field_folds() const { return drawn_field_folds_; }
  // The scene with the field's folds while the view draws it, for its pictures; else null.
  Scene* drawn_field_scene() { return drawn_field_folds_ ? &field_scene_ : nullptr; }
  // Whose folds A's cloth was drawn with at the last frame, in words for a caption ("folds from
  // the tension field"); empty for the closed form's.
  const char* drawn_folds_words() const;
  // The scene to draw A's cloth from this frame: the document's, or one with the field's folds
  // when they are chosen and converged (or, while the field of these inputs is being solved, the
  // last converged field's); sets what the view says of the fold source. The read-out over the
  // presented view asks before the view draws.
  Scene& scene_to_draw(PanelContext& context);
  // Whether the settings above the view are folded behind a "settings..." button.
  bool toolbar_folded() const { return toolbar_row_.folded(); }

 private:
  // The row of controls above the view; true when "reset camera" was clicked.
  bool toolbar(PanelContext& context);
  void steer_camera(FrameSize size);
  static void draw_hint(ImDrawList* draw, ImVec2 origin, FrameSize area, bool light);
  void name_halves(const Document& document, ImDrawList* draw, ImVec2 origin, FrameSize size,
                   FrameSize area) const;
  void settings_row();
  // The swatch that opens the colour picker, and the button back to the view's own colour.
  void colour_picker(Document& document);
  static float colour_field_width();
  // Loads a swatch photo as the print; the problem (also shown in the panel), if any.
  std::optional<std::string> load_photo(const std::string& path);
  static float colour_bar_width();
  void draw_colour_bar(ImVec2 min, float width, float height, double z_max_mm);
  void follow_the_cloth(Document& document, bool reset, bool hold);
  void fold_source_line() const;

  ClothStyle style_;
  FoldSource fold_source_ = FoldSource::closed_form;
  Scene field_scene_;  // the document's inputs with the field's folds
  std::optional<FoldOverride> drawn_field_folds_;
  // Whose folds A's cloth was drawn with at the last frame.
  enum class DrawnFolds { closed_form, field, previous_field };
  DrawnFolds drawn_from_ = DrawnFolds::closed_form;
  // Frames drawn while the field's folds were chosen, by DrawnFolds.
  std::array<std::uint64_t, 3> frames_drawn_{};
  // The colour bar's title and top value as last drawn, for the report.
  bool colour_bar_drawn_ = false;
  std::string colour_bar_title_;
  double colour_bar_z_max_mm_ = 0.0;
  std::string fold_words_;        // empty with the closed form chosen
  bool fold_words_warn_ = false;  // the field's folds were asked for and are not drawn
  OrbitCamera camera_;
  ClothView views_[2] = {kNoClothView, kNoClothView};  // A, B
  ClothBuffers buffers_[2];                            // what each view drew last
  bool camera_framed_ = false;
  Eigen::Vector3f framed_centre_ = Eigen::Vector3f::Zero();  // the sphere last framed
  float framed_radius_mm_ = 1.0f;
  bool camera_user_moved_ = false;
  std::uint64_t camera_grid_version_ = 0;
  std::uint64_t camera_loads_ = 0;
  std::uint64_t camera_compare_changes_ = 0;  // B as the camera was last framed for it
  std::uint64_t camera_b_grid_version_ =
      0;  // the document's preset loads the camera was framed for
  bool breeze_playing_ = true;
  bool fill_display_ = false;
  std::string photo_path_;
  char photo_input_[512] = {};
  std::string photo_problem_;
  PanelRect view_rect_;
  DrawnArea drawn_;
  ViewToolbar toolbar_row_;
};

}  // namespace foldlab::gui
