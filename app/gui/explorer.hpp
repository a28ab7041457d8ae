// The explorer: the coordinator of the FoldLab window. It owns the document (the one copy of the
// state the panels share) and one list of panels, and draws them once per frame with Dear
// ImGui. It draws through a Renderer, never GL itself: the GL renderer serves the window and
// headless pictures, the null renderer serves unit tests.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/common/inputs.hpp"
#include "app/gui/appearance.hpp"
#include "app/gui/document.hpp"
#include "app/gui/layout.hpp"
#include "app/gui/page_link.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/analysis_panel.hpp"
#include "app/gui/panels/calibration_panel.hpp"
#include "app/gui/panels/cloth_view_panel.hpp"
#include "app/gui/panels/export_panel.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "app/gui/panels/fold_plot_panel.hpp"
#include "app/gui/panels/intro_window.hpp"
#include "app/gui/panels/parameters_panel.hpp"
#include "app/gui/panels/photo_overlay.hpp"
#include "app/gui/panels/presets_panel.hpp"
#include "app/gui/panels/results_panel.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/picture.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/screen.hpp"
#include "core/io/preset.hpp"

namespace foldlab::gui {

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
  // land on another widget than the one drawn where it was made.
  bool layout_pending() const { return appearance_.pending(); }
  // Builds every window for this frame; between ImGui::NewFrame and ImGui::Render.
  void frame();

  // Sets one input by its --set key through Document::apply, as one undo step (scripted runs,
  // --animate, tests): a refused value is kept with its reason, as a slider's is.
  std::optional<std::string> set_input(std::string_view key, double value);
  // A view setting by name (see ClothViewPanel::set_view, plus sweep=table1|table2|fig4).
  std::optional<std::string> set_view(std::string_view key, std::string_view value);
  void load_preset_file(const std::filesystem::path& path) { document_.load_preset_file(path); }
  // Ctrl+S, as the keys do.
  void save() { panel<PresetsPanel>().save(document_, status_); }

  Document& document() { return document_; }
  // The status line as the presentation's read-out showed it at the last frame (empty: none):
  // while a panel is presented the status line, in the Presets panel, is out of sight.
  const std::string& presented_message() const { return presented_message_; }
  UiStatus& status() { return status_; }
  const UiStatus& status() const { return status_; }
  Scene& scene() { return document_.scene(); }
  const Parameters& edited() const { return document_.edited(); }
  const RenderCounters& renderer_counters() const {
    return renderer_.cloth_counters(panel<ClothViewPanel>().a_view());
  }
  const RenderCounters& compare_counters() const {
    return renderer_.cloth_counters(panel<ClothViewPanel>().b_view());
  }
  // The panel of type P (tests, reports and the frame loop look into one by its type).
  template <class P>
  P& panel() const {
    return find_panel<P>(panels_);
  }
  // The tiled panel with this key, or null.
  const Panel* tiled_panel(std::string_view key) const {
    for (const std::unique_ptr<Panel>& p : panels_) {
      if (Layout::tiled(*p) && key == p->key()) {
        return p.get();
      }
    }
    return nullptr;
  }
  const AnalysisPanel& analysis() const { return panel<AnalysisPanel>(); }
  const PresetsPanel& presets() const { return panel<PresetsPanel>(); }
  const ParametersPanel& parameters_panel() const { return panel<ParametersPanel>(); }
  const FoldPlotPanel& fold_plot() const { return panel<FoldPlotPanel>(); }
  const ClothViewPanel& cloth_view() const { return panel<ClothViewPanel>(); }
  PhotoOverlay& photo() const { return panel<PhotoOverlay>(); }
  const CalibrationPanel& calibration() const { return panel<CalibrationPanel>(); }
  // Every panel, in the order they are drawn (the tiled ones first, in the layout's order).
  const std::vector<std::unique_ptr<Panel>>& panels() const { return panels_; }
  // How a background job that finished wakes the frame loop while it sleeps (the window's
  // empty event); callable from any thread. None by default: a test's loop never sleeps.
  void set_wake(std::function<void()> wake) { wake_ = std::move(wake); }
  Appearance& appearance() { return appearance_; }
  // Where the panels go (layout.hpp); presentation shows a read-out of n, Q and z_max above the
  // presented panel.
  Layout& layout() { return layout_; }
  // The read-out's window over a presented panel ("presentation" is its key for playback's "in"),
  // the menu bar's item that shows or hides its strip of inputs, and the one back to the tiles
  // (short when the bar is narrow).
  static constexpr const char* kPresentationWindow = "##presentation read-out###presentation";
  static constexpr const char* kShowInputsLabel = "Show inputs";
  static constexpr const char* kHideInputsLabel = "Hide inputs";
  static constexpr const char* kBackToTilesLabel = "Back to the tiles (Esc)";
  static constexpr const char* kBackToTilesShortLabel = "Tiles (Esc)";
  const Layout& layout() const { return layout_; }
  bool automatic_layout() const { return layout_.automatic(); }
  std::vector<std::pair<std::string, PanelRect>> panel_rects() const {
    return layout_.panel_rects();
  }
  bool panels_fill_window() const { return layout_.fills_window(); }
  void reset_layout() { layout_.reset(); }
  const LayoutSplits& layout_splits() const { return layout_.splits(); }
  // Presents the tiled panel with this key ("fold_plot"); an unknown key returns to the tiles.
  void present(std::string_view key) { layout_.present(tiled_panel(key)); }
  // The presented panel's key, empty while the tiles are shown.
  std::string presented() const {
    return layout_.presented() != nullptr ? layout_.presented()->key() : "";
  }
  // Where the link goes: the platform's (make_page_link()); the desktop's until set.
  void set_page_link(std::unique_ptr<PageLink> link) { page_link_ = std::move(link); }
  // The fabric A as a link's fragment (core/io/link.hpp: every input, as edited, refused or not),
  // with the view keys (kLinkViewKeys) that differ from a fresh start.
  std::string link() const;
  // "Export > Copy link": the link, as the platform hands it out, on the clipboard, with a notice.
  void copy_link();

