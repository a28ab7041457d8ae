#include "app/cli/stress.hpp"

#include <charconv>
#include <iostream>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/io/export_budget.hpp"

namespace foldlab::cli {
namespace stress_command {
namespace {

std::uint64_t parse_seed(const std::string& seed) {
  std::uint64_t out = 0;
  const auto [end, error] = std::from_chars(seed.data(), seed.data() + seed.size(), out);
  if (seed.empty() || error != std::errc() || end != seed.data() + seed.size()) {
    throw InputError("--seed " + seed +
                     " must be a whole number from 0 to 18446744073709551615 (2^64 - 1)");
  }
  return out;
}

}  // namespace

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand("stress", "numerical stress test: both methods over " +
                                                       stress_sampled_ranges() +
                                                       "; exit 1 on any NaN, inf or solve > 1 s");
  command->add_option("--samples", options.samples, "input samples (default 100000)")
      ->transform(app::whole_number_in(1, kMaxStressSamples));
  command->add_option("--seed", options.seed, "seed of the samples, 0 to 2^64 - 1 (default 1)");
  command->add_option("--threads", options.threads, "worker threads (default: hardware threads)")
      ->check(CLI::Range(0, 256));
  command->add_flag("--json", options.json, "print one JSON object instead of a table");
}

StressReport run(const Options& options) {
  return run_stress(
      {.samples = options.samples, .seed = parse_seed(options.seed), .threads = options.threads});
}

void print_text(const StressReport& report, std::ostream& out) {
  out << stress_table(report);
}

nlohmann::json print_json(const StressReport& report) {
  return stress_to_json(report);
}

int execute(const Options& options) {
  const StressReport report = run(options);
  if (options.json) {
    write_json(print_json(report), std::cout);
  } else {
    print_text(report, std::cout);
  }
  return report.passed() ? kExitOk : kExitInternal;
}

}  // namespace stress_command

Command add_stress_command(CLI::App& app) {
  return make_command(app, stress_command::declare, stress_command::execute);
}

}  // namespace foldlab::cli
