#include "app/gui/panels/cloth_view_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include <imgui.h>

#include <variant>

#include <nlohmann/json.hpp>

#include "app/gui/appearance.hpp"
#include "app/gui/colour_map.hpp"
#include "app/gui/compare.hpp"
#include "app/gui/input_words.hpp"
#include "app/gui/panels/field_panel.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "app/gui/panels/widgets.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

using nlohmann::json;

// The 3D view's numbers and the range each may take: the panel's sliders, a scripted `--view` and
// the remembered settings all read these rows, so that a value one accepts the others accept.
// A breeze below 5 mm is not seen: switching the breeze off says "none".
constexpr ViewRange<float> kBreezeMm{5.0f, 300.0f, " mm"};
constexpr ViewRange<float> kTimeS{0.0f, 1e6f, " s"};
constexpr ViewRange<float> kZExaggeration{1.0f, 20.0f, " (times)"};
constexpr ViewRange<float> kPrintMm{10.0f, 300.0f, " mm"};
constexpr std::string_view kPrintNames[] = {"plain", "checks", "stripes", "photo"};
constexpr std::string_view kColourByNames[] = {"none", "z", "fold_sign"};
constexpr std::string_view kFoldSourceNames[] = {"closed_form", "field"};
// As ClothViewPanel::DrawnFolds.
constexpr std::string_view kDrawnFoldsNames[] = {"closed_form", "field", "previous_field"};

constexpr const char* kFoldsFromLabel = "folds from";

// A logarithmic slider over the row's range, kept within it.
bool view_slider(const char* label, float& value, const ViewRange<float>& range,
                 const char* format) {
  return notched_slider(
      [&] {
        return ImGui::SliderFloat(label, &value, range.lo, range.hi, format,
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
      },
      [&] { return std::log(double{value} / range.lo) / std::log(double{range.hi} / range.lo); });
}

json counters_json(const RenderCounters& c) {
  return json{{"mesh_uploads", c.mesh_uploads},
              {"fold_line_uploads", c.fold_line_uploads},
              {"frames", c.frames},
              {"view_renders", c.view_renders},
              {"view_cache_hits", c.view_cache_hits},
              {"drawn_columns", c.drawn_columns},
              {"drawn_rows", c.drawn_rows}};
}

Eigen::Vector3f to_floats(ColourRgb8 c) {
  return Eigen::Vector3f(static_cast<float>(c.r), static_cast<float>(c.g),
                         static_cast<float>(c.b)) /
         255.0f;
}

ColourRgb8 to_bytes(const float rgb[3]) {
  const auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return ColourRgb8{byte(rgb[0]), byte(rgb[1]), byte(rgb[2])};
}

}  // namespace

ClothStyle in_fabric_colour(ClothStyle style, const foldlab::Appearance& appearance) {
  style.front_colour =
      appearance.colour ? to_floats(*appearance.colour) : ClothStyle{}.front_colour;
  return style;
}

std::optional<std::string> ClothViewPanel::load_photo(const std::string& path) {
  auto loaded = load_print_image(path);
  if (const std::string* problem = std::get_if<std::string>(&loaded)) {
    photo_problem_ = *problem;
    return *problem;
  }
  style_.photo = std::get<std::shared_ptr<const PrintImage>>(std::move(loaded));
  style_.print = ClothStyle::Print::photo;
  photo_problem_.clear();
  return std::nullopt;
}

