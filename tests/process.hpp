// Runs a program as a user or a script would (no shell), capturing its exit status, stdout and
// stderr, for the end-to-end tests of the foldlab executable.
#pragma once

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace foldlab::testing {

struct RunResult {
  int exit_status = -1;  // the exit code, or 128 + signal number if killed by a signal
  std::string out;
  std::string err;
};

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct Environment {
  std::vector<std::string> unset = {"DISPLAY", "WAYLAND_DISPLAY"};
  std::vector<std::pair<std::string, std::string>> set;
};

// argv[0] is `program`; stdout and stderr go through files in `capture_dir`, removed afterwards.
inline RunResult run_process(const std::string& program, const std::vector<std::string>& args,
                             const std::filesystem::path& capture_dir,
                             const Environment& environment = {}) {
  const std::filesystem::path out_path = capture_dir / ".stdout";
  const std::filesystem::path err_path = capture_dir / ".stderr";
  RunResult result;
  const pid_t pid = ::fork();
  if (pid < 0) {
    result.err = "fork failed";
    return result;
  }
  if (pid == 0) {
    const int out_fd = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out_fd < 0 || err_fd < 0 || ::dup2(out_fd, STDOUT_FILENO) < 0 ||
        ::dup2(err_fd, STDERR_FILENO) < 0) {
      ::_exit(126);
    }
    ::close(out_fd);
    ::close(err_fd);
    for (const std::string& name : environment.unset) {
      ::unsetenv(name.c_str());
    }
    for (const auto& [name, value] : environment.set) {
      ::setenv(name.c_str(), value.c_str(), 1);
    }
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& a : args) {
      argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    ::execvp(program.c_str(), argv.data());
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      result.err = "waitpid failed";
      return result;
    }
  }
  if (WIFEXITED(status)) {
    result.exit_status = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.exit_status = 128 + WTERMSIG(status);
  }
  result.out = read_file(out_path);
  result.err = read_file(err_path);
  std::filesystem::remove(out_path);
  std::filesystem::remove(err_path);
  return result;
}

}  // namespace foldlab::testing
