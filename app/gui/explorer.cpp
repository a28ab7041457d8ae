#include "app/gui/explorer.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>

#include <imgui.h>
#include <imgui_internal.h>  // FindWindowByName: where the user moved a panel

#include "app/common/version.hpp"
#include "app/gui/panels/compare_table.hpp"
#include "app/gui/panels/stats_overlay.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/session.hpp"
#include "app/gui/surface.hpp"
#include "core/io/link.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

Explorer::Explorer(const Preset& initial, const std::string& initial_path, bool restore_session,
                   ExplorerOptions options, Renderer& renderer)
    : options_(std::move(options)),
      renderer_(renderer),
      appearance_(options_.font_file),
      document_(initial, initial_path, status_),
      files_(options_.start_folder.empty() ? std::filesystem::current_path()
                                           : options_.start_folder) {
  // A panel moves by its title bar only: a drag that misses a slider's handle by a few pixels
  // would otherwise carry the whole panel out of the tiles. (ImGui's context exists before the
  // explorer, in the app and in the tests.)
  ImGui::GetIO().ConfigWindowsMoveFromTitleBarOnly = true;
  // The panels, in drawing order: the tiled ones in the layout's order, then the floating windows.
  add<ParametersPanel>();
  add<PresetsPanel>(options_.presets_dir, options_.user_presets_dir);
  add<FoldPlotPanel>();
  add<ClothViewPanel>();
  add<ResultsPanel>();
  add<AnalysisPanel>(options_.presets_dir, options_.analysis_tab);
  add<CalibrationPanel>();
  add<PhotoOverlay>(PhotoPaths{options_.measurements_file, options_.user_presets_dir,
                               shipped_measurements_file(options_.presets_dir)});
  add<IntroWindow>();

  layout_.remember(remembered_);
  for (const std::unique_ptr<Panel>& panel : panels_) {
    panel->remember(remembered_);
  }
  panel<PresetsPanel>().set_footer([this] {
    panel<CalibrationPanel>().open_button(document_.scene().parameters());
    if (!appearance_.notice().empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, kNoteText);
      wrapped_text("%s", appearance_.notice().c_str());
      ImGui::PopStyleColor();
    }
  });
  appearance_.request(options_.preferred.text_scale_percent.value_or(appearance_.scale_percent()),
                      options_.preferred.light_theme.value_or(appearance_.light_theme()));
  if (!options_.session_file.empty()) {
    read_session(restore_session);
  }
  for (const std::string& notice : panel<PresetsPanel>().notices()) {
    status_.add_notice(notice);
  }
  document_.forget_history();  // undo goes back no further than what the window opened with
  remembered_.take_changed();  // what the window opened with is what the session has
  status_.session_saved();
  appearance_.apply(renderer_);
}

void Explorer::read_session(bool restore_session) {
  // Read even when not restored: saving over what is there is allowed only when it reads as a
  // session (or nothing is there).
  std::string error;
  bool may_save = true;
  std::optional<Session> s = load_session(options_.session_file, error, may_save);
  if (!restore_session) {
    s.reset();
    error.clear();
  }
  if (s) {
    if (s->fabric_restored) {
      document_.adopt(s->loaded, s->loaded_preset_path);
      document_.apply(Edit::replace(s->current.parameters));
    }
    document_.set_grid_resolution(s->grid_resolution);
    if (s->compare) {
      document_.compare().pin(
          {*s->compare, s->compare_origin.value_or(*s->compare), s->compare_origin_path});
    }
    load_settings(s->view);
    status_.notify("Restored the last session.", MessageKind::info);
    for (const std::string& notice : s->notices) {
      status_.add_notice(notice);
    }
  } else if (!error.empty()) {
    status_.add_notice(error);  // present but unusable: say why the defaults are shown
  }
  std::filesystem::path set_aside = options_.session_file;
  set_aside += ".unread";
  std::error_code set_aside_error;
  if (!may_save && options_.owns_config_folder &&
      (std::filesystem::rename(options_.session_file, set_aside, set_aside_error),
       !set_aside_error)) {
    status_.add_notice("The session that did not read is kept as " + set_aside.string() +
                       "; a new session is saved in its place.");
  } else if (!may_save) {
    status_.add_notice("The session will not be saved over " + options_.session_file.string() +
                       ", which is not a session file the explorer can read; move it away to "
                       "have the session kept.");
    options_.session_file.clear();  // nothing is saved, and closing asks about unsaved edits
  }
}

