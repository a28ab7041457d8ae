#include "app/gui/page_link.hpp"

#include <algorithm>
#include <cstdlib>

#include <imgui.h>

namespace foldlab::gui {

bool is_link_view_key(std::string_view key) {
  return std::find(std::begin(kLinkViewKeys), std::end(kLinkViewKeys), key) !=
         std::end(kLinkViewKeys);
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
