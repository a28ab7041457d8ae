// `foldlab sweep`: one input over a range, n, Q and z_max for each value as a table or CSV.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/common/inputs.hpp"
#include "core/analysis/sweep.hpp"

namespace foldlab::cli::sweep_command {

struct Options {
  app::InputOptions inputs;
  app::SweepAxisText axis;
  bool csv = false;
};

// The explorer's Sweep tab shows the same points (core's sweep()).
struct Result {
  SweepAxis axis;
  std::vector<SweepPoint> points;
  int refused = 0;                 // values the other inputs refuse ("invalid" rows)
  std::string first_reason;        // "d = 700: ...", the first refused value and why
  int capped = 0;                  // values where n is kMaxWrinkles, the cap
  std::vector<std::string> notes;  // for stderr, after the rows
};

void declare(CLI::App& app, Options& options);
// Throws app::InputError for a malformed axis and for a range with no valid value.
Result run(const Options& options);
void print_text(const Result& result, std::ostream& out);
void print_csv(const Result& result, std::ostream& out);

// The command after parsing: run, write what the command writes, print; the exit status.
int execute(const Options& options);

}  // namespace foldlab::cli::sweep_command
