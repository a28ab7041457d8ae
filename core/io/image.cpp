#include "core/io/image.hpp"

#include <cstring>
#include <memory>
#include <system_error>

#include <stb_image.h>

#include "core/io/io.hpp"

namespace foldlab {
namespace {

std::string stb_reason() {
  const char* reason = stbi_failure_reason();
  return reason != nullptr ? std::string(reason) : std::string("unknown format");
}

// The file's bytes, refused over the budget before they are read.
std::string read_within_budget(const std::filesystem::path& path) {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (!error && bytes > kMaxImageFileBytes) {
    throw ImageError(path.string() + ": " + std::to_string(bytes / (1024 * 1024)) +
                     " MB is larger than the " +
                     std::to_string(kMaxImageFileBytes / (1024 * 1024)) + " MB a photo may have");
  }
  try {
    return read_text_file(path);
  } catch (const ReadError& e) {
    throw ImageError(e.what());
  }
}

ImageSize checked_size(const std::filesystem::path& path, const std::string& bytes) {
  ImageSize size;
  int channels = 0;
  if (stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                            static_cast<int>(bytes.size()), &size.width_px, &size.height_px,
                            &channels) == 0) {
    throw ImageError(path.string() + ": cannot read the image (" + stb_reason() + "; PNG or JPEG)");
  }
  if (size.width_px <= 0 || size.height_px <= 0 || size.width_px > kMaxImageSidePx ||
      size.height_px > kMaxImageSidePx) {
    throw ImageError(path.string() + ": " + std::to_string(size.width_px) + " x " +
                     std::to_string(size.height_px) + " px; a photo may have at most " +
                     std::to_string(kMaxImageSidePx) + " px a side (scale it down)");
  }
  return size;
}

}  // namespace

ImageSize image_size(const std::filesystem::path& path) {
  return checked_size(path, read_within_budget(path));
}

Image load_image(const std::filesystem::path& path) {
  const std::string bytes = read_within_budget(path);
  const ImageSize size = checked_size(path, bytes);
  int width = 0;
  int height = 0;
  int channels = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                            static_cast<int>(bytes.size()), &width, &height, &channels, 4),
      stbi_image_free);
  if (!pixels || width != size.width_px || height != size.height_px) {
    throw ImageError(path.string() + ": cannot decode the image (" + stb_reason() + ")");
  }
  Image image;
  image.width_px = width;
  image.height_px = height;
  image.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  // Bytes R, G, B, A in memory are one little-endian word with red lowest, as IM_COL32 packs it.
  std::memcpy(image.rgba.data(), pixels.get(), image.rgba.size() * 4);
  return image;
}

}  // namespace foldlab
