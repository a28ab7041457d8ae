// The explorer's commands: `foldlab gui` (the window), `foldlab render` (headless PNG of the
// window) and `foldlab picture` (headless PNG of one view, no interface).
#pragma once

#include <CLI/CLI.hpp>

#include "app/common/inputs.hpp"

namespace foldlab::gui {

app::Command add_gui_command(CLI::App& app);
app::Command add_render_command(CLI::App& app);
// `foldlab picture VIEW`: the 3D cloth or the fold plot alone, headless, into a PNG.
app::Command add_picture_command(CLI::App& app);
// `foldlab` with no command and a display: the explorer until closed. kExitInternal when no
// window can be opened, so that the caller can fall back to the headless solve.
int run_default_window();

}  // namespace foldlab::gui
