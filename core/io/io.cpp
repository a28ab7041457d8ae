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

// Linux's limit on one name in a path, in bytes.
constexpr std::size_t kMaxNameBytes = 255;
// The most ".PID.N" can take: two 32-bit numbers and their dots.
constexpr std::size_t kMaxTemporarySuffixBytes = 2 * 10 + 2;

// "NAME.tmp.", the start of the name of every temporary of `target`: NAME cut (at a character's
// start, so the name stays readable UTF-8) to leave room for ".PID.N" within the name limit, so
// that every name an output may have can be written.
std::string temporary_prefix(const fs::path& target) {
  constexpr std::string_view kTmp = ".tmp.";
  std::string name = target.filename().string();
  const std::size_t room = kMaxNameBytes - kMaxTemporarySuffixBytes - kTmp.size();
  if (name.size() > room) {
    std::size_t cut = room;
    while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) {
      --cut;
    }
    name.resize(cut);
  }
  return name + std::string(kTmp);
}

// Removes temporaries that an earlier save of `target` left behind when its process was killed:
// `NAME.tmp.PID.N` whose PID no longer runs. A running process's temporaries are left alone.
void remove_stale_temporaries(const fs::path& target) {
  const std::string prefix = temporary_prefix(target);
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
// A placeholder (NewFilePlaceholder) carries the identity it had when created, and is removed
// only while the name still holds that file, empty.
struct PendingTemporary {
  std::atomic<int> state{0};  // kFree, kNaming, kNamed
  std::array<char, 4096> name{};
  bool placeholder = false;
  dev_t device = 0;
  ino_t inode = 0;
};
constexpr int kFree = 0;
constexpr int kNaming = 1;
constexpr int kNamed = 2;
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler reads the state");
std::array<PendingTemporary, 16> pending_temporaries;

// The slot `name` took, or -1 when none could.
int register_pending(const std::string& name, const struct stat* placeholder) {
  for (std::size_t i = 0; i < pending_temporaries.size(); ++i) {
    PendingTemporary& slot = pending_temporaries[i];
    int expected = kFree;
    if (name.size() < slot.name.size() && slot.state.compare_exchange_strong(expected, kNaming)) {
      std::memcpy(slot.name.data(), name.c_str(), name.size() + 1);
      slot.placeholder = placeholder != nullptr;
      slot.device = placeholder != nullptr ? placeholder->st_dev : 0;
      slot.inode = placeholder != nullptr ? placeholder->st_ino : 0;
      slot.state.store(kNamed);
      return static_cast<int>(i);
    }
  }
  return -1;
}

void release_pending(int slot) noexcept {
  if (slot >= 0) {
    pending_temporaries[static_cast<std::size_t>(slot)].state.store(kFree);
  }
}

// Whether `slot` may be unlinked now: a temporary always, a placeholder while its name still
// holds the empty file it created. Async-signal-safe.
bool removable(const PendingTemporary& slot) noexcept {
  if (!slot.placeholder) {
    return true;
  }
  struct stat now {};
  return ::stat(slot.name.data(), &now) == 0 && now.st_dev == slot.device &&
         now.st_ino == slot.inode && now.st_size == 0;
}

// Registers `path` for the life of the write.
class PendingRegistration {
 public:
  explicit PendingRegistration(const fs::path& path)
      : slot_(register_pending(path.native(), nullptr)) {}
  ~PendingRegistration() { release_pending(slot_); }
  PendingRegistration(const PendingRegistration&) = delete;
  PendingRegistration& operator=(const PendingRegistration&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace

void remove_pending_temporaries() noexcept {
  for (PendingTemporary& slot : pending_temporaries) {
    if (slot.state.load() == kNamed && removable(slot)) {
      ::unlink(slot.name.data());
    }
  }
}

int NewFilePlaceholder::create(const std::filesystem::path& path, int flags) {
  remove_unless_kept();
  // Held off from the open until the file is registered, so that no moment of its life is
  // hidden from a signal handler.
  sigset_t stopping;
  sigset_t previous;
  ::sigemptyset(&stopping);
  ::sigaddset(&stopping, SIGINT);
  ::sigaddset(&stopping, SIGTERM);
  ::pthread_sigmask(SIG_BLOCK, &stopping, &previous);
  const int fd = ::open(path.c_str(), flags | O_CREAT, 0644);
  const int open_error = errno;
  struct stat created {};
  if (fd >= 0 && ::fstat(fd, &created) == 0 && S_ISREG(created.st_mode)) {
    slot_ = register_pending(path.native(), &created);
    path_ = path;
    device_ = created.st_dev;
    inode_ = created.st_ino;
    kept_ = false;
  }
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  errno = open_error;
  return fd;
}

void NewFilePlaceholder::keep() noexcept {
  kept_ = true;
  release_pending(slot_);
  slot_ = -1;
}

void NewFilePlaceholder::remove_unless_kept() noexcept {
  if (!kept_ && !path_.empty()) {
    struct stat now {};
    if (::stat(path_.c_str(), &now) == 0 && now.st_dev == device_ && now.st_ino == inode_ &&
        now.st_size == 0) {
      ::unlink(path_.c_str());
    }
  }
  release_pending(slot_);
  slot_ = -1;
  path_.clear();
}

NewFilePlaceholder::~NewFilePlaceholder() {
  remove_unless_kept();
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
  const fs::path temporary =
      target.parent_path() /
      (temporary_prefix(target) + std::to_string(::getpid()) + "." + std::to_string(counter++));
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
