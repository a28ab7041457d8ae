// The explorer: the coordinator of the FoldLab window. It owns the document (the one copy of the
// state the panels share), the panel list (panel_list.hpp) and the pieces around it (the layout,
// the menu bar, the presentation's read-out, the session), and draws them once per frame with
// Dear ImGui. It knows no panel by its type: what it reports, the view settings it takes and the
// pictures it draws, it asks of every panel in the list. It draws through a Renderer, never GL
// itself: the GL renderer serves the window and headless pictures, the null renderer unit tests.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "app/common/inputs.hpp"
#include "app/gui/appearance.hpp"
#include "app/gui/document.hpp"
#include "app/gui/layout.hpp"
#include "app/gui/page_link.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/picture.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/ui_status.hpp"
#include "app/gui/view_settings.hpp"
#include "core/io/preset.hpp"

namespace foldlab::gui {

class FileDialog;
class FileTransfer;
class MenuBar;
class PresentationBar;
class SessionKeeper;

struct ExplorerOptions {
  std::filesystem::path presets_dir;       // shipped presets (may be empty)
  std::filesystem::path user_presets_dir;  // "Save as..." writes here
  std::filesystem::path session_file;      // empty: nothing is restored or saved
  std::string analysis_tab;         // "equations", "method", "sweep" or "map": selected at start
  std::filesystem::path font_file;  // empty: ImGui's built-in font (no Greek)
  std::filesystem::path measurements_file;  // the photo's "Add to measurements" appends here
  std::filesystem::path start_folder;       // where the first file dialog opens; empty: the
                                            // working folder
  // The theme and text size the browser prefers: the start's, unless a restored session says
  // otherwise (then the session's; a link's `theme` and `scale` win over both).
  ScreenPreferences preferred{};
  // The config folder is the explorer's alone (ConfigStore::owns_folder): a session file there
  // that does not read is set aside and replaced rather than left for its owner.
  bool owns_config_folder = false;
};

// A picture the user asked for, taken by the frame loop after drawing: the whole window, or the
// part `crop` covers (display pixels).
struct PictureRequest {
  std::string path;
  std::optional<PanelRect> crop;
  // A picture drawn apart from the window (picture.hpp) rather than taken from it.
  std::optional<PictureSpec> spec;
};

class Explorer {
 public:
  // `initial` is shown unless a saved session is restored (only when no preset was asked for).
  // The renderer must outlive the explorer.
  Explorer(const Preset& initial, const std::string& initial_path, bool restore_session,
           ExplorerOptions options, Renderer& renderer);
  ~Explorer();
  Explorer(const Explorer&) = delete;
  Explorer& operator=(const Explorer&) = delete;

  // Before ImGui::NewFrame: applies a new UI scale or theme (fonts cannot change within a frame).
  void prepare_frame() { appearance_.apply(renderer_); }
  // The last frame asked for another text size or theme, which the next prepare_frame builds:
  // what it drew is laid out with the old fonts, and a click read against the next frame would
  // land on another widget than the one drawn where it was made. Likewise when it closed a
  // floating window or a menu (Escape on the introduction): ImGui finds the window under the
  // pointer among those the frame before drew, so the next frame's click would go to the window
  // just closed and be lost.
  bool layout_pending() const { return appearance_.pending() || window_closed_; }
  // Builds every window for this frame; between ImGui::NewFrame and ImGui::Render.
  void frame();

  // Sets one input by its --set key through Document::apply, as one undo step (scripted runs,
  // --animate, tests): a refused value is kept with its reason, as a slider's is.
  std::optional<std::string> set_input(std::string_view key, double value);
  // A view setting by its one name (`--view`; view_settings.hpp): the panels', the layout's and
  // the explorer's own (theme, scale, grid, expert). Returns the problem, if any.
  std::optional<std::string> set_view(std::string_view key, std::string_view value) {
    return view_settings_.set(key, value);
  }
  const ViewSettings& view_settings() const { return view_settings_; }
  void load_preset_file(const std::filesystem::path& path) { document_.load_preset_file(path); }

  Document& document() { return document_; }
  Scene& scene() { return document_.scene(); }
  const Parameters& edited() const { return document_.edited(); }
  UiStatus& status() { return status_; }
  const UiStatus& status() const { return status_; }
  // The status line as the presentation's read-out showed it at the last frame (empty: none):
  // while a panel is presented the status line, in the Presets panel, is out of sight.
  const std::string& presented_message() const;
  // Where a phone's row of views drew each view's button at the last frame, by panel key.
  const std::map<std::string, PanelRect>& view_buttons() const;
  const std::map<std::string, PanelRect>& menu_bar_items() const;
  // Every panel, in the order they are drawn (the tiled ones first, in the layout's order).
  const std::vector<std::unique_ptr<Panel>>& panels() const { return panels_; }
  // What every panel reports (each under its own keys) and the reported view settings ("view").
  nlohmann::json report();
  // How a background job that finished wakes the frame loop while it sleeps (the window's
  // empty event); callable from any thread. None by default: a test's loop never sleeps.
  void set_wake(std::function<void()> wake) { wake_ = std::move(wake); }
  Appearance& appearance() { return appearance_; }
  // Where the panels go (layout.hpp).
  Layout& layout() { return layout_; }
  const Layout& layout() const { return layout_; }
  // Presents the tiled panel with this key ("fold_plot"); an unknown key returns to the tiles.
  void present(std::string_view key) { layout_.present(layout_.presentable_panel(key)); }
  // The presented panel's key, empty while the tiles are shown.
  std::string presented() const {
    return layout_.presented() != nullptr ? layout_.presented()->key() : "";
  }
  // Where the link goes: the platform's (make_page_link()); the desktop's until set.
  void set_page_link(std::unique_ptr<PageLink> link) {
    page_link_ = std::move(link);
    link_choices_.page_knows_address = page_link_->knows_address();
  }
  // The fabrics as a link's fragment (explorer_link): the preset they start from, A's name and
  // inputs (as edited, refused or not; dragged ones at the slider's digits), B when pinned, and
  // the view keys (kLinkViewKeys) that differ from a fresh start.
  std::string link() const;
  // What "Copy link" puts around the fragment and sends with it, set in the Export menu.
  LinkChoices& link_choices() { return link_choices_; }
  // Where the toast was drawn at the last frame (display pixels); none when no toast is shown.
  const std::optional<PanelRect>& toast_rect() const { return toast_rect_; }
  // "Export > Copy link": the link, as the platform hands it out, on the clipboard, with a notice.
  void copy_link();

