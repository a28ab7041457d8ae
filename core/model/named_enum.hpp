// Reading an enum by the name its to_string gives, so that each enum's names are written once
// (in its to_string) and parsing cannot disagree with printing.
#pragma once

#include <initializer_list>
#include <string_view>

namespace foldlab {

// Sets `out` to the one of `values` whose to_string is `s`; false, leaving `out`, for none.
template <class Enum, class Values>
bool parse_named(std::string_view s, Enum& out, const Values& values) {
  for (Enum v : values) {
    if (s == to_string(v)) {
      out = v;
      return true;
    }
  }
  return false;
}
template <class Enum>
bool parse_named(std::string_view s, Enum& out, std::initializer_list<Enum> values) {
  return parse_named<Enum, std::initializer_list<Enum>>(s, out, values);
}

}  // namespace foldlab
