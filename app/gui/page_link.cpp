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

bool is_link_fabric_key(std::string_view key) {
  return key == kLinkNameKey || key == kLinkPresetKey || key.starts_with(kLinkBPrefix);
}

std::string explorer_link(const LinkContent& content, const LinkView& view) {
  std::string out;
  const auto add = [&out](std::string_view key, const std::string& value) {
    out += (out.empty() ? "" : "&") + std::string(key) + "=" + percent_encode(value);
  };
  const auto add_fabric = [&](const LinkFabric& fabric, std::string_view prefix) {
    const std::string inputs = fabric_link(
        fabric.parameters, LinkWriting{&content.base.parameters, fabric.dragged_keys, prefix});
    if (!inputs.empty()) {
      out += (out.empty() ? "" : "&") + inputs;
    }
  };
  if (!content.preset.empty()) {
    add(kLinkPresetKey, content.preset);
  }
  if (content.a.name != content.base.name) {
    add(kLinkNameKey, content.a.name);
  }
  add_fabric(content.a, "");
  if (content.b) {
    // Always named, so that a B equal to the preset is still pinned.
    add(std::string(kLinkBPrefix) + std::string(kLinkNameKey), content.b->name);
    add_fabric(*content.b, kLinkBPrefix);
  }
  if (!view.presented.empty()) {
    add(kLinkPresentKey, view.presented);
  }
  if (view.carries_look) {
    add(kLinkThemeKey, view.light_theme ? "light" : "dark");
    add(kLinkScaleKey, std::to_string(view.scale_percent));
  }
  return out;
}

std::string copied_link_notice(const std::string& address) {
  constexpr std::size_t kShownAddressBytes = 80;
  if (address.starts_with(kLinkScheme)) {
    // Whoever pastes it should know where it opens, and how to make it one for everybody.
    return "Copied the fabric as a foldlab: link, " + detail::cut(address, kShownAddressBytes) +
           ", which opens in an installed FoldLab. Export > Page address makes it a web address "
           "anyone can open.";
  }
  return "Copied the fabric as a link: " + detail::cut(address, kShownAddressBytes);
}

std::string PageLink::address(std::string_view fragment, std::string_view page_address) const {
  const char* page = std::getenv("FOLDLAB_PAGE_URL");
  std::string_view prefix = page != nullptr && *page != '\0' ? page : page_address;
  prefix = prefix.substr(0, prefix.find('#'));
  return std::string(prefix.empty() ? kLinkScheme : prefix) + "#" + std::string(fragment);
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
