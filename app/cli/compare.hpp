// `foldlab compare`: both methods beside the published n, z_max and Q of the presets that carry
// them, row by row and per table of the paper.
#pragma once

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/analysis/comparison.hpp"
#include "core/model/parameters.hpp"

namespace foldlab::cli::compare_command {

struct Options {
  std::vector<std::string> presets;  // empty: every preset in the presets folder
  std::vector<std::string> assignments;
  std::string law;
  bool json = false;
};

// The methods compared, in the order of every column and array below.
inline constexpr std::array<Method, 2> kMethods{Method::paper, Method::exact};

// How close the model gets to the published results, one group of rows at a time: the paper's
// tables (and Fig. 4) are told apart by the part of a preset's name before its first comma
// ("Table 1, h = 900 mm" is in "Table 1"); a name without a comma is a group of its own.
struct PublishedGroupAccuracy {
  std::string group;
  int rows = 0;
  std::array<ComparisonSummary, kMethods.size()> method;
};

struct Result {
  std::vector<std::string> names;  // the presets with published results, in the order given
  // Per method, per preset: core's comparison with the published values.
  std::array<std::vector<PublishedComparison>, kMethods.size()> rows;
  std::array<ComparisonSummary, kMethods.size()> totals;
  std::vector<PublishedGroupAccuracy> accuracy_by_table;
  std::vector<std::string> notes;  // for stderr: the presets folder's files passed over
};

void declare(CLI::App& app, Options& options);
// Throws app::InputError when no presets folder is found or no preset carries published results.
Result run(const Options& options);
void print_markdown(const Result& result, std::ostream& out);
nlohmann::json print_json(const Result& result);

// The command after parsing: run, write what the command writes, print; the exit status.
int execute(const Options& options);

}  // namespace foldlab::cli::compare_command
