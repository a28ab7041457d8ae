// How a file crosses between the explorer and the user's disk. On the desktop the file dialog
// browses the disk and reads and writes where the user points: nothing crosses, and this base
// class does nothing. In the browser the explorer's files live in the page's memory: a file
// written for the user is handed over as a download, and a file to open comes from the
// browser's file picker, copied into memory first (app/web/browser_files.cpp). One
// implementation per platform, chosen at link time by make_file_transfer().
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace foldlab::gui {

class FileTransfer {
 public:
  virtual ~FileTransfer() = default;
  // Whether the file dialog shows the disk's folders. Otherwise saving asks for a file name
  // alone and the file is written into outbox() and then delivered, and opening asks pick().
  virtual bool browses_folders() const { return true; }
  // Where a file is written before it is delivered.
  virtual std::filesystem::path outbox() const { return {}; }
  // Hands the file written at `path` to the user (the browser downloads it); true when it went.
  virtual bool deliver(const std::filesystem::path& /*path*/) { return true; }
  // Asks the user for a file to open, one of `extensions` (".png", lower case; any if empty).
  // Its copy arrives later through take_picked().
  virtual void pick(const std::vector<std::string>& /*extensions*/) {}
  // The copy of a file the user picked since the last call, if any.
  virtual std::optional<std::filesystem::path> take_picked() { return std::nullopt; }
};

// The platform's FileTransfer; defined once per program (desktop or page).
std::unique_ptr<FileTransfer> make_file_transfer();

}  // namespace foldlab::gui
