// The page's screen: the browser's devicePixelRatio, its colour scheme and default font size, its
// pointer (a finger or a mouse), and the hidden text field index.html focuses so that a touch
// screen shows its keyboard.
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>

#include <string>

#include "app/gui/screen.hpp"

namespace foldlab::gui {
namespace {

// 1 light, 0 dark, -1 when the browser states no preference.
EM_JS(int, page_prefers_light, (), {
  if (!window.matchMedia)
    return -1;
  if (window.matchMedia('(prefers-color-scheme: light)').matches)
    return 1;
  if (window.matchMedia('(prefers-color-scheme: dark)').matches)
    return 0;
  return -1;
});

// The browser's default font size ("medium", which the user's text size setting changes) in
// percent of the 16 px browsers start with; -1 when it cannot be read.
EM_JS(int, page_text_percent, (), {
  const probe = document.createElement('div');
  probe.style.fontSize = 'medium';
  probe.style.position = 'absolute';
  probe.style.visibility = 'hidden';
  document.body.appendChild(probe);
  const px = parseFloat(getComputedStyle(probe).fontSize);
  probe.remove();
  return px > 0 ? Math.round(100 * px / 16) : -1;
});

EM_JS(void, page_text_input, (int wanted, int number), {
  if (Module.foldlabTextInput)
    Module.foldlabTextInput(wanted != 0, number != 0);
});

// index.html's judgement of the pointer: (pointer: coarse), or a touch since a mouse's last press.
EM_JS(int, page_pointer_is_coarse, (), { return Module.foldlabCoarsePointer ? 1 : 0; });

// The page's clipboard as ImGui sees it: the text of the last paste event (Ctrl+V fires one
// before the frame that reads the keys) or of the explorer's last copy, whichever came later.
// A copy also goes to the browser's clipboard where the page may write it (a key press just
// before gives it the right).
EM_JS(void, listen_for_paste, (), {
  Module.foldlabClipboard = "";
  document.addEventListener(
      'paste',
      function(event) {
        if (event.clipboardData)
          Module.foldlabClipboard = event.clipboardData.getData('text/plain');
      },
      true);
});

EM_JS(void, copy_to_page_clipboard, (const char* text), {
  const value = UTF8ToString(text);
  Module.foldlabClipboard = value;
  if (navigator.clipboard && navigator.clipboard.writeText) {
    navigator.clipboard.writeText(value).catch(function(){});
  }
});

const char* page_clipboard_text(void* /*user_data*/) {
  static std::string text;
  text = emscripten_run_script_string("Module.foldlabClipboard || ''");
  return text.c_str();
}

void set_page_clipboard_text(void* /*user_data*/, const char* text) {
  copy_to_page_clipboard(text);
}

// A browser's default of 16 px is FoldLab's 100 %.
constexpr int kBrowserDefaultPercent = 100;

}  // namespace

float screen_pixel_ratio() {
  return static_cast<float>(emscripten_get_device_pixel_ratio());
}

ScreenPreferences screen_preferences() {
  ScreenPreferences preferences;
  if (const int light = page_prefers_light(); light >= 0) {
    preferences.light_theme = light == 1;
  }
  if (const int percent = page_text_percent(); percent > kBrowserDefaultPercent) {
    preferences.text_scale_percent = percent;
  }
  return preferences;
}

bool screen_pointer_is_coarse() {
  return page_pointer_is_coarse() != 0;
}

void screen_wants_text_input(bool wanted, bool number) {
  static int shown = -1;  // what the page was last told: 0 none, 1 text, 2 a number
  const int asked = wanted ? (number ? 2 : 1) : 0;
  if (shown != asked) {
    shown = asked;
    page_text_input(wanted ? 1 : 0, number ? 1 : 0);
  }
}

void screen_shares_clipboard() {
  listen_for_paste();
  ImGuiIO& io = ImGui::GetIO();
  io.GetClipboardTextFn = page_clipboard_text;
  io.SetClipboardTextFn = set_page_clipboard_text;
}

}  // namespace foldlab::gui
