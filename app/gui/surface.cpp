#include "app/gui/surface.hpp"

#include <charconv>

namespace foldlab::gui {
namespace {

// A whole number from the front of `text`, which it leaves after the digits; nullopt with no
// digit or one too many for a size.
std::optional<int> leading_number(std::string_view& text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end == text.data() || end - text.data() > 5) {
    return std::nullopt;
  }
  text.remove_prefix(static_cast<std::size_t>(end - text.data()));
  return value;
}

}  // namespace

std::optional<FrameSize> parse_frame_size(std::string_view text) {
  const std::optional<int> width = leading_number(text);
  if (!width || !text.starts_with('x')) {
    return std::nullopt;
  }
  text.remove_prefix(1);
  const std::optional<int> height = leading_number(text);
  if (!height || !text.empty() || *width < kMinFrameSize.width || *width > kMaxFrameSize.width ||
      *height < kMinFrameSize.height || *height > kMaxFrameSize.height) {
    return std::nullopt;
  }
  return FrameSize{*width, *height};
}

std::string frame_size_rule() {
  return "WxH with " + std::to_string(kMinFrameSize.width) +
         " <= W <= " + std::to_string(kMaxFrameSize.width) + ", " +
         std::to_string(kMinFrameSize.height) + " <= H <= " + std::to_string(kMaxFrameSize.height);
}

}  // namespace foldlab::gui