  void save_session_now();
  // The session saved now if it changed since the last save (rather than a second after the
  // last change): the page is being left, and what a person did last must not be lost.
  void keep_session();
  // The window is asked to close: true when nothing would be lost (no unsaved edits, or a session
  // that brings them back); otherwise asks "Save / Discard / Cancel" and returns false, and
  // quit_confirmed() turns true once the answer lets the window close.
  bool may_quit();
  bool quit_confirmed() const { return quit_confirmed_; }
  // A PNG the user asked for in the Export menu, taken by the frame loop after drawing this
  // frame, which shows neither the menu nor the dialog it was asked with.
  std::optional<PictureRequest> take_screenshot_request();
  // The 3D cloth or the fold plot alone at spec.size, as `foldlab picture` draws it, written as
  // PNG to `path`. Throws SurfaceError when it cannot be drawn or written.
  void write_picture(const std::filesystem::path& path, const PictureSpec& spec);
  FileDialog& file_dialog() { return files_; }
  // How files reach the user: the platform's (make_file_transfer()); the desktop's until set.
  void set_file_transfer(std::unique_ptr<FileTransfer> transfer) {
    transfer_ = std::move(transfer);
    files_.set_transfer(*transfer_);
  }
  IntroWindow& intro() const { return panel<IntroWindow>(); }
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
  bool animating() const {
    return busy() || panel<ClothViewPanel>().animating() || panel<ParametersPanel>().animating();
  }
  // True while a frame would differ from the last after a while, with no input: a message that
  // will fade, a session or window layout to save, a text cursor blinking. (Tooltips show at
  // once, in the frames that follow the mouse's move.) Call after a frame; otherwise a sleeping
  // window needs no timeout.
  bool awaits_time() const;
  const ClothStyle& cloth_style() const { return panel<ClothViewPanel>().style(); }
  // The files the explorer has open now (the 3D view's swatch, the fold plot's photo), each named
  // as the user knows it; no picture may be written over them.
  std::vector<app::NamedPath> files_in_use() const {
    return {{"the 3D view's print file", panel<ClothViewPanel>().print_file()},
            {"the fold plot's photo", panel<PhotoOverlay>().photo_file()}};
  }
  // The last finished regime map's wall time in ms (0 before one finishes).
  double regime_map_ms() const { return panel<AnalysisPanel>().regime_map().last_map_ms(); }

 private:
  // The session file: restored when asked (the fabric, B, the view), set aside or left alone
  // when it does not read as a session.
  void read_session(bool restore_session);
  void save_session_when_idle();
  // Ctrl+Z undo, Ctrl+Shift+Z and Ctrl+Y redo, Ctrl+S save.
  void handle_shortcuts();
  // "Save / Discard / Cancel" before a preset load replaces unsaved edits.
  void draw_unsaved_dialog();

  // Escape closes an open menu or combo first, then leaves presentation.
  void handle_escape();
  // The read-out over a presented panel; returns where the panel starts below it.
  float presentation_bar();
  // The status line to show under a presented panel's read-out, or "" when it is seen elsewhere.
  std::string message_for_presented(bool strip);
  // The menu bar (View, Export); returns its height, where the tiled panels start.
  float main_menu();
  void view_menu();
  // What the session keeps of the view: the UI scale and theme, expert mode, and every
  // remembered setting.
  void save_settings(SessionSettings& settings) const;
  void load_settings(const SessionSettings& settings);
  template <class P, class... Args>
  void add(Args&&... args) {
    panels_.push_back(std::make_unique<P>(std::forward<Args>(args)...));
  }

  ExplorerOptions options_;
  Renderer& renderer_;
  Appearance appearance_;
  UiStatus status_;  // before the document, which reports to it
  Document document_;
  ExportPanel export_;                             // the Export menu, in the menu bar
  ClothView picture_view_ = kNoClothView;          // the cloth of pictures (write_picture)
  ClothView compare_picture_view_ = kNoClothView;  // B's cloth in pictures of A and B
  std::unique_ptr<FileTransfer> transfer_;         // before files_, which points to it once set
  FileDialog files_;                               // every panel's open and save dialog
  // The panels, in drawing order, each type once (panel<P>() finds one).
  std::vector<std::unique_ptr<Panel>> panels_;
  std::function<void()> wake_;
  std::unique_ptr<PageLink> page_link_ = std::make_unique<PageLink>();
  LinkThrottle address_;  // when the page's address follows the link
  bool show_stats_ = false;
  float menu_height_ = 0.0f;
  std::string presented_message_;
  Layout layout_{panels_};
  // What the session keeps of the panels' and the layout's settings (each declares its own).
  RememberedSettings remembered_;
  bool quit_confirmed_ = false;
  double last_session_save_time_ = 0.0;
};

}  // namespace foldlab::gui
