// Writing files so that a crash or a full disk never leaves half of one behind.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace foldlab {

class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What each kind of input file may weigh: far above any real one, far below what would take the
// machine's memory or minutes (a 64-row measurements file is a few kB, a preset with its
// calibration record some 10 kB, the longest play script 7 kB).
inline constexpr std::uintmax_t kMaxPresetFileBytes = 1u << 20;
inline constexpr std::uintmax_t kMaxMeasurementsFileBytes = 4u << 20;
inline constexpr std::uintmax_t kMaxScriptFileBytes = 4u << 20;

// The whole file as text, the one way every loader reads a file. Throws ReadError naming the
// path and the reason: absent, not a regular file (a FIFO or a device is refused without waiting
// for a writer or reading forever), unreadable, or larger than `max_bytes` (checked before
// reading, and again while reading a file that grows).
std::string read_text_file(const std::filesystem::path& path, std::uintmax_t max_bytes);

// Writes `contents` to a temporary file beside `path`, flushes it to disk and renames it over
// `path`: readers see the old file or the new one, never a mix. A symbolic link is followed to
// its target, which is replaced (the link stays); a target that exists but is not a regular file
// (directory, FIFO, device), or that the user could not open for writing (read-only, another
// user's), is refused. Temporaries of this path left by a killed process are
// removed. Throws WriteError naming the path and the system's reason.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// Unlinks the temporaries write_file_atomically is writing now. Async-signal-safe: a handler of
// SIGINT or SIGTERM calls it, so that a stopped write leaves no temporary as large as the file.
void remove_pending_temporaries() noexcept;

// A file a run creates empty to hold its place before its contents are written (an append's lock
// on a new measurements file). Until keep(), a SIGINT or SIGTERM (remove_pending_temporaries) and
// the destructor remove it while its name still holds that file, empty: a run stopped or refused
// before writing leaves no empty file where there was none, which a later read would refuse.
class NewFilePlaceholder {
 public:
  NewFilePlaceholder() = default;
  ~NewFilePlaceholder();
  NewFilePlaceholder(const NewFilePlaceholder&) = delete;
  NewFilePlaceholder& operator=(const NewFilePlaceholder&) = delete;

  // open(path, flags | O_CREAT, 0644), to be called when `path` does not exist; the file is
  // registered before SIGINT or SIGTERM can be handled. Returns the descriptor, or -1 with errno.
  int create(const std::filesystem::path& path, int flags);
  // The file now holds what was written: it stays.
  void keep() noexcept;
  // What the destructor does, before it: an append removes its placeholder while it holds the
  // lock, so that no other process finds it empty.
  void remove_unless_kept() noexcept;

 private:
  std::filesystem::path path_;  // empty: nothing created
  int slot_ = -1;
  dev_t device_ = 0;
  ino_t inode_ = 0;
  bool kept_ = false;
};

}  // namespace foldlab