void ClothViewPanel::view_settings(ViewSettings& settings, Document& document) {
  // The fabric's colour belongs to the fabric, not to the view: the session keeps it with the
  // edited preset, and a scripted one is an edit that undo takes back.
  settings.add_action(
      "colour",
      [&document](std::string_view value) -> std::optional<std::string> {
        foldlab::Appearance appearance = document.appearance();
        if (value == "none") {
          appearance.colour.reset();
        } else if (const std::optional<ColourRgb8> colour = parse_hex_colour(value)) {
          appearance.colour = colour;
        } else {
          return "colour = " + detail::cut(std::string(value)) +
                 " is not an sRGB colour: give #RRGGBB (six hex digits) or none for the view's "
                 "own colour";
        }
        document.set_appearance(appearance);
        return std::nullopt;
      },
      [&document] {
        const std::optional<ColourRgb8>& colour = document.appearance().colour;
        return colour ? json(hex_colour(*colour)) : json(nullptr);
      });
  // A swatch photo needs its file, which is not kept: the print it replaced is.
  settings.add_choice<ClothStyle::Print>(
      "print", &style_.print, kPrintNames, kEveryUse,
      [this] { return style_.print != ClothStyle::Print::photo; },
      [this](ClothStyle::Print print) -> std::optional<std::string> {
        if (print == ClothStyle::Print::photo && style_.photo == nullptr) {
          return "print = photo needs a photo: give print_file=PATH (or --print PATH)";
        }
        return std::nullopt;
      });
  settings.add_action(
      "print_file",
      [this](std::string_view value) {
        photo_path_ = std::string(value);
        const std::size_t shown = std::min(photo_path_.size(), sizeof photo_input_ - 1);
        std::copy_n(photo_path_.begin(), shown, photo_input_);
        photo_input_[shown] = '\0';
        return load_photo(photo_path_);
      },
      [this] { return style_.photo ? json(style_.photo->path) : json(nullptr); });
  settings.add_number("print_mm", &style_.print_mm, kPrintMm, kEveryUse);
  settings.add_choice<ClothStyle::ColourBy>("colour_by", &style_.colour_by, kColourByNames,
                                            kEveryUse);
  settings.add_switch("breeze", &style_.breeze, kScripted);
  settings.add_number("breeze_mm", &style_.breeze_mm, kBreezeMm, kScripted);
  // A scripted picture shows that instant.
  settings.add_number("time", &style_.time_s, kTimeS, kScripted,
                      [this] { breeze_playing_ = false; });
  settings.add_number("z_exaggeration", &style_.z_exaggeration, kZExaggeration, kEveryUse);
  settings.add_switch("wireframe", &style_.wireframe, kRemembered | kScripted);
  settings.add_switch("lod", &style_.level_of_detail, kScripted);
  settings.add_switch("fold_lines", &style_.fold_lines, kRemembered | kScripted);
  settings.add_switch("ground", &style_.ground, kRemembered | kScripted);
  settings.add_choice<FoldSource>("fold_source", &fold_source_, kFoldSourceNames, kEveryUse);
  // A view that fills the window.
  settings.add_switch("full", &fill_display_, kScripted);
}

void ClothViewPanel::begin_frame(PanelContext& context) {
  if (fold_source_ == FoldSource::field) {
    context.panel<FieldPanel>().ask_for_folds();
  }
}

Scene& ClothViewPanel::scene_to_draw(PanelContext& context) {
  Scene& closed = context.document.scene();
  fold_words_.clear();
  fold_words_warn_ = false;
  drawn_field_folds_.reset();
  drawn_from_ = DrawnFolds::closed_form;
  if (fold_source_ == FoldSource::closed_form) {
    return closed;
  }
  // Brought up to date for this frame's inputs before the view draws: the field's folds of the
  // inputs on show, not of the last frame's.
  const FieldFoldsNow now = context.panel<FieldPanel>().folds_now(context);
  const field::FieldFolds* folds = now.folds;
  if (now.state == FieldFoldsNow::State::solving && now.previous != nullptr) {
    // The frame's slice ran out before the field of these inputs converged: the last field that
    // did stands in, said to be of the inputs before.
    folds = now.previous;
    drawn_from_ = DrawnFolds::previous_field;
    fold_words_ = detail::printf_string(
        "Folds from the tension field of the previous inputs: n = %d, z_max = %.0f mm; the field "
        "of "
        "these inputs: %s",
        folds->n, folds->z_max_mm, now.words.c_str());
    fold_words_warn_ = true;
  } else if (now.state != FieldFoldsNow::State::converged) {
    // Never a field that has not converged as if it had: the closed form's folds stand in.
    fold_words_ = "Folds from the tension field: " + now.words +
                  "; the closed form's folds are drawn meanwhile.";
    fold_words_warn_ = true;
    return closed;
  } else {
    drawn_from_ = DrawnFolds::field;
    fold_words_ = detail::printf_string(
        "Folds from the tension field: n = %d, Q = %.3f, z_max = %.0f mm (the closed form's: "
        "n = %d, z_max = %.0f mm).",
        folds->n, folds->Q, folds->z_max_mm, closed.solution().n, closed.solution().z_max_mm);
  }
  field_scene_.set_parameters(closed.parameters());
  field_scene_.set_grid_resolution(closed.grid_nx(), closed.grid_ny());
  field_scene_.set_folds(FoldOverride{folds->n, folds->Q, folds->z_max_mm, folds->a_mm});
  // As the scene draws them, which is what the report says was drawn.
  const Solution& drawn = field_scene_.solution();
  drawn_field_folds_ = FoldOverride{drawn.n, drawn.Q, drawn.z_max_mm, drawn.a_mm};
  return field_scene_;
}

