// Named inputs by the paper's symbols (MODEL.md units), shared by `foldlab --set KEY=VALUE`, the
// GUI and the preset loader, so that every front end names and parses a value the same way.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "foldlab/parameters.hpp"

namespace foldlab {

struct SettingKey {
  std::string_view key;          // as typed after --set: "t", "E", ...
  std::string_view unit;         // "mm", "MPa", ... ; empty when dimensionless
  std::string_view description;  // one line for help texts
};

// Every key apply_setting accepts, in the order help texts list them.
const std::vector<SettingKey>& setting_keys();

// Sets one input from its text. Returns an error sentence for an unknown key or a value that is
// not a number (or not one of the allowed names); range checks are validate()'s job. `K` sets c so
// that c / (1 - nu²) = K at the Poisson ratio in force: apply it after `nu`.
std::optional<std::string> apply_setting(Parameters& p, std::string_view key,
                                         std::string_view value);

// A numeric input by its key without going through text (K sets c at the current nu, as above).
// False, or nullopt, for keys that do not name a number (method, shape, whole numbers, ...).
bool set_numeric_setting(Parameters& p, std::string_view key, double value);
std::optional<double> numeric_setting(const Parameters& p, std::string_view key);

// Applies "KEY=VALUE" assignments in order, except that every K comes after all the others
// (so `--set K=30 --set nu=0.2` means K = 30 at nu = 0.2). Returns every error at once.
std::vector<std::string> apply_assignments(Parameters& p,
                                           const std::vector<std::string>& assignments);

// Strict number parsing: the whole text must be one finite decimal number.
std::optional<double> parse_number(std::string_view text);

}  // namespace foldlab
