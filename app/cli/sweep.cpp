#include <cstdio>
#include <iostream>
#include <memory>

#include "app/cli/commands.hpp"
#include "app/common/inputs.hpp"
#include "core/analysis/sweep.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {

Command add_sweep_command(CLI::App& app) {
  struct Options {
    InputOptions inputs;
    SweepAxis axis;
    bool csv = false;
    bool log = false;
    bool linear = false;
  };
  auto options = std::make_shared<Options>();
  options->axis.steps = 50;
  CLI::App* command = app.add_subcommand(
      "sweep", "solve over a range of one input and print n, Q and z_max for each value");
  add_input_options(*command, options->inputs);
  command->add_option("--param", options->axis.key, "the input to sweep: t, E, w, h, L, d, K, nu")
      ->required();
  command->add_option("--from", options->axis.from, "first value (its unit: mm, MPa, N/mm²)")
      ->required();
  command->add_option("--to", options->axis.to, "last value")->required();
  command->add_option("--steps", options->axis.steps, "number of values (default 50)");
  command->add_flag("--log", options->log, "logarithmic spacing (default for t, E, w, K)");
  command->add_flag("--linear", options->linear, "linear spacing (default for h, L, d, nu)");
  command->add_flag("--csv", options->csv, "CSV instead of a table");
  return [options] {
    return guarded([&] {
      SweepAxis axis = options->axis;
      if (options->log && options->linear) {
        throw InputError("--log and --linear exclude each other");
      }
      axis.logarithmic = options->log || (!options->linear && natural_log_scale(axis.key));
      if (auto problem = check_axis(axis)) {
        throw InputError(*problem);
      }
      const Preset preset = resolve_inputs(options->inputs);
      const std::vector<SweepPoint> points = sweep(preset.parameters, axis);
      // Checked before the first row goes out, so that a bad row never leaves half a table.
      for (const SweepPoint& p : points) {
        detail::finite_or_throw(p.value, axis.key);
        detail::finite_or_throw(p.Q, "Q");
        detail::finite_or_throw(p.z_max_mm, "z_max_mm");
      }
      // A range may run past what the other inputs allow (d up to L/2, say): those rows say
      // "invalid" and the reason is given once; a range with no valid value is an input error.
      int refused = 0;
      std::string first_reason;
      for (const SweepPoint& p : points) {
        if (!p.valid) {
          if (refused++ == 0) {
            Parameters at = preset.parameters;
            set_number(at, axis.key, p.value);
            const std::vector<ValidationIssue> issues = validate(at);
            first_reason = axis.key + " = " + detail::shortest_number(p.value) + ": " +
                           (issues.empty() ? std::string("refused") : issues.front().message);
          }
        }
      }
      if (refused == static_cast<int>(points.size())) {
        throw InputError("no value of the range is valid given the other inputs; at " +
                         first_reason);
      }
      if (options->csv) {
        std::printf("%s,n,Q,z_max_mm,regime,n_capped\n", axis.key.c_str());
      } else {
        std::printf("%14s %6s %10s %12s  %s\n", axis.key.c_str(), "n", "Q", "z_max (mm)", "regime");
      }
      int capped = 0;
      for (const SweepPoint& p : points) {
        // A refused value has no solution: empty fields, so that a spreadsheet plots no zeros.
        if (!p.valid) {
          if (options->csv) {
            std::printf("%.9g,,,,invalid,\n", p.value);
          } else {
            std::printf("%14.6g %6s %10s %12s  invalid\n", p.value, "-", "-", "-");
          }
          continue;
        }
        const std::string regime(to_string(p.regime));
        capped += p.n_capped ? 1 : 0;
        if (options->csv) {
          std::printf("%.9g,%d,%.9g,%.9g,%s,%d\n", p.value, p.n, p.Q, p.z_max_mm, regime.c_str(),
                      p.n_capped ? 1 : 0);
        } else {
          // A capped n is the cap, not a count: "10000+" and the regime says so.
          const std::string n = std::to_string(p.n) + (p.n_capped ? "+" : "");
          std::printf("%14.6g %6s %10.4f %12.2f  %s%s\n", p.value, n.c_str(), p.Q, p.z_max_mm,
                      regime.c_str(), p.n_capped ? ", n capped" : "");
        }
      }
      if (capped > 0) {
        std::cerr << "foldlab: at " << capped << " of " << points.size()
                  << " values eq. 10 asks for more than " << kMaxWrinkles
                  << " folds; n is capped there (n_capped)\n";
      }
      if (refused > 0) {
        std::cerr << "foldlab: " << refused << " of " << points.size()
                  << " values are refused given the other inputs (their rows say invalid); at "
                  << first_reason << "\n";
      }
      return kExitOk;
    });
  };
}

}  // namespace foldlab::cli
