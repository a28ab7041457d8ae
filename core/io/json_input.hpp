// The one way FoldLab reads JSON from a file: a bounded nesting depth (a hostile file cannot
// exhaust the stack of whatever walks the value later) and no duplicate keys (a second "t" would
// silently win over the first). Messages describe values without printing them whole.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace foldlab {

// Deeper than any FoldLab file (a preset is 3 levels) and far from any stack limit.
inline constexpr std::size_t kMaxJsonDepth = 64;

// Text that is not JSON FoldLab reads: the message names `origin` and the problem.
class JsonInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses `text`. Throws JsonInputError for invalid JSON, a number no double holds, nesting deeper
// than kMaxJsonDepth, or a key that appears twice in one object (the message names the key's JSON
// pointer).
nlohmann::json parse_json(std::string_view text, const std::string& origin);

// A short description of a value for messages: its type and a cut excerpt ("string \"abc…\"",
// "array of 3 items"), never the whole value.
std::string describe_json(const nlohmann::json& value);

}  // namespace foldlab
