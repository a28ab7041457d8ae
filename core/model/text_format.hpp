// Small text helpers for messages and writers. In the lowest layer, so that every layer uses the
// same ones.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdarg>
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
// The same from a va_list, for other checked printf-style helpers; `args` is used up.
[[gnu::format(printf, 1, 0)]] std::string vprintf_string(const char* format, std::va_list args);

// The same text and the same reading as std::to_chars and std::from_chars on a double, without
// them: some standard libraries (libc++ as emscripten ships it for the browser build) have only
// the integer overloads. Always compiled, so that the native tests check them against the real
// ones.
namespace portable {
std::string shortest_number(double value);
std::from_chars_result read_double(const char* first, const char* last, double& value);
}  // namespace portable

// The shortest text that reads back as exactly this double (5.0000001 stays 5.0000001).
inline std::string shortest_number(double value) {
#if __cpp_lib_to_chars >= 201611L
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
#else
  return portable::shortest_number(value);
#endif
}

// std::from_chars on a double (general format: no leading space or '+', "inf" and "nan" read).
inline std::from_chars_result read_double(const char* first, const char* last, double& value) {
#if __cpp_lib_to_chars >= 201611L
  return std::from_chars(first, last, value);
#else
  return portable::read_double(first, last, value);
#endif
}

// A number as a sentence for people shows it: at most 12 significant digits (so that a value
// converted between units reads 5, not 5.000000000000001), a real minus sign, thousands grouped
// from five digits on ("1,000,000", "1400"), and an exponent only beyond that ("9.1e8",
// "1e-5"). `exact`: as many digits as it takes to read back as this double, for a value that 12
// digits would round onto a limit it is refused by.
std::string message_number(double value, bool exact = false);

// The length of the well-formed UTF-8 character starting at text[i] (1 to 4 bytes), or 0 when the
// bytes there are not one (a stray continuation byte, a sequence cut short, an overlong form, a
// surrogate or a code point above U+10FFFF).
inline std::size_t utf8_length_at(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) {
    return 1;
  }
  std::size_t length = 0;
  unsigned char lo = 0x80;  // the second byte's range, narrowed to exclude overlongs etc.
  unsigned char hi = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    lo = lead == 0xE0 ? 0xA0 : 0x80;
    hi = lead == 0xED ? 0x9F : 0xBF;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    lo = lead == 0xF0 ? 0x90 : 0x80;
    hi = lead == 0xF4 ? 0x8F : 0xBF;
  } else {
    return 0;
  }
  if (i + length > text.size() || byte(i + 1) < lo || byte(i + 1) > hi) {
    return 0;
  }
  for (std::size_t k = 2; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) {
      return 0;
    }
  }
  return length;
}

inline bool is_valid_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8_length_at(text, i);
    if (length == 0) {
      return false;
    }
    i += length;
  }
  return true;
}

// Text echoed in a message, as every message that quotes input shows it: control characters
// (C0, DEL, C1, the line separators and bidirectional controls) and bytes that are not UTF-8
// written as \xNN, so that a name or value cannot move
// the cursor, recolour or clear the terminal or break the line; then cut to about `max_bytes`
// with "…" so that a 5 MB value stays a line. Never cuts inside a UTF-8 character.
inline std::string cut(std::string_view text, std::size_t max_bytes = 60) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8_length_at(text, i);
    const auto lead = static_cast<unsigned char>(text[i]);
    const bool c1 = length == 2 && lead == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0;
    // Line and paragraph separators and the bidirectional controls (U+200E-F, U+2028-202E,
    // U+2066-2069): printed, they break a line or reverse the text that follows.
    const auto at = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
    const bool layout =
        length == 3 && lead == 0xE2 &&
        ((at(1) == 0x80 && (at(2) == 0x8E || at(2) == 0x8F || (at(2) >= 0xA8 && at(2) <= 0xAE))) ||
         (at(1) == 0x81 && at(2) >= 0xA6 && at(2) <= 0xA9));
    std::string piece;
    if (length == 0 || lead < 0x20 || lead == 0x7F || c1 || layout) {
      for (std::size_t k = 0; k < std::max<std::size_t>(length, 1); ++k) {
        const auto b = static_cast<unsigned char>(text[i + k]);
        piece += {'\\', 'x', kHex[b >> 4], kHex[b & 0xF]};
      }
    } else {
      piece = std::string(text.substr(i, length));
    }
    if (out.size() + piece.size() > max_bytes) {
      return out + "…";
    }
    out += piece;
    i += std::max<std::size_t>(length, 1);
  }
  return out;
}

// User text (a preset's or a row's name) wherever it reaches a terminal, a report or a one-line
// comment in a file: the same \xNN spelling as cut(), nothing cut.
inline std::string escaped(std::string_view text) {
  return cut(text, std::string_view::npos);
}

// A name as a caption or a drawing's title shows it: escaped() and cut to about kMaxCaptionBytes,
// so that a name as long as a preset may hold (up to its 1 MB) stays a line of a picture rather
// than seconds of laying out text nobody can read.
inline constexpr std::size_t kMaxCaptionBytes = 200;
inline std::string caption_text(std::string_view text) {
  return cut(text, kMaxCaptionBytes);
}

// User text in a cell of a Markdown table: escaped(), and a '|' written "\|" so that it cannot
// start a cell of its own.
inline std::string markdown_cell(std::string_view text) {
  std::string out;
  for (const char c : escaped(text)) {
    out += c == '|' ? std::string("\\|") : std::string(1, c);
  }
  return out;
}

// A message of several lines that quotes the user's text (a path, a value, a name): each line
// escaped(), the line breaks kept. Every message the program prints goes through it, so that no
// quoted text reaches a terminal as control characters.
inline std::string escaped_lines(std::string_view text) {
  std::string out;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    out += escaped(text.substr(start, end - start));
    if (end < text.size()) {
      out += '\n';
    }
    start = end + 1;
  }
  return out;
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

// The value of one hexadecimal digit (either case), or -1 for any other character.
int hex_digit(char c);

}  // namespace foldlab::detail
