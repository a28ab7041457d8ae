#include "core/io/io.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

namespace foldlab {

std::string read_text_file(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error)) {
    throw ReadError(path.string() + ": cannot open for reading: not a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ReadError(path.string() + ": cannot open for reading");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    throw ReadError(path.string() + ": read error");
  }
  return text.str();
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  // Unique per process and per call, so concurrent saves of one path never share a temporary.
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = path;
  temporary += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  auto fail = [&](const std::string& what, int error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw WriteError(path.string() + ": " + what + " (" + std::strerror(error) + ")");
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw WriteError(path.string() + ": cannot write (" + std::strerror(errno) + ")");
  }
  std::size_t written = 0;
  while (written < contents.size()) {
    const ssize_t w = ::write(fd, contents.data() + written, contents.size() - written);
    if (w < 0 && errno == EINTR) {
      continue;
    }
    if (w < 0) {
      const int error = errno;
      ::close(fd);
      fail("write failed", error);
    }
    written += static_cast<std::size_t>(w);
  }
  const int sync_error = ::fsync(fd) == 0 ? 0 : errno;
  const int close_error = ::close(fd) == 0 ? 0 : errno;
  if (sync_error != 0 || close_error != 0) {
    fail("could not flush to disk", sync_error != 0 ? sync_error : close_error);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    fail("could not replace the file", errno);
  }
  // The rename itself is durable only once the directory entry is on disk.
  const std::filesystem::path parent = path.has_parent_path() ? path.parent_path() : ".";
  if (const int dir = ::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace foldlab
