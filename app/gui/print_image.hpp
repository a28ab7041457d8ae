// A swatch photo (PNG or JPEG, read as the photos measured are) to print on the 3D view's cloth,
// tiled over the flat cloth's material coordinates. Loaded here, with no GL, so that a bad file is
// refused with a sentence before anything reaches the GPU.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace foldlab::gui {

// Larger pictures are refused: a swatch needs no more, and a GPU texture has limits.
inline constexpr int kMaxPrintSidePx = 4096;

struct PrintImage {
  std::string path;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // top row first, 4 bytes a pixel
};

// The image, or a sentence naming the file and what is wrong with it.
std::variant<std::shared_ptr<const PrintImage>, std::string> load_print_image(
    const std::string& path);

}  // namespace foldlab::gui