  void save_session_now();
  // The session saved now if it changed since the last save (the page is being left).
  void keep_session();
  // The window is asked to close: true when nothing would be lost (no unsaved edits, or a session
  // that brings them back); otherwise asks "Save / Discard / Cancel" and returns false, and
  // quit_confirmed() turns true once the answer lets the window close.
  bool may_quit();
  bool quit_confirmed() const { return quit_confirmed_; }
  // A PNG the user asked for in the Export menu, taken by the frame loop after drawing this
  // frame, which shows neither the menu nor the dialog it was asked with.
  std::optional<PictureRequest> take_screenshot_request();
  // A view alone at spec.size, as `foldlab picture` draws it, written as PNG to `path`. Throws
  // SurfaceError when it cannot be drawn or written.
  void write_picture(const std::filesystem::path& path, const PictureSpec& spec);
  FileDialog& file_dialog() { return *files_; }
  // How files reach the user: the platform's (make_file_transfer()); the desktop's until set.
  void set_file_transfer(std::unique_ptr<FileTransfer> transfer);
  // Shows a line in the Presets panel (the outcome of an export done by the frame loop).
  void notify(const std::string& message, bool is_error) { status_.notify(message, is_error); }
  // A line kept in the Presets panel and listed by `gui --report` (see UiStatus::add_notice).
  void add_notice(const std::string& notice) { status_.add_notice(notice); }
  const std::vector<std::string>& notices() const { return status_.notices(); }
  // True while background work of any panel (the regime map, a calibration, the photo's fit) is
  // still to show up in what the window shows.
  bool busy() const;
  // True while a frame would differ from the last without any input: background work, the
  // breeze or an input the play button sweeps. Otherwise the window may sleep until an event (or a
  // finished job's wake) comes.
  bool animating() const;
  // True while a frame would differ from the last after a while, with no input: a message that
  // will fade, a session or window layout to save, a text cursor blinking. Call after a frame.
  bool awaits_time() const;
  // The files the panels have open now, each named as the user knows it; no picture may be
  // written over them.
  std::vector<app::NamedPath> files_in_use() const;

 private:
  // The explorer's own view settings: text size, theme, grid and expert mode.
  void declare_view_settings();
  // Ctrl+Z undo, Ctrl+Shift+Z and Ctrl+Y redo.
  void handle_undo_keys();
  // The toast (UiStatus::toast) over the foot of the window.
  void draw_toast();
  // Escape closes an open menu or combo first, then leaves presentation.
  void handle_escape();
  PanelContext context();
  // An input is being played (the views hold their frame, the undo step stays open).
  bool plays_input() const;

  ExplorerOptions options_;
  Renderer& renderer_;
  Appearance appearance_;
  UiStatus status_;  // before the document, which reports to it
  Document document_;
  std::unique_ptr<FileTransfer> transfer_;  // before files_, which points to it once set
  std::unique_ptr<FileDialog> files_;       // every panel's open and save dialog
  // The panels, in drawing order, each type once.
  std::vector<std::unique_ptr<Panel>> panels_;
  std::function<void()> wake_;
  std::unique_ptr<PageLink> page_link_ = std::make_unique<PageLink>();
  LinkThrottle address_;  // when the page's address follows the link
  LinkChoices link_choices_;
  // The shipped preset links start from, as its file (path) has it: read once, not every frame.
  mutable std::optional<std::pair<std::string, Preset>> link_base_;
  std::optional<PanelRect> toast_rect_;  // where the toast was drawn at the last frame
  Layout layout_{panels_};
  std::unique_ptr<MenuBar> menu_;
  std::unique_ptr<PresentationBar> presentation_;
  ViewSettings view_settings_;
  std::unique_ptr<SessionKeeper> session_;
  ClothView picture_view_ = kNoClothView;          // the cloth of pictures (write_picture)
  ClothView compare_picture_view_ = kNoClothView;  // B's cloth in pictures of A and B
  bool quit_confirmed_ = false;
  bool window_closed_ = false;  // the last frame closed a floating window or a menu
  // The inputs when no widget was last active: a finger's change is said against them.
  std::optional<Parameters> rest_inputs_;
};

}  // namespace foldlab::gui
