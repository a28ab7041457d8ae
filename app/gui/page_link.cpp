#include "app/gui/page_link.hpp"

#include <algorithm>
#include <cstdlib>

#include <imgui.h>

#include "app/gui/appearance.hpp"
#include "core/io/link.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

bool is_link_view_key(std::string_view key) {
  return std::find(std::begin(kLinkViewKeys), std::end(kLinkViewKeys), key) !=
         std::end(kLinkViewKeys);
}

std::string explorer_link(const Parameters& edited, const LinkView& view) {
  std::string out = fabric_link(edited);
  const auto add = [&out](std::string_view key, const std::string& value) {
    out += "&" + std::string(key) + "=" + percent_encode(value);
  };
  if (!view.presented.empty()) {
    add(kLinkPresentKey, view.presented);
  }
  if (view.light_theme) {
    add(kLinkThemeKey, "light");
  }
  if (view.scale_percent != kMinUiScalePercent) {
    add(kLinkScaleKey, std::to_string(view.scale_percent));
  }
  return out;
}

std::string copied_link_notice(const std::string& address) {
  // With no page address configured it is the fragment alone, which only `foldlab gui --link`
  // opens, and whoever pastes it should know that.
  constexpr std::size_t kShownAddressBytes = 80;
  constexpr std::size_t kShownFragmentBytes = 40;
  if (address.starts_with('#')) {
    return "Copied the fabric as a link's fragment alone, " +
           detail::cut(address, kShownFragmentBytes) +
           ", which only foldlab gui --link opens. FOLDLAB_PAGE_URL makes it a whole address "
           "(docs/web.md).";
  }
  return "Copied the fabric as a link: " + detail::cut(address, kShownAddressBytes);
}

std::string PageLink::address(std::string_view fragment) const {
  const char* page = std::getenv("FOLDLAB_PAGE_URL");
  std::string_view prefix = page != nullptr ? page : "";
  prefix = prefix.substr(0, prefix.find('#'));
  return std::string(prefix) + "#" + std::string(fragment);
}

void PageLink::copy(const std::string& text) const {
  ImGui::SetClipboardText(text.c_str());
}

std::optional<std::string> LinkThrottle::due(const std::string& link, double now_s) {
  if (!written_) {
    written_ = link;
    return std::nullopt;
  }
  pending_ = link != *written_;
  if (!pending_ || (written_at_s_ && now_s - *written_at_s_ < interval_s_)) {
    return std::nullopt;
  }
  written_ = link;
  written_at_s_ = now_s;
  pending_ = false;
  return link;
}

}  // namespace foldlab::gui
