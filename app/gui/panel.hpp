// What every panel of the explorer is to the Explorer: a name (its window's title, said once,
// here), a draw with what panels share, whether it has background work in progress, its view
// settings, what it reports, the pictures it gives and the points a script may press in it. The
// Explorer keeps its panels in one list (panel_list.cpp), draws them in a loop and asks them all,
// so that adding a panel is its two files and one line in that list.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeinfo>
#include <utility>
#include <vector>

#include <imgui.h>

#include "app/common/inputs.hpp"
#include "app/gui/document.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/session.hpp"
#include "app/gui/tiles.hpp"
#include "app/gui/ui_status.hpp"
#include "app/gui/view_settings.hpp"

namespace foldlab::gui {

class Appearance;
class FileDialog;
class Panel;

// The views a picture can show alone at any size (`foldlab picture VIEW`, the Export menu).
enum class PictureView { cloth, fold_plot, sweep, compare, field };

// A picture a panel gives of what it shows: the Export menu's items, the save dialog's title, the
// picture dialog's words and the word the offered file name gives it.
struct PictureOffer {
  PictureView view;
  const char* name;           // as `foldlab picture` takes it: "fold_plot"
  const char* title;          // the save dialog's: "Export fold plot picture"
  const char* window_item;    // the view as drawn in the window, or null: "Fold plot picture
                              // (.png)..."
  const char* any_size_item;  // "Fold plot picture, any size (.png)..."
  const char* dialog_words;   // what the picture dialog says it draws
  const char* file_word;      // "fold-plot"
};

// What a picture asks of a panel that draws it: sizes in the picture's pixels.
struct PictureStyle {
  float text_px = 0.0f;
  float line_px = 1.0f;
  bool legend = false;
  bool dark = false;  // drawn over a dark background
};

// Where a view drew its picture last (a plot's data area, the 3D viewport, the map), in display
// pixels, and in which ImGui frame: a view hidden since keeps an old rectangle that is no longer on
// screen, so only one drawn in this frame or the last counts.
class DrawnArea {
 public:
  void mark(PanelRect rect) {
    rect_ = rect;
    frame_ = ImGui::GetFrameCount();
  }
  std::optional<PanelRect> recent() const {
    if (frame_ < 0 || ImGui::GetFrameCount() - frame_ > 1) {
      return std::nullopt;
    }
    return rect_;
  }

 private:
  PanelRect rect_;
  int frame_ = -1;
};

// A view's drawing area by the view's name in reports ("cloth", "fold_plot", "sweep", ...).
using DrawingAreas = std::vector<std::pair<std::string, PanelRect>>;

// The panel of type P in a list of panels; every panel type is in the explorer's list once.
template <class P>
P& find_panel(std::span<const std::unique_ptr<Panel>> panels);

// What a panel's draw is given: the one copy of the state, the way to the GPU and the pieces one
// panel lends another.
struct PanelContext {
  Document& document;
  UiStatus& status;
  Renderer& renderer;
  FileDialog& files;  // the one open/save dialog, which remembers the folder last used
  // Wakes the frame loop when it sleeps; callable from any thread (a background job's end).
  std::function<void()> wake;
  // Every panel of the explorer, in drawing order, for one that lists the others.
  std::span<const std::unique_ptr<Panel>> panels;
  // The text size and theme (a panel draws a note when the font could not be read).
  const Appearance& appearance;
  // An input is being played: the views keep their frame, growing it but never shrinking it, so
  // that the cloth is seen to change size.
  bool holding_frame = false;
  // The panel presented over the window, or null: a view presented to a room folds its controls
  // and gives the screen to its picture.
  const Panel* presented = nullptr;

  // Another panel, for one that works with it (the fold plot draws the photo overlay's photo
  // behind its lines and passes it the clicks).
  template <class P>
  P& panel() const {
    return find_panel<P>(panels);
  }
};

class Panel {
 public:
  virtual ~Panel() = default;