const char* ClothViewPanel::drawn_folds_words() const {
  switch (drawn_from_) {
    case DrawnFolds::field:
      return "folds from the tension field";
    case DrawnFolds::previous_field:
      return "folds from the tension field of the previous inputs";
    case DrawnFolds::closed_form:
      break;
  }
  return "";
}

void ClothViewPanel::fold_source_line() const {
  if (fold_words_.empty()) {
    return;
  }
  ImGui::PushStyleColor(ImGuiCol_Text, fold_words_warn_ ? kNoteText : kDimText);
  wrapped_text("%s", fold_words_.c_str());
  ImGui::PopStyleColor();
}

void ClothViewPanel::report(json& state, PanelContext& context) const {
  {
    json source = {
        {"source", std::string(kFoldSourceNames[static_cast<std::size_t>(fold_source_)])},
        {"drawn", std::string(kDrawnFoldsNames[static_cast<std::size_t>(drawn_from_)])},
        {"words", fold_words_.empty() ? json(nullptr) : json(fold_words_)}};
    // Frames drawn while the field's folds were chosen, by the folds each was drawn with.
    json frames = json::object();
    for (std::size_t i = 0; i < frames_drawn_.size(); ++i) {
      frames[std::string(kDrawnFoldsNames[i])] = frames_drawn_[i];
    }
    source["frames"] = std::move(frames);
    source["colour_bar"] =
        colour_bar_drawn_ ? json{{"title", colour_bar_title_}, {"z_max_mm", colour_bar_z_max_mm_}}
                          : json(nullptr);
    const auto folds = [&](int n, double Q, double z_max_mm, const std::vector<double>& a_mm) {
      source["n"] = n;
      source["Q"] = Q;
      source["z_max_mm"] = z_max_mm;
      source["a_mm"] = a_mm;
    };
    if (drawn_field_folds_) {
      folds(drawn_field_folds_->n, drawn_field_folds_->Q, drawn_field_folds_->z_max_mm,
            drawn_field_folds_->a_mm);
    } else {
      const Solution& s = context.document.scene().solution();
      folds(s.n, s.Q, s.z_max_mm, s.a_mm);
    }
    state["fold_source"] = std::move(source);
  }
  state["camera"] = {{"yaw_rad", camera_.yaw_rad},
                     {"pitch_rad", camera_.pitch_rad},
                     {"distance_mm", camera_.distance_mm}};
  json renderer = counters_json(context.renderer.cloth_counters(views_[0]));
  renderer["compare"] = counters_json(context.renderer.cloth_counters(views_[1]));
  state["renderer"] = renderer;
  // The colour each cloth is drawn in, as its preset stores it: null draws the view's own.
  const auto colour = [](const foldlab::Appearance& appearance) {
    return appearance.colour ? json(hex_colour(*appearance.colour)) : json(nullptr);
  };
  const Document& document = context.document;
  state["cloth_colour"] = {
      {"a", colour(document.appearance())},
      {"b",
       document.compare().pinned() ? colour(document.compare().b().appearance) : json(nullptr)},
      {"a_drawn",
       hex_colour(to_bytes(in_fabric_colour(style_, document.appearance()).front_colour.data()))}};
}

