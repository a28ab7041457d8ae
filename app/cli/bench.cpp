#include "app/cli/bench.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/io/export_budget.hpp"
#include "core/io/io.hpp"
#include "core/io/preset.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {
namespace bench_command {
namespace {

using detail::printf_string;
using nlohmann::json;

std::string machine_description() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string model = "unknown CPU";
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

// Tables 1-2 from the presets folder, when there is one: cases whose n is known.
std::vector<BenchmarkCase> paper_table_cases() {
  std::vector<BenchmarkCase> out;
  if (const std::filesystem::path dir = find_presets_dir(); !dir.empty()) {
    const FolderPresets folder = readable_presets(dir);
    write_notes(folder.skipped, std::cerr);
    for (std::size_t i = 0; i < folder.files.size(); ++i) {
      if (folder.files[i].filename().string().rfind("paper-table", 0) == 0) {
        out.push_back({folder.presets[i].name, folder.presets[i].parameters});
      }
    }
  }
  return out;
}

// Every method variant on every case: accuracy against the long-double references and the timed
// solves; `reference` says how far the exact method lands from the references.
std::vector<BenchmarkRow> method_rows(const std::vector<BenchmarkCase>& cases, int repeats,
                                      ReferenceCheck& reference) {
  std::vector<ReferenceSolution> references;
  for (const BenchmarkCase& c : cases) {
    references.push_back(reference_solution(c.parameters));
  }
  std::vector<BenchmarkRow> rows;
  std::vector<std::vector<Parameters>> variants;
  for (const BenchmarkMethod& method : benchmark_methods()) {
    std::vector<Parameters> variant;
    std::vector<Solution> solutions;
    for (const BenchmarkCase& c : cases) {
      variant.push_back(with_method(c.parameters, method));
      solutions.push_back(solve(variant.back()));
    }
    BenchmarkRow& row = rows.emplace_back();
    row.method = method;
    row.accuracy = method_accuracy(solutions, references);
    variants.push_back(std::move(variant));
    if (method.method == Method::exact) {
      reference = check_references(solutions, references);
    }
  }
  const std::vector<TimingSummary> timings = time_methods(variants, repeats);
  for (std::size_t m = 0; m < rows.size(); ++m) {
    rows[m].timing = timings[m];
  }
  mark_pareto_front(rows);
  return rows;
}

void time_pipeline_stages(const Options& options, Result& result) {
  const Preset& preset = default_preset();
  result.pipeline_case = preset.name;
  result.threads = options.threads > 0
                       ? options.threads
                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (options.no_pipeline) {
    return;
  }
  Parameters p = preset.parameters;
  p.model.method = Method::exact;
  const Solution solution = solve(p);
  result.pipeline_n = solution.n;
  result.pipeline = time_pipeline(solution, p, {64, 256, 1024}, 5, result.threads);
}

std::string percent(double fraction) {
  return printf_string("%.1f", 100.0 * fraction);
}

std::string scientific(double value) {
  return printf_string("%.2g", value);
}

void print_reference(const ReferenceCheck& check, std::ostream& out) {
  out << printf_string(
      "Reference: the exact method's n; a_n, z_max and Q re-solved for it in long double "
      "(eq. 8 by a\n2048-point periodic trapezoid rule, eq. 9 term by term). Over %d cases "
      "with folds the double\nexact method differs from it by at most %.1e (z_max), %.1e "
      "(Q), %.1e (a_n); the references'\nown residuals are below %.1e; eq. 10 gives back n "
      "in all but %d wrinkled cases.\n\n",
      check.cases, check.max_z_difference, check.max_Q_difference, check.max_an_difference,
      check.max_reference_residual, check.n_not_fixed_point);
}

void print_methods_table(const std::vector<BenchmarkRow>& rows, std::ostream& out) {
  out << "| method | median ns/solve | p10 ns | p90 ns | mean ns | n exact % | max abs dn "
         "| Q err median | Q err max | z_max err median | z_max err max | Pareto |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchmarkRow& r : rows) {
    const MethodAccuracy& a = r.accuracy;
    out << printf_string("| %s | %.0f | %.0f | %.0f | %.0f | %s | %d | %s | %s | %s | %s | %s |\n",
                         r.method.name.c_str(), r.timing.median_ns, r.timing.p10_ns,
                         r.timing.p90_ns, r.timing.mean_ns,
                         percent(a.cases ? static_cast<double>(a.n_exact) / a.cases : 0.0).c_str(),
                         a.max_abs_n_error, scientific(a.median_Q_error).c_str(),
                         scientific(a.max_Q_error).c_str(), scientific(a.median_z_error).c_str(),
                         scientific(a.max_z_error).c_str(), r.pareto ? "yes" : "");
  }
}

void print_pipeline_table(const Result& result, std::ostream& out) {
  out << printf_string(
      "\nPipeline, exact solution of \"%s\" (n = %d), median of 5 runs, ms:\n\n"
      "| grid | fold lines (201 points) | grid + normals, 1 thread | of which normals | "
      "grid + normals, %d threads |\n|---|---|---|---|---|\n",
      detail::escaped(result.pipeline_case).c_str(), result.pipeline_n, result.threads);
  for (const PipelineTiming& t : result.pipeline) {
    out << printf_string("| %d² | %.3f | %.3f | %.3f | %.3f |\n", t.grid_size, t.fold_lines_ms,
                         t.grid_serial_ms, t.normals_serial_ms, t.grid_parallel_ms);
  }
}

json method_json(const BenchmarkRow& r) {
  const MethodAccuracy& a = r.accuracy;
  return {{"method", r.method.name},
          {"median_ns", r.timing.median_ns},
          {"p10_ns", r.timing.p10_ns},
          {"p90_ns", r.timing.p90_ns},
          {"mean_ns", r.timing.mean_ns},
          {"cases", a.cases},
          {"n_exact", a.n_exact},
          {"max_abs_n_error", a.max_abs_n_error},
          {"median_Q_error", a.median_Q_error},
          {"max_Q_error", a.max_Q_error},
          {"median_z_error", a.median_z_error},
          {"max_z_error", a.max_z_error},
          {"pareto", r.pareto}};
}

json stage_json(const PipelineTiming& t) {
  return {{"grid_size", t.grid_size},
          {"fold_lines_ms", t.fold_lines_ms},
          {"grid_serial_ms", t.grid_serial_ms},
          {"normals_serial_ms", t.normals_serial_ms},
          {"grid_parallel_ms", t.grid_parallel_ms},
          {"threads", t.threads}};
}

json reference_json(const ReferenceCheck& check) {
  return {{"cases_with_folds", check.cases},
          {"max_exact_Q_difference", check.max_Q_difference},
          {"max_exact_z_difference", check.max_z_difference},
          {"max_exact_an_difference", check.max_an_difference},
          {"max_reference_residual", check.max_reference_residual},
          {"n_not_fixed_point", check.n_not_fixed_point}};
}

}  // namespace

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand(
      "bench",
      "run time against error of every method variant over a fixed case set (plus Tables 1-2), "
      "and the time of each pipeline stage");
  command->add_flag("--json", options.json, "print one JSON object instead of tables");
  command
      ->add_option("--cases", options.cases,
                   "random realistic fabrics in the set (default 1000; Tables 1-2 are added)")
      ->transform(app::whole_number_in(1, kMaxBenchCases));
  command->add_option("--repeats", options.repeats, "timed solves per case (default 5)")
      ->transform(app::whole_number_in(1, 1000));
  command
      ->add_option("--threads", options.threads,
                   "threads for the parallel grid (default: hardware threads)")
      ->check(CLI::Range(0, 256));
  command->add_option("--csv", options.csv_path, "also write the method table as CSV")
      ->check(app::non_empty_path());
  command->add_option("--svg", options.svg_path, "also write the run-time-against-error plot")
      ->check(app::non_empty_path());
  command->add_flag("--no-pipeline", options.no_pipeline, "skip the fold line and grid timings");
}

