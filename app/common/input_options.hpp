// The command-line options every command shares, and the validators that refuse a bad value in
// the words --set uses. Kept apart from inputs.hpp so that the explorer's files, which never parse
// a command line, do not compile CLI11 (about 10 s a file at -O3).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/common/field_cut.hpp"
#include "app/common/inputs.hpp"

namespace foldlab::app {

// For every option that names a file: an empty path (`--preset ''`, an unset shell variable) is
// refused as invalid input rather than read as "not given", which would silently use a default.
CLI::Validator non_empty_path();
// A count given in any notation ("1e3" is 1000), refused unless whole and within [lo, hi]; use it
// with ->transform() on an integer option.
CLI::Validator whole_number_in(std::int64_t lo, std::int64_t hi);
// A finite number within [lo, hi], for ->check() on a double option: "nan" and "inf" are refused
// (a range check alone lets nan through, every comparison with it being false).
CLI::Validator number_in(double lo, double hi);

// An option that takes one of an input's choices (--method: the "method" row), refused in the
// words --set uses: "method = 'Exact' is not one of: paper, exact".
CLI::Validator input_choice(std::string_view key);
// An option that takes one of `choices`, refused in the same words: "fit = 'k' is not one of:
// K, K,p".
CLI::Validator one_of(std::string name, std::vector<std::string> choices);

// --preset, --set, --method and --law, for every command that solves.
void add_input_options(CLI::App& command, InputOptions& options);
// --law alone, for a command that gathers its inputs otherwise (InputOptions::law).
void add_law_option(CLI::App& command, std::string& law);
// --shape and --outline (one or the other), the cut a tension field is solved on.
void add_field_cut_options(CLI::App& command, FieldCutOptions& options);

}  // namespace foldlab::app