std::optional<std::string> ClothViewPanel::picture_unavailable(PictureView view,
                                                               const Document& document,
                                                               bool /*as_drawn*/) const {
  if (view == PictureView::compare && !document.compare().pinned()) {
    return "Pin a fabric as B first (Compare > Pin as B).";
  }
  return std::nullopt;
}

float ClothViewPanel::colour_bar_width() {
  return ImGui::CalcTextSize("-000.0 mm").x + 28.0f;
}

// Beside the view, as Polyscope shows a scalar quantity's map: the colours from +z_max (top)
// to -z_max with their values, or the two fold signs; under the title, whose folds they are when
// not the closed form's.
void ClothViewPanel::draw_colour_bar(ImVec2 min, float width, float height, double z_max_mm) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float x0 = min.x + 6.0f;
  const float x1 = x0 + 14.0f;
  colour_bar_title_ = style_.colour_by == ClothStyle::ColourBy::z ? "z" : "fold";
  switch (drawn_from_) {
    case DrawnFolds::field:
      colour_bar_title_ += "\ntension field";
      break;
    case DrawnFolds::previous_field:
      colour_bar_title_ += "\ntension field, previous inputs";
      break;
    case DrawnFolds::closed_form:
      break;
  }
  colour_bar_z_max_mm_ = z_max_mm;
  const std::string title = wrap_at_spaces(colour_bar_title_, width - 8.0f);
  const float title_height = ImGui::CalcTextSize(title.c_str()).y;
  const float top = min.y + 8.0f + title_height;
  const float bottom = min.y + std::max(height - 24.0f, top - min.y + 48.0f);
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  const auto to_u32 = [](const Eigen::Vector3f& c) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x(), c.y(), c.z(), 1.0f));
  };
  const float label_x = x1 + 4.0f;
  const float line = ImGui::GetTextLineHeight();
  if (style_.colour_by == ClothStyle::ColourBy::z) {
    constexpr int kSteps = 32;
    for (int i = 0; i < kSteps; ++i) {
      const float t0 = static_cast<float>(i) / kSteps;
      const float t1 = static_cast<float>(i + 1) / kSteps;
      // Top is +z_max: t = 1 on the map.
      draw->AddRectFilledMultiColor(
          ImVec2(x0, top + t0 * (bottom - top)), ImVec2(x1, top + t1 * (bottom - top)),
          to_u32(diverging_colour(1.0f - t0)), to_u32(diverging_colour(1.0f - t0)),
          to_u32(diverging_colour(1.0f - t1)), to_u32(diverging_colour(1.0f - t1)));
    }
    const std::string high = detail::printf_string("+%.1f mm", z_max_mm);
    const std::string low = detail::printf_string("-%.1f mm", z_max_mm);
    draw->AddText(ImVec2(x0, min.y + 4.0f), text, title.c_str());
    draw->AddText(ImVec2(label_x, top), text, high.c_str());
    draw->AddText(ImVec2(label_x, 0.5f * (top + bottom) - 0.5f * line), text, "0");
    draw->AddText(ImVec2(label_x, bottom - line), text, low.c_str());
  } else {
    const float middle = 0.5f * (top + bottom);
    draw->AddRectFilled(ImVec2(x0, top), ImVec2(x1, middle), to_u32(style_.positive_fold_colour));
    draw->AddRectFilled(ImVec2(x0, middle), ImVec2(x1, bottom),
                        to_u32(style_.negative_fold_colour));
    draw->AddText(ImVec2(x0, min.y + 4.0f), text, title.c_str());
    draw->AddText(ImVec2(label_x, 0.5f * (top + middle) - 0.5f * line), text, "z > 0");
    draw->AddText(ImVec2(label_x, 0.5f * (middle + bottom) - 0.5f * line), text, "z < 0");
  }
  draw->AddRect(ImVec2(x0, top), ImVec2(x1, bottom), text);
}

