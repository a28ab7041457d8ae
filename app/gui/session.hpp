// What the explorer remembers between runs: the parameters being edited (as a preset), which
// preset they came from, and the view settings. Stored as JSON in the user's config folder, beside
// ImGui's own imgui.ini that holds the window layout.
#pragma once

#include "app/common/presets_dir.hpp"

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/preset.hpp"

namespace foldlab::gui {

// The grid slider's range; a stored resolution outside it is brought inside.
inline constexpr int kMinGridResolution = 8;
inline constexpr int kMaxGridResolution = 512;
// Config files larger than these are not read: the explorer starts from its defaults instead, so
// that a corrupted or hostile config folder cannot delay the start (200,000 windows in imgui.ini
// took 35 s). A real session is a few KB, a real imgui.ini a few KB.
inline constexpr std::uintmax_t kMaxSessionBytes = 1024 * 1024;
inline constexpr std::uintmax_t kMaxImguiIniBytes = 256 * 1024;
// Presets in the user's folder larger than this are listed as too large, without being read.
inline constexpr std::uintmax_t kMaxListedPresetBytes = 1024 * 1024;
// Presets listed from one folder: each is read to show its name.
inline constexpr std::size_t kMaxListedPresets = 500;

// The session's "view" object: settings by name, true/false or numbers. Each panel declares its
// own once, with its key and range (Panel::view_settings, view_settings.hpp); the member's initial
// value is the default.
// The view keys stored as text (ViewSettings::add_text): the page's address links are made with.
inline constexpr std::string_view kTextViewKeys[] = {"page_address"};

class SessionSettings {
 public:
  // The stored value, or `fallback` when it is absent or of another type.
  template <class T>
  T get(const char* key, T fallback) const {
    const auto found = values_.find(key);
    if (found == values_.end()) {
      return fallback;
    }
    if constexpr (std::is_same_v<T, bool>) {
      return found->is_boolean() ? found->template get<bool>() : fallback;
    } else {
      if (!found->is_number()) {
        return fallback;
      }
      // Through double: a stored 1e308 read straight into an int or a float is undefined.
      const double value = found->template get<double>();
      return value >= static_cast<double>(std::numeric_limits<T>::lowest()) &&
                     value <= static_cast<double>(std::numeric_limits<T>::max())
                 ? static_cast<T>(value)
                 : fallback;
    }
  }
  template <class T>
  void set(const char* key, T value) {
    values_[key] = value;
  }
  bool has(const char* key) const { return values_.contains(key); }
  // A stored line of text; nullopt when absent or not text.
  std::optional<std::string> text(const char* key) const {
    const auto found = values_.find(key);
    return found != values_.end() && found->is_string()
               ? std::optional<std::string>(found->template get<std::string>())
               : std::nullopt;
  }
  // As stored in the file.
  const nlohmann::json& json() const { return values_; }
  // The entries of `view` that are true, false or a number, or text for kTextViewKeys; each other
  // one is left out and named in `dropped`. Throws when `view` is not an object.
  static SessionSettings from_json(const nlohmann::json& view, std::vector<std::string>& dropped);

 private:
  nlohmann::json values_ = nlohmann::json::object();
};

struct Session {
  Preset current;                  // the edited parameters, named after their preset
  std::string loaded_preset_path;  // empty for the built-in default
  Preset loaded;                   // the preset as loaded, for "reset" and the unsaved marker
  int grid_resolution = 128;
  // The fabric pinned as B (compare.hpp), if any: its label, parameters and calibration.
  std::optional<Preset> compare;
  // The preset B came from and its file (absent in sessions from before B kept them: then B is
  // its own preset).
  std::optional<Preset> compare_origin;
  std::string compare_origin_path;
  // Everything else the panels and the explorer remember (the 3D view's switches, the UI scale
  // and theme, whether the layout is automatic, expert mode), saved by each of them.
  SessionSettings view;
  // What was changed or dropped while loading (a grid resolution brought into the slider's range,
  // a part that did not read), to show.
  std::vector<std::string> notices;
  // False when a part was dropped: the file is kept aside before it is saved over.
  bool complete = true;
  // False when neither fabric could be read: the explorer keeps the preset it opened with.
  bool fabric_restored = true;
};

// nullopt when the file at `path` is absent or at most `limit` bytes; else a sentence saying that
// it is too large and is not read.
std::optional<std::string> oversized_file(const std::filesystem::path& path, std::uintmax_t limit);

// One of the explorer's own files in the config folder (session.json, imgui.ini) as found at
// start: its text when it could be read, and whether the explorer may write over it later.
struct ConfigFile {
  std::optional<std::string> text;  // nullopt: absent, or not read (see problem)
  std::string problem;              // why it was not read, naming the file; empty otherwise
  // False when something is there that the explorer could not read as its own (not a regular
  // file, another user's, a broken link, too large, unreadable): saving would destroy it.
  bool may_save = true;
};

// Reads `path` only if it is (or links to) a regular file of this user's of at most `limit`
// bytes. A FIFO or device is never opened, so a start cannot wait on one.
ConfigFile read_config_file(const std::filesystem::path& path, std::uintmax_t limit);

// $XDG_CONFIG_HOME/foldlab, else $HOME/.config/foldlab (created on demand by the savers); the
// command line finds the user's presets there too.
using app::config_dir;
using app::user_presets_dir;

// Reads a session file; nullopt when it is absent (`error` empty) or unusable (`error` says why;
// the caller starts from the default preset and shows it). A session with a part that does not
// read keeps the rest, says what was dropped, and keeps the file as it was beside it
// (PATH.unread). `may_save` turns false when what is there could not be read as a session, or
// could not be kept aside: the caller must not save over it.
std::optional<Session> load_session(const std::filesystem::path& path, std::string& error,
                                    bool& may_save);
// The same from the file's text; `origin` names it in `error`.
std::optional<Session> session_from_text(const std::string& text, const std::string& origin,
                                         std::string& error);
// Atomic write (see write_file_atomically); throws WriteError.
void save_session(const std::filesystem::path& path, const Session& session);

}  // namespace foldlab::gui
