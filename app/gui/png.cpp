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

}  // namespace foldlab::gui
