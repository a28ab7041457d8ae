// A refused value as data: what kind of refusal, which bound and in which unit, for hand-picked
// inputs. Every bound and sentence below is written as docs/cli.md states it, not read from the
// input table, so that a row whose range drifts from the documentation fails here.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "core/model/parameters.hpp"
#include "core/model/settings.hpp"

namespace {

using foldlab::InputRefusal;
using foldlab::Parameters;
using foldlab::RefusalKind;

// The weight of 1 g/m² in N/mm²: 1e-3 kg × 9.81 m/s² spread over 1e6 mm².
constexpr double kNPerMm2PerGsm = 1e-3 * 9.81 / 1e6;

// Parameters with the one text assigned, which must be read (a range is checked later).
Parameters with(const char* key, const char* text) {
  Parameters p;
  const std::optional<InputRefusal> refusal = foldlab::assign_text(p, key, text);
  EXPECT_FALSE(refusal.has_value())
      << key << "=" << text << ": " << foldlab::refusal_sentence(*refusal);
  return p;
}

// The refusal of a text that cannot be read, with the field it was for left as it was.
InputRefusal unread(const char* key, const char* text) {
  Parameters p;
  const std::optional<InputRefusal> refusal = foldlab::assign_text(p, key, text);
  EXPECT_TRUE(p == Parameters{}) << key << "=" << text;
  return refusal.value_or(InputRefusal{.kind = RefusalKind::out_of_range});
}

TEST(InputRefusal, AWeightBelowTheLightestTissueNamesTheLowerEndInTheStoredUnit) {
  // docs/cli.md: w must be between 0.1 and 1,000,000 g/m².
  const std::vector<InputRefusal> refusals = foldlab::input_refusals(with("w", "-5g/m2"));
  ASSERT_EQ(refusals.size(), 1u);
  const InputRefusal& r = refusals[0];
  EXPECT_EQ(r.kind, RefusalKind::out_of_range);
  EXPECT_EQ(r.key, "w");
  EXPECT_EQ(r.unit, "N/mm²");
  EXPECT_DOUBLE_EQ(r.value, -5.0 * kNPerMm2PerGsm);
  EXPECT_DOUBLE_EQ(r.bound, 0.1 * kNPerMm2PerGsm);
  EXPECT_EQ(foldlab::refusal_sentence(r),
            "weight per area w = \u22125 g/m\u00b2 must be between 0.1 and 1,000,000 g/m\u00b2: "
            "from the lightest tissue to a tonne per square metre");
}

TEST(InputRefusal, ABareWeightIsNPerMm2AndBreaksTheUpperEnd) {
  // docs/cli.md: `--set w=150` is 150 N/mm², above the 1,000,000 g/m² end.
  const std::vector<InputRefusal> refusals = foldlab::input_refusals(with("w", "150"));
  ASSERT_EQ(refusals.size(), 1u);
  EXPECT_EQ(refusals[0].kind, RefusalKind::out_of_range);
  EXPECT_EQ(refusals[0].value, 150.0);
  EXPECT_DOUBLE_EQ(refusals[0].bound, 1e6 * kNPerMm2PerGsm);
  EXPECT_EQ(refusals[0].unit, "N/mm²");
}

TEST(InputRefusal, AHeightAboveAHundredMetresNamesItsUpperEnd) {
  const std::vector<InputRefusal> refusals = foldlab::input_refusals(with("h", "2e5"));
  ASSERT_EQ(refusals.size(), 1u);
  EXPECT_EQ(refusals[0].kind, RefusalKind::out_of_range);
  EXPECT_EQ(refusals[0].bound, 100000.0);
  EXPECT_EQ(refusals[0].unit, "mm");
  EXPECT_EQ(foldlab::refusal_sentence(refusals[0]),
            "height h = 200,000 mm must be between 1 and 100,000 mm: the cloth's height, from 1 "
            "mm to 100 m");
}

TEST(InputRefusal, ADisplacementAtHalfTheWidthNamesTheBoundFromTheOtherInputs) {
  // docs/cli.md: d = 900 mm is refused where L/2 = 700 mm.
  Parameters p = with("L", "1400");
  ASSERT_FALSE(foldlab::assign_text(p, "d", "900"));
  const std::vector<InputRefusal> refusals = foldlab::input_refusals(p);
  ASSERT_EQ(refusals.size(), 1u);
  EXPECT_EQ(refusals[0].kind, RefusalKind::not_below_bound);
  EXPECT_EQ(refusals[0].key, "d");
  EXPECT_EQ(refusals[0].value, 900.0);
  EXPECT_EQ(refusals[0].bound, 700.0);
  EXPECT_EQ(refusals[0].bound_name, "L/2");
  EXPECT_EQ(refusals[0].unit, "mm");
  // 700 mm itself is refused too: d stays below L/2.
  ASSERT_FALSE(foldlab::assign_text(p, "d", "70cm"));
  ASSERT_EQ(foldlab::input_refusals(p).size(), 1u);
  EXPECT_EQ(foldlab::input_refusals(p)[0].kind, RefusalKind::not_below_bound);
  ASSERT_FALSE(foldlab::assign_text(p, "d", "699"));
  EXPECT_TRUE(foldlab::input_refusals(p).empty());
}

TEST(InputRefusal, AUnitInTheWrongCaseIsNamedWithTheOneMeant) {
  const InputRefusal r = unread("h", "2.4M");
  EXPECT_EQ(r.kind, RefusalKind::unknown_unit);
  EXPECT_EQ(r.typed, "2.4M");
  EXPECT_EQ(r.typed_unit, "M");
  EXPECT_EQ(r.meant_unit, "m");
  EXPECT_EQ(r.unit, "mm");
  const InputRefusal spaced = unread("h", "2.4  furlong");
  EXPECT_EQ(spaced.kind, RefusalKind::unknown_unit);
  EXPECT_EQ(spaced.typed_unit, "furlong");
  EXPECT_EQ(spaced.meant_unit, "");
}

TEST(InputRefusal, WhatIsNoNumberIsToldFromANumberBeyondADouble) {
  // docs/cli.md: a division by zero says so; a number no double holds is "beyond the range of a
  // double" whether typed (1e999) or computed on the way (1e200*1e200/1e200).
  EXPECT_EQ(unread("t", "1/0").kind, RefusalKind::divides_by_zero);
  EXPECT_EQ(unread("t", "0/0 mm").kind, RefusalKind::divides_by_zero);
  EXPECT_EQ(unread("t", "1e200*1e200").kind, RefusalKind::beyond_double);
  EXPECT_EQ(unread("t", "1e200*1e200/1e200 mm").kind, RefusalKind::beyond_double);
  EXPECT_EQ(unread("t", "abc").kind, RefusalKind::not_a_number);
  EXPECT_EQ(unread("t", "2*").kind, RefusalKind::not_a_number);
  EXPECT_EQ(unread("t", "1e999").kind, RefusalKind::beyond_double);
  EXPECT_EQ(unread("t", "-1e-999").kind, RefusalKind::beyond_double);
  // A whole number is read without arithmetic, and told the same way.
  EXPECT_EQ(unread("supports", "1e999").kind, RefusalKind::beyond_double);
  EXPECT_EQ(unread("supports", "2*3").kind, RefusalKind::not_a_number);
}

TEST(InputRefusal, ArithmeticNestsSixteenParenthesesDeepAndNoDeeper) {
  // docs/cli.md: parentheses more than 16 deep are "nested too deeply".
  const auto nested = [](int depth) {
    return std::string(static_cast<std::size_t>(depth), '(') + "12" +
           std::string(static_cast<std::size_t>(depth), ')');
  };
  const InputRefusal r = unread("h", nested(17).c_str());
  EXPECT_EQ(r.kind, RefusalKind::nested_too_deeply);
  EXPECT_EQ(r.typed, nested(17));
  EXPECT_EQ(with("h", nested(16).c_str()).hanging.height_mm, 12.0);
}

TEST(InputRefusal, KeysChoicesAndWholeNumbersAreRefusedByKind) {
  Parameters p;
  const std::optional<InputRefusal> unknown = foldlab::assign_text(p, "zz", "1");
  ASSERT_TRUE(unknown.has_value());
  EXPECT_EQ(unknown->kind, RefusalKind::unknown_key);
  EXPECT_EQ(unknown->spec, nullptr);
  const std::optional<InputRefusal> method = foldlab::assign_text(p, "method", "fast");
  ASSERT_TRUE(method.has_value());
  EXPECT_EQ(method->kind, RefusalKind::not_a_choice);
  EXPECT_EQ(method->typed, "fast");
  const std::optional<InputRefusal> number = foldlab::assign_number(p, "method", 1.0);
  ASSERT_TRUE(number.has_value());
  EXPECT_EQ(number->kind, RefusalKind::number_for_choice);
  const std::optional<InputRefusal> fraction = foldlab::assign_number(p, "supports", 2.5);
  ASSERT_TRUE(fraction.has_value());
  EXPECT_EQ(fraction->kind, RefusalKind::not_whole);
  EXPECT_EQ(fraction->value, 2.5);
  EXPECT_TRUE(p == Parameters{});
}

TEST(InputRefusal, ABareNumberIsReadInTheUnitItIsTypedIn) {
  // As the explorer's w slider reads it: a bare number in g/m².
  const foldlab::InputSpec& w = *foldlab::find_input("w");
  const std::variant<double, InputRefusal> grams = foldlab::read_quantity(w, "150", "g/m²");
  ASSERT_TRUE(std::holds_alternative<double>(grams));
  EXPECT_DOUBLE_EQ(std::get<double>(grams), 150.0 * kNPerMm2PerGsm);
  const std::variant<double, InputRefusal> heavy = foldlab::read_quantity(w, "heavy", "g/m²");
  ASSERT_TRUE(std::holds_alternative<InputRefusal>(heavy));
  EXPECT_EQ(std::get<InputRefusal>(heavy).kind, RefusalKind::not_a_number);
  EXPECT_EQ(std::get<InputRefusal>(heavy).typed, "heavy");
}

}  // namespace
