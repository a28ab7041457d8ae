#include <stb_image_write.h>

#include <algorithm>

#include <string>

#include "app/gui/surface.hpp"
#include "core/io/io.hpp"

namespace foldlab::gui {

void write_png(const char* path, FrameSize size, const std::vector<std::uint8_t>& rgba) {
  std::string encoded;
  auto append = [](void* context, void* data, int bytes) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(bytes));
  };
  if (!stbi_write_png_to_func(append, &encoded, size.width, size.height, 4, rgba.data(),
                              size.width * 4)) {
    throw SurfaceError(std::string(path) + ": cannot encode the PNG");
  }
  try {
    write_file_atomically(path, encoded);
  } catch (const WriteError& e) {
    throw SurfaceError(e.what());
  }
}

FrameSize crop_pixels(std::vector<std::uint8_t>& rgba, FrameSize size, int x, int y, int width,
                      int height) {
  const int x0 = std::clamp(x, 0, std::max(size.width - 1, 0));
  const int y0 = std::clamp(y, 0, std::max(size.height - 1, 0));
  const int x1 = std::clamp(x + width, x0 + 1, std::max(size.width, x0 + 1));
  const int y1 = std::clamp(y + height, y0 + 1, std::max(size.height, y0 + 1));
  const FrameSize kept{x1 - x0, y1 - y0};
  const auto row_bytes = static_cast<std::size_t>(kept.width) * 4;
  for (int row = 0; row < kept.height; ++row) {
    const std::size_t from =
        (static_cast<std::size_t>(y0 + row) * static_cast<std::size_t>(size.width) +
         static_cast<std::size_t>(x0)) *
        4;
    std::copy_n(
        rgba.begin() + static_cast<std::ptrdiff_t>(from), row_bytes,
        rgba.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(row) * row_bytes));
  }
  rgba.resize(row_bytes * static_cast<std::size_t>(kept.height));
  return kept;
}

}  // namespace foldlab::gui