  // The window's title as shown ("Fold lines (2D)"): the one place it is written.
  virtual const char* name() const = 0;
  // The panel's key in reports, scripts and ImGui's window id ("fold_plot"): lower case, stable
  // when the title changes.
  virtual const char* key() const = 0;
  // What the introduction says the panel shows, after its name; null for a panel it does not
  // list.
  virtual const char* introduction() const { return nullptr; }
  // Once per frame, between ImGui::NewFrame and ImGui::Render.
  virtual void draw(PanelContext& context) = 0;
  // Once, when the explorer has read its session (a panel says what it could not read).
  virtual void session_read(PanelContext& /*context*/) {}
  // Before any panel draws (an input being played takes this frame's value, so that every view
  // shows it), and after all have (dialogs over the panels); every frame, shown or not.
  virtual void begin_frame(PanelContext& /*context*/) {}
  virtual void end_frame(PanelContext& /*context*/) {}
  // True while a frame would differ from the last without any input (the breeze, a played input).
  virtual bool animating() const { return false; }
  // True while an input is being played: the views hold their frame and the undo step stays open.
  virtual bool plays_input() const { return false; }
  // The files the panel has open now, each named as the user knows it: no picture is written
  // over them.
  virtual std::vector<app::NamedPath> files_in_use() const { return {}; }
  // True while background work of the panel is still to show up in what it draws: the frame loop
  // keeps drawing, and scripted runs wait for it before their last frame.
  virtual bool busy() const { return false; }
  // The panel's view settings, each added once with its one name (view_settings.hpp).
  virtual void view_settings(ViewSettings& /*settings*/, Document& /*document*/) {}
  // What `gui --report` and the play scripts' state say of the panel, added to `state` under
  // keys of its own.
  virtual void report(nlohmann::json& /*state*/, PanelContext& /*context*/) const {}
  // The views it drew in the last frame and where their pictures went (DrawnArea): what
  // `gui --report` gives as layout.drawing_areas, so that how much of the window a view really
  // uses is measured rather than taken from its panel's size.
  virtual void drawing_areas(DrawingAreas& /*areas*/) const {}
  // The pictures the panel gives (Export menu, `foldlab picture`).
  virtual std::span<const PictureOffer> pictures() const { return {}; }
  // Why the panel cannot give `view` now, drawn alone or (`as_drawn`) as the window shows it (the
  // sweep is not on screen, no B is pinned), or nullopt.
  virtual std::optional<std::string> picture_unavailable(PictureView /*view*/,
                                                         const Document& /*document*/,
                                                         bool /*as_drawn*/) const {
    return std::nullopt;
  }
  // Where `view` was drawn last (display pixels), when it is a part of the panel; nullopt: the
  // whole panel.
  virtual std::optional<PanelRect> picture_rect(PictureView /*view*/) const { return std::nullopt; }
  // Where a script presses `target` with arguments `at` (a photo's pixel, a sweep plot's x), or
  // nullopt when the panel has no such point on screen now.
  virtual std::optional<ImVec2> locate(std::string_view /*target*/,
                                       std::span<const double> /*at*/) const {
    return std::nullopt;
  }

  // A window that is not tiled and that the View menu opens and closes: its open flag (a panel
  // that always shows, or that opens otherwise, gives null).
  virtual bool* open_flag() { return nullptr; }
  virtual bool is_open() const { return true; }
  // Whether View > Present offers the panel although it has no tile.
  virtual bool presentable() const { return false; }
  // Presented on a screen, the panel's title bar is a menu in the menu bar, named after it: what
  // the title bar held (its settings, its tabs) as that menu's items, before "Back to the tiles".
  virtual void presented_menu_items(PanelContext& /*context*/) {}
  // Draws `view` alone into the current ImGui window, `size_px` from the cursor, for a picture
  // (picture.hpp). False: the panel leaves its pictures to picture.cpp.
  virtual bool draw_picture(PictureView /*view*/, ImVec2 /*size_px*/, Document& /*document*/,
                            const PictureStyle& /*style*/) {
    return false;
  }
  // A picture's caption lines of the panel's own for `view`, between the fabric's name and its
  // inputs (the tension field's cut, weight, thrust and folds); empty: the caption's usual lines.
  virtual std::vector<std::string> picture_figures(PictureView /*view*/,
                                                   Document& /*document*/) const {
    return {};
  }

  // What ImGui::Begin is given: the title, then after "###" the key, so that a title with a
  // changing mark ("Parameters *") is the same window. `mark` is appended to the title.
  std::string window_label(const char* mark = "") const {
    return std::string(name()) + mark + "###" + key();
  }
  // ImGui::Begin with the window label and the renderer's background (begin_panel). Call
  // ImGui::End() whatever it returns.
  bool begin(Renderer& renderer, const char* mark = "") const {
    return begin_panel(window_label(mark).c_str(), renderer);
  }
};

template <class P>
P& find_panel(std::span<const std::unique_ptr<Panel>> panels) {
  for (const std::unique_ptr<Panel>& panel : panels) {
    if (auto* found = dynamic_cast<P*>(panel.get())) {
      return *found;
    }
  }
  throw std::logic_error(std::string("no such panel in the list: ") + typeid(P).name());
}

}  // namespace foldlab::gui
