// `foldlab stress`: both methods over inputs far wider than real fabrics; exit 1 on any NaN, inf
// or hang. The result is core's StressReport. `--solver field`: the tension field's cold solves
// over the same inputs and every outline (core's FieldStressReport); exit 1 also on a false
// "converged" or a converged field out of balance.
#pragma once

#include <ostream>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/tools/field_stress.hpp"
#include "core/tools/stress.hpp"

namespace foldlab::cli::stress_command {

struct Options {
  std::string solver = "closed-form";  // or "field": the tension field's stress test
  int samples = 100000;
  bool samples_given = false;  // else the field's default count (kFieldStressDefaultSamples)
  int index = -1;              // field: the first sample's index (one sample unless --samples)
  std::string seed = "1";  // text: CLI11 turns "-1" and 2^64 into 2^64 - 1 as an unsigned number
  bool json = false;
  int threads = 0;             // 0: hardware threads
  double hang_margin_s = 1.0;  // field: a solve past its budget by more than this is a hang
};

void declare(CLI::App& app, Options& options);
// Throws app::InputError for a seed that is not a whole number from 0 to 2^64 - 1.
StressReport run(const Options& options);
// The field's stress test. Throws app::InputError for a bad seed or too many samples.
FieldStressReport run_field(const Options& options);
void print_text(const StressReport& report, std::ostream& out);
nlohmann::json print_json(const StressReport& report);

// The command after parsing: run, write what the command writes, print; the exit status.
int execute(const Options& options);

}  // namespace foldlab::cli::stress_command
