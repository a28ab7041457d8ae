// `foldlab calibrate`: fits eq. 7's constants to measured n, z_max and Q (core's calibrate()) and
// prints the fit beside its held-out figures, so that a user sees how much of it is real. run()
// fits; the command's glue writes --save-preset's file.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/common/inputs.hpp"
#include "core/analysis/calibration.hpp"
#include "core/io/preset.hpp"

namespace foldlab::cli::calibrate_command {

struct Options {
  std::string data_path;
  std::string fit = "K";     // or "K,p"
  app::InputOptions inputs;  // the base preset, --set, --method and --law
  std::string save_preset_path;
  std::string calibrated_on;  // empty: the --data file's name
  bool json = false;
  bool no_held_out = false;
  bool coverage = false;
};

struct Result {
  Preset base;
  std::string data_path;
  CalibrationReport report;  // core's, as the explorer's calibration window shows it
  // How often the prediction intervals covered rows they were not fitted to; empty: not measured.
  std::string coverage;
  std::optional<double> interval_level;  // the fitted constants' interval level (JSON only)
  std::vector<std::string> notes;        // for stderr
  bool interrupted = false;              // Ctrl+C: nothing is to be printed or written
};

void declare(CLI::App& app, Options& options);
// Throws app::InputError for unreadable or implausible data, and for --save-preset or --coverage
// beyond their row limits. Shows its progress on stderr when that is a terminal, and stops at
// Ctrl+C while the command's handler is up (result.interrupted).
Result run(const Options& options);
void print_text(const Result& result, std::ostream& out);
nlohmann::json print_json(const Result& result);
// Writes the base preset with the fitted constants and the calibration record to
// options.save_preset_path.
void save_calibrated_preset(const Options& options, const Result& result);

// The command after parsing: run, write what the command writes, print; the exit status.
int execute(const Options& options);

}  // namespace foldlab::cli::calibrate_command
