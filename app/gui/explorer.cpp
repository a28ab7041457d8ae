#include "app/gui/explorer.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <span>
#include <utility>

#include <imgui.h>
#include <imgui_internal.h>  // the focused window: Escape closes a floating one first
#include <nlohmann/json.hpp>

#include "app/gui/file_transfer.hpp"
#include "app/gui/menu_bar.hpp"
#include "app/gui/panel_list.hpp"
#include "app/gui/panels/cloth_view_panel.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "app/gui/panels/parameters_panel.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/presentation_bar.hpp"
#include "app/gui/session.hpp"
#include "app/gui/session_keeper.hpp"
#include "app/gui/surface.hpp"
#include "core/model/settings.hpp"

namespace foldlab::gui {
namespace {

template <class Predicate>
bool any_panel(const std::vector<std::unique_ptr<Panel>>& panels, Predicate predicate) {
  return std::any_of(panels.begin(), panels.end(),
                     [&](const std::unique_ptr<Panel>& panel) { return predicate(*panel); });
}

// What changed between two fabrics, in the words a slider reads: "h = 1,500 mm (was 1,400 mm)",
// or the changed inputs' symbols when there are several. Empty when nothing did.
std::string changed_inputs_words(const Parameters& before, const Parameters& after) {
  std::vector<std::string> symbols;
  std::string one;
  for (const InputSpec& spec : input_table()) {
    const std::optional<double> was = spec.value(before);
    const std::optional<double> now = spec.value(after);
    if (was && now) {
      if (*was == *now || (std::isnan(*was) && std::isnan(*now))) {
        continue;
      }
      // With the digits the slider shows (a finger's drag leaves 12 more); all of them where
      // those would read the same before and after.
      std::string now_text = shown_text(spec, *now);
      std::string was_text = shown_text(spec, *was);
      if (now_text == was_text) {
        now_text = shown_quantity(spec, *now);
        was_text = shown_quantity(spec, *was);
      }
      one = input_title(spec) + " = " + now_text + " (was " + was_text + ")";
    } else if (spec.choice != nullptr) {
      const std::string_view choice_was = spec.choice(before);
      const std::string_view choice_now = spec.choice(after);
      if (choice_was == choice_now) {
        continue;
      }
      one = input_title(spec) + ": " + std::string(choice_now) + " (was " +
            std::string(choice_was) + ")";
    } else {
      continue;
    }
    symbols.emplace_back(input_symbol(spec));
  }
  if (symbols.size() <= 1) {
    return symbols.empty() ? std::string() : "Changed " + one;
  }
  constexpr std::size_t kNamed = 4;
  std::string words = "Changed ";
  for (std::size_t i = 0; i < symbols.size() && i < kNamed; ++i) {
    words += (i == 0 ? "" : ", ") + symbols[i];
  }
  if (symbols.size() > kNamed) {
    words += " and " + std::to_string(symbols.size() - kNamed) + " more";
  }
  return words;
}

}  // namespace

Explorer::Explorer(const Preset& initial, const std::string& initial_path, bool restore_session,
                   ExplorerOptions options, Renderer& renderer)
    : options_(std::move(options)),
      renderer_(renderer),
      appearance_(options_.font_file),
      document_(initial, initial_path, status_),
      files_(std::make_unique<FileDialog>(
          options_.start_folder.empty() ? std::filesystem::current_path() : options_.start_folder)),
      panels_(make_panels({options_.presets_dir, options_.user_presets_dir, options_.analysis_tab,
                           options_.measurements_file})),
      menu_(
          std::make_unique<MenuBar>(layout_, appearance_, link_choices_, [this] { copy_link(); })),
      presentation_(std::make_unique<PresentationBar>(layout_)),
      session_(std::make_unique<SessionKeeper>(options_.session_file, options_.owns_config_folder,
                                               document_, status_, view_settings_)) {
  // A panel moves by its title bar only: a drag that misses a slider's handle by a few pixels
  // would otherwise carry the whole panel out of the tiles. (ImGui's context exists before the
  // explorer, in the app and in the tests.)
  ImGui::GetIO().ConfigWindowsMoveFromTitleBarOnly = true;
  declare_view_settings();
  appearance_.request(options_.preferred.text_scale_percent.value_or(appearance_.scale_percent()),
                      options_.preferred.light_theme.value_or(appearance_.light_theme()));
  session_->read(restore_session);
  PanelContext start = context();
  for (const std::unique_ptr<Panel>& panel : panels_) {
    panel->session_read(start);
  }
  document_.forget_history();     // undo goes back no further than what the window opened with
  view_settings_.take_changed();  // what the window opened with is what the session has
  status_.session_saved();
  appearance_.apply(renderer_);
}

Explorer::~Explorer() {
  try {
    save_session_now();
  } catch (const std::exception&) {
    // Leaving must not fail because the config folder is read-only; the session is a convenience.
  }
}

void Explorer::declare_view_settings() {
  ViewSettings& s = view_settings_;
  for (const std::unique_ptr<Panel>& panel : panels_) {
    panel->view_settings(s, document_);
  }
  layout_.view_settings(s);
  appearance_.view_settings(s);
  appearance_.emulation_settings(s);
  s.add_number_by(
      "grid", {kMinGridResolution, kMaxGridResolution, " (vertices per side)"},
      kScripted | kReported, [this] { return document_.scene().grid_nx(); },
      [this](double per_side) { document_.set_grid_resolution(static_cast<int>(per_side)); }, true);
  // What Copy link writes: the sender's theme and text size or not, and the page's address.
  s.add_switch("link_look", &link_choices_.carries_look, kEveryUse);
  s.add_text("page_address", &link_choices_.page_address, kEveryUse);
  s.add_switch_by(
      "expert", kEveryUse, [this] { return status_.expert_mode(); },
      [this](bool on) { status_.set_expert_mode(on); });
}

PanelContext Explorer::context() {
  return PanelContext{document_,   status_,       renderer_,          *files_, wake_, panels_,
                      appearance_, plays_input(), layout_.presented()};
}

std::optional<std::string> Explorer::set_input(std::string_view key, double value) {
  return document_.apply(Edit::input(std::string(key), value));
}

const std::string& Explorer::presented_message() const {
  return presentation_->message();
}

const std::map<std::string, PanelRect>& Explorer::view_buttons() const {
  return presentation_->view_buttons();
}

const std::map<std::string, PanelRect>& Explorer::menu_bar_items() const {
  return menu_->item_rects();
}

nlohmann::json Explorer::report() {
  nlohmann::json state = nlohmann::json::object();
  PanelContext now = context();
  for (const std::unique_ptr<Panel>& panel : panels_) {
    panel->report(state, now);
  }
  state["view"] = view_settings_.report();
  return state;
}

namespace {

// The shipped preset `path` is, by its file's stem: what a link names for the reader to start
// from. Empty for the built-in default and for a file outside the shipped folder (a user's
// preset, which the reader does not have).
std::string shipped_preset_name(const std::string& path, const std::filesystem::path& shipped) {
  if (path.empty() || shipped.empty()) {
    return "";
  }
  std::error_code error;
  const std::filesystem::path file(path);
  return std::filesystem::equivalent(file.parent_path(), shipped, error) && !error
             ? file.stem().string()
             : "";
}

}  // namespace

std::string Explorer::link() const {
  LinkContent content;
  content.preset = shipped_preset_name(document_.loaded_path(), options_.presets_dir);
  // As its file has it, which is what the reader loads: the preset as loaded here may carry
  // --set overrides.
  if (!content.preset.empty() && (!link_base_ || link_base_->first != document_.loaded_path())) {
    try {
      link_base_.emplace(document_.loaded_path(), load_preset(document_.loaded_path()));
    } catch (const PresetError&) {
      link_base_.reset();
    }
  }
  if (content.preset.empty() || !link_base_) {
    content.preset.clear();
    content.base = default_preset();
  } else {
    content.base = link_base_->second;
  }
  content.a = {document_.edited(), document_.dragged_keys(), document_.loaded().name};
  if (document_.compare().pinned()) {
    const PinnedFabric& b = document_.compare().pinned_fabric();
    content.b = LinkFabric{b.fabric.parameters, b.dragged_keys, b.fabric.name};
  }
  // A phone's one view is its screen's, not a choice to send: a link opened on a laptop shows
  // its tiles.
  return explorer_link(content,
                       {shows_one_view() ? std::string() : presented(), appearance_.light_theme(),
                        appearance_.scale_percent(), link_choices_.carries_look});
}

void Explorer::copy_link() {
  const std::string address = page_link_->address(link(), link_choices_.page_address);
  page_link_->copy(address);
  // Said where it is seen: the Presets panel's status line may be below the window's foot, and is
  // hidden while a panel is presented.
  status_.notify(copied_link_notice(address), MessageKind::success);
  status_.toast(copied_link_notice(address));
}

std::optional<PictureRequest> Explorer::take_screenshot_request() {
  std::optional<ExportPanel::PictureRequest> asked = menu_->export_menu().take_picture_request();
  if (!asked) {
    return std::nullopt;
  }
  PictureRequest request{asked->path, std::nullopt, asked->spec};
  if (asked->spec || !asked->part) {
    return request;
  }
  // The part of the window the panel giving the picture drew it in.
  for (const std::unique_ptr<Panel>& panel : panels_) {
    for (const PictureOffer& offer : panel->pictures()) {
      if (offer.view == *asked->part) {
        request.crop = panel->picture_rect(offer.view).value_or(layout_.rect_of(*panel));
      }
    }
  }
  return request;
}

void Explorer::write_picture(const std::filesystem::path& path, const PictureSpec& spec) {
  for (ClothView* view : {&picture_view_, &compare_picture_view_}) {
    if (*view == kNoClothView) {
      *view = renderer_.create_cloth_view();
    }
  }
  const PictureSource source = picture_source(document_, panels_, picture_view_,
                                              compare_picture_view_, appearance_.font_file());
  write_png(path.c_str(), spec.size, draw_picture(renderer_, source, spec));
}

void Explorer::set_file_transfer(std::unique_ptr<FileTransfer> transfer) {
  transfer_ = std::move(transfer);
  files_->set_transfer(*transfer_);
}

bool Explorer::plays_input() const {
  return any_panel(panels_, [](const Panel& p) { return p.plays_input(); });
}

bool Explorer::busy() const {
  return any_panel(panels_, [](const Panel& p) { return p.busy(); });
}

bool Explorer::animating() const {
  return any_panel(panels_, [](const Panel& p) { return p.busy() || p.animating(); });
}

std::vector<app::NamedPath> Explorer::files_in_use() const {
  std::vector<app::NamedPath> files;
  for (const std::unique_ptr<Panel>& panel : panels_) {
    for (app::NamedPath& file : panel->files_in_use()) {
      files.push_back(std::move(file));
    }
  }
  return files;
}

void Explorer::save_session_now() {
  session_->save_now();
}

void Explorer::keep_session() {
  session_->keep();
}

bool Explorer::may_quit() {
  if (quit_confirmed_ || session_->keeps_edits() || !document_.unsaved()) {
    return true;
  }
  if (status_.modal_title().empty()) {
    document_.replace_edits("Closing the window loses them.",
                            [this](Document&) { quit_confirmed_ = true; });
  }
  return false;
}

// Letters by the platform's key codes: GLFW's, which are the upper-case ASCII codes.
void Explorer::handle_undo_keys() {
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
  }
}

