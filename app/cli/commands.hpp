// The headless commands of the foldlab executable, registered on a CLI11 app.
#pragma once

#include <memory>

#include <CLI/CLI.hpp>

#include "app/common/input_options.hpp"
#include "app/common/presets_dir.hpp"
#include "app/common/version.hpp"

namespace foldlab::cli {

using app::add_input_options;
using app::check_outputs;
using app::Command;
using app::EnvironmentError;
using app::find_presets_dir;
using app::FolderPresets;
using app::guarded;
using app::InputError;
using app::InputOptions;
using app::kExitInternal;
using app::kExitInvalidInput;
using app::kExitOk;
using app::preset_files;
using app::readable_presets;
using app::resolve_inputs;

// A command from its parts: `declare` registers its flags on an Options after which, once
// parsed, `execute` (run, write what the command writes, print) gives the exit status, with the
// statuses of guarded() for what it throws.
template <class Options>
Command make_command(CLI::App& app, void (*declare)(CLI::App&, Options&),
                     int (*execute)(const Options&)) {
  auto options = std::make_shared<Options>();
  declare(app, *options);
  return [options, execute] { return guarded([&] { return execute(*options); }); };
}

Command add_solve_command(CLI::App& app);
Command add_export_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
// Fits eq. 7's constants to measurements (calibrate.cpp).
Command add_calibrate_command(CLI::App& app);
// Folds measured on a real cloth to n, Q and a measurements row (measure.cpp).
Command add_measure_command(CLI::App& app);
// The tension field of the hung cloth (field.cpp).
Command add_field_command(CLI::App& app);
// Run time against error (bench.cpp) and the numerical stress test (stress.cpp).
Command add_bench_command(CLI::App& app);
Command add_stress_command(CLI::App& app);

// `foldlab` with no command and no display: the default preset solved and printed as a table.
int run_default_headless();

}  // namespace foldlab::cli
