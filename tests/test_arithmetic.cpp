// The typed-value arithmetic against values worked out by hand, and against text meant to break
// it.
#include <gtest/gtest.h>

#include <string>

#include "core/model/arithmetic.hpp"

using foldlab::arithmetic_prefix;
using foldlab::evaluate_arithmetic;

TEST(Arithmetic, ComputesWhatAPersonTypes) {
  EXPECT_EQ(evaluate_arithmetic("2*153"), 306.0);
  EXPECT_EQ(evaluate_arithmetic("153+20"), 173.0);
  EXPECT_EQ(evaluate_arithmetic("(1+2)/4"), 0.75);
  EXPECT_EQ(evaluate_arithmetic(" 7 "), 7.0);
  // Precedence: * before +, and left to right within a level: 10 - 4 - 3 = 3, not 9;
  // 24 / 4 / 2 = 3, not 12.
  EXPECT_EQ(evaluate_arithmetic("1 + 2 * 3"), 7.0);
  EXPECT_EQ(evaluate_arithmetic("10 - 4 - 3"), 3.0);
  EXPECT_EQ(evaluate_arithmetic("24 / 4 / 2"), 3.0);
  EXPECT_EQ(evaluate_arithmetic("2 * (3 + 4) * 5"), 70.0);
  // Unary signs, decimals and exponents.
  EXPECT_EQ(evaluate_arithmetic("-5"), -5.0);
  EXPECT_EQ(evaluate_arithmetic("-(2 - 7)"), 5.0);
  EXPECT_EQ(evaluate_arithmetic("3 * -2"), -6.0);
  EXPECT_EQ(evaluate_arithmetic("+.5"), 0.5);
  EXPECT_EQ(evaluate_arithmetic("1.5e3 + 2E-1"), 1500.2);
  EXPECT_EQ(evaluate_arithmetic("1e-3*1e3"), 1.0);
}

TEST(Arithmetic, StopsWhereAUnitBegins) {
  const auto prefix = arithmetic_prefix("2*153 g/m2");
  ASSERT_TRUE(prefix.has_value());
  EXPECT_EQ(prefix->value, 306.0);
  EXPECT_EQ(prefix->end, 5u);  // "2*153", the space before the unit left to it
  // A trailing operator belongs to no expression: "5 -" is 5 followed by " -".
  const auto dangling = arithmetic_prefix("5 -");
  ASSERT_TRUE(dangling.has_value());
  EXPECT_EQ(dangling->value, 5.0);
  EXPECT_EQ(dangling->end, 1u);
  EXPECT_FALSE(evaluate_arithmetic("5 -").has_value());
}

// Why a value failed, for the message: the same cause in one word whether typed or computed.
TEST(Arithmetic, SaysWhyAResultHasNoValue) {
  using foldlab::ArithmeticFault;
  for (const char* text : {"1e999", "-1e-999", "1e200*1e200", "1e200*1e200/1e200", "1e308+1e308",
                           "2*(1e300*1e300) mm"}) {
    EXPECT_EQ(foldlab::arithmetic_fault(text), ArithmeticFault::beyond_double) << text;
  }
  for (const char* text : {"1/0", "-1/0", "0/0", "(2+3)/(1-1) m"}) {
    EXPECT_EQ(foldlab::arithmetic_fault(text), ArithmeticFault::division_by_zero) << text;
  }
  for (const char* text : {"2*153 g/m2", "abc", "1e", "()", "1e-300/1e10"}) {
    EXPECT_EQ(foldlab::arithmetic_fault(text), ArithmeticFault::none) << text;
  }
}

TEST(Arithmetic, RefusesHostileText) {
  for (const char* text : {"",     " ",   "((((",     "(((1",   "1)))",        "()",          "1/0",
                           "-1/0", "0/0", "1e999",    "-1e999", "1e200*1e200", "1e308+1e308", "inf",
                           "nan",  "NaN", "infinity", "--1",    "2**3",        "2 * * 3",     "1 +",
                           "*2",   "x1",  "heavy",    "0x10",   "\xff\xfe",    "1e",          "e5",
                           "."}) {
    EXPECT_FALSE(evaluate_arithmetic(text).has_value()) << "\"" << text << "\"";
  }
  // Nesting is allowed to kMaxArithmeticDepth and refused beyond, without recursing further.
  const auto nested = [](int depth) {
    return std::string(static_cast<std::size_t>(depth), '(') + "1" +
           std::string(static_cast<std::size_t>(depth), ')');
  };
  EXPECT_EQ(evaluate_arithmetic(nested(foldlab::kMaxArithmeticDepth)), 1.0);
  EXPECT_FALSE(evaluate_arithmetic(nested(foldlab::kMaxArithmeticDepth + 1)).has_value());
  EXPECT_FALSE(evaluate_arithmetic(std::string(100000, '(')).has_value());
  // Long text: a sum of 333 ones still fits the limit and is 333; past the limit it is refused,
  // even when it would be arithmetic.
  std::string sum = "1";
  for (int i = 1; i < 333; ++i) {
    sum += "+1";
  }
  ASSERT_LE(sum.size(), foldlab::kMaxArithmeticChars);
  EXPECT_EQ(evaluate_arithmetic(sum), 333.0);
  EXPECT_FALSE(evaluate_arithmetic(std::string(foldlab::kMaxArithmeticChars + 1, '1')).has_value());
  EXPECT_FALSE(evaluate_arithmetic(std::string(1 << 20, '-') + "1").has_value());
}
