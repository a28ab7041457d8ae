#include "app/cli/sweep.hpp"

#include <iostream>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/io/export_budget.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {
namespace sweep_command {
namespace {

using detail::printf_string;

// "d = 700: d_mm = 700 must be in [0, 700): ...": why the other inputs refuse `value`.
std::string refusal(const Parameters& base, const std::string& key, double value) {
  Parameters at = base;
  set_number(at, key, value);
  const std::vector<ValidationIssue> issues = validate(at);
  return key + " = " + detail::shortest_number(value) + ": " +
         (issues.empty() ? std::string("refused") : issues.front().message);
}

std::vector<std::string> notes(const Result& result) {
  std::vector<std::string> out;
  const std::string values = std::to_string(result.points.size());
  if (result.capped > 0) {
    out.push_back("at " + std::to_string(result.capped) + " of " + values +
                  " values eq. 10 asks for more than " + std::to_string(kMaxWrinkles) +
                  " folds; n is capped there (n_capped)");
  }
  if (result.refused > 0) {
    out.push_back(std::to_string(result.refused) + " of " + values +
                  " values are refused given the other inputs (their rows say invalid); at " +
                  result.first_reason);
  }
  return out;
}

}  // namespace

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand(
      "sweep", "solve over a range of one input and print n, Q and z_max for each value");
  add_input_options(*command, options.inputs);
  command
      ->add_option("--param", options.axis.key,
                   "the input to sweep: " + detail::join_comma(sweepable_keys()))
      ->required();
  command
      ->add_option("--from", options.axis.from,
                   "first value, in the input's unit or with a unit as --set takes it (w=150gsm: "
                   "--from 150gsm)")
      ->required();
  command->add_option("--to", options.axis.to, "last value, as --from")->required();
  command->add_option("--steps", options.axis.steps, "number of values (default 50)")
      ->transform(app::whole_number_in(2, kMaxSweepSteps));
  command->add_flag("--log", options.axis.log,
                    "logarithmic spacing (default for " + sweepable_keys_on_scale(true) + ")");
  command->add_flag("--linear", options.axis.linear,
                    "linear spacing (default for " + sweepable_keys_on_scale(false) + ")");
  command->add_flag("--csv", options.csv, "CSV instead of a table");
}

Result run(const Options& options) {
  Result result;
  result.axis = app::read_sweep_axis(options.axis);
  const Preset preset = app::resolve_inputs_in_full(options.inputs, &result.axis).preset;
  result.points = sweep(preset.parameters, result.axis);
  // Checked before the first row goes out, so that a bad row never leaves half a table.
  for (const SweepPoint& p : result.points) {
    detail::finite_or_throw(p.value, result.axis.key);
    detail::finite_or_throw(p.Q, "Q");
    detail::finite_or_throw(p.z_max_mm, "z_max_mm");
  }
  // A range may run past what the other inputs allow (d up to L/2, say): those rows say
  // "invalid" and the reason is given once (resolve_inputs_in_full refused a range with none).
  for (const SweepPoint& p : result.points) {
    if (!p.valid && result.refused++ == 0) {
      result.first_reason = refusal(preset.parameters, result.axis.key, p.value);
    }
    result.capped += p.valid && p.n_capped ? 1 : 0;
  }
  result.notes = notes(result);
  return result;
}

void print_text(const Result& result, std::ostream& out) {
  out << printf_string("%14s %6s %10s %12s  %s\n", result.axis.key.c_str(), "n", "Q", "z_max (mm)",
                       "regime");
  for (const SweepPoint& p : result.points) {
    if (!p.valid) {
      out << printf_string("%14.6g %6s %10s %12s  invalid\n", p.value, "-", "-", "-");
      continue;
    }
    // A capped n is the cap, not a count: "10000+" and the regime says so.
    const std::string n = std::to_string(p.n) + (p.n_capped ? "+" : "");
    out << printf_string("%14.6g %6s %10.4f %12.2f  %s%s\n", p.value, n.c_str(), p.Q, p.z_max_mm,
                         std::string(to_string(p.regime)).c_str(), p.n_capped ? ", n capped" : "");
  }
}

void print_csv(const Result& result, std::ostream& out) {
  out << result.axis.key << ",n,Q,z_max_mm,regime,n_capped\n";
  for (const SweepPoint& p : result.points) {
    // A refused value has no solution: empty fields, so that a spreadsheet plots no zeros.
    if (!p.valid) {
      out << printf_string("%.9g,,,,invalid,\n", p.value);
      continue;
    }
    out << printf_string("%.9g,%d,%.9g,%.9g,%s,%d\n", p.value, p.n, p.Q, p.z_max_mm,
                         std::string(to_string(p.regime)).c_str(), p.n_capped ? 1 : 0);
  }
}

int execute(const Options& options) {
  const Result result = run(options);
  if (options.csv) {
    print_csv(result, std::cout);
  } else {
    print_text(result, std::cout);
  }
  write_notes(result.notes, std::cerr);
  return kExitOk;
}

}  // namespace sweep_command

Command add_sweep_command(CLI::App& app) {
  return make_command(app, sweep_command::declare, sweep_command::execute);
}

}  // namespace foldlab::cli
