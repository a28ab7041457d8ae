// What the screen the explorer is drawn on says about itself and asks of it: how many device
// pixels make one of the page's CSS pixels, the theme and text size its user prefers, and an
// on-screen keyboard for typing. One implementation per platform, chosen at link time as
// PageLink is: the desktop's (app/gui/desktop_screen.cpp) knows none of these and does nothing,
// the page's (app/web/page_screen.cpp) asks the browser.
#pragma once

#include <optional>

namespace foldlab::gui {

// Device pixels per CSS pixel (window.devicePixelRatio; 1 on the desktop). The page sizes its
// canvas in device pixels, so the explorer lays out in device pixels and scales its UI by this
// to keep the layout of a screen at ratio 1 with text rasterised at the screen's own pixel size.
float screen_pixel_ratio();

struct ScreenPreferences {
  std::optional<bool> light_theme;        // prefers-color-scheme, when the browser says
  std::optional<int> text_scale_percent;  // the browser's default font size against 16 px
};
// What the user's browser prefers, read once at start; nothing on the desktop.
ScreenPreferences screen_preferences();

// Whether the user points with a finger rather than a mouse: the page's `(pointer: coarse)`, or a
// touch seen since the last press of a mouse. Never on the desktop. Asked before every frame.
bool screen_pointer_is_coarse();

// Called after every frame with whether a text field has the keyboard, and whether what it takes
// is a number (a slider's typed value): the page focuses a hidden text field then, so that a touch
// screen brings up its keyboard, the number keyboard for a number. Nothing on the desktop.
void screen_wants_text_input(bool wanted, bool number);

// Called once the window's ImGui backend is set up: ImGui's copy and paste (Ctrl+C, Ctrl+V in a
// text field) reach the screen's clipboard. The desktop's GLFW gives ImGui the system's; the
// page's GLFW has none, so the page takes the browser's paste events and hands copies to the
// browser's clipboard.
void screen_shares_clipboard();

}  // namespace foldlab::gui
