// `foldlab stress`: both methods over inputs far wider than real fabrics; exit 1 on any NaN, inf
// or hang.
#include <charconv>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/commands.hpp"
#include "app/common/inputs.hpp"
#include "core/io/export_budget.hpp"
#include "core/tools/stress.hpp"

namespace foldlab::cli {

Command add_stress_command(CLI::App& app) {
  struct Options {
    int samples = 100000;
    std::string seed = "1";
    bool json = false;
    int threads = 0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "stress",
      "numerical stress test: both methods over t 0.01-2 mm, E 1-5000 MPa, w 1e-7-1e-4 N/mm², "
      "h and L 100-5000 mm, d 0-L/2, nu 0-0.49; exit 1 on any NaN, inf or solve > 1 s");
  command->add_option("--samples", options->samples, "input samples (default 100000)")
      ->transform(app::whole_number_in(1, kMaxStressSamples));
  // Read as text: CLI11 turns "-1" and 2^64 into 2^64 - 1 when reading an unsigned number.
  command->add_option("--seed", options->seed, "seed of the samples, 0 to 2^64 - 1 (default 1)");
  command->add_option("--threads", options->threads, "worker threads (default: hardware threads)")
      ->check(CLI::Range(0, 256));
  command->add_flag("--json", options->json, "print one JSON object instead of a table");
  return [options] {
    return guarded([&] {
      StressOptions o;
      o.samples = options->samples;
      const std::string& seed = options->seed;
      const auto [end, error] = std::from_chars(seed.data(), seed.data() + seed.size(), o.seed);
      if (seed.empty() || error != std::errc() || end != seed.data() + seed.size()) {
        throw InputError("--seed " + seed +
                         " must be a whole number from 0 to 18446744073709551615 (2^64 - 1)");
      }
      o.threads = options->threads;
      const StressReport report = run_stress(o);
      if (options->json) {
        std::cout << stress_to_json(report).dump(2) << "\n";
      } else {
        std::cout << stress_table(report);
      }
      return report.passed() ? kExitOk : kExitInternal;
    });
  };
}

}  // namespace foldlab::cli
