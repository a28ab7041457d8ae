// Where the shipped presets live, for commands and the GUI that list them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace foldlab::app {

// The first that exists of: $FOLDLAB_PRESETS_DIR, ../share/foldlab/presets beside the executable
// (an installed or unpacked program: bin/foldlab and share/foldlab/presets), and the source
// tree's presets/ only while the executable runs from the build folder it was built in. Empty
// when none does. A $FOLDLAB_PRESETS_DIR that is no folder is passed over with a notice on stderr
// (once a run).
std::filesystem::path find_presets_dir();

// The *.json files of a folder, sorted by name.
std::vector<std::filesystem::path> preset_files(const std::filesystem::path& dir);

// $XDG_CONFIG_HOME/foldlab, else $HOME/.config/foldlab, else ./.foldlab.
std::filesystem::path config_dir();
// Where the explorer's "Save as" puts the user's presets: config_dir()/presets.
std::filesystem::path user_presets_dir();

// A preset's name as a file name: lower-case letters and digits, every other run a '-'
// ("Linen (medium weight)" -> "linen-medium-weight"): what "Save as" writes.
std::string preset_slug(const std::string& name);

// The preset file a name means, as the Presets panel lists it: the user's presets first, then the
// shipped ones; a preset whose name reads as `name` (case and punctuation aside: the same
// preset_slug) or whose file is `name` or `name`.json. nullopt when none is; a file that cannot
// be read is passed over.
std::optional<std::filesystem::path> preset_named(const std::string& name);
// The names preset_named() knows, for a message: the user's and the shipped presets' names.
std::vector<std::string> preset_names();

}  // namespace foldlab::app
