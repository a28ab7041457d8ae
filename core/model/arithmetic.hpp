// Simple arithmetic as a person types it into a value field: "2*153", "153 + 20", "(1+2)/4",
// "-1.5e3". Pure: no state, no locale, no allocation beyond the caller's text.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace foldlab {

// The value of the arithmetic at the front of `text`, and where it ended (what follows may be a
// unit). + - * / with the usual precedence, left to right within one level, unary signs,
// parentheses up to kMaxArithmeticDepth deep, and decimal numbers with an optional exponent.
struct ArithmeticPrefix {
  double value = 0.0;
  std::size_t end = 0;
};
inline constexpr int kMaxArithmeticDepth = 16;

// nullopt when no expression starts the text (after spaces), when a result is not finite
// (1/0, 1e999, 1e200*1e200), or when the text is longer than kMaxArithmeticChars: a value typed
// by hand is short, and a long one is a paste gone wrong.
inline constexpr std::size_t kMaxArithmeticChars = 1000;
std::optional<ArithmeticPrefix> arithmetic_prefix(std::string_view text);

// Why the arithmetic at the front of `text` has no value, when a step of it has none: a number or a
// result beyond the range of a double (1e999, 1e200*1e200), or a division by zero (1/0, 0/0).
enum class ArithmeticFault { none, beyond_double, division_by_zero };
ArithmeticFault arithmetic_fault(std::string_view text);

// The whole text as arithmetic (spaces around it allowed), else nullopt.
std::optional<double> evaluate_arithmetic(std::string_view text);

}  // namespace foldlab
