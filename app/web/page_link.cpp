// The page's link: the page's own address, which follows the inputs (history.replaceState: the
// address changes, the history does not grow), and "Copy link" through the browser's clipboard.
#include <emscripten/emscripten.h>

#include "app/gui/page_link.hpp"

namespace foldlab::gui {
namespace {

// A browser that refuses the clipboard (no focus, no permission) keeps ImGui's copy alone.
EM_JS(void, copy_to_browser_clipboard, (const char* text), {
  const value = UTF8ToString(text);
  if (navigator.clipboard && navigator.clipboard.writeText) {
    navigator.clipboard.writeText(value).catch(function(){});
  }
});

EM_JS(void, replace_address_fragment, (const char* fragment),
      { history.replaceState(history.state, "", "#" + UTF8ToString(fragment)); });

// An address edited by hand (or Back to an earlier one) is a link to open, as it would be in a
// new tab: the page opens it afresh, its session kept as it goes (the page saves when it is
// left). replaceState, which the page's own updates use, fires no hashchange.
EM_JS(void, reopen_on_edited_address, (), {
  window.addEventListener('hashchange', function() { location.reload(); });
});

class BrowserLink final : public PageLink {
 public:
  BrowserLink() { reopen_on_edited_address(); }
  // The page's address as it is now, its query (?preset=NAME) kept, its fragment replaced.
  std::string address(std::string_view fragment) const override {
    const std::string page = emscripten_run_script_string("location.href.split('#')[0]");
    return page + "#" + std::string(fragment);
  }
  void copy(const std::string& text) const override {
    PageLink::copy(text);
    copy_to_browser_clipboard(text.c_str());
  }
  bool follows() const override { return true; }
  void show(std::string_view fragment) override {
    replace_address_fragment(std::string(fragment).c_str());
  }
};

}  // namespace

std::unique_ptr<PageLink> make_page_link() {
  return std::make_unique<BrowserLink>();
}

}  // namespace foldlab::gui
