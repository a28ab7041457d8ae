// The page's program: `gui` with the desktop's options (the page passes them from its address),
// run in the browser's frame loop. The explorer keeps running after main returns.
#include <cstdlib>
#include <iostream>
#include <sstream>

#include <emscripten/emscripten.h>
#include <CLI/CLI.hpp>

#include "app/common/inputs.hpp"
#include "app/gui/commands.hpp"
#include "core/model/text_format.hpp"

int main(int argc, char** argv) {
  using namespace foldlab;
  // foldlab.data holds the presets here (app/web/CMakeLists.txt).
  setenv("FOLDLAB_PRESETS_DIR", "/presets", 0);
  CLI::App app{"FoldLab in the browser"};
  // The address is no command line: what the explorer cannot read of it is a notice in the
  // explorer, not a page that never opens.
  const app::Command gui = gui::add_gui_command(app, gui::GuiCaller::page);
  app.require_subcommand(1, 1);
  int status = app::kExitOk;
  try {
    app.parse(argc, argv);
    status = gui();
  } catch (const CLI::ParseError& e) {
    std::ostringstream message;
    app.exit(e, std::cout, message);
    std::cerr << detail::escaped_lines(message.str());
    status = app::kExitInvalidInput;
  }
  if (status != app::kExitOk) {
    // No frame loop started: the page says why (stderr) and that the run ended.
    EM_ASM(
        {
          if (Module.foldlabFinished)
            Module.foldlabFinished($0);
        },
        status);
  }
  return status;
}
