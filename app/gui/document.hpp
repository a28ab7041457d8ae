// What the explorer's panels share, one copy of each: the preset as loaded, the parameters being
// edited (possibly invalid) with their validation, the scene that always holds the last valid
// parameters, and the status line. Panels change it only through these members, so that a slider,
// a map click, a preset load and a scripted run all take the same path to the scene.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/scene.hpp"
#include "core/io/preset.hpp"
#include "core/model/parameters.hpp"

namespace foldlab::gui {

class Document {
 public:
  Document(const Preset& initial, std::string initial_path);

  const Preset& loaded() const { return loaded_; }
  const std::string& loaded_path() const { return loaded_path_; }
  // What the widgets show. After writing into it, call commit().
  Parameters& edited() { return edited_; }
  const Parameters& edited() const { return edited_; }
  const std::vector<ValidationIssue>& issues() const { return issues_; }
  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }

  // The model sees an edit only when it validates; otherwise the scene keeps the last valid state
  // and the widgets show the user's number with the reason it was refused.
  void commit();
  // One input by its --set key, as moving its slider does; the reason when the key or the value
  // cannot be applied at all (range problems are issues(), as for a slider).
  std::optional<std::string> set_input(std::string_view key, double value);
  void reset_to_loaded();
  // Loads a preset file in place of the edits; on failure keeps everything and says why.
  void load_preset_file(const std::filesystem::path& path);
  // Replaces the preset as loaded (a restored session, or the file just saved).
  void adopt(const Preset& loaded, std::string path);
  // True when the valid parameters differ from the preset as loaded.
  bool unsaved() const;
  // Counts preset loads, so that views can reframe for a new cloth.
  std::uint64_t loads() const { return loads_; }

  void notify(std::string message, bool is_error);
  const std::string& message() const { return message_; }
  bool message_is_error() const { return message_is_error_; }
  // Lines shown in the Presets panel until the explorer closes, and listed by `gui --report`:
  // config files that were not used, values brought into range. Repeats are kept once.
  void add_notice(const std::string& notice);
  const std::vector<std::string>& notices() const { return notices_; }

  // Set by every accepted change; the explorer saves the session and clears it.
  bool session_dirty = false;

 private:
  Preset loaded_;
  std::string loaded_path_;
  Parameters edited_;
  std::vector<ValidationIssue> issues_;
  Scene scene_;
  std::uint64_t loads_ = 0;
  std::string message_;
  bool message_is_error_ = false;
  std::vector<std::string> notices_;
};

}  // namespace foldlab::gui
