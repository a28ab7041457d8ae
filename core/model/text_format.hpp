// Small text helpers for messages and writers. In the lowest layer, so that every layer uses the
// same ones.
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace foldlab::detail {

// snprintf into a std::string of exactly the right size.
template <class... Args>
std::string printf_string(const char* format, Args... args) {
  const int size = std::snprintf(nullptr, 0, format, args...);
  std::string out(static_cast<std::size_t>(std::max(0, size)), '\0');
  std::snprintf(out.data(), out.size() + 1, format, args...);
  return out;
}

// The shortest text that reads back as exactly this double (5.0000001 stays 5.0000001).
inline std::string shortest_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// Text safe inside XML (SVG) elements and attribute values.
inline std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Items joined with a separator, none after the last.
template <class Range>
std::string join(const Range& items, std::string_view separator) {
  std::string out;
  bool first = true;
  for (const auto& item : items) {
    if (!first) {
      out += separator;
    }
    out += std::string_view(item);
    first = false;
  }
  return out;
}

inline std::string join_lines(const std::vector<std::string>& lines) {
  return join(lines, "\n");
}

inline std::string join_comma(const std::vector<std::string>& items) {
  return join(items, ", ");
}

}  // namespace foldlab::detail
