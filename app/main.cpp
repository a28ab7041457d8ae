// foldlab: the explorer GUI and the headless commands that scripts and tests rely on.
#include <cstdlib>
#include <iostream>
#include <map>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/inputs.hpp"

int main(int argc, char** argv) {
  using namespace foldlab::cli;
  CLI::App app{
      "FoldLab: how a vertically hung fabric wrinkles after it buckles (tension field theory, "
      "A. Conci). Units: mm, MPa, N/mm².\nWith no command: opens the explorer where a display "
      "exists, else solves the default preset and prints it."};
  app.set_help_all_flag("--help-all", "help for every command");
  std::map<std::string, Command> commands;
  commands["solve"] = add_solve_command(app);
  commands["export"] = add_export_command(app);
  commands["compare"] = add_compare_command(app);
  commands["sweep"] = add_sweep_command(app);
  commands["calibrate"] = add_calibrate_command(app);
  commands["bench"] = add_bench_command(app);
  commands["stress"] = add_stress_command(app);
#ifdef FOLDLAB_WITH_GUI
  commands["gui"] = add_gui_command(app);
  commands["render"] = add_render_command(app);
#endif
  app.require_subcommand(0, 1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message
    return kExitInvalidInput;
  }
  for (CLI::App* sub : app.get_subcommands()) {
    return commands.at(sub->get_name())();
  }
#ifdef FOLDLAB_WITH_GUI
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return run_default((display && *display) || (wayland && *wayland));
#else
  return run_default_headless();
#endif
}
