#include "app/gui/print_image.hpp"

#include <cstring>

#include "core/io/image.hpp"

namespace foldlab::gui {

std::variant<std::shared_ptr<const PrintImage>, std::string> load_print_image(
    const std::string& path) {
  Image loaded;
  try {
    loaded = load_image(path, kMaxPrintSidePx);
  } catch (const ImageError& e) {
    return std::string("print photo ") + e.what();
  }
  auto image = std::make_shared<PrintImage>();
  image->path = path;
  image->width = loaded.width_px;
  image->height = loaded.height_px;
  image->rgba.resize(loaded.rgba.size() * 4);
  // One RGBA word a pixel with red in the lowest byte is R, G, B, A in memory.
  std::memcpy(image->rgba.data(), loaded.rgba.data(), image->rgba.size());
  return std::shared_ptr<const PrintImage>(std::move(image));
}

}  // namespace foldlab::gui
