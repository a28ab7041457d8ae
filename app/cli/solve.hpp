// `foldlab solve`: one case solved and printed as a table or as JSON.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/common/inputs.hpp"
#include "core/geometry/scene.hpp"
#include "core/io/preset.hpp"
#include "core/io/report.hpp"

namespace foldlab::cli::solve_command {

struct Options {
  app::InputOptions inputs;
  bool json = false;
  bool stats = false;  // the pipeline's per-stage counters beside the solution
};

// The explorer's Results panel shows the same: the scene's solution and the model's standing.
struct Result {
  Preset preset;
  Scene scene;  // solved, nothing more: `solve` never builds a grid
  Solution solution;
  ModelStanding standing;
  bool stats = false;
};

void declare(CLI::App& app, Options& options);
// Throws app::InputError for an input the model refuses.
Result run(const Options& options);
void print_text(const Result& result, std::ostream& out);
nlohmann::json print_json(const Result& result);

// The command after parsing: run, write what the command writes, print; the exit status.
int execute(const Options& options);

}  // namespace foldlab::cli::solve_command
