// `foldlab bench`: run time against error of every method variant, and the pipeline's stages.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/cli/commands.hpp"
#include "app/common/inputs.hpp"
#include "app/common/presets_dir.hpp"
#include "core/io/export_budget.hpp"
#include "core/io/io.hpp"
#include "core/io/preset.hpp"
#include "core/tools/benchmark_cases.hpp"

namespace foldlab::cli {
namespace {

// "AMD EPYC, 2 threads": what the numbers were measured on.
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

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", 100.0 * fraction);
  return text;
}

std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", value);
  return text;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  struct Options {
    bool json = false;
    int cases = 1000;
    int repeats = 5;
    int threads = 0;
    std::string csv_path;
    std::string svg_path;
    bool no_pipeline = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "bench",
      "run time against error of every method variant over a fixed case set (plus Tables 1-2), "
      "and the time of each pipeline stage");
  command->add_flag("--json", options->json, "print one JSON object instead of tables");
  command
      ->add_option("--cases", options->cases,
                   "random realistic fabrics in the set (default 1000; Tables 1-2 are added)")
      ->transform(app::whole_number_in(1, kMaxBenchCases));
  command->add_option("--repeats", options->repeats, "timed solves per case (default 5)")
      ->transform(app::whole_number_in(1, 1000));
  command
      ->add_option("--threads", options->threads,
                   "threads for the parallel grid (default: hardware threads)")
      ->check(CLI::Range(0, 256));
  command->add_option("--csv", options->csv_path, "also write the method table as CSV")
      ->check(app::non_empty_path());
  command->add_option("--svg", options->svg_path, "also write the run-time-against-error plot")
      ->check(app::non_empty_path());
  command->add_flag("--no-pipeline", options->no_pipeline, "skip the fold line and grid timings");
  return [options] {
    return guarded([&] {
      check_distinct_files({{"--csv", options->csv_path}, {"--svg", options->svg_path}}, {});
      if (auto problem = check_count_budget(
              "--cases x --repeats", static_cast<std::int64_t>(options->cases) * options->repeats,
              kMaxBenchSolves)) {
        throw InputError(*problem);
      }
      std::vector<BenchmarkCase> cases = realistic_cases(options->cases);
      int table_rows = 0;
      if (const std::filesystem::path dir = find_presets_dir(); !dir.empty()) {
        for (const std::filesystem::path& file : preset_files(dir)) {
          if (file.filename().string().rfind("paper-table", 0) == 0) {
            const Preset preset = load_preset(file);
            cases.push_back({preset.name, preset.parameters});
            ++table_rows;
          }
        }
      }
      std::vector<ReferenceSolution> references;
      std::vector<Parameters> inputs;
      for (const BenchmarkCase& c : cases) {
        references.push_back(reference_solution(c.parameters));
        inputs.push_back(c.parameters);
      }

      std::vector<BenchmarkRow> rows;
      std::vector<std::vector<Parameters>> variants;
      std::vector<Solution> exact_solutions;
      for (const BenchmarkMethod& method : benchmark_methods()) {
        std::vector<Parameters> variant;
        std::vector<Solution> solutions;
        for (const Parameters& p : inputs) {
          variant.push_back(with_method(p, method));
          solutions.push_back(solve(variant.back()));
        }
        BenchmarkRow row;
        row.method = method;
        row.accuracy = method_accuracy(solutions, references);
        rows.push_back(row);
        variants.push_back(std::move(variant));
        if (method.method == Method::exact) {
          exact_solutions = std::move(solutions);
        }
      }
      const std::vector<TimingSummary> timings = time_methods(variants, options->repeats);
      for (std::size_t m = 0; m < rows.size(); ++m) {
        rows[m].timing = timings[m];
      }
      mark_pareto_front(rows);
      const ReferenceCheck check = check_references(exact_solutions, references);

      std::vector<PipelineTiming> pipeline;
      Solution pipeline_solution;
      const int threads = options->threads > 0
                              ? options->threads
                              : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
      const Preset& preset = default_preset();
      if (!options->no_pipeline) {
        Parameters p = preset.parameters;
        p.model.method = Method::exact;
        pipeline_solution = solve(p);
        pipeline = time_pipeline(pipeline_solution, p, {64, 256, 1024}, 5, threads);
      }

      const std::string machine = machine_description();
      const std::string subtitle =
          std::to_string(cases.size()) + " cases (" + std::to_string(options->cases) +
          " random realistic + " + std::to_string(table_rows) + " rows of Tables 1-2), " +
          std::to_string(options->repeats) + " timed solves each; " + machine;
      if (!options->csv_path.empty()) {
        write_file_atomically(options->csv_path, benchmark_csv(rows));
      }
      if (!options->svg_path.empty()) {
        write_file_atomically(options->svg_path, benchmark_svg(rows, subtitle));
      }

      if (options->json) {
        nlohmann::json methods = nlohmann::json::array();
        for (const BenchmarkRow& r : rows) {
          const MethodAccuracy& a = r.accuracy;
          methods.push_back({{"method", r.method.name},
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
                             {"pareto", r.pareto}});
        }
        nlohmann::json stages = nlohmann::json::array();
        for (const PipelineTiming& t : pipeline) {
          stages.push_back({{"grid_size", t.grid_size},
                            {"fold_lines_ms", t.fold_lines_ms},
                            {"grid_serial_ms", t.grid_serial_ms},
                            {"normals_serial_ms", t.normals_serial_ms},
                            {"grid_parallel_ms", t.grid_parallel_ms},
                            {"threads", t.threads}});
        }
        const nlohmann::json out = {
            {"machine", machine},
            {"cases", cases.size()},
            {"random_cases", options->cases},
            {"table_rows", table_rows},
            {"repeats", options->repeats},
            {"reference",
             {{"cases_with_folds", check.cases},
              {"max_exact_Q_difference", check.max_Q_difference},
              {"max_exact_z_difference", check.max_z_difference},
              {"max_exact_an_difference", check.max_an_difference},
              {"max_reference_residual", check.max_reference_residual},
              {"n_not_fixed_point", check.n_not_fixed_point}}},
            {"methods", methods},
            {"pipeline", {{"case", preset.name}, {"n", pipeline_solution.n}, {"stages", stages}}}};
        std::cout << out.dump(2) << "\n";
        return kExitOk;
      }

      std::cout << "FoldLab bench: " << subtitle << "\n\n";
      std::printf(
          "Reference: the exact method's n; a_n, z_max and Q re-solved for it in long double "
          "(eq. 8 by a\n2048-point periodic trapezoid rule, eq. 9 term by term). Over %d cases "
          "with folds the double\nexact method differs from it by at most %.1e (z_max), %.1e "
          "(Q), %.1e (a_n); the references'\nown residuals are below %.1e; eq. 10 gives back n "
          "in all but %d wrinkled cases.\n\n",
          check.cases, check.max_z_difference, check.max_Q_difference, check.max_an_difference,
          check.max_reference_residual, check.n_not_fixed_point);
      std::cout
          << "| method | median ns/solve | p10 ns | p90 ns | mean ns | n exact % | max abs dn "
             "| Q err median | Q err max | z_max err median | z_max err max | Pareto |\n"
             "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
      for (const BenchmarkRow& r : rows) {
        const MethodAccuracy& a = r.accuracy;
        std::printf("| %s | %.0f | %.0f | %.0f | %.0f | %s | %d | %s | %s | %s | %s | %s |\n",
                    r.method.name.c_str(), r.timing.median_ns, r.timing.p10_ns, r.timing.p90_ns,
                    r.timing.mean_ns,
                    percent(a.cases ? static_cast<double>(a.n_exact) / a.cases : 0.0).c_str(),
                    a.max_abs_n_error, scientific(a.median_Q_error).c_str(),
                    scientific(a.max_Q_error).c_str(), scientific(a.median_z_error).c_str(),
                    scientific(a.max_z_error).c_str(), r.pareto ? "yes" : "");
      }
      if (!pipeline.empty()) {
        std::printf(
            "\nPipeline, exact solution of \"%s\" (n = %d), median of 5 runs, ms:\n\n"
            "| grid | fold lines (201 points) | grid + normals, 1 thread | of which normals | "
            "grid + normals, %d threads |\n|---|---|---|---|---|\n",
            detail::escaped(preset.name).c_str(), pipeline_solution.n, threads);
        for (const PipelineTiming& t : pipeline) {
          std::printf("| %d² | %.3f | %.3f | %.3f | %.3f |\n", t.grid_size, t.fold_lines_ms,
                      t.grid_serial_ms, t.normals_serial_ms, t.grid_parallel_ms);
        }
      }
      return kExitOk;
    });
  };
}

}  // namespace foldlab::cli
