// The explorer's commands: `foldlab gui` (the window), `foldlab render` (headless PNG of the
// window) and `foldlab picture` (headless PNG of one view, no interface).
#pragma once

#include <CLI/CLI.hpp>

#include "app/common/input_options.hpp"

namespace foldlab::gui {

// Who starts `gui`: a command line, whose mistakes are refused (exit 2) for the person who typed
// them to correct, or the page, which hands on its address (--link, --preset-name) and must open
// the explorer whatever the address says, saying there what it left out.
enum class GuiCaller { command_line, page };
app::Command add_gui_command(CLI::App& app, GuiCaller caller = GuiCaller::command_line);
app::Command add_render_command(CLI::App& app);
// `foldlab picture VIEW`: the 3D cloth or the fold plot alone, headless, into a PNG.
app::Command add_picture_command(CLI::App& app);
// `foldlab` with no command and a display: the explorer until closed. kExitInternal when no
// window can be opened, so that the caller can fall back to the headless solve.
int run_default_window();

}  // namespace foldlab::gui
