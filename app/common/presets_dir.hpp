// Where the shipped presets live, for commands and the GUI that list them.
#pragma once

#include <filesystem>
#include <vector>

namespace foldlab::app {

// The first that exists of: $FOLDLAB_PRESETS_DIR, the source tree's presets/ (a build run in
// place), and ../share/foldlab/presets beside the executable. Empty when none does.
std::filesystem::path find_presets_dir();

// The *.json files of a folder, sorted by name.
std::vector<std::filesystem::path> preset_files(const std::filesystem::path& dir);

}  // namespace foldlab::app
