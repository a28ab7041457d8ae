#include "app/cli/solve.hpp"

#include <iostream>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/io/scene_report.hpp"

namespace foldlab::cli {
namespace solve_command {

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand("solve", "solve one case and print the result");
  add_input_options(*command, options.inputs);
  command->add_flag("--json", options.json, "print one JSON object instead of a table");
  command->add_flag("--stats", options.stats,
                    "add the pipeline's per-stage counters (evaluations, time)");
}

Result run(const Options& options) {
  const Preset preset = app::resolve_named_inputs(options.inputs);
  Scene scene(preset.parameters);
  Solution solution = scene.solution();
  ModelStanding standing = model_standing(preset.parameters, preset.calibration, solution);
  return {std::move(preset), std::move(scene), std::move(solution), std::move(standing),
          options.stats};
}

void print_text(const Result& result, std::ostream& out) {
  out << solution_table(result.solution, result.preset.parameters, result.preset.name,
                        &result.standing);
  if (result.stats) {
    out << "\n" << scene_stats_table(result.scene);
  }
}

nlohmann::json print_json(const Result& result) {
  nlohmann::json out =
      solution_to_json(result.solution, result.preset.parameters, &result.standing);
  if (result.stats) {
    out["stats"] = scene_stats_to_json(result.scene);
  }
  return out;
}

int execute(const Options& options) {
  const Result result = run(options);
  print_result(result, options.json, &print_text);
  return kExitOk;
}

}  // namespace solve_command

Command add_solve_command(CLI::App& app) {
  return make_command(app, solve_command::declare, solve_command::execute);
}

int run_default_headless() {
  return guarded([] {
    solve_command::print_text(solve_command::run({}), std::cout);
    return kExitOk;
  });
}

}  // namespace foldlab::cli