void Explorer::handle_escape() {
  // A dialog answers Escape itself, and a field being typed in takes it back to its old text.
  if (!ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false) ||
      !status_.modal_title().empty() || ImGui::IsAnyItemActive()) {
    return;
  }
  // A floating window (the introduction) closes itself on Escape while it has the focus.
  if (const ImGuiWindow* focused = ImGui::GetCurrentContext()->NavWindow; focused != nullptr) {
    if (any_panel(panels_, [focused](const Panel& p) {
          return !Layout::presentable(p) && p.window_label() == focused->RootWindow->Name;
        })) {
      return;
    }
  }
  if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) {
    ImGui::ClosePopupsExceptModals();
  } else if (layout_.presented() != nullptr) {
    layout_.present(nullptr);
  }
}

bool Explorer::awaits_time() const {
  const ImGuiIO& io = ImGui::GetIO();
  return !status_.message().empty() || !status_.toast().empty() || status_.session_dirty() ||
         address_.pending() || io.WantTextInput || io.WantSaveIniSettings ||
         ImGui::GetCurrentContext()->SettingsDirtyTimer > 0.0f;
}

void Explorer::draw_toast() {
  toast_rect_.reset();
  const std::string& text = status_.toast();
  if (text.empty()) {
    return;
  }
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float margin = ImGui::GetFontSize();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x * 0.5f,
                                 viewport->WorkPos.y + viewport->WorkSize.y - margin),
                          ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowSizeConstraints(
      ImVec2(0.0f, 0.0f),
      ImVec2(viewport->WorkSize.x - 2.0f * margin, viewport->WorkSize.y - 2.0f * margin));
  constexpr ImGuiWindowFlags kFlags =
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
      ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("##toast", nullptr, kFlags)) {
    // Wrapped at most at 40 font heights: a line across a wide window is hard to read.
    ImGui::PushTextWrapPos(std::min(viewport->WorkSize.x - 4.0f * margin, 40.0f * margin));
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    const ImVec2 pos = ImGui::GetWindowPos();
    const ImVec2 size = ImGui::GetWindowSize();
    toast_rect_ = PanelRect{pos, size};
  }
  ImGui::End();
  // Above the panels, which the frame draws before it.
  ImGui::BringWindowToDisplayFront(ImGui::FindWindowByName("##toast"));
}

