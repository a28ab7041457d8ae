#include "app/common/input_options.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::app {

CLI::Validator non_empty_path() {
  return CLI::Validator(
      [](std::string& path) {
        return path.empty() ? std::string("empty path: name a file, or leave the option out")
                            : std::string();
      },
      "FILE", "non-empty path");
}

CLI::Validator whole_number_in(std::int64_t lo, std::int64_t hi) {
  const std::string range =
      "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) {
        // Read as a number, so that 1e3 is 1000, then handed on as digits to the option's type.
        const std::optional<double> value = parse_number(text);
        if (!value || *value != std::floor(*value) || *value < static_cast<double>(lo) ||
            *value > static_cast<double>(hi)) {
          return detail::cut(text) + " must be " + range;
        }
        text = std::to_string(static_cast<std::int64_t>(*value));
        return std::string();
      },
      "N", range);
}

CLI::Validator number_in(double lo, double hi) {
  const std::string range =
      "a number from " + detail::printf_string("%g", lo) + " to " + detail::printf_string("%g", hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) {
        const std::optional<double> value = parse_number(text);
        if (!value || !std::isfinite(*value) || *value < lo || *value > hi) {
          return detail::cut(text) + " must be " + range;
        }
        return std::string();
      },
      "FLOAT in [" + detail::printf_string("%g", lo) + " - " + detail::printf_string("%g", hi) +
          "]",
      range);
}

CLI::Validator input_choice(std::string_view key) {
  const InputSpec* spec = find_input(key);
  if (spec == nullptr || spec->kind != InputKind::choice) {
    throw std::logic_error("no input with choices: " + std::string(key));
  }
  return CLI::Validator(
      [key = std::string(key)](std::string& text) {
        Parameters scratch;
        return apply_setting(scratch, key, text).value_or(std::string());
      },
      "{" + std::string(spec->choices) + "}", std::string(key));
}

CLI::Validator one_of(std::string name, std::vector<std::string> choices) {
  const std::string listed = detail::join(choices, ", ");
  return CLI::Validator(
      [name, choices, listed](std::string& text) {
        if (std::find(choices.begin(), choices.end(), text) != choices.end()) {
          return std::string();
        }
        return name + " = '" + detail::cut(text) + "' is not one of: " + listed;
      },
      "{" + listed + "}", name);
}

void add_input_options(CLI::App& command, InputOptions& options) {
  command
      .add_option("--preset", options.preset_path,
                  "preset JSON file (default: the built-in presets/default.json, eq. 7 calibrated "
                  "on Conci's Tables 1–2)")
      ->check(non_empty_path());
  std::string keys;
  for (const InputSpec& spec : input_table()) {
    keys += "\n    " + input_label(spec) + ": " + std::string(spec.help);
  }
  command
      .add_option("--set", options.assignments,
                  "override an input, KEY=VALUE; a value may end in a unit written as SI writes "
                  "it (h=1.4m, E=0.165GPa, w=80g/m2; M is mega, not a metre) or gsm in any case; "
                  "a bare number is in the key's unit; keys:" +
                      keys)
      ->type_name("KEY=VALUE");
  command.add_option("--method", options.method, "solution method (default: the preset's)")
      ->check(input_choice("method"));
  add_law_option(command, options.law);
}

void add_law_option(CLI::App& command, std::string& law) {
  command
      .add_option("--law", law,
                  "the law that counts the folds, with its published constants (c, p = 1); "
                  "--set c=, K= or p= override them (default: the preset's law and constants)")
      ->check(input_choice("law"));
}

void add_field_cut_options(CLI::App& command, FieldCutOptions& options) {
  CLI::Option* shape =
      command.add_option("--shape", options.shape,
                         "the cut: " + field::outline_kind_names() +
                             " (default: the preset's own cut when it has one, else its shape)");
  command
      .add_option("--outline", options.outline_path,
                  "a cut of your own: JSON {\"top\": [[x, y], ...], \"bottom\": [[x, y], "
                  "...], \"supports\": [{\"at\": [X, Y], \"to\": [x, y]}, ...]}, mm, y down")
      ->check(non_empty_path())
      ->excludes(shape);
}

}  // namespace foldlab::app