Explorer::~Explorer() {
  try {
    save_session_now();
  } catch (const std::exception&) {
    // Leaving must not fail because the config folder is read-only; the session is a convenience.
  }
}

std::optional<std::string> Explorer::set_input(std::string_view key, double value) {
  return document_.apply(Edit::input(std::string(key), value));
}

std::optional<std::string> Explorer::set_view(std::string_view key, std::string_view value) {
  if (key == "sweep") {
    static const char* const names[] = {"table1", "table2", "fig4"};
    for (int which = 0; which < SweepPanel::kPaperCases; ++which) {
      if (value == names[which]) {
        panel<AnalysisPanel>().show_paper_case(which, document_);
        return std::nullopt;
      }
    }
    return "sweep = '" + detail::cut(value) + "' is not one of: table1, table2, fig4";
  }
  if (key == "present") {
    if (value == "none") {
      layout_.present(nullptr);
      return std::nullopt;
    }
    if (const Panel* tiled = tiled_panel(value)) {
      layout_.present(tiled);
      return std::nullopt;
    }
    std::string known = "none";
    for (const std::unique_ptr<Panel>& panel : panels_) {
      if (Layout::tiled(*panel)) {
        known += std::string(", ") + panel->key();
      }
    }
    return "present = '" + detail::cut(value) + "' is not one of: " + known;
  }
  if (key == "theme") {
    if (value != "dark" && value != "light") {
      return "theme = '" + std::string(value) + "' is not one of: dark, light";
    }
    appearance_.request(appearance_.scale_percent(), value == "light");
    return std::nullopt;
  }
  if (key == "scale") {
    const std::optional<double> percent = parse_number(value);
    if (!percent) {
      return "scale = '" + std::string(value) + "' is not a number (percent)";
    }
    if (*percent < kMinUiScalePercent || *percent > kMaxUiScalePercent) {
      return "scale = " + detail::shortest_number(*percent) + " must be in [" +
             std::to_string(kMinUiScalePercent) + ", " + std::to_string(kMaxUiScalePercent) +
             "] (percent)";
    }
    appearance_.request(static_cast<int>(std::lround(*percent)), appearance_.light_theme());
    return std::nullopt;
  }
  if (key == "grid") {
    const std::optional<double> per_side = parse_number(value);
    if (!per_side || *per_side < kMinGridResolution || *per_side > kMaxGridResolution ||
        *per_side != std::floor(*per_side)) {
      return detail::printf_string(
          "grid = '%s' is not a whole number from %d to %d (vertices per side)",
          detail::cut(value).c_str(), kMinGridResolution, kMaxGridResolution);
    }
    const int n = static_cast<int>(*per_side);
    document_.set_grid_resolution(n);
    return std::nullopt;
  }
  return panel<ClothViewPanel>().set_view(key, value);
}

std::string Explorer::link() const {
  std::string out = fabric_link(document_.edited());
  const auto add = [&out](std::string_view key, const std::string& value) {
    out += "&" + std::string(key) + "=" + percent_encode(value);
  };
  if (const Panel* presented = layout_.presented()) {
    add(kLinkPresentKey, presented->key());
  }
  if (appearance_.light_theme()) {
    add(kLinkThemeKey, "light");
  }
  if (appearance_.scale_percent() != kMinUiScalePercent) {
    add(kLinkScaleKey, std::to_string(appearance_.scale_percent()));
  }
  return out;
}

void Explorer::copy_link() {
  const std::string address = page_link_->address(link());
  page_link_->copy(address);
  // What was copied, by its start (the whole link is a few hundred characters, which would push
  // the Presets panel's buttons out of sight): with no page address configured it is the fragment
  // alone, which only `foldlab gui --link` opens, and whoever pastes it should know that.
  constexpr std::size_t kShownAddressBytes = 80;
  constexpr std::size_t kShownFragmentBytes = 40;
  if (address.starts_with('#')) {
    status_.notify("Copied the fabric as a link's fragment alone, " +
                       detail::cut(address, kShownFragmentBytes) +
                       ", which only foldlab gui --link opens. FOLDLAB_PAGE_URL makes it a whole "
                       "address (docs/web.md).",
                   MessageKind::success);
  } else {
    status_.notify("Copied the fabric as a link: " + detail::cut(address, kShownAddressBytes),
                   MessageKind::success);
  }
}

