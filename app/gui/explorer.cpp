#include "app/gui/explorer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <imgui.h>

#include "app/common/presets_dir.hpp"
#include "app/gui/analysis_panels.hpp"
#include "app/gui/fast_fill.hpp"
#include "app/gui/plot_widget.hpp"
#include "core/io/export.hpp"
#include "core/io/gltf_export.hpp"
#include "core/io/io.hpp"
#include "core/model/equations.hpp"
#include "core/model/settings.hpp"

namespace foldlab::gui {
namespace {

constexpr ImU32 kPositiveFold = IM_COL32(31, 58, 147, 255);
constexpr ImU32 kNegativeFold = IM_COL32(214, 39, 40, 255);
const ImVec4 kErrorText(1.0f, 0.45f, 0.40f, 1.0f);
const ImVec4 kOkText(0.55f, 0.85f, 0.55f, 1.0f);
const ImVec4 kNoteText(1.0f, 0.78f, 0.35f, 1.0f);
const ImVec4 kDimText(0.65f, 0.65f, 0.70f, 1.0f);
constexpr double kGramsPerSquareMetrePerNPerMm2 = 1.0 / 9.81e-9;  // w in N/mm² -> g/m²

// First-use layout: parameters and presets on the left, the two views on top, numbers below.
void place_window(float x, float y, float w, float h) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(x * display.x, y * display.y), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(w * display.x, h * display.y), ImGuiCond_FirstUseEver);
}

std::string regime_label(const Solution& s) {
  return std::string(to_string(s.regime));
}

// A file name from a preset name: letters, digits and dashes.
std::string slug(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!out.empty() && out.back() != '-') {
      out += '-';
    }
  }
  while (!out.empty() && out.back() == '-') {
    out.pop_back();
  }
  return out;
}

// ImGui::Begin for the tiled panels, with the background filled the fast way (see fast_fill.hpp).
bool begin_panel(const char* title) {
  if (!ImGui::Begin(title)) {
    return false;
  }
  fill_current_window_background();
  return true;
}

// ImGui 1.86 has no SeparatorText.
void section(const char* title) {
  ImGui::Spacing();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", title);
  ImGui::Separator();
}

void help_marker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

// Sliders leave room on their right for the longest label and its (?) marker.
float slider_width() {
  return ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("nu (Poisson) (?)").x -
         2.0f * ImGui::GetStyle().ItemInnerSpacing.x - ImGui::GetStyle().ItemSpacing.x;
}

