// The explorer's commands: `foldlab gui` (the window) and `foldlab render` (headless PNG).
#pragma once

#include <CLI/CLI.hpp>

#include "app/common/inputs.hpp"

namespace foldlab::gui {

app::Command add_gui_command(CLI::App& app);
app::Command add_render_command(CLI::App& app);
// `foldlab` with no command and a display: the explorer until closed. kExitInternal when no
// window can be opened, so that the caller can fall back to the headless solve.
int run_default_window();

}  // namespace foldlab::gui
