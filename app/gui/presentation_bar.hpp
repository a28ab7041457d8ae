// The read-out over a presented view: n, Q and z_max as large as the width allows (read from the
// back of a room), the strip of the cloth's inputs under it when shown, and the status line,
// which the Presets panel shows out of sight.
#pragma once

#include <map>
#include <string>

#include "app/gui/layout.hpp"
#include "app/gui/panel.hpp"

namespace foldlab::gui {

// A phone: a finger on a screen narrower than 40 lines of text are tall (600 CSS px at 100 %), or
// lower than 30 (450 CSS px: a phone held sideways), where six tiles squeeze into columns too
// narrow, or rows too low, for their labels. Then the explorer shows one
// view at a time, as presented, with the read-out and the inputs' strip over it and a row of the
// views under them to switch with a thumb.
bool shows_one_view();

class PresentationBar {
 public:
  // The read-out's window ("presentation" is its key for playback's "in").
  static constexpr const char* kWindow = "##presentation read-out###presentation";

  explicit PresentationBar(Layout& layout) : layout_(layout) {}
  // Draws the bar below the menu bar (at `top`); returns where the presented panel starts.
  float draw(PanelContext& context, float top);
  // The status line as the bar showed it at the last frame (empty: none).
  const std::string& message() const { return message_; }
  // Where the phone's row of views drew each view's button at the last frame, by the panel's key
  // (none while the tiles or a laptop's presented view are shown).
  const std::map<std::string, PanelRect>& view_buttons() const { return view_buttons_; }
  void clear() {
    message_.clear();
    view_buttons_.clear();
  }

 private:
  // The status line to show under the read-out and the strip, or "" when it is seen elsewhere.
  std::string message_for_presented(PanelContext& context, bool strip) const;

  Layout& layout_;
  std::string message_;
  std::map<std::string, PanelRect> view_buttons_;
  // The read-out's scale only shrinks while the window's width, the text size and the view
  // presented stay: a read-out that loses its ranges (n cycles, a short cloth) while an input
  // plays would otherwise grow and push the strip down, and back, as the regimes pass.
  float scale_cap_ = 0.0f;
  float scale_cap_width_ = -1.0f;
  float scale_cap_font_ = -1.0f;
  const void* scale_cap_view_ = nullptr;
};

}  // namespace foldlab::gui