void ClothViewPanel::settings_row() {
  ImGui::Checkbox("wireframe", &style_.wireframe);
  same_line_if_fits(checkbox_width("fold lines"));
  ImGui::Checkbox("fold lines", &style_.fold_lines);
  same_line_if_fits(checkbox_width("ground"));
  ImGui::Checkbox("ground", &style_.ground);
  same_line_if_fits(button_width("reset camera"));
}

// The hex field as wide as its widest value, and the swatch beside it.
float ClothViewPanel::colour_field_width() {
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::CalcTextSize("#WWWWWW").x + 2.0f * style.FramePadding.x + style.ItemInnerSpacing.x +
         ImGui::GetFrameHeight();
}

void ClothViewPanel::colour_picker(Document& document) {
  const foldlab::Appearance& appearance = document.appearance();
  const Eigen::Vector3f shown = in_fabric_colour(style_, appearance).front_colour;
  float rgb[3] = {shown.x(), shown.y(), shown.z()};
  // The swatch opens the picker; the hex field beside it takes a typed value. The colour is kept
  // in bytes, as a preset stores it, so that what is saved is what was shown.
  ImGui::SetNextItemWidth(colour_field_width());
  if (ImGui::ColorEdit3("colour", rgb,
                        ImGuiColorEditFlags_DisplayHex | ImGuiColorEditFlags_Uint8)) {
    foldlab::Appearance changed = appearance;
    changed.colour = to_bytes(rgb);
    document.set_appearance(changed, false);  // a drag in the picker is one undo step
  }
  help_marker(
      "The fabric's colour in this view and its pictures, saved with the preset; click the "
      "swatch to pick one or type its hex value.");
  if (appearance.colour) {
    same_line_if_fits(button_width("default colour"));
    if (small_button("default colour")) {
      foldlab::Appearance cleared = appearance;
      cleared.colour.reset();
      document.set_appearance(cleared);
    }
  }
}

// Reframes for a new cloth (or on request), keeping the user's direction when only the cloth's
// size changed. With B pinned the camera frames both cloths, so that the two halves of the view
// show them at one scale.
void ClothViewPanel::follow_the_cloth(Document& document, bool reset, bool hold) {
  if (reset) {
    camera_user_moved_ = false;
  }
  // The view is about to draw the grid anyway: bringing it up to date first frames the cloth
  // of this frame, not the last one, so that one change of the cloth is one picture drawn.
  Scene& scene = document.scene();
  scene.grid();
  Comparison& compare = document.compare();
  const std::uint64_t b_grid_version =
      compare.pinned() ? compare.scene(scene.grid_nx()).version(Stage::grid) : 0;
  const bool b_changed =
      camera_compare_changes_ != compare.changes() || camera_b_grid_version_ != b_grid_version;
  if (reset || !camera_framed_ ||
      (!camera_user_moved_ && (camera_grid_version_ != scene.version(Stage::grid) || b_changed))) {
    Eigen::Vector3f centre;
    float radius = 1.0f;
    cloth_bounds(scene, centre, radius);
    if (compare.pinned()) {
      Eigen::Vector3f b_centre;
      float b_radius = 1.0f;
      cloth_bounds(compare.scene(scene.grid_nx()), b_centre, b_radius);
      enclose(centre, radius, b_centre, b_radius);
    }
    // While an input plays, the frame only grows: a cloth getting smaller is seen to shrink.
    if (hold && camera_framed_ && !reset) {
      enclose(centre, radius, framed_centre_, framed_radius_mm_);
    }
    framed_centre_ = centre;
    framed_radius_mm_ = radius;
    const OrbitCamera previous = camera_;
    camera_.frame(centre, radius);
    if (camera_framed_ && !reset) {
      camera_.yaw_rad = previous.yaw_rad;  // keep the user's direction, refit the distance only
      camera_.pitch_rad = previous.pitch_rad;
    }
    camera_framed_ = true;
    camera_grid_version_ = scene.version(Stage::grid);
  }
  camera_compare_changes_ = compare.changes();
  camera_b_grid_version_ = b_grid_version;
}

