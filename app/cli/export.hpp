// `foldlab export`: the deformed mesh (OBJ, glTF) and the fold lines (CSV, SVG) written to files.
// run() solves and builds the stages the files need; the command's glue writes the files.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/common/inputs.hpp"
#include "core/geometry/scene.hpp"
#include "core/io/export_formats.hpp"
#include "core/io/preset.hpp"

namespace foldlab::cli::export_command {

struct Options {
  app::InputOptions inputs;
  std::array<std::string, kExportFormats.size()> paths;  // by kExportFormats' row; empty: not asked
  std::string grid = "128x128";
  double samples = 201;  // a number, so that 1e3 is read as 1000 (a whole number is checked)
  bool stats = false;
};

struct Result {
  Preset preset;
  // Only the stages an output asks for have run: an SVG alone builds no grid.
  Scene scene;
  bool mesh = false;
  bool lines = false;
  std::vector<std::string> notes;  // for stderr: the regime's message, fold lines left out
};

void declare(CLI::App& app, Options& options);
// Throws app::InputError for no output, a malformed --grid or --samples, outputs on one file,
// and a grid or fold lines beyond their budgets.
Result run(const Options& options);
// Writes every file asked for, each atomically.
void write_files(const Options& options, Result& result);
// The pipeline's counters (--stats).
nlohmann::json print_json(const Result& result);

// The command after parsing: run, write what the command writes, print; the exit status.
int execute(const Options& options);

}  // namespace foldlab::cli::export_command
