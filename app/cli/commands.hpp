// The headless commands of the foldlab executable, registered on a CLI11 app.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace foldlab::cli {

// A registered command: run() is called after parsing when its subcommand was given, and returns
// the exit status.
using Command = std::function<int()>;

Command add_solve_command(CLI::App& app);
Command add_export_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
// Issue 6: fit eq. 7's constants to measurements (cli/calibrate.cpp).
Command add_calibrate_command(CLI::App& app);
// Issue 4: run time against error (cli/bench.cpp) and the numerical stress test (cli/stress.cpp).
Command add_bench_command(CLI::App& app);
Command add_stress_command(CLI::App& app);

// `foldlab` with no command and no display: the default preset solved and printed as a table.
int run_default_headless();

#ifdef FOLDLAB_WITH_GUI
Command add_gui_command(CLI::App& app);
Command add_render_command(CLI::App& app);
// `foldlab` with no command: the explorer where a display exists, else run_default_headless().
int run_default(bool display_available);
#endif

}  // namespace foldlab::cli
