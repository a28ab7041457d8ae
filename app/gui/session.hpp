// What the explorer remembers between runs: the parameters being edited (as a preset), which
// preset they came from, and the view settings. Stored as JSON in the user's config folder, beside
// ImGui's own imgui.ini that holds the window layout.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/io/preset.hpp"

namespace foldlab::gui {

struct Session {
  Preset current;                  // the edited parameters, named after their preset
  std::string loaded_preset_path;  // empty for the built-in default
  Preset loaded;                   // the preset as loaded, for "reset" and the unsaved marker
  int grid_resolution = 128;
  bool wireframe = false;
  bool fold_lines_3d = true;
  bool ground = true;
  int ui_scale_percent = 100;
  bool light_theme = false;
};

// $XDG_CONFIG_HOME/foldlab, else $HOME/.config/foldlab (created on demand by the savers).
std::filesystem::path config_dir();
std::filesystem::path user_presets_dir();

// Reads a session file; nullopt when it is absent (`error` empty) or unusable (`error` says why;
// the caller starts from the default preset and shows it).
std::optional<Session> load_session(const std::filesystem::path& path, std::string& error);
// Atomic write (see write_file_atomically); throws WriteError.
void save_session(const std::filesystem::path& path, const Session& session);

}  // namespace foldlab::gui
