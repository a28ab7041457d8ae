#include "core/io/image.hpp"

#include <cstring>
#include <memory>
#include <string_view>
#include <system_error>

#include <stb_image.h>

#include "core/io/io.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

std::string stb_reason() {
  const char* reason = stbi_failure_reason();
  return reason != nullptr ? std::string(reason) : std::string("unknown format");
}

// The file's bytes, refused over the budget before they are read.
std::string read_within_budget(const std::filesystem::path& path) {
  try {
    return read_text_file(path, kMaxImageFileBytes);
  } catch (const ReadError& e) {
    throw ImageError(e.what());
  }
}

// CRC-32 as PNG defines it (ISO/IEC 15948, annex D: polynomial 0xEDB88320, reflected).
std::uint32_t png_crc(std::string_view bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char c : bytes) {
    crc ^= static_cast<unsigned char>(c);
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
  }
  return crc ^ 0xFFFFFFFFu;
}

std::uint32_t big_endian_32(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    value = (value << 8) | static_cast<unsigned char>(bytes[at + k]);
  }
  return value;
}

// Why `bytes` is not a PNG or JPEG file FoldLab reads, or empty. stb_image also decodes GIF, BMP,
// HDR, PSD and more, and skips PNG's checksums: a damaged or unexpected file would be measured
// as if it were a photo, so the format is checked here, and every PNG chunk's CRC with it.
std::string not_png_or_jpeg(std::string_view bytes) {
  static constexpr std::string_view kPngSignature("\x89PNG\r\n\x1a\n", 8);
  if (bytes.size() >= 3 && static_cast<unsigned char>(bytes[0]) == 0xFF &&
      static_cast<unsigned char>(bytes[1]) == 0xD8 &&
      static_cast<unsigned char>(bytes[2]) == 0xFF) {
    return {};
  }
  if (!bytes.starts_with(kPngSignature)) {
    return "not a PNG or JPEG file";
  }
  for (std::size_t at = kPngSignature.size();;) {
    if (bytes.size() - at < 12) {
      return "a damaged PNG file (it ends inside a chunk, before IEND)";
    }
    const std::uint32_t length = big_endian_32(bytes, at);
    if (length > bytes.size() - at - 12) {
      return "a damaged PNG file (a chunk runs past the end of the file)";
    }
    const std::string_view type_and_data = bytes.substr(at + 4, 4 + length);
    if (png_crc(type_and_data) != big_endian_32(bytes, at + 8 + length)) {
      return "a damaged PNG file (the checksum of its " + detail::cut(type_and_data.substr(0, 4)) +
             " chunk is wrong)";
    }
    if (type_and_data.starts_with("IEND")) {
      return {};
    }
    at += 12 + length;
  }
}

ImageSize checked_size(const std::filesystem::path& path, const std::string& bytes,
                       int max_side_px) {
  if (const std::string problem = not_png_or_jpeg(bytes); !problem.empty()) {
    throw ImageError(path.string() + ": " + problem + "; FoldLab reads PNG or JPEG photos");
  }
  ImageSize size;
  int channels = 0;
  if (stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                            static_cast<int>(bytes.size()), &size.width_px, &size.height_px,
                            &channels) == 0) {
    throw ImageError(path.string() + ": cannot read the image (" + stb_reason() + "; PNG or JPEG)");
  }
  if (size.width_px <= 0 || size.height_px <= 0 || size.width_px > max_side_px ||
      size.height_px > max_side_px) {
    throw ImageError(path.string() + ": " + std::to_string(size.width_px) + " x " +
                     std::to_string(size.height_px) + " px; a picture here may have at most " +
                     std::to_string(max_side_px) + " px a side (scale it down)");
  }
  return size;
}

}  // namespace

ImageSize image_size(const std::filesystem::path& path) {
  return checked_size(path, read_within_budget(path), kMaxImageSidePx);
}

Image load_image(const std::filesystem::path& path, int max_side_px) {
  const std::string bytes = read_within_budget(path);
  const ImageSize size = checked_size(path, bytes, max_side_px);
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
