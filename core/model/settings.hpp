// The one table of inputs. Every front end reads an input from here: `--set KEY=VALUE`, presets,
// measurements files, reports, sweeps, the stress test's sampling ranges, the validation of
// physical ranges and the explorer's sliders. Adding an input is one row in settings.cpp plus its
// physics (a field in Parameters and the code that uses it).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/parameters.hpp"

namespace foldlab {

enum class InputKind {
  number,        // a real number in a field of Parameters
  whole_number,  // an int field
  stiffness_K,   // K = c / (1 - nu²): derived, sets c at the Poisson ratio in force
  choice,        // one of a few names (method, span rule, ...)
};

enum class InputScale { linear, logarithmic };

// An interval with open or closed ends.
struct InputInterval {
  double lo = 0.0;
  double hi = 0.0;
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const;
  // "[0.001, 50]" or "[0, 0.5)": for messages.
  std::string text() const;
};

struct InputSpec {
  std::string_view key{};     // as typed after --set, and the sweep axis: "t", "E", ...
  std::string_view name{};    // what it is, for labels and help: "thickness"
  std::string_view unit{};    // "mm", "MPa", ...; empty when dimensionless
  std::string_view field{};   // validation and report name, with the unit: "t_mm"
  std::string_view preset{};  // JSON pointer in a preset file: "/fabric/thickness_mm"; empty: none
  std::string_view help{};    // one line for help texts and tooltips
  InputKind kind = InputKind::number;
  // Values that can describe a cloth; outside them validate() refuses, saying `why`.
  InputInterval valid{};
  std::string_view why{};
  // Where values of real fabrics lie: the slider's ends and the stress test's sampling range.
  double typical_lo = 0.0;
  double typical_hi = 0.0;
  InputScale scale = InputScale::linear;
  std::string_view format{};                 // printf format of the value alone, e.g. "%.3g"
  bool required = false;                     // must appear in a preset
  bool expert = false;                       // a model setting rather than a property of the cloth
  std::string_view choices{};                // for InputKind::choice: "paper, exact"
  double& (*number)(Parameters&) = nullptr;  // for number
  int& (*whole_number)(Parameters&) = nullptr;                  // for whole_number
  bool (*set_choice)(Parameters&, std::string_view) = nullptr;  // for choice
  std::string_view (*choice)(const Parameters&) = nullptr;      // for choice

  // The value of a number, whole number or K; nullopt for a choice.
  std::optional<double> value(const Parameters& p) const;
};

// Every input, in the order help texts and reports list them.
const std::vector<InputSpec>& input_table();
// The row of a key, or nullptr.
const InputSpec* find_input(std::string_view key);
// The row whose `field` (validation name, "t_mm") is this, or nullptr.
const InputSpec* find_input_by_field(std::string_view field);

// "t (mm)" or "nu": a key with its unit, for axis labels and tables.
std::string input_label(const InputSpec& spec);

// Sets one input from its text. Returns an error sentence for an unknown key or a value that is
// not a number (or not one of the allowed names); range checks are validate()'s job. `K` sets c so
// that c / (1 - nu²) = K at the Poisson ratio in force: apply it after `nu`.
std::optional<std::string> apply_setting(Parameters& p, std::string_view key,
                                         std::string_view value);

// A numeric input by its key without going through text (K sets c at the current nu, as above).
// False, or nullopt, for keys that do not name a real number (choices and whole numbers).
bool set_numeric_setting(Parameters& p, std::string_view key, double value);
std::optional<double> numeric_setting(const Parameters& p, std::string_view key);

// Applies "KEY=VALUE" assignments in order, except that every K comes after all the others
// (so `--set K=30 --set nu=0.2` means K = 30 at nu = 0.2). Returns every error at once.
std::vector<std::string> apply_assignments(Parameters& p,
                                           const std::vector<std::string>& assignments);

// Strict number parsing: the whole text must be one finite decimal number.
std::optional<double> parse_number(std::string_view text);

}  // namespace foldlab
