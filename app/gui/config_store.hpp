// Where the config folder (the session, the window layout, the user's presets, the measurements
// file) lasts from one run to the next. On the desktop it is a folder on disk, which lasts by
// itself: this base class does nothing. In the browser the page's file system is memory, gone
// with the page: the folder is copied in from the browser's storage at start and what changed
// is copied back after each frame (app/web/browser_files.cpp). One implementation per
// platform, chosen at link time by make_config_store().
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace foldlab::gui {

class ConfigStore {
 public:
  virtual ~ConfigStore() = default;
  // Before anything in `folder` is read: brings back what was stored of it.
  virtual void restore(const std::filesystem::path& /*folder*/) {}
  // After a frame and at the end of a run: stores what changed in `folder` since the last call.
  // Returns a sentence the first time the storage refuses a file.
  virtual std::optional<std::string> keep(const std::filesystem::path& /*folder*/) {
    return std::nullopt;
  }
  // Whether the folder belongs to the explorer alone. Then a session file it cannot read is set
  // aside and replaced (nobody else's file can be lost, and the user has no way to move it);
  // otherwise it is left for its owner and not saved over.
  virtual bool owns_folder() const { return false; }
};

// The platform's ConfigStore; defined once per program (desktop or page).
std::unique_ptr<ConfigStore> make_config_store();

}  // namespace foldlab::gui
