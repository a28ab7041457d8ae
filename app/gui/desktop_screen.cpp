// The desktop's screen: window pixels are the pixels drawn, no browser to ask, and a keyboard.
#include "app/gui/screen.hpp"

namespace foldlab::gui {

float screen_pixel_ratio() {
  return 1.0f;
}

ScreenPreferences screen_preferences() {
  return {};
}

bool screen_pointer_is_coarse() {
  return false;
}

void screen_wants_text_input(bool /*wanted*/, bool /*number*/) {}

void screen_shares_clipboard() {}

}  // namespace foldlab::gui