template <class Enum>
bool enum_combo(const char* label, Enum& value, std::initializer_list<Enum> options) {
  bool changed = false;
  if (ImGui::BeginCombo(label, std::string(to_string(value)).c_str())) {
    for (Enum option : options) {
      if (ImGui::Selectable(std::string(to_string(option)).c_str(), option == value)) {
        changed = option != value;
        value = option;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

}  // namespace

Explorer::Explorer(const Preset& initial, const std::string& initial_path, bool restore_session,
                   ExplorerOptions options)
    : options_(std::move(options)),
      loaded_(initial),
      loaded_path_(initial_path),
      edited_(initial.parameters),
      scene_(initial.parameters),
      sweep_panel_(options_.presets_dir) {
  if (restore_session && !options_.session_file.empty()) {
    std::string error;
    if (std::optional<Session> s = load_session(options_.session_file, error)) {
      loaded_ = s->loaded;
      loaded_path_ = s->loaded_preset_path;
      edited_ = s->current.parameters;
      grid_resolution_ = s->grid_resolution;
      style_.wireframe = s->wireframe;
      style_.fold_lines = s->fold_lines_3d;
      style_.ground = s->ground;
      session_message_ = "Restored the last session.";
    } else if (std::filesystem::exists(options_.session_file)) {
      session_message_ = error;
    }
  }
  commit_edits();
  scene_.set_grid_resolution(grid_resolution_, grid_resolution_);
  refresh_preset_list();
}

Explorer::~Explorer() {
  try {
    save_session_now();
  } catch (const std::exception&) {
    // Leaving must not fail because the config folder is read-only; the session is a convenience.
  }
}

std::optional<std::string> Explorer::set_view(std::string_view key, std::string_view value) {
  if (key == "sweep") {
    static const char* const names[] = {"table1", "table2", "fig4"};
    for (int which = 0; which < SweepPanel::kPaperCases; ++which) {
      if (value == names[which]) {
        sweep_panel_.select_paper_case(which, panel_actions());
        options_.analysis_tab = "sweep";
        return std::nullopt;
      }
    }
    return "sweep = '" + std::string(value) + "' is not one of: table1, table2, fig4";
  }
  if (key == "print") {
    if (value == "plain" || value == "checks" || value == "stripes") {
      style_.print = value == "plain"    ? ClothStyle::Print::plain
                     : value == "checks" ? ClothStyle::Print::checks
                                         : ClothStyle::Print::stripes;
      return std::nullopt;
    }
    return "print = '" + std::string(value) + "' is not one of: plain, checks, stripes";
  }
  const std::optional<double> number = parse_number(value);
  if (!number) {
    return std::string(key) + " = '" + std::string(value) + "' is not a number";
  }
  const float v = static_cast<float>(*number);
  if (key == "breeze") {
    style_.breeze = v != 0.0f;
  } else if (key == "breeze_mm") {
    style_.breeze_mm = v;
  } else if (key == "time") {
    style_.time_s = v;
    breeze_playing_ = false;  // a scripted picture shows that instant
  } else if (key == "z") {
    style_.z_exaggeration = std::clamp(v, 1.0f, 20.0f);
  } else if (key == "wireframe") {
    style_.wireframe = v != 0.0f;
  } else if (key == "fold_lines") {
    style_.fold_lines = v != 0.0f;
  } else if (key == "ground") {
    style_.ground = v != 0.0f;
  } else {
    return "unknown view key '" + std::string(key) +
           "' (known: print, breeze, breeze_mm, time, z, wireframe, fold_lines, ground)";
  }
  return std::nullopt;
}

void Explorer::notify(const std::string& message, bool is_error) {
  preset_message_ = message;
  preset_message_is_error_ = is_error;
}

std::optional<std::string> Explorer::take_screenshot_request() {
  std::optional<std::string> request;
  request.swap(screenshot_request_);
  return request;
}

// The mesh as the 3D view shows it now: with the breeze's offset at this instant when it blows
// (z exaggeration is a view aid and is not exported).
DeformedGrid Explorer::current_frame_mesh() {
  scene_.normals();
  DeformedGrid grid = scene_.grid();
  if (style_.breeze) {
    const float depth = static_cast<float>(
        lowest_point_mm(scene_.solution(), scene_.parameters().hanging.height_mm));
    for (Eigen::Vector3f& v : grid.positions_mm) {
      v += breeze_offset(v, depth, style_.breeze_mm, style_.time_s);
    }
    grid.normals = vertex_normals(grid.positions_mm, grid.triangle_indices);
  }
  return grid;
}

void Explorer::export_section() {
  if (!ImGui::CollapsingHeader("Export")) {
    return;
  }
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputText("##export stem", export_stem_, sizeof export_stem_);
  const std::string stem = export_stem_;
  auto write = [this](const std::string& path, auto&& make) {
    try {
      write_file_atomically(path, make());
      preset_message_ = "Wrote " + std::filesystem::absolute(path).string();
      preset_message_is_error_ = false;
    } catch (const std::exception& e) {
      preset_message_ = std::string("Not exported: ") + e.what();
      preset_message_is_error_ = true;
    }
  };
  if (ImGui::Button("OBJ")) {
    write(stem + ".obj", [&] { return mesh_to_obj(current_frame_mesh(), loaded_.name); });
  }
  ImGui::SameLine();
  if (ImGui::Button("glTF (.glb)")) {
    write(stem + ".glb", [&] { return mesh_to_glb(current_frame_mesh(), loaded_.name); });
  }
  ImGui::SameLine();
  if (ImGui::Button("SVG")) {
    write(stem + ".svg",
          [&] { return fold_lines_to_svg(scene_.fold_lines(), scene_.solution(), loaded_.name); });
  }
  ImGui::SameLine();
  if (ImGui::Button("CSV")) {
    write(stem + ".csv", [&] { return fold_lines_to_csv(scene_.fold_lines()); });
  }
  ImGui::SameLine();
  if (ImGui::Button("PNG")) {
    screenshot_request_ = stem + ".png";
  }
}

PanelActions Explorer::panel_actions() {
  return {[this](const std::string& key, double value) { set_input(key, value); },
          [this](const std::filesystem::path& path) { load_preset_file(path); }};
}

bool Explorer::busy() const {
  return regime_map_panel_.computing();
}

const RenderCounters* Explorer::renderer_counters() const {
  return renderer_ ? &renderer_->counters() : nullptr;
}

void Explorer::save_session_now() {
  if (options_.session_file.empty()) {
    return;
  }
  Session s;
  s.current = loaded_;
  s.current.parameters = scene_.parameters();  // the last valid state
  s.loaded = loaded_;
  s.loaded_preset_path = loaded_path_;
  s.grid_resolution = grid_resolution_;
  s.wireframe = style_.wireframe;
  s.fold_lines_3d = style_.fold_lines;
  s.ground = style_.ground;
  save_session(options_.session_file, s);
  session_dirty_ = false;
}

std::optional<std::string> Explorer::set_input(std::string_view key, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  if (auto error = apply_setting(edited_, key, text)) {
    return error;
  }
  commit_edits();
  return std::nullopt;
}

// The model sees an edit only when it validates; otherwise the scene keeps the last valid state
// and the widgets show the user's number with the reason it was refused.
void Explorer::commit_edits() {
  issues_ = validate(edited_);
  if (issues_.empty() && !(edited_ == scene_.parameters())) {
    scene_.set_parameters(edited_);
    session_dirty_ = true;
  }
}

bool Explorer::unsaved() const {
  return !(scene_.parameters() == loaded_.parameters);
}

void Explorer::refresh_preset_list() {
  presets_.clear();
  auto add_folder = [this](const std::filesystem::path& dir, bool user) {
    if (dir.empty()) {
      return;
    }
    for (const auto& file : app::preset_files(dir)) {
      PresetEntry entry{file.stem().string(), file, user};
      try {
        entry.name = load_preset(file).name;
      } catch (const PresetError&) {
        entry.name = file.filename().string() + " (unreadable)";
      }
      presets_.push_back(std::move(entry));
    }
  };
  add_folder(options_.presets_dir, false);
  add_folder(options_.user_presets_dir, true);
}

void Explorer::load_preset_file(const std::filesystem::path& path) {
  try {
    Preset preset = load_preset(path);
    loaded_ = preset;
    loaded_path_ = path.string();
    edited_ = preset.parameters;
    commit_edits();
    camera_framed_ = false;
    camera_user_moved_ = false;
    preset_message_ = "Loaded " + preset.name + ".";
    preset_message_is_error_ = false;
    session_dirty_ = true;
  } catch (const PresetError& e) {
    preset_message_ = std::string("Not loaded; the current state is kept.\n") + e.what();
    preset_message_is_error_ = true;
  }
}

void Explorer::save_as(const std::string& name, bool overwrite) {
  const std::string file = slug(name);
  if (file.empty()) {
    preset_message_ = "Give the preset a name with at least one letter or digit.";
    preset_message_is_error_ = true;
    return;
  }
  const std::filesystem::path path = options_.user_presets_dir / (file + ".json");
  if (!overwrite && std::filesystem::exists(path)) {
    pending_overwrite_ = name;
    ImGui::OpenPopup("Overwrite preset?");
    return;
  }
  Preset preset = loaded_;
  preset.name = name;
  preset.parameters = scene_.parameters();
  if (loaded_.name != name) {
    preset.description = "Saved from FoldLab, based on \"" + loaded_.name + "\".";
    preset.published = {};  // published results belong to the paper's case, not to an edit
  }
  try {
    std::filesystem::create_directories(options_.user_presets_dir);
    save_preset(preset, path);
    loaded_ = preset;
    loaded_path_ = path.string();
    preset_message_ = "Saved " + path.string();
    preset_message_is_error_ = false;
    refresh_preset_list();
    session_dirty_ = true;
  } catch (const std::exception& e) {
    preset_message_ = std::string("Not saved: ") + e.what();
    preset_message_is_error_ = true;
  }
}

void Explorer::frame() {
  begin_fast_fill_frame();
  parameters_panel();
  presets_panel();
  plot_panel();
  view3d_panel();
  results_panel();
  teaching_panel();
  if (calibration_panel_.draw(edited_, loaded_)) {
    commit_edits();  // the fitted constants, applied as a slider would
  }
  if (show_stats_) {
    stats_overlay();
  }
  // Keep the session on disk a second after the last change, so that a crash loses little.
  const double now = ImGui::GetTime();
  if (session_dirty_ && now - last_session_save_time_ > 1.0) {
    last_session_save_time_ = now;
    try {
      save_session_now();
    } catch (const std::exception& e) {
      session_message_ = std::string("Could not save the session: ") + e.what();
      session_dirty_ = false;
    }
  }
}

void Explorer::show_issue(const char* field) {
  for (const ValidationIssue& issue : issues_) {
    if (issue.field == field) {
      ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
      ImGui::TextWrapped("%s", issue.message.c_str());
      ImGui::PopStyleColor();
    }
  }
}

void Explorer::input_slider(const char* label, const char* field, double& value, double lo,
                            double hi, const char* format, bool logarithmic, const char* help) {
  ImGuiSliderFlags flags = logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
  // Without AlwaysClamp a typed (Ctrl+click) value outside the slider's range is kept as typed,
  // and validation, not the widget, decides whether the model accepts it.
  ImGui::SetNextItemWidth(slider_width());
  if (ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format, flags)) {
    commit_edits();
  }
  help_marker(help);
  show_issue(field);
}

void Explorer::parameters_panel() {
  place_window(0.0f, 0.0f, 0.30f, 0.62f);
  const std::string title = std::string("Parameters") + (unsaved() ? " *" : "") + "###parameters";
  if (!begin_panel(title.c_str())) {
    ImGui::End();
    return;
  }
  ImGui::TextColored(kDimText, "%s%s", loaded_.name.c_str(), unsaved() ? " (unsaved changes)" : "");
  if (ImGui::Button("Reset to preset")) {
    edited_ = loaded_.parameters;
    commit_edits();
  }
  ImGui::SameLine();
  ImGui::TextDisabled("Ctrl+click a slider to type a value");
  ImGui::Separator();

  Fabric& f = edited_.fabric;
  Hanging& g = edited_.hanging;
  input_slider("t (thickness)", "t_mm", f.thickness_mm, 0.01, 5.0, "%.3g mm", true,
               "Fabric thickness t in mm (logarithmic slider).");
  input_slider("E (Young's)", "E_MPa", f.youngs_modulus_MPa, 1.0, 10000.0, "%.4g MPa", true,
               "Young's modulus E in MPa = N/mm² (logarithmic slider).");
  input_slider("w (weight)", "w_N_per_mm2", f.weight_N_per_mm2, 1e-7, 1e-4, "%.3e N/mm²", true,
               "Weight per area w in N/mm² (logarithmic slider); 1.5e-6 N/mm² is about 150 g/m².");
  ImGui::TextColored(kDimText, "    w = %.0f g/m²",
                     f.weight_N_per_mm2 * kGramsPerSquareMetrePerNPerMm2);
  input_slider("h (height)", "h_mm", g.height_mm, 100.0, 5000.0, "%.0f mm", false,
               "Height h of the cloth at the centre, in mm.");
  input_slider("d (support)", "d_mm", g.support_displacement_mm, 0.0,
               std::max(1.0, 0.5 * g.length_mm), "%.1f mm", false,
               "Inward displacement d of each support, in mm; below L/2.");
  input_slider("L (width)", "L_mm", g.length_mm, 100.0, 5000.0, "%.0f mm", false,
               "Length L of the upper edge (the cloth's width), in mm.");
  input_slider("nu (Poisson)", "nu", f.poisson_ratio, 0.0, 0.49, "%.3f", false,
               "Poisson's ratio; eq. 7 uses K = c / (1 - nu²).");
  double K = stiffness_constant_K(edited_);
  const double K_before = K;
  input_slider("K of eq. 7", "c", K, 1.0, 300.0, "%.3g", true,
               "K = c/(1 - nu²) of eq. 7. Calibrated on the paper's Tables 1-2: 29.56 (c = 26.9).");
  if (K != K_before) {
    set_stiffness_constant_K(edited_, K);
    commit_edits();
  }
  ImGui::TextColored(kDimText, "    c = %.4g (load-condition constant)",
                     edited_.model.load_constant_c);

  ImGui::Separator();
  ImGui::SetNextItemWidth(120.0f);
  if (enum_combo("method", edited_.model.method, {Method::paper, Method::exact})) {
    commit_edits();
  }
  help_marker(
      "paper: the paper's 5%-tolerance iteration (Simpson). exact: eqs. 8 and 9 to machine "
      "precision, n a fixed point of eq. 10.");
  ImGui::SetNextItemWidth(120.0f);
  if (enum_combo("span l", edited_.model.span_rule, {SpanRule::L_minus_d, SpanRule::L_minus_2d})) {
    commit_edits();
  }
  help_marker(
      "How the span between the supports follows from L and d. L-d reproduces the "
      "paper's tables; L-2d is what its text says.");
  ImGui::SetNextItemWidth(120.0f);
  if (enum_combo("Int[] of eq. 10", edited_.model.int_rounding,
                 {IntRounding::nearest, IntRounding::floor})) {
    commit_edits();
  }
  ImGui::SetNextItemWidth(slider_width());
  if (ImGui::SliderInt("grid", &grid_resolution_, 8, 512, "%d per side",
                       ImGuiSliderFlags_AlwaysClamp)) {
    scene_.set_grid_resolution(grid_resolution_, grid_resolution_);
    session_dirty_ = true;
  }
  help_marker(
      "Resolution of the 3D cloth mesh (vertices per side). Changing it does not re-solve.");
  if (!issues_.empty()) {
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    ImGui::TextWrapped("%zu input(s) refused: the views show the last valid state.",
                       issues_.size());
    ImGui::PopStyleColor();
  }
  ImGui::End();
}

void Explorer::results_panel() {
  place_window(0.30f, 0.56f, 0.35f, 0.44f);
  if (!begin_panel("Results")) {
    ImGui::End();
    return;
  }
  const Solution& s = scene_.solution();
  const StageStats& timing = scene_.stats(Stage::solution);
  ImGui::Text("Regime: %s", regime_label(s).c_str());
  if (const std::string message = describe(s, scene_.parameters()); !message.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, s.regime == Regime::wrinkled ? kDimText : kNoteText);
    ImGui::TextWrapped("%s", message.c_str());
    ImGui::PopStyleColor();
  }
  if (ImGui::BeginTable("results", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    auto row = [](const char* name, const char* symbol, const std::string& value) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextUnformatted(name);
      ImGui::TableSetColumnIndex(1);
      ImGui::TextUnformatted(symbol);
      ImGui::TableSetColumnIndex(2);
      ImGui::TextUnformatted(value.c_str());
    };
    char text[96];
    auto fmt = [&text](const char* format, double v) {
      std::snprintf(text, sizeof text, format, v);
      return std::string(text);
    };
    row("number of wrinkles", "n", fmt("%.0f", s.n));
    row("amplitude ratio", "Q", fmt("%.4f", s.Q));
    row("root of eq. 7", "Q7", s.Q7 ? fmt("%.4f", *s.Q7) : std::string("none (s >= 1)"));
    row("stress ratio", "s", fmt("%.4g", s.stress_ratio));
    row("out-of-plane depth", "z_max", fmt("%.2f mm", s.z_max_mm));
    row("span", "l", fmt("%.1f mm", s.span_mm));
    row("sag of the upper edge", "A", fmt("%.2f mm", s.sag_amplitude_mm));
    row("iterations", "", fmt("%.0f", s.iterations));
    row("residual eq. 8", "L'/L-1", fmt("%.2e", s.residual_length));
    row("residual eq. 9", "fibre/h-1", fmt("%.2e", s.residual_height));
    row("solve time", "", fmt("%.1f µs", timing.last_ms * 1000.0));
    ImGui::EndTable();
  }
  if (!s.a_mm.empty() &&
      ImGui::CollapsingHeader("fold amplitudes a_i", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (ImGui::BeginTable(
            "amplitudes", 3,
            ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersInnerV,
            ImVec2(0.0f, std::max(80.0f, ImGui::GetContentRegionAvail().y)))) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("i");
      ImGui::TableSetupColumn("a_i (mm)");
      ImGui::TableSetupColumn("fold");
      ImGui::TableHeadersRow();
      ImGuiListClipper clipper;
      clipper.Begin(static_cast<int>(s.a_mm.size()));
      while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
          ImGui::TableNextRow();
          ImGui::TableSetColumnIndex(0);
          ImGui::Text("%d%s", i, i == 0 ? " (lower)" : (i == s.n ? " (upper edge)" : ""));
          ImGui::TableSetColumnIndex(1);
          ImGui::Text("%.2f", s.a_mm[static_cast<std::size_t>(i)]);
          ImGui::TableSetColumnIndex(2);
          const bool negative = fold_sign(i) < 0;
          ImGui::TextColored(
              negative ? ImVec4(0.95f, 0.35f, 0.35f, 1.0f) : ImVec4(0.45f, 0.6f, 1.0f, 1.0f),
              negative ? "negative" : "positive");
        }
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

void Explorer::plot_panel() {
  place_window(0.30f, 0.0f, 0.35f, 0.56f);
  if (!begin_panel("Fold lines (2D)")) {
    ImGui::End();
    return;  // hidden: the fold lines are not even computed
  }
  const FoldLines& lines = scene_.fold_lines();
  const Solution& s = scene_.solution();
  if (ImGui::SmallButton("autoscale")) {
    plot_autoscale_ = true;
  }
  ImGui::SameLine();
  ImGui::TextDisabled("wheel: zoom, drag: pan, double-click: autoscale");
  if (lines.stride > 1) {
    ImGui::TextColored(kDimText, "every %d-th of %d lines drawn", lines.stride, s.n + 1);
  }
  // The plot keeps pointers into these until end(): rebuild them only when the lines change.
  if (plot_lines_version_ != scene_.version(Stage::fold_lines)) {
    plot_lines_version_ = scene_.version(Stage::fold_lines);
    plot_xs_.assign(lines.lines.size(), {});
    plot_ys_.assign(lines.lines.size(), {});
    for (std::size_t k = 0; k < lines.lines.size(); ++k) {
      for (const Eigen::Vector3d& p : lines.lines[k].points_mm) {
        plot_xs_[k].push_back(p.x());
        plot_ys_[k].push_back(p.y());
      }
    }
  }
  if (fold_plot_.begin("fold lines", ImVec2(0.0f, 0.0f), PlotAxis{"x (mm)", false, false},
                       PlotAxis{"y (mm, down)", true, false})) {
    if (plot_autoscale_) {
      fold_plot_.request_autoscale();
      plot_autoscale_ = false;
    }
    for (std::size_t k = 0; k < lines.lines.size(); ++k) {
      const bool negative = lines.lines[k].sign < 0;
      fold_plot_.line(negative ? "negative fold" : "positive fold", plot_xs_[k], plot_ys_[k],
                      negative ? kNegativeFold : kPositiveFold, 1.6f);
    }
    if (lines.lines.empty()) {
      // No folds (no slack, short cloth): show the cloth itself, y = (A + h) cos(pi x / l).
      if (plot_outline_version_ != scene_.version(Stage::solution)) {
        plot_outline_version_ = scene_.version(Stage::solution);
        outline_xs_.clear();
        outline_ys_.clear();
        const double depth = lowest_point_mm(s, scene_.parameters().hanging.height_mm);
        for (int k = 0; k <= 100; ++k) {
          const double x = s.span_mm * (k / 100.0 - 0.5);
          outline_xs_.push_back(x);
          outline_ys_.push_back(depth * std::cos(std::numbers::pi * x / s.span_mm));
        }
      }
      fold_plot_.line("lower edge of the flat cloth", outline_xs_, outline_ys_,
                      IM_COL32(170, 170, 180, 255), 1.2f);
    }
    std::vector<double> supports_x;
    std::vector<double> supports_y;
    for (const Eigen::Vector3d& support : support_points(s.span_mm, scene_.parameters().shape)) {
      supports_x.push_back(support.x());
      supports_y.push_back(support.y());
    }
    fold_plot_.markers("supports", supports_x, supports_y, IM_COL32(240, 200, 60, 255),
                       MarkerShape::Triangle, 6.0f);
    const std::optional<PlotHit> hit = fold_plot_.end();
    if (hit && hit->series < static_cast<int>(lines.lines.size())) {
      const FoldLine& line = lines.lines[static_cast<std::size_t>(hit->series)];
      const Eigen::Vector3d& p = line.points_mm[static_cast<std::size_t>(hit->index)];
      ImGui::SetTooltip("fold line %d (%s)\nx = %.1f mm\ny = %.1f mm\nz = %+.1f mm", line.index,
                        line.sign < 0 ? "negative" : "positive", p.x(), p.y(), p.z());
    }
  }
  ImGui::End();
}

void Explorer::view3d_panel() {
  place_window(0.65f, 0.0f, 0.35f, 0.56f);
  if (!begin_panel("Cloth (3D)")) {
    ImGui::End();
    return;  // hidden: no grid, no normals, no upload, no draw
  }
  ImGui::Checkbox("wireframe", &style_.wireframe);
  ImGui::SameLine();
  ImGui::Checkbox("fold lines", &style_.fold_lines);
  ImGui::SameLine();
  ImGui::Checkbox("ground", &style_.ground);
  ImGui::SameLine();
  const bool reset = ImGui::SmallButton("reset camera");
  ImGui::SetNextItemWidth(160.0f);
  ImGui::SliderFloat("z exaggeration", &style_.z_exaggeration, 1.0f, 20.0f, "x %.1f",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  help_marker(
      "Draws the out-of-plane depth z this many times deeper, to see the folds; the "
      "numbers are not changed.");
  ImGui::SetNextItemWidth(100.0f);
  int print = static_cast<int>(style_.print);
  if (ImGui::Combo("print", &print, "plain\0woven checks\0stripes\0")) {
    style_.print = static_cast<ClothStyle::Print>(print);
  }
  if (style_.print != ClothStyle::Print::plain) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110.0f);
    ImGui::SliderFloat("##print size", &style_.print_mm, 10.0f, 300.0f, "%.0f mm",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  }
  ImGui::SameLine();
  ImGui::Checkbox("breeze", &style_.breeze);
  if (style_.breeze) {
    ImGui::SameLine();
    if (ImGui::SmallButton(breeze_playing_ ? "pause" : "play")) {
      breeze_playing_ = !breeze_playing_;
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(100.0f);
    ImGui::SliderFloat("##breeze", &style_.breeze_mm, 5.0f, 300.0f, "%.0f mm",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    if (breeze_playing_) {
      style_.time_s += ImGui::GetIO().DeltaTime;  // the solver does not run: only the shader moves
    }
  }
  const ImVec2 available = ImGui::GetContentRegionAvail();
  const FrameSize size{std::max(16, static_cast<int>(available.x)),
                       std::max(16, static_cast<int>(available.y))};
  if (!renderer_) {
    renderer_ = std::make_unique<ClothRenderer>();
  }
  // Until the user moves the camera it follows the cloth, so a slider never drags it out of view.
  if (reset) {
    camera_user_moved_ = false;
  }
  if (reset || !camera_framed_ ||
      (!camera_user_moved_ && camera_solution_version_ != scene_.version(Stage::grid))) {
    Eigen::Vector3f centre;
    float radius = 1.0f;
    ClothRenderer::bounds(scene_, centre, radius);
    const OrbitCamera previous = camera_;
    camera_.frame(centre, radius);
    if (camera_framed_ && !reset) {
      camera_.yaw_rad = previous.yaw_rad;  // keep the user's direction, refit the distance only
      camera_.pitch_rad = previous.pitch_rad;
    }
    camera_framed_ = true;
    camera_solution_version_ = scene_.version(Stage::grid);
  }
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("view",
                         ImVec2(static_cast<float>(size.width), static_cast<float>(size.height)),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
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
  renderer_->render(scene_, camera_, size, style_);
  add_framebuffer_blit(ImGui::GetWindowDrawList(), renderer_->framebuffer(), size, origin,
                       ImVec2(origin.x + static_cast<float>(size.width),
                              origin.y + static_cast<float>(size.height)));
  ImGui::GetWindowDrawList()->AddText(ImVec2(origin.x + 6, origin.y + 4),
                                      IM_COL32(200, 200, 200, 200),
                                      "drag: orbit, right-drag: pan, wheel: zoom");
  ImGui::End();
}

void Explorer::presets_panel() {
  place_window(0.0f, 0.62f, 0.30f, 0.38f);
  if (!begin_panel("Presets")) {
    ImGui::End();
    return;
  }
  const float list_height =
      std::max(60.0f, ImGui::GetContentRegionAvail().y - 4.4f * ImGui::GetFrameHeightWithSpacing());
  if (ImGui::BeginChild("preset list", ImVec2(0.0f, list_height), true)) {
    bool user_header = false;
    for (const PresetEntry& entry : presets_) {
      if (entry.user && !user_header) {
        ImGui::Separator();
        ImGui::TextDisabled("your presets (%s)", options_.user_presets_dir.string().c_str());
        user_header = true;
      }
      const bool current = entry.path.string() == loaded_path_;
      if (ImGui::Selectable(entry.name.c_str(), current)) {
        load_preset_file(entry.path);
      }
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s", entry.path.string().c_str());
      }
    }
  }
  ImGui::EndChild();
  ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Save as...").x -
                          2.0f * ImGui::GetStyle().ItemSpacing.x - 8.0f);
  ImGui::InputTextWithHint("##save name", "name of the new preset", save_name_, sizeof save_name_);
  ImGui::SameLine();
  if (ImGui::Button("Save as...")) {
    save_as(save_name_, false);
  }
  if (ImGui::BeginPopupModal("Overwrite preset?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("A preset named \"%s\" exists. Replace it?", pending_overwrite_.c_str());
    if (ImGui::Button("Replace")) {
      save_as(pending_overwrite_, true);
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      preset_message_ = "Not saved.";
      preset_message_is_error_ = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  if (!preset_message_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, preset_message_is_error_ ? kErrorText : kOkText);
    ImGui::TextWrapped("%s", preset_message_.c_str());
    ImGui::PopStyleColor();
  }
  if (!session_message_.empty()) {
    ImGui::TextColored(kDimText, "%s", session_message_.c_str());
  }
  ImGui::Checkbox("pipeline stats", &show_stats_);
  ImGui::SameLine();
  calibration_panel_.open_button(scene_.parameters());
  export_section();
  ImGui::End();
}

void Explorer::teaching_panel() {
  place_window(0.65f, 0.56f, 0.35f, 0.44f);
  if (!begin_panel("Analysis")) {
    ImGui::End();
    return;
  }
  // Only the selected tab draws, so a hidden sweep or map computes nothing.
  if (ImGui::BeginTabBar("analysis tabs")) {
    // The tab named by the options is selected once, at the first frame.
    auto flags_for = [this](const char* name) {
      return !analysis_tab_selected_ && options_.analysis_tab == name
                 ? ImGuiTabItemFlags_SetSelected
                 : ImGuiTabItemFlags_None;
    };
    const ImGuiTabItemFlags equations_flags = flags_for("equations");
    const ImGuiTabItemFlags sweep_flags = flags_for("sweep");
    const ImGuiTabItemFlags map_flags = flags_for("map");
    analysis_tab_selected_ = true;
    if (ImGui::BeginTabItem("Equations", nullptr, equations_flags)) {
      ImGui::BeginChild("equations");
      equations_tab();
      ImGui::EndChild();
      ImGui::EndTabItem();
    }
    const PanelActions actions = panel_actions();
    if (ImGui::BeginTabItem("Sweep", nullptr, sweep_flags)) {
      sweep_panel_.draw(scene_.parameters(), actions);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Regime map", nullptr, map_flags)) {
      regime_map_panel_.draw(scene_.parameters(), actions);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
}

void Explorer::equations_tab() {
  const Solution& s = scene_.solution();
  const Parameters& p = scene_.parameters();
  const double K = stiffness_constant_K(p);
  const double t = p.fabric.thickness_mm;
  ImGui::TextWrapped("The model with today's numbers (mm, MPa, N/mm²).");
  section("eq. 7: critical stress gives Q7");
  ImGui::TextWrapped("s = K E t³ / (w h l²) = %.4g × %.4g × %.4g³ / (%.3g × %.4g × %.5g²)", K,
                     p.fabric.youngs_modulus_MPa, t, p.fabric.weight_N_per_mm2, p.hanging.height_mm,
                     s.span_mm);
  ImGui::Text("  = %.5g", s.stress_ratio);
  // A calibrated eq. 7 uses s^p (p = 1 is the paper's form).
  const double exponent = p.model.stress_exponent_p;
  const double s_used = exponent == 1.0 ? s.stress_ratio : std::pow(s.stress_ratio, exponent);
  if (exponent != 1.0) {
    ImGui::TextColored(kNoteText, "calibrated form: s^p = %.5g^%.3g = %.5g", s.stress_ratio,
                       exponent, s_used);
  }
  if (s.Q7) {
    const double q = *s.Q7;
    ImGui::Text("(Q7 - 1)² = %s Q7 (Q7 + 1)  ->  Q7 = %.5f", exponent == 1.0 ? "s" : "s^p", q);
    ImGui::TextColored(kDimText, "  check: %.6g = %.6g", (q - 1) * (q - 1), s_used * q * (q + 1));
  } else {
    ImGui::TextColored(kErrorText, "s >= 1: no root; at most one fold.");
  }
  if (s.a_mm.empty()) {
    ImGui::Separator();
    ImGui::TextWrapped("%s", describe(s, p).c_str());
    return;
  }
  const double a0 = s.a_mm.front();
  const double an = s.a_mm.back();
  section("eq. 8: the upper edge keeps its length L");
  const double A = std::hypot(an, s.z_max_mm);
  ImGui::Text("A = sqrt(a_n² + z_max²) = sqrt(%.2f² + %.2f²) = %.2f mm", an, s.z_max_mm, A);
  ImGui::Text("L' = (2l/pi) sqrt(1+k²) E(k²/(1+k²)), k = pi A/l = %.4f",
              std::numbers::pi * A / s.span_mm);
  ImGui::Text("   = %.3f mm  vs  L = %.1f mm  (residual %.2e)",
              upper_edge_length_closed_form(A, s.span_mm), p.hanging.length_mm, s.residual_length);
  section("eq. 9: the centre fibre keeps its length h");
  ImGui::Text("h' = sum of sqrt((a_i-1 - a_i)² + (2 z_max)²), i = 1..%d", s.n);
  ImGui::Text("   = %.3f mm  vs  h = %.1f mm  (residual %.2e)",
              fibre_length(a0, s.Q, s.n, s.z_max_mm), p.hanging.height_mm, s.residual_height);
  section("eq. 10: the number of wrinkles");
  if (s.Q7) {
    const double argument = std::log(a0 / an) / std::log(*s.Q7);
    ImGui::TextWrapped("n = Int[log(a_0/a_n) / log Q7] = Int[log(%.1f/%.2f) / log %.4f]", a0, an,
                       *s.Q7);
    ImGui::Text("  = Int[%.3f] = %d   (Int = %s)", argument, s.n,
                std::string(to_string(p.model.int_rounding)).c_str());
    if (shown_n_ != s.n) {
      previous_n_ = shown_n_;
      shown_n_ = s.n;
    }
    if (previous_n_ >= 0 && previous_n_ != s.n) {
      ImGui::TextColored(
          kOkText, "n changed from %d to %d: log(a_0/a_n)/log Q7 crossed %s.", previous_n_, s.n,
          p.model.int_rounding == IntRounding::nearest ? "a half-integer" : "an integer");
    }
    previous_count_argument_ = argument;
  } else {
    ImGui::Text("n = 1 (no Q7: stiff)");
  }
  ImGui::Text("Q = (a_0/a_n)^(1/n) = %.4f", s.Q);
}

void Explorer::stats_overlay() {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, display.y - 10.0f), ImGuiCond_Always,
                          ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.8f);
  if (ImGui::Begin("pipeline", &show_stats_,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
    ImGui::Text("stage        evals     last ms");
    for (Stage stage : {Stage::solution, Stage::fold_lines, Stage::grid, Stage::normals}) {
      const StageStats& st = scene_.stats(stage);
      ImGui::Text("%-12s %5llu  %10.3f", std::string(to_string(stage)).c_str(),
                  static_cast<unsigned long long>(st.evaluations), st.last_ms);
    }
    if (renderer_) {
      ImGui::Text("mesh uploads %llu, fold-line uploads %llu",
                  static_cast<unsigned long long>(renderer_->counters().mesh_uploads),
                  static_cast<unsigned long long>(renderer_->counters().fold_line_uploads));
    }
    ImGui::Text("%.1f ms/frame", 1000.0f / std::max(ImGui::GetIO().Framerate, 1e-3f));
  }
  ImGui::End();
}

}  // namespace foldlab::gui
