#include "app/gui/print_image.hpp"

#include <filesystem>
#include <system_error>

#include <stb_image.h>

#include "app/gui/session.hpp"

namespace foldlab::gui {

std::variant<std::shared_ptr<const PrintImage>, std::string> load_print_image(
    const std::string& path) {
  const std::string name = "print photo '" + path + "'";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return name + ": no such file";
  }
  if (std::optional<std::string> too_large = oversized_file(path, kMaxPrintFileBytes)) {
    return "print photo " + *too_large;
  }
  int width = 0;
  int height = 0;
  int channels = 0;
  if (stbi_info(path.c_str(), &width, &height, &channels) == 0) {
    return name + ": not an image FoldLab reads (PNG or JPEG): " + stbi_failure_reason();
  }
  if (width > kMaxPrintSidePx || height > kMaxPrintSidePx) {
    return name + ": " + std::to_string(width) + " x " + std::to_string(height) +
           " pixels, more than " + std::to_string(kMaxPrintSidePx) + " on a side";
  }
  stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (pixels == nullptr) {
    return name + ": cannot be decoded: " + stbi_failure_reason();
  }
  auto image = std::make_shared<PrintImage>();
  image->path = path;
  image->width = width;
  image->height = height;
  image->rgba.assign(pixels, pixels + static_cast<std::size_t>(width) * height * 4);
  stbi_image_free(pixels);
  return std::shared_ptr<const PrintImage>(std::move(image));
}

}  // namespace foldlab::gui