Result run(const Options& options) {
  check_outputs({{"--csv", options.csv_path}, {"--svg", options.svg_path}}, {});
  app::check_output_extension("--csv", options.csv_path, ".csv", "CSV");
  app::check_output_extension("--svg", options.svg_path, ".svg", "SVG");
  if (auto problem = check_count_budget("--cases x --repeats",
                                        static_cast<std::int64_t>(options.cases) * options.repeats,
                                        kMaxBenchSolves)) {
    throw InputError(*problem);
  }
  std::vector<BenchmarkCase> cases = realistic_cases(options.cases);
  const std::vector<BenchmarkCase> tables = paper_table_cases();
  cases.insert(cases.end(), tables.begin(), tables.end());
  Result result;
  result.machine = machine_description();
  result.cases = cases.size();
  result.random_cases = options.cases;
  result.table_rows = static_cast<int>(tables.size());
  result.repeats = options.repeats;
  result.rows = method_rows(cases, options.repeats, result.reference);
  time_pipeline_stages(options, result);
  result.subtitle = std::to_string(result.cases) + " cases (" + std::to_string(options.cases) +
                    " random realistic + " + std::to_string(result.table_rows) +
                    " rows of Tables 1-2), " + std::to_string(options.repeats) +
                    " timed solves each; " + result.machine;
  return result;
}

void write_files(const Options& options, const Result& result) {
  if (!options.csv_path.empty()) {
    write_file_atomically(options.csv_path, benchmark_csv(result.rows));
  }
  if (!options.svg_path.empty()) {
    write_file_atomically(options.svg_path, benchmark_svg(result.rows, result.subtitle));
  }
}

void print_markdown(const Result& result, std::ostream& out) {
  out << "FoldLab bench: " << result.subtitle << "\n\n";
  print_reference(result.reference, out);
  print_methods_table(result.rows, out);
  if (!result.pipeline.empty()) {
    print_pipeline_table(result, out);
  }
}

json print_json(const Result& result) {
  json methods = json::array();
  for (const BenchmarkRow& r : result.rows) {
    methods.push_back(method_json(r));
  }
  json stages = json::array();
  for (const PipelineTiming& t : result.pipeline) {
    stages.push_back(stage_json(t));
  }
  return {
      {"machine", result.machine},
      {"cases", result.cases},
      {"random_cases", result.random_cases},
      {"table_rows", result.table_rows},
      {"repeats", result.repeats},
      {"reference", reference_json(result.reference)},
      {"methods", methods},
      {"pipeline", {{"case", result.pipeline_case}, {"n", result.pipeline_n}, {"stages", stages}}}};
}

int execute(const Options& options) {
  const Result result = run(options);
  write_files(options, result);
  print_result(result, options.json, &print_markdown);
  return kExitOk;
}

}  // namespace bench_command

Command add_bench_command(CLI::App& app) {
  return make_command(app, bench_command::declare, bench_command::execute);
}

}  // namespace foldlab::cli
