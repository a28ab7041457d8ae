// Where the shipped presets live, for commands and the GUI that list them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/io/preset.hpp"

namespace foldlab::app {

// The first that exists of: $FOLDLAB_PRESETS_DIR, ../share/foldlab/presets beside the executable
// (an installed or unpacked program: bin/foldlab and share/foldlab/presets), and the source
// tree's presets/ only while the executable runs from the build folder it was built in. Empty
// when none does. A $FOLDLAB_PRESETS_DIR that is no folder is passed over with a notice on stderr
// (once a run).
std::filesystem::path find_presets_dir();

// The *.json files of a folder, sorted by name.
std::vector<std::filesystem::path> preset_files(const std::filesystem::path& dir);

// The presets of a folder that can be read, sorted as preset_files(), each with what it holds; a
// file that cannot be read (not JSON, not a preset, a value out of range) is passed over and said
// in `skipped` ("skipped F: why"), so that one stray file does not stop a command that lists the
// folder.
struct FolderPresets {
  std::vector<std::filesystem::path> files;
  std::vector<Preset> presets;  // presets[i] is what files[i] holds
  std::vector<std::string> skipped;
};
FolderPresets readable_presets(const std::filesystem::path& dir);

// $XDG_CONFIG_HOME/foldlab, else $HOME/.config/foldlab, else ./.foldlab.
std::filesystem::path config_dir();
// Where the explorer's "Save as" puts the user's presets: config_dir()/presets.
std::filesystem::path user_presets_dir();

// A preset's name as a file name: lower-case letters and digits, every other run a '-'
// ("Linen (medium weight)" -> "linen-medium-weight"): what "Save as" writes.
std::string preset_slug(const std::string& name);

struct NamedPreset {
  std::filesystem::path file;
  std::string name;  // as the preset file writes it
};

// The preset files a name means, as the Presets panel lists them (the user's presets, then the
// shipped ones; a file that cannot be read is passed over). A preset named exactly `name` is the
// one meant, else one whose file is `name` or `name`.json: the first such. Else each preset whose
// name or file reads as `name` case and punctuation aside (the same preset_slug), in the first
// folder that holds one: more than one is ambiguous. Empty when none is.
std::vector<NamedPreset> presets_named(const std::string& name);
// The names presets_named() knows, for a message: the user's and the shipped presets' names.
std::vector<std::string> preset_names();

}  // namespace foldlab::app
