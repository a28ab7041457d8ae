// Small text helpers for messages and writers. In the lowest layer, so that every layer uses the
// same ones.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace foldlab::detail {

// snprintf into a std::string of exactly the right size. A C variadic function rather than a
// template so that the format attribute lets -Wformat check every call's arguments against its
// format, as it checks printf's.
[[gnu::format(printf, 1, 2)]] std::string printf_string(const char* format, ...);

// The shortest text that reads back as exactly this double (5.0000001 stays 5.0000001).
inline std::string shortest_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// Text echoed in a message, cut to about `max_bytes` with "…" so that a 5 MB value stays a line.
// Never cuts inside a UTF-8 character.
inline std::string cut(std::string_view text, std::size_t max_bytes = 60) {
  if (text.size() <= max_bytes) {
    return std::string(text);
  }
  std::size_t end = max_bytes;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) {
    --end;
  }
  return std::string(text.substr(0, end)) + "…";
}

// `value` itself when finite. A writer calls this on every number it puts out: an infinity or NaN
// there is a bug upstream (the input ranges exclude them), so it stops as an internal error naming
// the field rather than writing "inf", "nan" or JSON null.
inline double finite_or_throw(double value, std::string_view field) {
  if (!std::isfinite(value)) {
    throw std::logic_error("non-finite " + std::string(field) + " (" + shortest_number(value) +
                           "): refusing to write it");
  }
  return value;
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
