#include "core/io/json_input.hpp"

#include <optional>
#include <set>
#include <vector>

#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

using nlohmann::json;

// Where the parser is: one entry per open object or array, so that a duplicate key can be named
// by its JSON pointer.
struct Level {
  bool is_object = false;
  std::set<std::string> keys;  // objects: the keys seen so far
  std::string key;             // objects: the current key
  std::size_t index = 0;       // arrays: the index of the next element
};

std::string escape_pointer_token(const std::string& token) {
  std::string out;
  for (char c : token) {
    out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  }
  return out;
}

std::string pointer_of(const std::vector<Level>& levels) {
  std::string out;
  for (const Level& level : levels) {
    out += "/" + (level.is_object ? escape_pointer_token(level.key) : std::to_string(level.index));
  }
  return out.empty() ? "/" : out;
}

// A child of the innermost array is complete: the next one has the next index.
void child_done(std::vector<Level>& levels) {
  if (!levels.empty() && !levels.back().is_object) {
    ++levels.back().index;
  }
}

}  // namespace

json parse_json(std::string_view text, const std::string& origin) {
  std::vector<Level> levels;
  std::optional<std::string> problem;
  const json::parser_callback_t check = [&](int /*depth*/, json::parse_event_t event,
                                            json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (levels.size() >= kMaxJsonDepth) {
          problem = detail::cut(pointer_of(levels)) + ": nested deeper than " +
                    std::to_string(kMaxJsonDepth) +
                    " levels (no FoldLab file needs more than a few)";
          throw JsonInputError(*problem);
        }
        levels.push_back(Level{event == json::parse_event_t::object_start, {}, {}, 0});
        break;
      case json::parse_event_t::key: {
        Level& level = levels.back();
        level.key = parsed.get<std::string>();
        if (!level.keys.insert(level.key).second) {
          problem = detail::cut(pointer_of(levels)) +
                    ": duplicate key (each key may appear once in an object; which one is meant?)";
          throw JsonInputError(*problem);
        }
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        levels.pop_back();
        child_done(levels);
        break;
      case json::parse_event_t::value:
        child_done(levels);
        break;
    }
    return true;
  };
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw JsonInputError(origin + ": is empty (a JSON object was expected)");
  }
  try {
    return json::parse(text.begin(), text.end(), check);
  } catch (const JsonInputError&) {
    throw JsonInputError(origin + ": " + *problem);
  } catch (const json::exception& e) {
    // parse_error, and out_of_range for a number no double holds (e.g. 1e400). The library's
    // "[json.exception.parse_error.101] parse error at line 1, column 3: syntax error while
    // parsing value - " says where in the words a person reads; the rest says what.
    std::string what = e.what();
    for (const std::string_view noise :
         {std::string_view("syntax error while parsing value - "),
          std::string_view("syntax error while parsing object key - "),
          std::string_view("syntax error while parsing object separator - "),
          std::string_view("syntax error while parsing object - "),
          std::string_view("syntax error while parsing array - ")}) {
      if (const std::size_t at = what.find(noise); at != std::string::npos) {
        what.erase(at, noise.size());
      }
    }
    if (const std::size_t close = what.find("] ");
        what.starts_with("[json.") && close != std::string::npos) {
      what.erase(0, close + 2);
    }
    if (what.starts_with("parse error ")) {
      what.erase(0, std::string_view("parse error ").size());
    }
    throw JsonInputError(origin + ": not valid JSON" + (what.starts_with("at ") ? " " : ": ") +
                         detail::cut(what, 200));
  }
}

std::string describe_json(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::object:
      return "an object with " + std::to_string(value.size()) +
             (value.size() == 1 ? " key" : " keys");
    case json::value_t::array:
      return "an array of " + std::to_string(value.size()) +
             (value.size() == 1 ? " item" : " items");
    case json::value_t::string:
      return "string \"" + detail::cut(value.get_ref<const std::string&>()) + "\"";
    default:
      // Numbers and booleans: short by nature.
      return std::string(value.type_name()) + " " + value.dump();
  }
}

}  // namespace foldlab
