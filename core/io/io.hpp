// Writing files so that a crash or a full disk never leaves half of one behind.
#pragma once

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

// The whole file as text. Throws ReadError naming the path and the system's reason: absent,
// not a regular file (a FIFO is refused without waiting for a writer), unreadable.
std::string read_text_file(const std::filesystem::path& path);

// Writes `contents` to a temporary file beside `path`, flushes it to disk and renames it over
// `path`: readers see the old file or the new one, never a mix. A symbolic link is followed to
// its target, which is replaced (the link stays); a target that exists but is not a regular file
// (directory, FIFO, device) is refused. Temporaries of this path left by a killed process are
// removed. Throws WriteError naming the path and the system's reason.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace foldlab
