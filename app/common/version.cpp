#include "app/common/version.hpp"

#include "foldlab_version.hpp"  // generated into the build folder by packaging/write_version.cmake

namespace foldlab::app {

std::string version() {
  return FOLDLAB_VERSION;
}

std::string git_commit() {
  return FOLDLAB_GIT_COMMIT;
}

std::string version_line() {
  std::string line = "FoldLab " + version();
  if (const std::string commit = git_commit(); !commit.empty()) {
    line += " (" + commit + ")";
  }
  return line;
}

}  // namespace foldlab::app