namespace {

// The floating windows open and whether a menu or list is: a frame that closes one is drawn
// again before the next click is read (layout_pending).
int windows_open(std::span<const std::unique_ptr<Panel>> panels) {
  const auto open = std::count_if(panels.begin(), panels.end(), [](const auto& panel) {
    return !Layout::tiled(*panel) && panel->is_open();
  });
  return static_cast<int>(open) + (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId) ? 1 : 0);
}

}  // namespace

void Explorer::frame() {
  const int open_before = windows_open(panels_);
  begin_target_tally();
  status_.tick(ImGui::GetTime());
  appearance_.handle_shortcuts();
  PanelContext context = this->context();
  for (const std::unique_ptr<Panel>& panel : panels_) {
    panel->begin_frame(context);  // Ctrl+S, and a played input's value for every view
  }
  handle_undo_keys();
  handle_escape();
  const float menu_height = menu_->draw(context);
  if (shows_one_view() && layout_.presented() == nullptr) {
    layout_.request_present(&context.panel<ClothViewPanel>());
  }
  layout_.begin_frame(menu_height);
  presentation_->clear();
  if (layout_.presented() != nullptr) {
    layout_.set_presented_top(presentation_->draw(context, menu_height));
  }
  for (const std::unique_ptr<Panel>& panel : panels_) {
    if (!layout_.shows(*panel)) {
      continue;  // hidden behind the presented one, and not drawn
    }
    const bool presentable = Layout::presentable(*panel);
    // On a phone the views are switched under the read-out, with no tiles to go back to; on a
    // screen the presented view's title bar is a menu of the menu bar (MenuBar).
    const bool title_in_menu = layout_.presented() == panel.get() && !shows_one_view();
    if (presentable) {
      layout_.place(*panel);
    }
    if (title_in_menu) {
      next_panel_without_title_bar();
    }
    panel->draw(context);
    if (presentable && !shows_one_view() && !title_in_menu) {
      layout_.present_button(*panel);
    }
  }
  layout_.tile_handles(finger_pointer(), kTouchTargetPx * appearance_.pixel_ratio());
  for (const std::unique_ptr<Panel>& panel : panels_) {
    panel->end_frame(context);
  }
  menu_->draw_after_panels(context);
  draw_toast();
  files_->draw(status_);
  // A drag ends when its widget lets go; an animation when it is paused.
  if (!ImGui::IsAnyItemActive() && !plays_input()) {
    document_.end_step();
    // A finger hides what it touches, and on a phone the view that shows an input may be another
    // than the one tapped (a preset chosen under Inputs, a map tapped): every change of the
    // inputs is said in the toast, over the foot of whatever view is shown.
    if (appearance_.coarse_pointer() && rest_inputs_) {
      const std::string said = changed_inputs_words(*rest_inputs_, document_.edited());
      if (!said.empty()) {
        status_.toast(said);
      }
    }
    rest_inputs_ = document_.edited();
  }
  session_->keep_when_idle(ImGui::GetTime());
  if (page_link_->follows()) {
    if (const std::optional<std::string> due = address_.due(link(), ImGui::GetTime())) {
      page_link_->show(*due);
    }
  }
  window_closed_ = windows_open(panels_) < open_before;
}

}  // namespace foldlab::gui