std::optional<PictureRequest> Explorer::take_screenshot_request() {
  std::optional<ExportPanel::PictureRequest> asked = export_.take_picture_request();
  if (!asked) {
    return std::nullopt;
  }
  PictureRequest request{asked->path, std::nullopt, asked->spec};
  if (asked->spec) {
    return request;
  }
  const auto rect_of = [this](std::string_view key) -> std::optional<PanelRect> {
    for (const auto& [name, rect] : panel_rects()) {
      if (name == key) {
        return rect;
      }
    }
    return std::nullopt;
  };
  switch (asked->picture) {
    case ExportPanel::Picture::window:
      break;
    case ExportPanel::Picture::cloth_view:
      request.crop = panel<ClothViewPanel>().view_rect();
      break;
    case ExportPanel::Picture::fold_plot:
      request.crop = rect_of(panel<FoldPlotPanel>().key());
      break;
    case ExportPanel::Picture::sweep:
      request.crop = rect_of(panel<AnalysisPanel>().key());
      break;
  }
  return request;
}

void Explorer::write_picture(const std::filesystem::path& path, const PictureSpec& spec) {
  for (ClothView* view : {&picture_view_, &compare_picture_view_}) {
    if (*view == kNoClothView) {
      *view = renderer_.create_cloth_view();
    }
  }
  // The 3D view's camera once it has framed the cloth (both cloths while B is pinned); until
  // then, framed as it would be.
  const PictureSource source{document_,
                             panel<ClothViewPanel>().style(),
                             panel<ClothViewPanel>().camera_framed()
                                 ? std::optional<OrbitCamera>(panel<ClothViewPanel>().camera())
                                 : std::nullopt,
                             picture_view_,
                             appearance_.font_file(),
                             &panel<AnalysisPanel>().sweep(),
                             compare_picture_view_};
  write_png(path.c_str(), spec.size, draw_picture(renderer_, source, spec));
}

bool Explorer::busy() const {
  return std::any_of(panels_.begin(), panels_.end(),
                     [](const std::unique_ptr<Panel>& panel) { return panel->busy(); });
}

void Explorer::save_settings(SessionSettings& settings) const {
  remembered_.save(settings);
  settings.set("ui_scale_percent", appearance_.scale_percent());
  settings.set("light_theme", appearance_.light_theme());
  settings.set("expert", status_.expert_mode());
}

void Explorer::load_settings(const SessionSettings& settings) {
  appearance_.request(settings.get("ui_scale_percent", appearance_.scale_percent()),
                      settings.get("light_theme", appearance_.light_theme()));
  remembered_.load(settings);
  status_.set_expert_mode(settings.get("expert", status_.expert_mode()));
}

void Explorer::save_session_now() {
  if (options_.session_file.empty()) {
    return;
  }
  Session s;
  s.current = document_.loaded();
  s.current.parameters = document_.scene().parameters();  // the last valid state
  s.loaded = document_.loaded();
  s.loaded_preset_path = document_.loaded_path();
  s.grid_resolution = document_.scene().grid_nx();
  if (document_.compare().pinned()) {
    s.compare = document_.compare().b();
    s.compare_origin = document_.compare().b_origin();
    s.compare_origin_path = document_.compare().b_origin_path();
  }
  save_settings(s.view);
  save_session(options_.session_file, s);
  status_.session_saved();
}

bool Explorer::may_quit() {
  if (quit_confirmed_ || !options_.session_file.empty() || !document_.unsaved()) {
    return true;
  }
  if (status_.modal_title().empty()) {
    document_.replace_edits("Closing the window loses them.",
                            [this](Document&) { quit_confirmed_ = true; });
  }
  return false;
}

// Keeps the session on disk a second after the last change, so that a crash loses little.
void Explorer::save_session_when_idle() {
  const double now = ImGui::GetTime();
  if (status_.session_dirty() && now - last_session_save_time_ > 1.0) {
    last_session_save_time_ = now;
    keep_session();
  }
}

void Explorer::keep_session() {
  if (!status_.session_dirty()) {
    return;
  }
  try {
    save_session_now();
  } catch (const std::exception& e) {
    status_.notify(std::string("Could not save the session: ") + e.what(), MessageKind::error);
    status_.session_saved();
  }
}

