// The session on disk: restored at the start when asked (the fabric, B, the view settings), set
// aside or left alone when it does not read as a session, saved a second after the last change
// so that a crash loses little, and at once when the page is left or the window closes.
#pragma once

#include <filesystem>

#include "app/gui/document.hpp"
#include "app/gui/ui_status.hpp"
#include "app/gui/view_settings.hpp"

namespace foldlab::gui {

class SessionKeeper {
 public:
  // `file` empty: nothing is restored or saved. `owns_folder`: the config folder is the
  // explorer's alone, so a file there that does not read is set aside and replaced rather than
  // left for its owner.
  SessionKeeper(std::filesystem::path file, bool owns_folder, Document& document, UiStatus& status,
                ViewSettings& settings)
      : file_(std::move(file)),
        owns_folder_(owns_folder),
        document_(document),
        status_(status),
        settings_(settings) {}
  // Reads the file, even when not restoring: saving over what is there is allowed only when it
  // reads as a session (or nothing is there).
  void read(bool restore);
  void save_now();
  // Saved now if it changed since the last save: the page is being left, and what a person did
  // last must not be lost.
  void keep();
  // Every frame: saved a second after the last change; `now_s` is the frame's time.
  void keep_when_idle(double now_s);
  // True when edits are kept by the session (there is a file to keep them in).
  bool keeps_edits() const { return !file_.empty(); }

 private:
  std::filesystem::path file_;
  bool owns_folder_;
  Document& document_;
  UiStatus& status_;
  ViewSettings& settings_;
  double last_save_s_ = 0.0;
};

}  // namespace foldlab::gui
