// The program's version: project(VERSION ...) in the top CMakeLists.txt, and the git commit it
// was built from when it was built from a git checkout.
#pragma once

#include <string>

namespace foldlab::app {

// "0.1.0"
std::string version();
// "66ffc2b" ("66ffc2b-dirty" with uncommitted changes); empty when not built from git.
std::string git_commit();
// "FoldLab 0.1.0 (66ffc2b)": `foldlab --version`, the explorer's About line, and the
// "written_by" of the presets and sessions the program saves.
std::string version_line();

}  // namespace foldlab::app
