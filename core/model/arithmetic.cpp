#include "core/model/arithmetic.hpp"

#include <cmath>
#include <system_error>

#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

// Recursive descent over the text. It stops at the first character that cannot continue the
// expression, so that a unit may follow.
class Reader {
 public:
  explicit Reader(std::string_view text) : text_(text) {}

  std::optional<double> expression() { return chain(&Reader::term, '+', '-'); }
  std::size_t end() const { return at_; }
  ArithmeticFault fault() const { return fault_; }

 private:
  std::optional<double> term() { return chain(&Reader::factor, '*', '/'); }

  // `operand (op operand)*` for the two operators of one precedence level, left to right.
  std::optional<double> chain(std::optional<double> (Reader::*operand)(), char first, char second) {
    std::optional<double> value = (this->*operand)();
    while (value) {
      const std::size_t before = at_;
      skip_spaces();
      const char op = at_ < text_.size() ? text_[at_] : '\0';
      if (op != first && op != second) {
        at_ = before;
        break;
      }
      ++at_;
      const std::optional<double> right = (this->*operand)();
      if (!right) {
        at_ = before;  // "5 -": the expression ends before the sign
        break;
      }
      value = op == '+'   ? *value + *right
              : op == '-' ? *value - *right
              : op == '*' ? *value * *right
                          : *value / *right;
      if (!std::isfinite(*value)) {
        // 1/0 or an overflow is no value, whatever follows.
        fault_ = op == '/' && *right == 0.0 ? ArithmeticFault::division_by_zero
                                            : ArithmeticFault::beyond_double;
        return std::nullopt;
      }
    }
    return value;
  }

  std::optional<double> factor() {
    skip_spaces();
    if (at_ >= text_.size()) {
      return std::nullopt;
    }
    const char c = text_[at_];
    if (c == '+' || c == '-') {
      ++at_;
      if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) {
        return std::nullopt;  // "--1" is a typo, not arithmetic
      }
      const std::optional<double> value = factor();
      return value && c == '-' ? std::optional<double>(-*value) : value;
    }
    if (c == '(') {
      // Deep nesting is no arithmetic a person types: refused before it costs the stack.
      if (depth_ == kMaxArithmeticDepth) {
        return std::nullopt;
      }
      ++at_;
      ++depth_;
      const std::optional<double> value = expression();
      --depth_;
      skip_spaces();
      if (!value || at_ >= text_.size() || text_[at_] != ')') {
        return std::nullopt;
      }
      ++at_;
      return value;
    }
    if ((c < '0' || c > '9') && c != '.') {
      return std::nullopt;  // from_chars would also read "inf" and "nan"
    }
    double number = 0.0;
    const char* start = text_.data() + at_;
    const auto [ptr, ec] = detail::read_double(start, text_.data() + text_.size(), number);
    if (ec != std::errc() || !std::isfinite(number)) {
      if (ec == std::errc::result_out_of_range) {
        fault_ = ArithmeticFault::beyond_double;  // 1e999 is out of range, not infinity
      }
      return std::nullopt;
    }
    at_ += static_cast<std::size_t>(ptr - start);
    return number;
  }

  void skip_spaces() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t')) {
      ++at_;
    }
  }

  std::string_view text_;
  std::size_t at_ = 0;
  int depth_ = 0;
  ArithmeticFault fault_ = ArithmeticFault::none;
};

}  // namespace

std::optional<ArithmeticPrefix> arithmetic_prefix(std::string_view text) {
  if (text.size() > kMaxArithmeticChars) {
    return std::nullopt;
  }
  Reader reader(text);
  const std::optional<double> value = reader.expression();
  if (!value || !std::isfinite(*value)) {
    return std::nullopt;
  }
  return ArithmeticPrefix{*value, reader.end()};
}

ArithmeticFault arithmetic_fault(std::string_view text) {
  if (text.size() > kMaxArithmeticChars) {
    return ArithmeticFault::none;
  }
  Reader reader(text);
  reader.expression();
  return reader.fault();
}

std::optional<double> evaluate_arithmetic(std::string_view text) {
  const std::optional<ArithmeticPrefix> prefix = arithmetic_prefix(text);
  if (!prefix) {
    return std::nullopt;
  }
  for (std::size_t i = prefix->end; i < text.size(); ++i) {
    if (text[i] != ' ' && text[i] != '\t') {
      return std::nullopt;
    }
  }
  return prefix->value;
}

}  // namespace foldlab