// Letters by the platform's key codes: GLFW's, which are the upper-case ASCII codes.
void Explorer::handle_shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  // A dialog answers its own keys; a widget being dragged or typed into keeps them (a text
  // field has its own Ctrl+Z).
  if (!status_.modal_title().empty() || ImGui::IsAnyItemActive() || !io.KeyCtrl || io.KeyAlt) {
    return;
  }
  if (ImGui::IsKeyPressed('Z', false)) {
    if (io.KeyShift) {
      document_.redo();
    } else {
      document_.undo();
    }
  } else if (ImGui::IsKeyPressed('Y', false)) {
    document_.redo();
  } else if (ImGui::IsKeyPressed('S', false)) {
    panel<PresetsPanel>().save(document_, status_);
  }
}

void Explorer::draw_unsaved_dialog() {
  const char* title = UiStatus::kUnsavedModal;
  if (status_.modal_title() != title) {
    return;
  }
  if (!ImGui::IsPopupOpen(title)) {
    ImGui::OpenPopup(title);
  }
  const bool escape = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
  if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("Your edits of \"%s\" are not saved.", document_.loaded().name.c_str());
    ImGui::TextUnformatted(document_.pending_replacement().c_str());
    if (ImGui::Button("Save")) {
      ImGui::CloseCurrentPopup();
      status_.set_modal("");
      panel<PresetsPanel>().save(document_,
                                 status_);  // then loads, unless it asks for a name or fails
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      ImGui::CloseCurrentPopup();
      document_.discard_and_replace();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape) {
      ImGui::CloseCurrentPopup();
      document_.cancel_replace();
      status_.notify("Cancelled; your edits are kept.", MessageKind::info);
    }
    ImGui::EndPopup();
  }
}

// The UI scale and theme, for a projector, beside the shortcuts that do the same.
void Explorer::view_menu() {
  int percent = appearance_.scale_percent();
  bool light = appearance_.light_theme();
  ImGui::Text("UI scale %d %%", percent);
  if (ImGui::MenuItem("Larger text", "Ctrl +", false, percent < kMaxUiScalePercent)) {
    percent += kUiScaleStepPercent;
  }
  if (ImGui::MenuItem("Smaller text", "Ctrl -", false, percent > kMinUiScalePercent)) {
    percent -= kUiScaleStepPercent;
  }
  if (ImGui::MenuItem("Default size", "Ctrl 0", false, percent != kMinUiScalePercent)) {
    percent = kMinUiScalePercent;
  }
  // The sizes a room needs, in one move rather than ten presses of Ctrl +.
  if (ImGui::BeginMenu("Text size")) {
    for (const int choice : {100, 125, 150, 200}) {
      if (ImGui::MenuItem((std::to_string(choice) + " %").c_str(), nullptr, percent == choice)) {
        percent = choice;
      }
    }
    ImGui::EndMenu();
  }
  ImGui::MenuItem("Light theme", nullptr, &light);
  appearance_.request(percent, light);
  ImGui::Separator();
  ImGui::MenuItem("Pipeline stats", nullptr, &show_stats_);
  if (layout_.presented()) {
    if (ImGui::MenuItem("Back to the tiles", "Esc")) {
      layout_.request_present(nullptr);
    }
  } else if (ImGui::BeginMenu("Present (fill the window)")) {
    for (const std::unique_ptr<Panel>& panel : panels_) {
      if (Layout::tiled(*panel) && ImGui::MenuItem(panel->name())) {
        layout_.request_present(panel.get());
      }
    }
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem(IntroWindow::kTitle)) {
    panel<IntroWindow>().open();
  }
  if (ImGui::MenuItem("Reset layout", nullptr, false,
                      !layout_.automatic() || layout_.splits().any())) {
    layout_.reset();
  }
  ImGui::Separator();
  ImGui::TextDisabled("About FoldLab: %s", app::version_line().c_str());
}

void Explorer::handle_escape() {
  // A dialog answers Escape itself, and a field being typed in takes it back to its old text.
  if (!ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false) ||
      !status_.modal_title().empty() || ImGui::IsAnyItemActive()) {
    return;
  }
  // A floating window (the introduction) closes itself on Escape while it has the focus.
  if (const ImGuiWindow* focused = ImGui::GetCurrentContext()->NavWindow; focused != nullptr) {
    for (const std::unique_ptr<Panel>& panel : panels_) {
      if (!Layout::tiled(*panel) && panel->window_label() == focused->RootWindow->Name) {
        return;
      }
    }
  }
  if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) {
    ImGui::ClosePopupsExceptModals();
  } else if (layout_.presented() != nullptr) {
    layout_.present(nullptr);
  }
}

