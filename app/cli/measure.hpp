// `foldlab measure`: folds measured on a real cloth (depths, or points clicked on a photo) to n
// and Q, and a row of the measurements file that `foldlab calibrate` fits. run() measures and
// checks the row; the command's glue adds it to the --append file.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/analysis/fold_measurement.hpp"
#include "core/io/measurements.hpp"

namespace foldlab::cli::measure_command {

struct Options {
  std::string preset_path;
  std::vector<std::string> assignments;
  std::string depths_mm;    // "A0,A1,...", or a photo:
  std::string photo;        // a PNG or JPEG,
  std::string supports_px;  // "X1,Y1,X2,Y2",
  std::string folds_px;     // "Y0,Y1,..."
  std::optional<double> z_max_mm;
  std::string name;
  std::string append_path;
  bool json = false;
};

// The explorer's photo overlay measures the same (core's measure_folds and measurement_row).
struct Result {
  FoldMeasurement folds;
  Measurement row;
  std::optional<double> z_max_mm;
  std::string append_path;  // the file the row goes to; empty: none
};

void declare(CLI::App& app, Options& options);
// Throws app::InputError for malformed input, a photo that cannot be read or shows nothing, and a
// row that `calibrate` would refuse.
Result run(const Options& options);
// Adds the row to result.append_path, if any; app::InputError when the file cannot take it.
void append_row(const Result& result);
void print_text(const Result& result, std::ostream& out);
nlohmann::json print_json(const Result& result);

// The command after parsing: run, write what the command writes, print; the exit status.
int execute(const Options& options);

}  // namespace foldlab::cli::measure_command
