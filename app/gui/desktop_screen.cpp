// The desktop's screen: window pixels are the pixels drawn, no browser to ask, and a keyboard.
#include "app/gui/screen.hpp"

namespace foldlab::gui {

float screen_pixel_ratio() {
  return 1.0f;
}

ScreenPreferences screen_preferences() {
  return {};
}

void screen_wants_text_input(bool /*wanted*/) {}

void screen_shares_clipboard() {}

}  // namespace foldlab::gui
