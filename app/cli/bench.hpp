// `foldlab bench`: run time against error of every method variant over a fixed case set, and the
// time of each pipeline stage. run() measures; the command's glue writes --csv and --svg.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/tools/benchmark_cases.hpp"

namespace foldlab::cli::bench_command {

struct Options {
  bool json = false;
  int cases = 1000;  // random realistic fabrics; the rows of Tables 1-2 are added
  int repeats = 5;
  int threads = 0;  // the parallel grid's; 0: hardware threads
  std::string csv_path;
  std::string svg_path;
  bool no_pipeline = false;
};

struct Result {
  std::string machine;   // "AMD EPYC, 2 hardware threads": what the numbers were measured on
  std::string subtitle;  // the case set, the repeats and the machine, in one line
  std::size_t cases = 0;
  int random_cases = 0;
  int table_rows = 0;
  int repeats = 0;
  std::vector<BenchmarkRow> rows;  // one per method variant
  ReferenceCheck reference;
  // The pipeline's stages on the default preset's exact solution (empty with --no-pipeline).
  std::string pipeline_case;
  int pipeline_n = 0;
  int threads = 1;
  std::vector<PipelineTiming> pipeline;
};

void declare(CLI::App& app, Options& options);
// Throws app::InputError for --csv and --svg on one file and cases x repeats over the budget.
Result run(const Options& options);
void write_files(const Options& options, const Result& result);
void print_markdown(const Result& result, std::ostream& out);
nlohmann::json print_json(const Result& result);

// The command after parsing: run, write what the command writes, print; the exit status.
int execute(const Options& options);

}  // namespace foldlab::cli::bench_command
