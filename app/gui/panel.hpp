// What every panel of the explorer is to the Explorer: a name (its window's title, said once,
// here), a draw with what panels share, whether it has background work in progress, and the
// settings it remembers in the session. The Explorer keeps its panels in one list, draws them in a
// loop, asks them all whether it is busy and keeps the settings each declares, so that
// adding a panel is its two files and one line in that list.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include "app/gui/document.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/remembered.hpp"
#include "app/gui/renderer.hpp"
#include "app/gui/session.hpp"
#include "app/gui/ui_status.hpp"

namespace foldlab::gui {

class FileDialog;
class Panel;

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
  // An input is being played: the views keep their frame, growing it but never shrinking it, so
  // that the cloth is seen to change size.
  bool holding_frame = false;

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
  // True while background work of the panel is still to show up in what it draws: the frame loop
  // keeps drawing, and scripted runs wait for it before their last frame.
  virtual bool busy() const { return false; }
  // The settings the panel remembers between runs, each added once with a key of its own.
  virtual void remember(RememberedSettings& /*settings*/) {}

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
