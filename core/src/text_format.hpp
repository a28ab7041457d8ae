// Small text helpers shared by the SVG and OBJ writers (private to foldlab_core).
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>
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

// Lines joined with newlines, none after the last.
inline std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (i > 0) {
      out += '\n';
    }
    out += lines[i];
  }
  return out;
}

}  // namespace foldlab::detail
