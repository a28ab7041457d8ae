// The portable number text (core/model/text_format.hpp) against the standard library's: the
// browser build writes and reads numbers through it, so it must give the same text and the same
// doubles as std::to_chars and std::from_chars do here.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <string_view>

#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

std::string standard_text(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// Same end, same error, same bits (any NaN for a NaN).
void expect_same_reading(std::string_view text) {
  double expected = 7.0;
  double read = 7.0;
  const auto a = std::from_chars(text.data(), text.data() + text.size(), expected);
  const auto b = detail::portable::read_double(text.data(), text.data() + text.size(), read);
  EXPECT_EQ(a.ptr - text.data(), b.ptr - text.data()) << text;
  EXPECT_EQ(a.ec, b.ec) << text;
  if (std::isnan(expected)) {
    EXPECT_TRUE(std::isnan(read)) << text;
  } else {
    EXPECT_EQ(std::memcmp(&expected, &read, sizeof read), 0) << text << " " << read;
  }
}

void expect_same_text(double value) {
  const std::string expected = standard_text(value);
  EXPECT_EQ(detail::portable::shortest_number(value), expected);
  expect_same_reading(expected);
}

TEST(PortableNumberText, WritesAndReadsAsTheStandardLibraryDoes) {
  for (const double value : {0.0,
                             -0.0,
                             1.0,
                             -1.5,
                             0.1,
                             0.001,
                             1e-5,
                             100.0,
                             123456.0,
                             1e15,
                             1e16,
                             1e17,
                             1e20,
                             1e21,
                             1e22,
                             1e23,
                             1e100,
                             5e-324,
                             2.2250738585072014e-308,
                             1.7976931348623157e308,
                             1152921504606846976.0,
                             5.0000001,
                             1.47e-6,
                             29.56,
                             HUGE_VAL,
                             -HUGE_VAL}) {
    expect_same_text(value);
  }
  std::mt19937_64 random(27);
  std::uniform_real_distribution<double> decade(-8.0, 8.0);
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t bits = random();
    double any = 0.0;
    std::memcpy(&any, &bits, sizeof any);
    if (!std::isnan(any)) {
      expect_same_text(any);
    }
    const double typed = std::pow(10.0, decade(random));
    expect_same_text(typed);
    expect_same_text(std::round(typed * 1000.0) / 1000.0);
  }
}

TEST(PortableNumberText, RefusesAndStopsWhereFromCharsDoes) {
  for (const char* text :
       {"1e400",    "-1e400", "1e-400", "1e-310", "1e-320",    "4.9e-324", "2e-324",
        "0e999",    "+1",     " 1",     "1e",     "1e+",       ".5",       "5.",
        ".",        "-",      "",       "inf",    "-INFINITY", "infin",    "nan",
        "nan(abc)", "nan(",   "0x10",   "1.5e3x", "00012",     "12 mm"}) {
    expect_same_reading(text);
  }
}

// Numbers in sentences for people: rounded past conversion noise, grouped, a real minus.
TEST(MessageNumber, ReadsAsAPersonWritesIt) {
  EXPECT_EQ(detail::message_number(0.0), "0");
  EXPECT_EQ(detail::message_number(-5.000000000000001), "\u22125");
  EXPECT_EQ(detail::message_number(0.1), "0.1");
  EXPECT_EQ(detail::message_number(1400.0), "1400");
  EXPECT_EQ(detail::message_number(10000.0), "10,000");
  EXPECT_EQ(detail::message_number(1e6), "1,000,000");
  EXPECT_EQ(detail::message_number(1234567.25), "1,234,567.25");
  EXPECT_EQ(detail::message_number(9.1e8), "9.1e8");
  EXPECT_EQ(detail::message_number(1e-5), "1e-5");
  EXPECT_EQ(detail::message_number(-1.5e-300), "\u22121.5e-300");
  EXPECT_EQ(detail::message_number(5.0000001), "5.0000001");
  EXPECT_EQ(detail::message_number(0.50000000000001), "0.5");
  EXPECT_EQ(detail::message_number(0.50000000000001, true), "0.50000000000001");
  EXPECT_EQ(detail::message_number(2e20, true), "2e20");
}

}  // namespace
}  // namespace foldlab