bool ClothViewPanel::toolbar(PanelContext& context) {
  settings_row();
  const bool reset = small_button("reset camera");
  // As long as the panel leaves room for, beside its label and (?): never cut.
  constexpr const char* kZLabel = "z exaggeration";
  const float z_room = ImGui::GetContentRegionAvail().x - labelled_width(0.0f, kZLabel) -
                       help_marker_width() - 2.0f * ImGui::GetStyle().ItemSpacing.x;
  ImGui::SetNextItemWidth(std::clamp(z_room, ems(3.0f), ems(12.0f)));
  view_slider(kZLabel, style_.z_exaggeration, kZExaggeration, "x %.1f");
  help_marker(
      "Draws the out-of-plane depth z this many times deeper, to see the folds; the "
      "numbers are not changed.");
  constexpr const char* kPrints = "plain\0woven checks\0stripes\0photo\0";
  ImGui::SetNextItemWidth(combo_width(kPrints));
  int print = static_cast<int>(style_.print);
  if (combo("print", &print, kPrints)) {
    style_.print = static_cast<ClothStyle::Print>(print);
  }
  same_line_if_fits(labelled_width(colour_field_width(), "colour") + help_marker_width());
  colour_picker(context.document);
  if (style_.print == ClothStyle::Print::photo) {
    same_line_if_fits(ems(13.0f));
    ImGui::SetNextItemWidth(ems(13.0f));
    if (ImGui::InputTextWithHint("##photo", "swatch PNG or JPEG path", photo_input_,
                                 sizeof photo_input_, ImGuiInputTextFlags_EnterReturnsTrue)) {
      photo_path_ = expand_home(photo_input_).string();
      load_photo(photo_path_);
    }
    same_line_if_fits(button_width(kBrowseLabel) + help_marker_width());
    if (small_button(kBrowseLabel)) {
      context.files.open({FileDialog::Mode::open, "Load swatch photo", "", kImageExtensions,
                          [this](const std::filesystem::path& path) {
                            std::snprintf(photo_input_, sizeof photo_input_, "%s",
                                          path.string().c_str());
                            photo_path_ = path.string();
                            return load_photo(photo_path_);
                          }},
                         context.status);
    }
    help_marker(
        "A photo of the fabric (PNG or JPEG), tiled over the cloth every print size; "
        "type its path (~/ is your home folder) and press Enter, or browse for it.");
  }
  if (style_.print != ClothStyle::Print::plain) {
    same_line_if_fits(ems(8.5f));
    ImGui::SetNextItemWidth(ems(8.5f));
    view_slider("##print size", style_.print_mm, kPrintMm, "%.0f mm");
  }
  same_line_if_fits(checkbox_width("breeze"));
  ImGui::Checkbox("breeze", &style_.breeze);
  if (style_.breeze) {
    same_line_if_fits(button_width(breeze_playing_ ? "pause" : "play"));
    if (small_button(breeze_playing_ ? "pause" : "play")) {
      breeze_playing_ = !breeze_playing_;
    }
    // Named, with its unit, so that the slider reads without the checkbox beside it (a row may
    // wrap between them).
    constexpr const char* kBreezeLabel = "sway (mm)";
    same_line_if_fits(labelled_width(ems(6.0f), kBreezeLabel));
    ImGui::SetNextItemWidth(ems(6.0f));
    view_slider(kBreezeLabel, style_.breeze_mm, kBreezeMm, "%.0f");
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("How far the breeze sways the cloth at most, in mm");
    }
  }
  constexpr const char* kColourBys = "fabric\0z\0fold sign\0";
  same_line_if_fits(labelled_width(combo_width(kColourBys), "colour by"));
  ImGui::SetNextItemWidth(combo_width(kColourBys));
  int colour_by = static_cast<int>(style_.colour_by);
  if (combo("colour by", &colour_by, kColourBys)) {
    style_.colour_by = static_cast<ClothStyle::ColourBy>(colour_by);
  }
  constexpr const char* kSources = "closed form\0tension field\0";
  same_line_if_fits(labelled_width(combo_width(kSources), kFoldsFromLabel) +
                    ImGui::CalcTextSize(" (?)").x);
  ImGui::SetNextItemWidth(combo_width(kSources));
  int source = static_cast<int>(fold_source_);
  if (combo(kFoldsFromLabel, &source, kSources)) {
    fold_source_ = static_cast<FoldSource>(source);
  }
  help_marker(
      "Whose folds the cloth is drawn with: the closed form's (n, Q, z_max and the a_i of "
      "Results) or those read from the tension field of the same inputs, which is then solved "
      "though its view is closed.");
  if (!photo_problem_.empty() && style_.print == ClothStyle::Print::photo) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    wrapped_text("%s", photo_problem_.c_str());
    ImGui::PopStyleColor();
  }
  return reset;
}

