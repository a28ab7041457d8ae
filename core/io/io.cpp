#include "core/io/io.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

namespace foldlab {
namespace {

namespace fs = std::filesystem;

// Linux's own limit on symbolic links followed in one path.
constexpr int kMaxSymlinkHops = 40;

std::string reason(int error) {
  return std::strerror(error);
}

std::string file_kind(mode_t mode) {
  if (S_ISDIR(mode)) {
    return "a directory";
  }
  if (S_ISFIFO(mode)) {
    return "a FIFO";
  }
  if (S_ISCHR(mode)) {
    return "a character device";
  }
  if (S_ISBLK(mode)) {
    return "a block device";
  }
  if (S_ISSOCK(mode)) {
    return "a socket";
  }
  return "not a regular file";
}

// Closes a descriptor on every way out.
struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) {
      ::close(fd);
    }
  }
};

// The file a save really replaces: `path` itself, or the end of its chain of symbolic links, so
// that saving through a link updates what it points to (as editors do) instead of replacing the
// link with a plain file. Sets `target_stat_valid` when the target exists.
fs::path resolve_symlinks(const fs::path& path, struct stat& target_stat, bool& exists) {
  fs::path target = path;
  for (int hops = 0;; ++hops) {
    if (::lstat(target.c_str(), &target_stat) != 0) {
      if (errno == ENOENT) {
        exists = false;
        return target;  // a new file (or a dangling link's target, created as editors do)
      }
      throw WriteError(path.string() + ": cannot write (" + reason(errno) + ")");
    }
    if (!S_ISLNK(target_stat.st_mode)) {
      exists = true;
      return target;
    }
    if (hops == kMaxSymlinkHops) {
      throw WriteError(path.string() + ": cannot write (" + reason(ELOOP) + ")");
    }
    std::error_code error;
    const fs::path link = fs::read_symlink(target, error);
    if (error) {
      throw WriteError(path.string() + ": cannot write (" + error.message() + ")");
    }
    target = link.is_absolute() ? link : target.parent_path() / link;
  }
}

// Removes temporaries that an earlier save of `target` left behind when its process was killed:
// `NAME.tmp.PID.N` whose PID no longer runs. A running process's temporaries are left alone.
void remove_stale_temporaries(const fs::path& target) {
  const std::string prefix = target.filename().string() + ".tmp.";
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (!name.starts_with(prefix)) {
      continue;
    }
    const std::string_view rest = std::string_view(name).substr(prefix.size());
    long long pid = 0;
    const auto [ptr, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), pid);
    const std::string_view counter(ptr, static_cast<std::size_t>(rest.data() + rest.size() - ptr));
    const bool well_formed = ec == std::errc() && pid > 0 && counter.size() > 1 &&
                             counter[0] == '.' &&
                             counter.find_first_not_of("0123456789", 1) == std::string_view::npos;
    if (!well_formed) {
      continue;
    }
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}

// "2.0 GB", "640 kB", "12 bytes": a size as a person reads it.
std::string describe_bytes(std::uintmax_t bytes) {
  constexpr std::uintmax_t kB = 1024;
  char text[32];
  if (bytes >= kB * kB * kB) {
    std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) / (kB * kB * kB));
  } else if (bytes >= kB * kB) {
    std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / (kB * kB));
  } else if (bytes >= kB) {
    std::snprintf(text, sizeof text, "%.0f kB", static_cast<double>(bytes) / kB);
  } else {
    std::snprintf(text, sizeof text, "%ju bytes", bytes);
  }
  return text;
}

// A temporary being written, where a signal handler can read its name: a fixed table, so that
// nothing is allocated, whose state says when a slot's name is whole. A name too long for a slot,
// or a slot wanted while all are taken, is not registered: the next save removes it as stale.
struct PendingTemporary {
  std::atomic<int> state{0};  // kFree, kNaming, kNamed
  std::array<char, 4096> name{};
};
constexpr int kFree = 0;
constexpr int kNaming = 1;
constexpr int kNamed = 2;
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler reads the state");
std::array<PendingTemporary, 16> pending_temporaries;

// Registers `path` for the life of the write.
class PendingRegistration {
 public:
  explicit PendingRegistration(const fs::path& path) {
    const std::string& name = path.native();
    for (PendingTemporary& slot : pending_temporaries) {
      int expected = kFree;
      if (name.size() < slot.name.size() && slot.state.compare_exchange_strong(expected, kNaming)) {
        std::memcpy(slot.name.data(), name.c_str(), name.size() + 1);
        slot.state.store(kNamed);
        slot_ = &slot;
        return;
      }
    }
  }
  ~PendingRegistration() {
    if (slot_ != nullptr) {
      slot_->state.store(kFree);
    }
  }
  PendingRegistration(const PendingRegistration&) = delete;
  PendingRegistration& operator=(const PendingRegistration&) = delete;

