// Where the shipped presets live, for commands and the GUI that list them.
#pragma once

#include <filesystem>
#include <vector>

namespace foldlab::app {

// The first that exists of: $FOLDLAB_PRESETS_DIR, ../share/foldlab/presets beside the executable
// (an installed or unpacked program: bin/foldlab and share/foldlab/presets), and the source
// tree's presets/ only while the executable runs from the build folder it was built in. Empty
// when none does.
std::filesystem::path find_presets_dir();

// The *.json files of a folder, sorted by name.
std::vector<std::filesystem::path> preset_files(const std::filesystem::path& dir);

}  // namespace foldlab::app
