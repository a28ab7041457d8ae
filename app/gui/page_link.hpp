// Where the explorer's link goes (the fabric as an address, core/io/link.hpp): "Copy link" puts
// it on the clipboard, and in the browser the page's own address follows it. One implementation
// per platform, chosen at link time by make_page_link(): the desktop's (app/gui/desktop_link.cpp)
// is this base class, the page's (app/web/page_link.cpp) talks to the browser.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/preset.hpp"
#include "core/model/parameters.hpp"

namespace foldlab::gui {

// The --view keys a link carries besides the inputs: how a presenter set the room up (the
// presented panel; the theme and the text size only when the sender chose to send them).
inline constexpr std::string_view kLinkPresentKey = "present";
inline constexpr std::string_view kLinkThemeKey = "theme";
inline constexpr std::string_view kLinkScaleKey = "scale";
// The scheme of a link that opens the installed explorer ("foldlab:#t=0.3&..."), registered by
// its desktop entry.
inline constexpr std::string_view kLinkScheme = "foldlab:";
inline constexpr std::string_view kLinkViewKeys[] = {kLinkPresentKey, kLinkThemeKey, kLinkScaleKey};
bool is_link_view_key(std::string_view key);
// The keys that say which fabrics a link shows rather than an input of A: the name, the preset
// the inputs left out come from, and B's keys (core/io/link.hpp).
bool is_link_fabric_key(std::string_view key);

// The view a link carries: the presented panel's key (empty: none), and, when `carries_look`
// (the sender ticked "the link sets my theme and text size"), the theme and the text size. Left
// out by default: a student's phone keeps the student's theme and text size.
struct LinkView {
  std::string presented;
  bool light_theme = false;
  int scale_percent = 100;
  bool carries_look = false;
};

// What the sender chose for the links copied (the Export menu): whether they set the sender's
// theme and text size, and the address the page is served at (empty: none known), remembered in
// the session, before which a copied link's fragment goes.
struct LinkChoices {
  bool carries_look = false;
  std::string page_address;
  bool page_knows_address = false;  // the browser's page: no address is asked for
};

// One fabric as a link writes it: its inputs, those a slider set last (written with the digits
// the slider shows) and its name.
struct LinkFabric {
  Parameters parameters;
  std::vector<std::string> dragged_keys;
  std::string name;
};
// What a link says: the shipped preset the reader starts from (by its file's stem; empty: the
// built-in default) with its inputs and name, A, and B when one is pinned. An input of A or B
// equal to the preset's is left out, and so is a name equal to the preset's.
struct LinkContent {
  std::string preset;
  Preset base;
  LinkFabric a;
  std::optional<LinkFabric> b;
};
// The link's fragment: preset=, name=, A's inputs, b.name= and B's inputs (b.t=...), then the
// view keys.
std::string explorer_link(const LinkContent& content, const LinkView& view);
// What the status line says of a link just copied, by its start: the whole link is a few hundred
// characters, which would push the Presets panel's buttons out of sight.
std::string copied_link_notice(const std::string& address);

class PageLink {
 public:
  virtual ~PageLink() = default;
  // The link handed out for `fragment` ("t=...", no '#'): "#" and the fragment behind the page's
  // address: FOLDLAB_PAGE_URL when the environment names one, else `page_address` (set in the
  // explorer), their own fragment dropped. With neither, a foldlab: link, which the installed
  // desktop entry opens in the explorer.
  virtual std::string address(std::string_view fragment, std::string_view page_address) const;
  // Whether the platform knows the page's address itself (the browser): then none is asked for.
  virtual bool knows_address() const { return false; }
  // Puts `text` on the clipboard (ImGui's, which the window gives the system's).
  virtual void copy(const std::string& text) const;
  // Whether the platform shows the link as it changes (the page's address bar); only then does
  // the explorer compose it every frame.
  virtual bool follows() const { return false; }
  // Shows `fragment` as the current address, in place of the last (no new history entry).
  virtual void show(std::string_view /*fragment*/) {}
};

// The platform's PageLink; defined once per program (desktop or page).
std::unique_ptr<PageLink> make_page_link();

// When a followed address is rewritten: the first link is the one the page was opened with and is
// not written; after that a changed link at once, then at most once every `interval_s` while it
// keeps changing (a dragged slider), the last one always; the same text never twice.
class LinkThrottle {
 public:
  explicit LinkThrottle(double interval_s = 0.25) : interval_s_(interval_s) {}
  // The link to write now, if any, given the current link and the frame's clock.
  std::optional<std::string> due(const std::string& link, double now_s);
  // A change waits for its turn: a frame must come by then, even in a resting window.
  bool pending() const { return pending_; }

 private:
  double interval_s_;
  std::optional<std::string> written_;
  std::optional<double> written_at_s_;
  bool pending_ = false;
};

}  // namespace foldlab::gui
