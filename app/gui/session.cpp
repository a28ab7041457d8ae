#include "app/gui/session.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/io/io.hpp"

namespace foldlab::gui {

std::filesystem::path config_dir() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) {
    return std::filesystem::path(xdg) / "foldlab";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".config" / "foldlab";
  }
  return std::filesystem::current_path() / ".foldlab";
}

std::filesystem::path user_presets_dir() {
  return config_dir() / "presets";
}

std::optional<Session> load_session(const std::filesystem::path& path, std::string& error) {
  std::ifstream in(path);
  if (!in) {
    error = "no saved session at " + path.string();
    return std::nullopt;
  }
  std::stringstream text;
  text << in.rdbuf();
  try {
    const nlohmann::json j = nlohmann::json::parse(text.str());
    Session s;
    s.current = preset_from_json(j.at("current"), path.string() + " (current)");
    s.loaded = preset_from_json(j.at("loaded"), path.string() + " (loaded)");
    s.loaded_preset_path = j.value("loaded_preset_path", "");
    const nlohmann::json& view = j.at("view");
    s.grid_resolution = view.value("grid_resolution", s.grid_resolution);
    s.wireframe = view.value("wireframe", s.wireframe);
    s.fold_lines_3d = view.value("fold_lines", s.fold_lines_3d);
    s.ground = view.value("ground", s.ground);
    return s;
  } catch (const std::exception& e) {
    error = "the saved session " + path.string() + " could not be read (" + e.what() +
            "); starting from the default preset";
    return std::nullopt;
  }
}

void save_session(const std::filesystem::path& path, const Session& session) {
  std::filesystem::create_directories(path.parent_path());
  const nlohmann::json j = {
      {"foldlab_session", 1},
      {"current", preset_to_json(session.current)},
      {"loaded", preset_to_json(session.loaded)},
      {"loaded_preset_path", session.loaded_preset_path},
      {"view",
       {{"grid_resolution", session.grid_resolution},
        {"wireframe", session.wireframe},
        {"fold_lines", session.fold_lines_3d},
        {"ground", session.ground}}},
  };
  write_file_atomically(path, j.dump(2) + "\n");
}

}  // namespace foldlab::gui
