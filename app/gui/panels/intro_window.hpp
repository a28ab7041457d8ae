// "What am I looking at?": a short introduction to tension field theory and to the panels, for a
// class seeing the explorer for the first time. A floating window, opened from the menu bar (and
// the View menu); its close button, "Close" or Escape close it.
#pragma once

#include "app/gui/panel.hpp"

namespace foldlab::gui {

class IntroWindow : public Panel {
 public:
  static constexpr const char* kTitle = "What am I looking at?";
  const char* name() const override { return kTitle; }
  const char* key() const override { return "intro"; }
  void draw(PanelContext& context) override;
  // Its first frames: the text's height, and with it the scrollbar, is known only from the frame
  // before, so that the first frame shows no scrollbar and the text cut at the window's foot.
  bool busy() const override { return open_ && frames_shown_ < kFramesToSettle; }

  void open() {
    open_ = true;
    focus_ = true;
    frames_shown_ = 0;
  }
  bool is_open() const override { return open_; }
  // "intro_open".
  void report(nlohmann::json& state, PanelContext& /*context*/) const override;

 private:
  static constexpr int kFramesToSettle = 2;
  bool open_ = false;
  bool focus_ = false;
  int frames_shown_ = 0;
};

}  // namespace foldlab::gui