// A drag on the view orbits (left) or pans (other buttons), the wheel zooms.
void ClothViewPanel::steer_camera(FrameSize size) {
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive() && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    camera_user_moved_ = true;
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      camera_.orbit(io.MouseDelta.x, io.MouseDelta.y);
    } else {
      camera_.pan(io.MouseDelta.x, io.MouseDelta.y, static_cast<float>(size.height));
    }
  }
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    camera_user_moved_ = true;
    camera_.zoom(io.MouseWheel);
  }
}

// With B pinned: each half named at its foot, in the colours the plots give A and B, below the
// cloth and its supports and clear of the hint at the top. A name that would wrap past two lines
// would climb over the cloth: then the letter alone (the names are in Results).
void ClothViewPanel::name_halves(const Document& document, ImDrawList* draw, ImVec2 origin,
                                 FrameSize size, FrameSize area) const {
  const auto label = [&](ImVec2 at, float width, ImU32 colour, const char* letter,
                         const std::string& name) {
    // Broken at spaces only: ImGui's own wrap would break "2.4 m" after the point.
    const float wrap = width - 12.0f;
    const std::string full = wrap_at_spaces(std::string(letter) + ": " + name, wrap);
    const ImVec2 full_size = ImGui::CalcTextSize(full.c_str());
    const bool fits = full_size.y <= 2.0f * ImGui::GetTextLineHeightWithSpacing();
    const float text_height = fits ? full_size.y : ImGui::GetTextLineHeight();
    const float foot = at.y + static_cast<float>(area.height) - text_height - 6.0f;
    // On a plate of the view's own backdrop: the ground's grid lines run under the names.
    const ImVec2 text_size = fits ? full_size : ImGui::CalcTextSize(letter);
    const Eigen::Vector3f& plate = style_.background;
    draw->AddRectFilled(ImVec2(at.x + 3, foot - 2),
                        ImVec2(at.x + 9 + text_size.x, foot + text_size.y + 2),
                        ImGui::GetColorU32(ImVec4(plate.x(), plate.y(), plate.z(), 0.85f)), 3.0f);
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(at.x + 6, foot), colour,
                  fits ? full.c_str() : letter);
  };
  const ImVec2 b_origin(origin.x + static_cast<float>(size.width), origin.y);
  label(origin, static_cast<float>(size.width), kSweepCurve.u32(), "A", fabric_label(document));
  label(b_origin, static_cast<float>(area.width - size.width), kCompareB.u32(), "B",
        document.compare().b().name);
  draw->AddLine(ImVec2(b_origin.x, origin.y),
                ImVec2(b_origin.x, origin.y + static_cast<float>(area.height)),
                ImGui::GetColorU32(ImGuiCol_Separator));
}

// Wrapped inside the view, so that a narrow view keeps it off the colour bar beside it; over a
// small view only while the pointer is on it (the view is the last item), not to cover the cloth.
void ClothViewPanel::draw_hint(ImDrawList* draw, ImVec2 origin, FrameSize area, bool light) {
  if (static_cast<float>(area.height) < 12.0f * ImGui::GetFontSize() && !ImGui::IsItemHovered()) {
    return;
  }
  draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(origin.x + 6, origin.y + 4),
                light ? IM_COL32(60, 60, 60, 220) : IM_COL32(200, 200, 200, 200),
                hint_words(Hint::cloth_view), nullptr, static_cast<float>(area.width) - 12.0f);
}

