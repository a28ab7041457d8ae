// Where the explorer's link goes (the fabric as an address, core/io/link.hpp): "Copy link" puts
// it on the clipboard, and in the browser the page's own address follows it. One implementation
// per platform, chosen at link time by make_page_link(): the desktop's (app/gui/desktop_link.cpp)
// is this base class, the page's (app/web/page_link.cpp) talks to the browser.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/model/parameters.hpp"

namespace foldlab::gui {

// The --view keys a link carries besides the inputs, when they differ from a fresh start: how a
// presenter set the room up (the presented panel, the theme, the text size).
inline constexpr std::string_view kLinkPresentKey = "present";
inline constexpr std::string_view kLinkThemeKey = "theme";
inline constexpr std::string_view kLinkScaleKey = "scale";
inline constexpr std::string_view kLinkViewKeys[] = {kLinkPresentKey, kLinkThemeKey, kLinkScaleKey};
bool is_link_view_key(std::string_view key);

// The view a link carries: the presented panel's key (empty: none), the theme and the text size.
struct LinkView {
  std::string presented;
  bool light_theme = false;
  int scale_percent = 100;
};
// The fabric as a link's fragment (core/io/link.hpp: every input, as edited, refused or not),
// with the view keys that differ from a fresh start.
std::string explorer_link(const Parameters& edited, const LinkView& view);
// What the status line says of a link just copied, by its start: the whole link is a few hundred
// characters, which would push the Presets panel's buttons out of sight.
std::string copied_link_notice(const std::string& address);

class PageLink {
 public:
  virtual ~PageLink() = default;
  // The link handed out for `fragment` ("t=...", no '#'): "#" and the fragment, behind the page's
  // address when the environment names one in FOLDLAB_PAGE_URL (its own fragment dropped).
  virtual std::string address(std::string_view fragment) const;
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