 private:
  PendingTemporary* slot_ = nullptr;
};

}  // namespace

void remove_pending_temporaries() noexcept {
  for (PendingTemporary& slot : pending_temporaries) {
    if (slot.state.load() == kNamed) {
      ::unlink(slot.name.data());
    }
  }
}

std::string read_text_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
  FileDescriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (file.fd < 0) {
    throw ReadError(path.string() + ": cannot open for reading (" + reason(errno) + ")");
  }
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) {
    throw ReadError(path.string() + ": cannot open for reading (" + reason(errno) + ")");
  }
  if (!S_ISREG(info.st_mode)) {
    throw ReadError(path.string() + ": cannot open for reading: " + file_kind(info.st_mode) +
                    ", not a regular file");
  }
  const auto too_large = [&](std::uintmax_t bytes) {
    return ReadError(path.string() + ": " + describe_bytes(bytes) + ", more than the " +
                     describe_bytes(max_bytes) + " such a file may have; not read");
  };
  if (static_cast<std::uintmax_t>(info.st_size) > max_bytes) {
    throw too_large(static_cast<std::uintmax_t>(info.st_size));
  }
  std::string text;
  char buffer[65536];
  while (true) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n < 0) {
      throw ReadError(path.string() + ": read error (" + reason(errno) + ")");
    }
    if (n == 0) {
      break;
    }
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) {
      throw too_large(text.size());
    }
  }
  return text;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  struct stat target_stat {};
  bool exists = false;
  const fs::path target = resolve_symlinks(path, target_stat, exists);
  const std::string through =
      target == path ? "" : " (the symbolic link's target " + target.string() + ")";
  if (exists && !S_ISREG(target_stat.st_mode)) {
    // Renaming over a device, FIFO or directory would replace it: refuse instead.
    throw WriteError(path.string() + through + ": cannot write: " + file_kind(target_stat.st_mode) +
                     ", not a regular file (FoldLab writes only regular files)");
  }
  // Renaming over a file needs only the folder's write permission: without this check a save
  // would replace a read-only file, or another user's file in a shared folder, and take it over.
  if (exists && ::faccessat(AT_FDCWD, target.c_str(), W_OK, AT_EACCESS) != 0) {
    const bool theirs = target_stat.st_uid != ::geteuid();
    throw WriteError("cannot write " + path.string() + through + ": " +
                     (theirs ? "owned by another user" : "read-only") + " (" + reason(errno) + ")");
  }
  remove_stale_temporaries(target);
  // Unique per process and per call, so concurrent saves of one path never share a temporary.
  static std::atomic<unsigned> counter{0};
  fs::path temporary = target;
  temporary += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  auto fail = [&](const std::string& what, int error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw WriteError(path.string() + through + ": " + what + " (" + reason(error) + ")");
  };
  // Before it exists, so that no moment of its life is hidden from a signal handler.
  const PendingRegistration registered(temporary);
  FileDescriptor file{
      ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_TRUNC | O_CLOEXEC, 0644)};
  if (file.fd < 0) {
    throw WriteError(path.string() + through + ": cannot write (" + reason(errno) + ")");
  }
  if (exists) {
    // Replacing a file keeps its permissions, as an in-place write would.
    ::fchmod(file.fd, target_stat.st_mode & 07777);
  }
  std::size_t written = 0;
  while (written < contents.size()) {
    const ssize_t w = ::write(file.fd, contents.data() + written, contents.size() - written);
    if (w < 0 && errno == EINTR) {
      continue;
    }
    if (w < 0) {
      fail("write failed", errno);
    }
    written += static_cast<std::size_t>(w);
  }
  const int sync_error = ::fsync(file.fd) == 0 ? 0 : errno;
  const int close_error = ::close(file.fd) == 0 ? 0 : errno;
  file.fd = -1;
  if (sync_error != 0 || close_error != 0) {
    fail("could not flush to disk", sync_error != 0 ? sync_error : close_error);
  }
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    fail("could not replace the file", errno);
  }
  // The rename itself is durable only once the directory entry is on disk.
  const fs::path parent = target.has_parent_path() ? target.parent_path() : ".";
  if (FileDescriptor dir{::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)}; dir.fd >= 0) {
    ::fsync(dir.fd);
  }
}

}  // namespace foldlab