void ClothViewPanel::draw(PanelContext& context) {
  Document& document = context.document;
  Renderer& renderer = context.renderer;
  if (fill_display_) {
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize, ImGuiCond_Always);
    ImGui::SetNextWindowFocus();
  }
  if (!begin(renderer)) {
    ImGui::End();
    return;  // hidden: no grid, no normals, no upload, no draw
  }
  stale_mark(document);
  if (camera_loads_ != document.loads()) {
    camera_loads_ = document.loads();  // another preset: frame it afresh
    camera_framed_ = false;
    camera_user_moved_ = false;
  }
  // Whether or not its settings are in sight (presented, they are behind a menu): the solver does
  // not run, only the shader moves.
  if (animating()) {
    style_.time_s += ImGui::GetIO().DeltaTime;
  }
  bool reset = false;
  const bool presented = context.presented == this;
  if (toolbar_row_.begin("view settings...", ems(12.0f), presented)) {
    reset = toolbar(context);
    toolbar_row_.end();
  }
  // Chosen before the view's area is measured: the line saying where the folds come from takes
  // its room above the view.
  Scene& drawn = scene_to_draw(context);
  if (fold_source_ == FoldSource::field) {
    ++frames_drawn_[static_cast<std::size_t>(drawn_from_)];
  }
  fold_source_line();
  // The view follows the theme: a light page gets a light backdrop.
  const bool light = style_is_light();
  style_.background =
      light ? Eigen::Vector3f(0.90f, 0.91f, 0.93f) : Eigen::Vector3f(0.16f, 0.17f, 0.20f);
  const ImVec4 support = kSupportMarker.get(light);
  style_.support_colour = Eigen::Vector3f(support.x, support.y, support.z);
  ImVec2 available = ImGui::GetContentRegionAvail();
  const float bar_width =
      style_.colour_by == ClothStyle::ColourBy::none ? 0.0f : colour_bar_width();
  available.x -= bar_width;
  const FrameSize area{std::max(16, static_cast<int>(available.x)),
                       std::max(16, static_cast<int>(available.y))};
  Scene& scene = document.scene();
  follow_the_cloth(document, reset, context.holding_frame);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  view_rect_ = PanelRect{
      origin, ImVec2(static_cast<float>(area.width) + bar_width, static_cast<float>(area.height))};
  drawn_.mark(
      PanelRect{origin, ImVec2(static_cast<float>(area.width), static_cast<float>(area.height))});
  ImGui::InvisibleButton("view",
                         ImVec2(static_cast<float>(area.width), static_cast<float>(area.height)),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  // With B pinned the view is split in two halves, A on the left and B on the right, under one
  // camera: a drag in either half turns both.
  const bool compare = document.compare().pinned();
  const FrameSize size{compare ? std::max(16, area.width / 2) : area.width, area.height};
  steer_camera(size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const auto draw_view = [&](int which, ImVec2 at, Scene& cloth, FrameSize view_size) {
    if (views_[which] == kNoClothView) {
      views_[which] = renderer.create_cloth_view();
    }
    const ClothStyle style = in_fabric_colour(
        style_, which == 0 ? document.appearance() : document.compare().b().appearance);
    update_cloth_buffers(cloth, style, buffers_[which]);
    renderer.draw_cloth(views_[which], draw, at, buffers_[which], camera_, view_size, style);
  };
  draw_view(0, origin, drawn, size);
  const ImVec2 b_origin(origin.x + static_cast<float>(size.width), origin.y);
  if (compare) {
    draw_view(1, b_origin, document.compare().scene(scene.grid_nx()),
              FrameSize{area.width - size.width, area.height});
  }
  // A room looking at a presented cloth needs no mouse hint over it.
  if (!presented) {
    draw_hint(draw, origin, area, light);
  }
  if (compare) {
    name_halves(document, draw, origin, size, area);
  }
  colour_bar_drawn_ = bar_width > 0.0f;
  if (colour_bar_drawn_) {
    draw_colour_bar(ImVec2(origin.x + static_cast<float>(area.width), origin.y), bar_width,
                    static_cast<float>(area.height), drawn.solution().z_max_mm);
  }
  ImGui::End();
}

}  // namespace foldlab::gui
