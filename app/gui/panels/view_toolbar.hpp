// A view's row of settings above it, which folds into one "... settings..." button when, drawn in
// full, it would leave the view under it less than its least useful height: at a large text size
// in a small window the plot or the cloth keeps the room rather than becoming a sliver under its
// own controls.
#pragma once

namespace foldlab::gui {

class ViewToolbar {
 public:
  // `label` is the button's ("view settings...") and names the popup it opens. Returns true when
  // the caller
  // draws the settings now (in full above the view, or inside the open popup); then call end().
  // `fold`: folded whatever the room, the button in the window's title bar after the title (a
  // view presented to a room keeps the screen for itself); a window without a title bar has no
  // button, and its settings open from menu_item().
  bool begin(const char* label, float least_view_height_px, bool fold = false);
  void end();
  // Whether the settings were folded behind the button in the last frame.
  bool folded() const { return folded_; }
  // The settings as an item of the menu that stands for a presented view's title bar: chosen, the
  // popup opens when the view next draws.
  void menu_item();

 private:
  // The full row's height, measured when it was last drawn in full at this width and text size.
  float full_height_px_ = 0.0f;
  float measured_width_px_ = -1.0f;
  float measured_font_px_ = -1.0f;
  float decided_height_px_ = -1.0f;  // the panel's free height when folded_ was decided
  float start_y_px_ = 0.0f;
  bool folded_ = false;
  bool in_popup_ = false;
  const char* label_ = nullptr;  // the last begin()'s
  bool open_requested_ = false;
};

}  // namespace foldlab::gui
