#include "core/model/text_format.hpp"

#include <cerrno>
#include <cstdarg>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace foldlab::detail {

std::string vprintf_string(const char* format, std::va_list args) {
  std::va_list again;
  va_copy(again, args);
  const int size = std::vsnprintf(nullptr, 0, format, args);
  std::string out(static_cast<std::size_t>(std::max(0, size)), '\0');
  std::vsnprintf(out.data(), out.size() + 1, format, again);
  va_end(again);
  return out;
}

std::string printf_string(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::string out = vprintf_string(format, args);
  va_end(args);
  return out;
}

namespace portable {
namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Whether [first, last) starts with `word` in either case; `first` moves past it when it does.
bool take_word(const char*& first, const char* last, std::string_view word) {
  if (static_cast<std::size_t>(last - first) < word.size()) {
    return false;
  }
  for (std::size_t i = 0; i < word.size(); ++i) {
    if ((first[i] | 0x20) != word[i]) {
      return false;
    }
  }
  first += word.size();
  return true;
}

}  // namespace

std::string shortest_number(double value) {
  if (std::isnan(value)) {
    return std::signbit(value) ? "-nan" : "nan";
  }
  if (std::isinf(value)) {
    return value < 0 ? "-inf" : "inf";
  }
  if (value == 0.0) {
    return std::signbit(value) ? "-0" : "0";
  }
  // The fewest significant digits that read back exactly: printf rounds correctly, so the first
  // precision whose text reads back is the shortest, and nearest, such text (17 always does).
  const double magnitude = std::fabs(value);
  char scientific[48];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(scientific, sizeof scientific, "%.*e", digits - 1, magnitude);
    if (std::strtod(scientific, nullptr) == magnitude) {
      break;
    }
  }
  std::string digits;
  const char* c = scientific;
  for (; *c != 'e'; ++c) {
    if (*c != '.') {
      digits += *c;
    }
  }
  const int exponent = std::atoi(c + 1);
  const int count = static_cast<int>(digits.size());
  const std::string sign = value < 0 ? "-" : "";
  std::string sci = digits.substr(0, 1);
  if (count > 1) {
    sci += "." + digits.substr(1);
  }
  sci += printf_string("e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
  std::string fixed;
  if (exponent >= count - 1) {
    // A whole number: its exact digits, as to_chars writes them, not the shortest ones padded.
    fixed = printf_string("%.0f", magnitude);
  } else if (exponent >= 0) {
    fixed = digits.substr(0, static_cast<std::size_t>(exponent) + 1) + "." +
            digits.substr(static_cast<std::size_t>(exponent) + 1);
  } else {
    fixed = "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
  }
  // Of the two styles the shorter, fixed on a tie, as to_chars chooses.
  return sign + (fixed.size() <= sci.size() ? fixed : sci);
}

std::from_chars_result read_double(const char* first, const char* last, double& value) {
  const char* at = first;
  const bool negative = at != last && *at == '-';
  at += negative ? 1 : 0;
  if (take_word(at, last, "inf")) {
    take_word(at, last, "inity");
    value = negative ? -HUGE_VAL : HUGE_VAL;
    return {at, std::errc()};
  }
  if (take_word(at, last, "nan")) {
    // An optional (n-char-sequence), taken only when closed.
    const char* tail = at;
    if (tail != last && *tail == '(') {
      ++tail;
      while (tail != last && (is_digit(*tail) || ((*tail | 0x20) >= 'a' && (*tail | 0x20) <= 'z') ||
                              *tail == '_')) {
        ++tail;
      }
      if (tail != last && *tail == ')') {
        at = tail + 1;
      }
    }
    value = negative ? -std::numeric_limits<double>::quiet_NaN()
                     : std::numeric_limits<double>::quiet_NaN();
    return {at, std::errc()};
  }
  // The longest prefix of the pattern digits [. digits] [e [sign] digits]; strtod alone would
  // also take a '+', spaces and hexadecimal.
  bool any_digit = false;
  bool nonzero = false;
  while (at != last && is_digit(*at)) {
    any_digit = true;
    nonzero = nonzero || *at != '0';
    ++at;
  }
  if (at != last && *at == '.') {
    ++at;
    while (at != last && is_digit(*at)) {
      any_digit = true;
      nonzero = nonzero || *at != '0';
      ++at;
    }
  }
  if (!any_digit) {
    return {first, std::errc::invalid_argument};
  }
  if (at != last && (*at | 0x20) == 'e') {
    const char* exponent = at + 1;
    if (exponent != last && (*exponent == '+' || *exponent == '-')) {
      ++exponent;
    }
    if (exponent != last && is_digit(*exponent)) {
      while (exponent != last && is_digit(*exponent)) {
        ++exponent;
      }
      at = exponent;
    }
  }
  const std::string text(first, at);
  errno = 0;
  const double read = std::strtod(text.c_str(), nullptr);
  if (std::isinf(read) || (read == 0.0 && nonzero)) {
    return {at, std::errc::result_out_of_range};
  }
  value = read;
  return {at, std::errc()};
}

}  // namespace portable

std::string message_number(double value, bool exact) {
  if (!std::isfinite(value)) {
    return shortest_number(value);
  }
  const double magnitude = std::abs(value);
  int digits = 12;
  while (exact && digits < 17 &&
         std::strtod(printf_string("%.*e", digits - 1, magnitude).c_str(), nullptr) != magnitude) {
    ++digits;
  }
  std::string text;
  if (magnitude != 0.0 && (magnitude >= 1e7 || magnitude < 1e-4)) {
    // "9.10000000000e+08" as "9.1e8", "1.00000000000e-05" as "1e-5".
    text = printf_string("%.*e", digits - 1, magnitude);
    const std::size_t e = text.find('e');
    std::string mantissa = text.substr(0, e);
    if (mantissa.find('.') != std::string::npos) {
      mantissa.erase(mantissa.find_last_not_of('0') + 1);
      if (mantissa.back() == '.') {
        mantissa.pop_back();
      }
    }
    std::string exponent = text.substr(e + 1);
    const bool negative = exponent.front() == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    text = mantissa + "e" + (negative ? "-" : "") + exponent;
  } else {
    text = printf_string("%.*g", digits, magnitude);
    const std::size_t point = std::min(text.find('.'), text.size());
    if (point > 4) {
      for (std::size_t at = point; at > 3; at -= 3) {
        text.insert(at - 3, 1, ',');
      }
    }
  }
  return (value < 0.0 ? "\u2212" : "") + text;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') {
    return c - '0';
  }
  if (c >= 'a' && c <= 'f') {
    return c - 'a' + 10;
  }
  if (c >= 'A' && c <= 'F') {
    return c - 'A' + 10;
  }
  return -1;
}

}  // namespace foldlab::detail