namespace {

// The read-out's lines at one scale: as large as the width allows, up to two and a half times the
// text, as it is read from the back of a room (a hair short of the width, so that rounding never
// wraps it). Only a line too long at the text's own size (scale 1) wraps: between n, Q and z_max
// (headline()), never after a number's '.' as ImGui's wrapping would.
struct Headlines {
  std::vector<std::pair<std::string, ImVec4>> lines;
  float scale = 1.0f;
  float height = 0.0f;
};

Headlines fit_headlines(std::vector<std::pair<std::string, ImVec4>> lines, float available) {
  constexpr float kLargestScale = 2.5f;
  float text_width = 1.0f;
  for (const auto& [line, colour] : lines) {
    text_width = std::max(text_width, ImGui::CalcTextSize(line.c_str()).x);
  }
  Headlines fitted;
  fitted.scale = std::clamp(0.98f * available / text_width, 1.0f, kLargestScale);
  for (auto& [line, colour] : lines) {
    line = wrap_at_spaces(line, available);
    fitted.height += fitted.scale * ImGui::CalcTextSize(line.c_str()).y;
  }
  fitted.height += static_cast<float>(lines.size() - 1) * ImGui::GetStyle().ItemSpacing.y;
  fitted.lines = std::move(lines);
  return fitted;
}

void draw_headlines(const Headlines& headlines) {
  ImGui::SetWindowFontScale(headlines.scale);
  for (const auto& [line, colour] : headlines.lines) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextUnformatted(line.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::SetWindowFontScale(1.0f);
}

}  // namespace

// The status line under the read-out and the strip (a copied link, a refused file): the Presets
// panel that shows it is out of sight unless it is the one presented. Under the strip, so that a
// message coming and going never moves the strip's sliders; not when the strip already says it
// (the reason typed text was no value, under its slider).
std::string Explorer::message_for_presented(bool strip) {
  if (layout_.presented() == &panel<PresetsPanel>()) {
    return "";
  }
  const std::string& message = status_.message();
  // (std::any_of, not std::ranges: the page's libc++ has no ranges algorithms.)
  const std::map<std::string, std::string> reasons = panel<ParametersPanel>().unread_reasons();
  if (strip && std::any_of(reasons.begin(), reasons.end(),
                           [&](const auto& entry) { return entry.second == message; })) {
    return "";
  }
  return message;
}

float Explorer::presentation_bar() {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = std::floor(display.x);
  const float available = width - 2.0f * style.WindowPadding.x;
  const Headlines headlines = fit_headlines(panel<ResultsPanel>().headlines(document_), available);
  // The inputs under the read-out, for a "what if" without leaving the view; not over the
  // Parameters panel itself.
  const bool presents_parameters = layout_.presented() == &panel<ParametersPanel>();
  const bool strip = layout_.presents_inputs() && !presents_parameters;
  presented_message_ = message_for_presented(strip);
  float text_height = headlines.height;
  if (!presented_message_.empty()) {
    text_height += style.ItemSpacing.y +
                   ImGui::CalcTextSize(presented_message_.c_str(), nullptr, false, available).y;
  }
  if (strip) {
    text_height +=
        style.ItemSpacing.y + panel<ParametersPanel>().strip_height(document_, available);
  } else if (!presents_parameters) {
    panel<ParametersPanel>().forget_slider_places();
  }
  const float height = std::ceil(text_height + 2.0f * style.WindowPadding.y);
  ImGui::SetNextWindowPos(ImVec2(0.0f, menu_height_), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar |
                                 ImGuiWindowFlags_NoScrollWithMouse;
  if (ImGui::Begin(kPresentationWindow, nullptr, flags)) {
    renderer_.fill_window_background();
    ImGui::PushTextWrapPos(0.0f);
    draw_headlines(headlines);
    if (strip) {
      panel<ParametersPanel>().draw_strip(document_, status_, available);
    }
    if (!presented_message_.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, message_colour(status_.message_kind()));
      ImGui::TextUnformatted(presented_message_.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
  return menu_height_ + height;
}

float Explorer::main_menu() {
  float height = 0.0f;
  if (ImGui::BeginMainMenuBar()) {
    height = ImGui::GetWindowHeight();
    if (ImGui::BeginMenu("View")) {
      view_menu();
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Compare")) {
      compare_menu(document_, status_);
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Export")) {
      export_.menu(document_, status_, panel<ClothViewPanel>().style(), files_,
                   panel<AnalysisPanel>().sweep_shown());
      ImGui::Separator();
      if (ImGui::MenuItem("Copy link")) {
        copy_link();
      }
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "The fabric as an address: open it in the page, or with foldlab gui --link");
      }
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem(IntroWindow::kTitle)) {
      panel<IntroWindow>().open();
    }
    // One click from the menu bar while the user's own arrangement is shown.
    const bool presenting = layout_.presented() != nullptr;
    if ((!layout_.automatic() || layout_.splits().any()) && !presenting &&
        ImGui::MenuItem("Reset layout")) {
      layout_.reset();
    }
    if (presenting) {
      const bool strip_item = layout_.presented() != &panel<ParametersPanel>();
      const char* strip_label = layout_.presents_inputs() ? kHideInputsLabel : kShowInputsLabel;
      // At a large text size in a small window the long label would push the last item off the
      // bar.
      // A menu bar item takes its text and twice the item spacing.
      const ImGuiStyle& style = ImGui::GetStyle();
      const auto item_width = [&style](const char* label) {
        return ImGui::CalcTextSize(label).x + 2.0f * style.ItemSpacing.x;
      };
      const float needed =
          item_width(kBackToTilesLabel) + (strip_item ? item_width(strip_label) : 0.0f);
      const bool fits =
          ImGui::GetCursorPosX() + needed <= ImGui::GetWindowWidth() - style.WindowPadding.x;
      if (ImGui::MenuItem(fits ? kBackToTilesLabel : kBackToTilesShortLabel)) {
        layout_.request_present(nullptr);
      }
      if (strip_item && ImGui::MenuItem(strip_label)) {
        layout_.set_presents_inputs(!layout_.presents_inputs());
      }
    }
    ImGui::EndMainMenuBar();
  }
  return height;
}

bool Explorer::awaits_time() const {
  const ImGuiIO& io = ImGui::GetIO();
  return !status_.message().empty() || status_.session_dirty() || address_.pending() ||
         io.WantTextInput || io.WantSaveIniSettings ||
         ImGui::GetCurrentContext()->SettingsDirtyTimer > 0.0f;
}

void Explorer::frame() {
  export_.new_frame();
  status_.tick(ImGui::GetTime());
  const int scale_before = appearance_.scale_percent();
  const bool light_before = appearance_.light_theme();
  appearance_.handle_shortcuts();
  handle_shortcuts();
  handle_escape();
  menu_height_ = main_menu();
  layout_.begin_frame(menu_height_);
  presented_message_.clear();
  // Before anything is drawn, so that every view and the read-out show this frame's value.
  panel<ParametersPanel>().play_frame(document_);
  if (layout_.presented() != nullptr) {
    layout_.set_presented_top(presentation_bar());
  }
  PanelContext context{
      document_, status_, renderer_, files_, wake_, panels_, panel<ParametersPanel>().animating()};
  for (const std::unique_ptr<Panel>& panel : panels_) {
    if (!layout_.shows(*panel)) {
      continue;  // hidden behind the presented one, and not drawn
    }
    const bool tiled = Layout::tiled(*panel);
    if (tiled) {
      layout_.place(*panel);
    }
    panel->draw(context);
    if (tiled) {
      layout_.present_button(*panel);
    }
  }

  stats_overlay(show_stats_, document_.scene(), renderer_counters());
  draw_unsaved_dialog();
  panel<PresetsPanel>().draw_dialogs(document_, status_);
  export_.draw_picture_dialog(status_, files_);
  files_.draw(status_);
  if (panel<PhotoOverlay>().take_saved_preset()) {
    panel<PresetsPanel>().refresh();  // the fitted preset joins the list
  }
  // A drag ends when its widget lets go; an animation when it is paused.
  if (!ImGui::IsAnyItemActive() && !panel<ParametersPanel>().animating()) {
    document_.end_step();
  }
  if (appearance_.scale_percent() != scale_before || appearance_.light_theme() != light_before ||
      remembered_.take_changed()) {
    status_.mark_session_dirty();
  }
  save_session_when_idle();
  if (page_link_->follows()) {
    if (const std::optional<std::string> due = address_.due(link(), ImGui::GetTime())) {
      page_link_->show(*due);
    }
  }
}

}  // namespace foldlab::gui
