// Photos read for measuring folds or printed on the cloth (PNG or JPEG, checked: a PNG's
// checksums must hold), with a size budget
// checked from the header before any pixel is decoded: a hostile or mistaken file (a panorama, a
// decompression bomb) is refused instead of taking memory and seconds.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace foldlab {

// Larger photos are refused: 8192 px a side is more than any camera needs to show folds, and
// 8192² RGBA pixels are 256 MB.
inline constexpr int kMaxImageSidePx = 8192;
inline constexpr std::uintmax_t kMaxImageFileBytes = 64 * 1024 * 1024;

// A file that is not an image FoldLab reads, or is over the budget; the message names the file
// and says why.
class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ImageSize {
  int width_px = 0;
  int height_px = 0;
};

struct Image {
  int width_px = 0;
  int height_px = 0;
  // One RGBA pixel per element, its red in the lowest byte (ImGui's IM_COL32 order), top row first.
  std::vector<std::uint32_t> rgba;
};

// The image's size from its header, within the budget; throws ImageError.
ImageSize image_size(const std::filesystem::path& path);
// The decoded image, within the budget and `max_side_px` a side; throws ImageError.
Image load_image(const std::filesystem::path& path, int max_side_px = kMaxImageSidePx);

}  // namespace foldlab
