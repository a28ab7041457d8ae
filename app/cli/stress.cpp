#include "app/cli/stress.hpp"

#include <algorithm>
#include <charconv>
#include <iostream>
#include <optional>
#include <string_view>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/io/export_budget.hpp"

namespace foldlab::cli {
namespace stress_command {
namespace {

// The whole number "DIGITS[.DIGITS]e[+]DIGITS" names (1e19, 1.5e3), read exactly: a double
// holds no 64-bit number past 2^53. nullopt when it names a fraction or more than 2^64 - 1.
std::optional<std::uint64_t> whole_with_exponent(std::string_view text) {
  const std::size_t e = text.find_first_of("eE");
  if (e == std::string_view::npos || e == 0) {
    return std::nullopt;
  }
  std::string_view mantissa = text.substr(0, e);
  std::string_view exponent = text.substr(e + 1);
  if (exponent.starts_with('+')) {
    exponent.remove_prefix(1);
  }
  int power = 0;
  const auto [exponent_end, exponent_error] =
      std::from_chars(exponent.data(), exponent.data() + exponent.size(), power);
  if (exponent.empty() || exponent_error != std::errc() ||
      exponent_end != exponent.data() + exponent.size()) {
    return std::nullopt;
  }
  std::string digits;
  const std::size_t point = mantissa.find('.');
  digits += mantissa.substr(0, point);
  if (point != std::string_view::npos) {
    const std::string_view fraction = mantissa.substr(point + 1);
    digits += fraction;
    power -= static_cast<int>(fraction.size());
  }
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) {
    return std::nullopt;
  }
  for (; power < 0; ++power) {  // 1.50e3: the fraction's digits must end in as many zeros
    if (digits.back() != '0') {
      return std::nullopt;
    }
    digits.pop_back();
  }
  std::uint64_t out = 0;
  for (const char c : digits) {
    if (__builtin_mul_overflow(out, 10u, &out) ||
        __builtin_add_overflow(out, static_cast<unsigned>(c - '0'), &out)) {
      return std::nullopt;
    }
  }
  for (; power > 0; --power) {
    if (__builtin_mul_overflow(out, 10u, &out)) {
      return std::nullopt;
    }
  }
  return out;
}

std::uint64_t parse_seed(const std::string& seed) {
  std::uint64_t out = 0;
  const auto [end, error] = std::from_chars(seed.data(), seed.data() + seed.size(), out);
  if (!seed.empty() && error == std::errc() && end == seed.data() + seed.size()) {
    return out;
  }
  if (const std::optional<std::uint64_t> named = whole_with_exponent(seed)) {
    return *named;
  }
  throw InputError("--seed " + detail::cut(seed) +
                   " must be a whole number from 0 to 18446744073709551615 (2^64 - 1), in digits "
                   "or with an exponent (1e19)");
}

}  // namespace

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand(
      "stress", "numerical stress test: both methods over " + stress_sampled_ranges() +
                    "; exit 1 on any NaN, inf or solve > 1 s. --solver field: the tension "
                    "field's cold solves over the same inputs, every outline, the live and "
                    "refined meshes; exit 1 also on a false \"converged\" or a converged field "
                    "whose reactions miss its weight");
  command
      ->add_option("--solver", options.solver,
                   "closed-form (default: both methods of the closed form) or field")
      ->check(app::one_of("solver", {"closed-form", "field"}));
  command
      ->add_option("--samples", options.samples,
                   "input samples (default 100000; field: 280, at most 10000)")
      ->transform(app::whole_number_in(1, kMaxStressSamples))
      ->each([&options](const std::string&) { options.samples_given = true; });
  command
      ->add_option("--index", options.index,
                   "field: start at sample I (alone unless --samples): a case of a run again")
      ->transform(app::whole_number_in(0, 2'000'000'000));
  command->add_option("--seed", options.seed, "seed of the samples, 0 to 2^64 - 1 (default 1)");
  command->add_option("--threads", options.threads, "worker threads (default: hardware threads)")
      ->check(CLI::Range(0, 256));
  command
      ->add_option("--hang-margin", options.hang_margin_s,
                   "field: seconds past its 10 s budget after which a solve counts as a hang "
                   "(default 1; the budget is checked between Newton steps, so this is the "
                   "longest a step may take: more under a sanitizer or a loaded machine)")
      ->check(app::number_in(0.0, 3600.0));
  command->add_flag("--json", options.json, "print one JSON object instead of a table");
}

StressReport run(const Options& options) {
  return run_stress(
      {.samples = options.samples, .seed = parse_seed(options.seed), .threads = options.threads});
}

FieldStressReport run_field(const Options& options) {
  FieldStressOptions o;
  o.seed = parse_seed(options.seed);
  o.threads = options.threads;
  o.hang_margin_s = options.hang_margin_s;
  o.first_index = std::max(0, options.index);
  o.samples = options.samples_given ? options.samples : options.index >= 0 ? 1 : o.samples;
  if (const auto refused = check_count_budget("--samples", o.samples, kMaxFieldStressSamples)) {
    throw InputError(*refused + " (field samples take up to a few seconds each)");
  }
  if (static_cast<std::int64_t>(o.first_index) + o.samples > 2'000'000'000) {
    throw InputError("--index + --samples must stay below 2000000000");
  }
  return run_field_stress(o);
}

void print_text(const StressReport& report, std::ostream& out) {
  out << stress_table(report);
}

nlohmann::json print_json(const StressReport& report) {
  return stress_to_json(report);
}

int execute(const Options& options) {
  if (options.solver == "field") {
    const FieldStressReport report = run_field(options);
    if (options.json) {
      write_json(field_stress_to_json(report), std::cout);
    } else {
      std::cout << field_stress_table(report);
    }
    return report.passed() ? kExitOk : kExitInternal;
  }
  if (options.index >= 0) {
    throw InputError("--index picks a sample of --solver field");
  }
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
