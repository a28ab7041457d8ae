#include <epoxy/gl.h>

#include <stb_image_write.h>

#include <algorithm>

#include <string>

#include "app/gui/surface.hpp"
#include "core/io/io.hpp"

namespace foldlab::gui {

std::vector<std::uint8_t> read_framebuffer_rgba(FrameSize size) {
  const auto row_bytes = static_cast<std::size_t>(size.width) * 4;
  std::vector<std::uint8_t> pixels(row_bytes * static_cast<std::size_t>(size.height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size.width, size.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  // GL's first row is the bottom one; images start at the top.
  std::vector<std::uint8_t> top_down(pixels.size());
  for (int y = 0; y < size.height; ++y) {
    std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(row_bytes * (size.height - 1 - y)),
                row_bytes, top_down.begin() + static_cast<std::ptrdiff_t>(row_bytes * y));
  }
  // The picture is opaque whatever ImGui's blending left in the alpha channel.
  for (std::size_t i = 3; i < top_down.size(); i += 4) {
    top_down[i] = 255;
  }
  return top_down;
}

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
