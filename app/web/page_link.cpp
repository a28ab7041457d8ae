// The page's link: the page's own address, which follows the inputs (history.replaceState: the
// address changes, the history does not grow). "Copy link" goes through ImGui's clipboard, which
// the page hands to the browser's (app/web/page_screen.cpp).
#include <emscripten/emscripten.h>

#include "app/gui/page_link.hpp"

namespace foldlab::gui {
namespace {

EM_JS(void, replace_address_fragment, (const char* fragment),
      { history.replaceState(history.state, "", "#" + UTF8ToString(fragment)); });

// An address edited by hand (or Back to an earlier one) is a link to open, as it would be in a
// new tab: the page opens it afresh, its session kept as it goes (the page saves when it is
// left). replaceState, which the page's own updates use, fires no hashchange.
EM_JS(void, reopen_on_edited_address, (), {
  window.addEventListener(
      'hashchange', function() { location.reload(); });
});

class BrowserLink final : public PageLink {
 public:
  BrowserLink() { reopen_on_edited_address(); }
  // The page's address as it is now, its query (?preset=NAME) kept, its fragment replaced.
  std::string address(std::string_view fragment, std::string_view /*page_address*/) const override {
    const std::string page = emscripten_run_script_string("location.href.split('#')[0]");
    return page + "#" + std::string(fragment);
  }
  bool follows() const override { return true; }
  bool knows_address() const override { return true; }
  void show(std::string_view fragment) override {
    replace_address_fragment(std::string(fragment).c_str());
  }
};

}  // namespace

std::unique_ptr<PageLink> make_page_link() {
  return std::make_unique<BrowserLink>();
}

}  // namespace foldlab::gui
