// foldlab: parses the command line and hands over to the CLI's or the explorer's command.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/cli/commands.hpp"
#include "app/common/presets_dir.hpp"
#include "app/common/version.hpp"
#include "core/model/text_format.hpp"
#ifdef FOLDLAB_WITH_GUI
#include "app/gui/commands.hpp"
#endif

namespace {

bool display_available() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

}  // namespace

int main(int argc, char** argv) {
  using namespace foldlab;
  CLI::App app{
      "FoldLab: how a vertically hung fabric wrinkles after it buckles (tension field theory, "
      "A. Conci). Units: mm, MPa, N/mm².\nWith no command: opens the explorer where a display "
      "exists, else solves the default preset and prints it."};
  app.set_help_all_flag("--help-all", "help for every command");
  app.set_version_flag(
      "--version",
      [] {
        const std::filesystem::path presets = app::find_presets_dir();
        return app::version_line() +
               "\npresets: " + (presets.empty() ? "none found" : detail::escaped(presets.string()));
      },
      "print the version, the git commit it was built from and the presets folder, and exit");
  std::map<std::string, app::Command> commands;
  commands["solve"] = cli::add_solve_command(app);
  commands["export"] = cli::add_export_command(app);
  commands["compare"] = cli::add_compare_command(app);
  commands["sweep"] = cli::add_sweep_command(app);
  commands["calibrate"] = cli::add_calibrate_command(app);
  commands["measure"] = cli::add_measure_command(app);
  commands["field"] = cli::add_field_command(app);
  commands["bench"] = cli::add_bench_command(app);
  commands["stress"] = cli::add_stress_command(app);
#ifdef FOLDLAB_WITH_GUI
  commands["gui"] = gui::add_gui_command(app);
  commands["render"] = gui::add_render_command(app);
  commands["picture"] = gui::add_picture_command(app);
#endif
  app.require_subcommand(0, 1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::ostringstream message;  // CLI11 quotes the arguments as given: escaped before printing
    app.exit(e, std::cout, message);
    std::cerr << detail::escaped_lines(message.str());
    return app::kExitInvalidInput;
  }
  for (CLI::App* sub : app.get_subcommands()) {
    return commands.at(sub->get_name())();
  }
#ifdef FOLDLAB_WITH_GUI
  if (display_available()) {
    const int status = gui::run_default_window();
    if (status != app::kExitInternal) {
      return status;
    }
    std::cerr << "foldlab: no window could be opened; printing the default preset instead\n";
  }
#endif
  return cli::run_default_headless();
}
