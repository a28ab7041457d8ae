// Writes a "photo" of a preset's folds that FoldLab draws itself (tests/fold_photo.hpp) and a
// playback script that loads it in the explorer, clicks its supports and folds where they were
// drawn, and expects the preset's n and Q back. The play test runs the script; scripts/docs.sh
// uses it for the picture of the photo workflow.
//
//   make_fold_photo PRESET.json PHOTO.png SCRIPT.json [SCREENSHOT.png]
#include <exception>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "core/io/preset.hpp"
#include "core/model/solver.hpp"
#include "fold_photo.hpp"

int main(int argc, char** argv) {
  using nlohmann::json;
  if (argc != 4 && argc != 5) {
    std::cerr << "usage: make_fold_photo PRESET.json PHOTO.png SCRIPT.json [SCREENSHOT.png]\n";
    return 2;
  }
  try {
    const foldlab::Preset preset = foldlab::load_preset(argv[1]);
    const foldlab::Solution s = foldlab::solve(preset.parameters);
    const foldlab::testing::FoldPhoto photo =
        foldlab::testing::write_fold_photo(s, preset.parameters, argv[2]);
    json steps = json::array();
    steps.push_back({{"click", "Load photo..."}});
    steps.push_back({{"type", argv[2]}});
    steps.push_back({{"key", "enter"}});  // in the path field: loads
    steps.push_back({{"expect", {{"modal", nullptr}, {"photo.width_px", photo.width_px}}}});
    for (const foldlab::PixelPoint& p : {photo.left_support, photo.right_support}) {
      steps.push_back({{"click_photo", {p.x, p.y}}});
    }
    for (const foldlab::PixelPoint& p : photo.folds) {
      steps.push_back({{"click_photo", {p.x, p.y}}});
    }
    steps.push_back({{"frames", 3}});
    // Clicks land on whole screen pixels, a few mm on the cloth: n exactly, Q within 2 %.
    steps.push_back({{"expect", {{"measured.n", s.n}, {"measured.Q", {0.98 * s.Q, 1.02 * s.Q}}}}});
    if (argc == 5) {
      steps.push_back({{"click", "Measured"}});  // a heading: moves the mouse off the plot
      steps.push_back({{"screenshot", argv[4]}});
    }
    std::ofstream(argv[3]) << json{{"steps", steps}}.dump(1) << "\n";
    std::cout << "n = " << s.n << ", Q = " << s.Q << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "make_fold_photo: " << e.what() << "\n";
    return 1;
  }
}
