// Named inputs (--set KEY=VALUE): apply_setting, apply_assignments, parse_number, and validate().
#include "core/model/settings.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/model/parameters.hpp"

namespace {

using foldlab::Parameters;

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

// Every numeric input, read back as a double, so a test can check that one key changes one field.
struct NumericField {
  const char* key;
  const char* name;
  std::function<double(const Parameters&)> get;
};

std::vector<NumericField> numeric_fields() {
  return {
      {"t", "thickness_mm", [](const Parameters& p) { return p.fabric.thickness_mm; }},
      {"E", "youngs_modulus_MPa", [](const Parameters& p) { return p.fabric.youngs_modulus_MPa; }},
      {"w", "weight_N_per_mm2", [](const Parameters& p) { return p.fabric.weight_N_per_mm2; }},
      {"nu", "poisson_ratio", [](const Parameters& p) { return p.fabric.poisson_ratio; }},
      {"h", "height_mm", [](const Parameters& p) { return p.hanging.height_mm; }},
      {"L", "length_mm", [](const Parameters& p) { return p.hanging.length_mm; }},
      {"d", "support_displacement_mm",
       [](const Parameters& p) { return p.hanging.support_displacement_mm; }},
      {"c", "load_constant_c", [](const Parameters& p) { return p.model.load_constant_c; }},
      {"length_tolerance", "length_tolerance",
       [](const Parameters& p) { return p.model.length_tolerance; }},
      {"simpson_intervals", "simpson_intervals",
       [](const Parameters& p) { return static_cast<double>(p.model.simpson_intervals); }},
      {"max_iterations", "max_iterations",
       [](const Parameters& p) { return static_cast<double>(p.model.max_iterations); }},
  };
}

void expect_unchanged_enums(const Parameters& a, const Parameters& b) {
  EXPECT_EQ(a.model.method, b.model.method);
  EXPECT_EQ(a.model.span_rule, b.model.span_rule);
  EXPECT_EQ(a.model.int_rounding, b.model.int_rounding);
}

TEST(Settings, EachNumericKeySetsItsOwnFieldOnly) {
  // Values different from every default and from each other.
  const std::vector<std::pair<std::string, double>> cases = {
      {"t", 0.41},
      {"E", 222.5},
      {"w", 3.25e-6},
      {"nu", 0.35},
      {"h", 1777.0},
      {"L", 1333.0},
      {"d", 55.5},
      {"c", 19.75},
      {"length_tolerance", 0.0125},
      {"simpson_intervals", 42},
      {"max_iterations", 99},
  };
  const std::vector<NumericField> fields = numeric_fields();
  for (const auto& [key, value] : cases) {
    SCOPED_TRACE(key);
    const Parameters before;
    Parameters p;
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", value);
    const auto error = foldlab::apply_setting(p, key, text);
    ASSERT_FALSE(error.has_value()) << *error;
    bool found = false;
    for (const NumericField& f : fields) {
      if (key == f.key) {
        found = true;
        EXPECT_EQ(f.get(p), value) << f.name;
      } else {
        EXPECT_EQ(f.get(p), f.get(before)) << f.name << " changed by " << key;
      }
    }
    EXPECT_TRUE(found);
    expect_unchanged_enums(p, before);
  }
}

TEST(Settings, NamedKeysParseTheirNames) {
  Parameters p;
  EXPECT_FALSE(foldlab::apply_setting(p, "method", "exact"));
  EXPECT_EQ(p.model.method, foldlab::Method::exact);
  EXPECT_FALSE(foldlab::apply_setting(p, "method", "paper"));
  EXPECT_EQ(p.model.method, foldlab::Method::paper);

  EXPECT_FALSE(foldlab::apply_setting(p, "span_rule", "L-2d"));
  EXPECT_EQ(p.model.span_rule, foldlab::SpanRule::L_minus_2d);
  EXPECT_FALSE(foldlab::apply_setting(p, "span_rule", "L-d"));
  EXPECT_EQ(p.model.span_rule, foldlab::SpanRule::L_minus_d);

  EXPECT_FALSE(foldlab::apply_setting(p, "int_rounding", "floor"));
  EXPECT_EQ(p.model.int_rounding, foldlab::IntRounding::floor);
  EXPECT_FALSE(foldlab::apply_setting(p, "int_rounding", "nearest"));
  EXPECT_EQ(p.model.int_rounding, foldlab::IntRounding::nearest);
}

TEST(Settings, NamedKeysRejectOtherNamesListingTheAllowedOnes) {
  struct Case {
    const char* key;
    const char* value;
    const char* allowed;
  };
  for (const Case& c :
       {Case{"method", "fast", "paper, exact"}, Case{"method", "Exact", "paper, exact"},
        Case{"span_rule", "L-3d", "L-d, L-2d"}, Case{"span_rule", "", "L-d, L-2d"},
        Case{"int_rounding", "up", "nearest, floor"}}) {
    SCOPED_TRACE(std::string(c.key) + "=" + c.value);
    Parameters p;
    p.model.method = foldlab::Method::exact;
    p.model.span_rule = foldlab::SpanRule::L_minus_2d;
    p.model.int_rounding = foldlab::IntRounding::floor;
    const Parameters before = p;
    const auto error = foldlab::apply_setting(p, c.key, c.value);
    ASSERT_TRUE(error.has_value());
    EXPECT_TRUE(contains(*error, c.allowed)) << *error;
    EXPECT_TRUE(contains(*error, c.key)) << *error;
    expect_unchanged_enums(p, before);
  }
}

TEST(Settings, KSetsCAtTheCurrentPoissonRatio) {
  Parameters p;
  ASSERT_EQ(p.fabric.poisson_ratio, 0.3);
  ASSERT_FALSE(foldlab::apply_setting(p, "K", "40"));
  EXPECT_NEAR(p.model.load_constant_c, 40.0 * 0.91, 1e-12);  // c = K (1 - 0.3²)
  EXPECT_NEAR(foldlab::stiffness_constant_K(p), 40.0, 1e-12);
  EXPECT_EQ(p.fabric.poisson_ratio, 0.3);
}

TEST(Settings, AssignmentsApplyKAfterNuWhateverTheOrder) {
  for (const std::vector<std::string>& order :
       {std::vector<std::string>{"K=30", "nu=0.2"}, std::vector<std::string>{"nu=0.2", "K=30"}}) {
    SCOPED_TRACE(order[0] + " " + order[1]);
    Parameters p;
    const std::vector<std::string> errors = foldlab::apply_assignments(p, order);
    EXPECT_TRUE(errors.empty());
    EXPECT_EQ(p.fabric.poisson_ratio, 0.2);
    EXPECT_NEAR(foldlab::stiffness_constant_K(p), 30.0, 1e-12);
    EXPECT_NEAR(p.model.load_constant_c, 30.0 * 0.96, 1e-12);  // c = K (1 - 0.2²)
  }
}

TEST(Settings, AssignmentsApplyInOrderSoTheLastWins) {
  Parameters p;
  EXPECT_TRUE(foldlab::apply_assignments(p, {"t=0.5", "h=1000", "t=0.7"}).empty());
  EXPECT_EQ(p.fabric.thickness_mm, 0.7);
  EXPECT_EQ(p.hanging.height_mm, 1000.0);
}

TEST(Settings, UnknownKeyIsReported) {
  Parameters p;
  const Parameters before = p;
  for (const char* key : {"bogus", "T", "thickness_mm", "k", ""}) {
    SCOPED_TRACE(key);
    const auto error = foldlab::apply_setting(p, key, "1");
    ASSERT_TRUE(error.has_value());
    EXPECT_TRUE(contains(*error, "unknown key")) << *error;
  }
  EXPECT_EQ(p.fabric.thickness_mm, before.fabric.thickness_mm);
  EXPECT_EQ(p.model.load_constant_c, before.model.load_constant_c);
}

TEST(Settings, MalformedNumbersAreRejected) {
  for (const char* value :
       {"1.5.3", "abc", "", "nan", "NaN", "inf", "-inf", " 1", "1 ", "1,5", "0x10", "--1"}) {
    SCOPED_TRACE(std::string("'") + value + "'");
    Parameters p;
    const auto error = foldlab::apply_setting(p, "t", value);
    ASSERT_TRUE(error.has_value());
    EXPECT_TRUE(contains(*error, "is not a number")) << *error;
    EXPECT_EQ(p.fabric.thickness_mm, 0.25);
    EXPECT_FALSE(foldlab::parse_number(value).has_value());
  }
}

TEST(Settings, NumbersBeyondADoubleAreNamedAsSuch) {
  for (const char* value : {"1e400", "-1e400", "1e-400"}) {
    SCOPED_TRACE(value);
    Parameters p;
    const auto error = foldlab::apply_setting(p, "t", value);
    ASSERT_TRUE(error.has_value());
    EXPECT_TRUE(contains(*error, "beyond the range of a double")) << *error;
    EXPECT_EQ(p.fabric.thickness_mm, 0.25);
  }
}

// Conversions computed by hand: 1 g/m² weighs 9.81e-9 N/mm² (g = 9.81 m/s²), and
// 1 oz/yd² = 28.349523125 g / 0.83612736 m² = 33.9057 g/m².
TEST(Settings, WeightsAreReadInGramsPerSquareMetreAndOuncesPerSquareYard) {
  const foldlab::InputSpec& w = *foldlab::find_input("w");
  for (const char* text : {"80 g/m2", "80 g/m²", "80gsm", "80 GSM", "80g / m2", "80 g/m^2x"}) {
    SCOPED_TRACE(text);
    const std::optional<double> value = foldlab::parse_quantity(w, text);
    if (std::string(text).ends_with("x")) {
      EXPECT_FALSE(value.has_value());
      continue;
    }
    ASSERT_TRUE(value.has_value());
    EXPECT_NEAR(*value, 7.848e-7, 1e-18);  // 80 x 9.81e-9
  }
  // 2.4 oz/yd² = 81.37379 g/m² = 7.9827692e-7 N/mm².
  ASSERT_TRUE(foldlab::parse_quantity(w, "2.4 oz/yd2").has_value());
  EXPECT_NEAR(*foldlab::parse_quantity(w, "2.4 oz/yd2"), 7.9827692e-7, 1e-14);
  EXPECT_NEAR(*foldlab::parse_quantity(w, "2.4oz/yd²"), 7.9827692e-7, 1e-14);
  // A bare number is in the unit the caller names: g/m² in the explorer, N/mm² on the CLI.
  EXPECT_NEAR(*foldlab::parse_quantity(w, "80", "g/m²"), 7.848e-7, 1e-18);
  EXPECT_EQ(foldlab::parse_quantity(w, "1.5e-6"), 1.5e-6);
  EXPECT_EQ(foldlab::parse_quantity(w, "1.5e-6 N/mm2"), 1.5e-6);
  EXPECT_FALSE(foldlab::parse_quantity(w, "80 g/cm2").has_value());
  EXPECT_FALSE(foldlab::parse_quantity(w, "g/m2").has_value());
  // The shown unit of w and its read-out: 150 g/m² = 4.424 oz/yd².
  EXPECT_EQ(foldlab::shown_unit(w).symbol, "g/m²");
  EXPECT_NEAR(150.0 * foldlab::kNPerMm2PerGramPerM2 / foldlab::input_units(w)[2].per_unit, 4.4240,
              1e-4);
}

// SI writes m for a metre and M for mega: a unit is read in its own case, so 2.4M is no length.
// gsm, a name no prefix changes, is read in any case.
TEST(Settings, UnitsAreReadInTheirOwnCase) {
  const foldlab::InputSpec& h = *foldlab::find_input("h");
  const foldlab::InputSpec& w = *foldlab::find_input("w");
  const foldlab::InputSpec& E = *foldlab::find_input("E");
  for (const char* text : {"2.4M", "1Mm", "2.4MM", "140CM", "2.4 M"}) {
    EXPECT_FALSE(foldlab::parse_quantity(h, text).has_value()) << text;
  }
  EXPECT_EQ(foldlab::parse_quantity(h, "2.4m"), 2400.0);
  EXPECT_EQ(foldlab::parse_quantity(h, "1mm"), 1.0);
  EXPECT_EQ(foldlab::parse_quantity(h, "140 cm"), 1400.0);
  EXPECT_EQ(foldlab::parse_quantity(E, "0.165GPa"), 165.0);
  EXPECT_EQ(foldlab::parse_quantity(E, "160MPa"), 160.0);
  for (const char* text : {"0.165gpa", "0.165GPA", "160mpa", "160 Mpa"}) {
    EXPECT_FALSE(foldlab::parse_quantity(E, text).has_value()) << text;
  }
  for (const char* text : {"150gsm", "150GSM", "150 Gsm", "150g/m2", "150 g/m²"}) {
    ASSERT_TRUE(foldlab::parse_quantity(w, text).has_value()) << text;
    EXPECT_NEAR(*foldlab::parse_quantity(w, text), 1.4715e-6, 1e-17) << text;  // 150 x 9.81e-9
  }
  EXPECT_FALSE(foldlab::parse_quantity(w, "150 G/M2").has_value());
  // In the explorer a bare number is g/m² (its shown unit): still case-sensitive after it.
  EXPECT_FALSE(foldlab::parse_quantity(w, "150 G/m2", "g/m²").has_value());
}

TEST(Settings, ARefusedUnitNamesTheKnownOnesAndTheRightCase) {
  Parameters p;
  const auto h_mega = foldlab::apply_setting(p, "h", "2.4M");
  ASSERT_TRUE(h_mega.has_value());
  EXPECT_EQ(*h_mega,
            "h = '2.4M': 'M' is not a unit of length (known: mm, cm, m); did you mean 'm'?");
  const auto h_feet = foldlab::apply_setting(p, "h", "8 ft");
  ASSERT_TRUE(h_feet.has_value());
  EXPECT_EQ(*h_feet, "h = '8 ft': 'ft' is not a unit of length (known: mm, cm, m)");
  const auto e_giga = foldlab::apply_setting(p, "E", "0.1gpa");
  ASSERT_TRUE(e_giga.has_value());
  EXPECT_TRUE(contains(*e_giga,
                       "'gpa' is not a unit of stress (known: MPa, GPa); did you mean "
                       "'GPa'?"))
      << *e_giga;
  const auto w_caps = foldlab::apply_setting(p, "w", "80 G/M2");
  ASSERT_TRUE(w_caps.has_value());
  EXPECT_TRUE(contains(*w_caps,
                       "'G/M2' is not a unit of weight per area (known: N/mm², g/m², "
                       "oz/yd², gsm); did you mean 'g/m²'?"))
      << *w_caps;
  EXPECT_EQ(p.hanging.height_mm, Parameters{}.hanging.height_mm);
  EXPECT_TRUE(
      std::holds_alternative<double>(foldlab::read_quantity(*foldlab::find_input("h"), "2.4m")));
}

// A key set twice is refused in the words a preset file uses for a duplicate key.
TEST(Settings, RepeatedKeysAreNamedWithEveryValueGiven) {
  EXPECT_TRUE(foldlab::repeated_keys({"h=2.4m", "t=0.3", "K=20"}, "--set").empty());
  const std::vector<std::string> twice =
      foldlab::repeated_keys({"h=2.4m", "t=0.3", "h=1000", "t=0.4", "h=2"}, "--set");
  ASSERT_EQ(twice.size(), 2u);
  EXPECT_EQ(twice[0],
            "--set h=2.4m, --set h=1000 and --set h=2: duplicate key (each key may appear once; "
            "which one is meant?)");
  EXPECT_EQ(twice[1],
            "--set t=0.3 and --set t=0.4: duplicate key (each key may appear once; which one is "
            "meant?)");
}

// Simple arithmetic before the unit, with the usual precedence; what is not arithmetic is refused
// rather than read in part.
TEST(Settings, TypedValuesMayBeSimpleArithmetic) {
  const foldlab::InputSpec& h = *foldlab::find_input("h");
  EXPECT_EQ(foldlab::parse_quantity(h, "2*700"), 1400.0);
  EXPECT_EQ(foldlab::parse_quantity(h, "1000 + 200 * 2"), 1400.0);
  EXPECT_EQ(foldlab::parse_quantity(h, "(1000 + 400) / 2 cm"), 7000.0);
  EXPECT_EQ(foldlab::parse_quantity(h, "-(-1.4) m"), 1400.0);
  EXPECT_EQ(foldlab::parse_quantity(h, "1.4e3 - 0.5e2"), 1350.0);
  for (const char* text : {"2*", "1/0", "()", "(1", "1)", "2 * * 3", "inf", "nan", "1 +", "x1",
                           "((((((((((((((((((1))))))))))))))))))"}) {
    EXPECT_FALSE(foldlab::parse_quantity(h, text).has_value()) << text;
  }
}

// The explorer shows every input in its slider's unit, from the one place that says what it is.
TEST(Settings, ShownLabelsAndValuesUseTheSlidersUnit) {
  const foldlab::InputSpec& w = *foldlab::find_input("w");
  // 1.5e-6 N/mm² / 9.81e-9 = 152.905 g/m²; 100 g/m² = 9.81e-7 N/mm².
  EXPECT_NEAR(foldlab::to_shown_unit(w, 1.5e-6), 152.905, 1e-3);
  EXPECT_NEAR(foldlab::from_shown_unit(w, 100.0), 9.81e-7, 1e-18);
  EXPECT_EQ(foldlab::shown_label(w), "w (g/m²)");
  EXPECT_EQ(foldlab::shown_label(*foldlab::find_input("h")), "h (mm)");
  EXPECT_EQ(foldlab::to_shown_unit(*foldlab::find_input("h"), 1400.0), 1400.0);
  // As the paper writes it: ν, dimensionless.
  EXPECT_EQ(foldlab::shown_label(*foldlab::find_input("nu")), "ν");
  EXPECT_EQ(foldlab::input_symbol(*foldlab::find_input("E")), "E");
}

TEST(Settings, SetAcceptsAUnitAfterTheNumber) {
  Parameters p;
  EXPECT_FALSE(foldlab::apply_setting(p, "w", "80g/m2"));
  EXPECT_NEAR(p.fabric.weight_N_per_mm2, 7.848e-7, 1e-18);
  EXPECT_FALSE(foldlab::apply_setting(p, "h", "1.4 m"));
  EXPECT_EQ(p.hanging.height_mm, 1400.0);
  EXPECT_FALSE(foldlab::apply_setting(p, "L", "140cm"));
  EXPECT_EQ(p.hanging.length_mm, 1400.0);
  EXPECT_FALSE(foldlab::apply_setting(p, "E", "0.165 GPa"));
  EXPECT_NEAR(p.fabric.youngs_modulus_MPa, 165.0, 1e-12);
  const auto error = foldlab::apply_setting(p, "w", "80 furlongs");
  ASSERT_TRUE(error.has_value());
  EXPECT_TRUE(contains(*error, "N/mm², g/m², oz/yd²")) << *error;
  EXPECT_TRUE(foldlab::apply_setting(p, "nu", "0.3 mm").has_value()) << "nu has no unit";
}

// The slider of d stops below L/2 and that of L above 2 d, where validation starts refusing.
TEST(Settings, SliderIntervalsStopWhereValidationRefuses) {
  Parameters p;
  p.hanging.length_mm = 1400.0;
  p.hanging.support_displacement_mm = 100.0;
  const foldlab::InputInterval d = foldlab::slider_interval(*foldlab::find_input("d"), p);
  EXPECT_EQ(d.lo, 0.0);
  EXPECT_LT(d.hi, 700.0);
  EXPECT_GT(d.hi, 700.0 - 1e-9);
  Parameters at_hi = p;
  at_hi.hanging.support_displacement_mm = d.hi;
  EXPECT_TRUE(foldlab::validate(at_hi).empty());
  p.hanging.support_displacement_mm = 600.0;
  const foldlab::InputInterval L = foldlab::slider_interval(*foldlab::find_input("L"), p);
  EXPECT_GT(L.lo, 1200.0);
  EXPECT_LT(L.lo, 1200.0 + 1e-9);
  EXPECT_EQ(L.hi, 5000.0);
  // Inputs that nothing else constrains keep the table's typical range.
  const foldlab::InputInterval w = foldlab::slider_interval(*foldlab::find_input("w"), p);
  EXPECT_EQ(w.lo, 1e-7);
  EXPECT_EQ(w.hi, 1e-4);
  // A refused value gives no hint where validity lies: the typical range.
  p.hanging.support_displacement_mm = 900.0;
  EXPECT_EQ(foldlab::slider_interval(*foldlab::find_input("d"), p).hi, 2500.0);
}

TEST(Settings, ParseNumberAcceptsDecimalNumbers) {
  EXPECT_EQ(foldlab::parse_number("1.5"), 1.5);
  EXPECT_EQ(foldlab::parse_number("0"), 0.0);
  EXPECT_EQ(foldlab::parse_number("-2e3"), -2000.0);
  EXPECT_EQ(foldlab::parse_number("1.5e-6"), 1.5e-6);
  EXPECT_EQ(foldlab::parse_number(".25"), 0.25);
  EXPECT_EQ(foldlab::parse_number("700"), 700.0);
}

TEST(Settings, AssignmentWithoutEqualsSignIsNotKeyValue) {
  Parameters p;
  const std::vector<std::string> errors = foldlab::apply_assignments(p, {"x"});
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_TRUE(contains(errors[0], "not KEY=VALUE")) << errors[0];
  EXPECT_TRUE(contains(errors[0], "x")) << errors[0];

  const std::vector<std::string> empty_key = foldlab::apply_assignments(p, {"=5"});
  ASSERT_EQ(empty_key.size(), 1u);
  EXPECT_TRUE(contains(empty_key[0], "not KEY=VALUE")) << empty_key[0];
}

TEST(Settings, SeveralErrorsAreReturnedAtOnce) {
  Parameters p;
  const std::vector<std::string> errors =
      foldlab::apply_assignments(p, {"bogus=1", "t=abc", "x", "h=1200", "K=zz"});
  ASSERT_EQ(errors.size(), 4u);
  std::string all;
  for (const std::string& e : errors) {
    all += e + "\n";
  }
  EXPECT_TRUE(contains(all, "unknown key 'bogus'")) << all;
  EXPECT_TRUE(contains(all, "is not a number")) << all;
  EXPECT_TRUE(contains(all, "not KEY=VALUE")) << all;
  EXPECT_TRUE(contains(all, "K = 'zz'")) << all;
  // The good assignment among them still applies.
  EXPECT_EQ(p.hanging.height_mm, 1200.0);
}

TEST(Settings, WholeNumberKeysRejectFractions) {
  Parameters p;
  const auto error = foldlab::apply_setting(p, "simpson_intervals", "2.5");
  ASSERT_TRUE(error.has_value());
  EXPECT_TRUE(contains(*error, "whole number")) << *error;
  EXPECT_EQ(p.model.simpson_intervals, 20);

  const auto iterations = foldlab::apply_setting(p, "max_iterations", "10.25");
  ASSERT_TRUE(iterations.has_value());
  EXPECT_TRUE(contains(*iterations, "whole number")) << *iterations;
  EXPECT_EQ(p.model.max_iterations, 200);

  EXPECT_FALSE(foldlab::apply_setting(p, "simpson_intervals", "30"));
  EXPECT_EQ(p.model.simpson_intervals, 30);
}

TEST(Settings, ShapeKeysSetTheShape) {
  Parameters p;
  EXPECT_FALSE(foldlab::apply_setting(p, "shape", "inclined"));
  EXPECT_EQ(p.shape.kind, foldlab::ShapeKind::inclined);
  EXPECT_FALSE(foldlab::apply_setting(p, "incline_deg", "20"));
  EXPECT_EQ(p.shape.incline_deg, 20.0);
  EXPECT_FALSE(foldlab::apply_setting(p, "supports", "5"));
  EXPECT_EQ(p.shape.supports, 5);
  const auto error = foldlab::apply_setting(p, "shape", "round");
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("cosine, rectangular, strip, inclined"), std::string::npos);
  p.shape.supports = 1;
  p.shape.incline_deg = 85.0;
  const auto issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].field, "supports");
  EXPECT_EQ(issues[1].field, "incline_deg");
}

TEST(Settings, EveryListedKeyIsAccepted) {
  const std::vector<std::string> expected = {"t",
                                             "E",
                                             "w",
                                             "nu",
                                             "h",
                                             "L",
                                             "d",
                                             "K",
                                             "c",
                                             "p",
                                             "method",
                                             "law",
                                             "span_rule",
                                             "int_rounding",
                                             "simpson_intervals",
                                             "length_tolerance",
                                             "max_iterations",
                                             "length_quadrature",
                                             "shape",
                                             "supports",
                                             "incline_deg"};
  std::vector<std::string> listed;
  for (const foldlab::InputSpec& k : foldlab::input_table()) {
    listed.emplace_back(k.key);
    EXPECT_FALSE(k.help.empty()) << k.key;
    Parameters p;
    const char* value = k.key == "method"              ? "exact"
                        : k.key == "law"               ? "cerda-mahadevan"
                        : k.key == "span_rule"         ? "L-2d"
                        : k.key == "int_rounding"      ? "floor"
                        : k.key == "length_quadrature" ? "trapezoid"
                        : k.key == "shape"             ? "strip"
                                                       : "4";
    const auto error = foldlab::apply_setting(p, k.key, value);
    EXPECT_FALSE(error.has_value()) << k.key << ": " << error.value_or("");
  }
  EXPECT_EQ(listed, expected);
}

// validate()

TEST(SettingsValidate, DefaultsAreValid) {
  const Parameters p;
  const auto issues = foldlab::validate(p);
  EXPECT_TRUE(issues.empty()) << foldlab::format_issues(issues);
}

TEST(SettingsValidate, ReportsEveryProblemAtOnce) {
  Parameters p;
  p.fabric.thickness_mm = -1.0;
  p.hanging.length_mm = 1400.0;
  p.hanging.support_displacement_mm = 800.0;
  const auto issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 2u) << foldlab::format_issues(issues);
  EXPECT_EQ(issues[0].field, "t_mm");
  EXPECT_EQ(issues[0].value, -1.0);
  EXPECT_EQ(issues[1].field, "d_mm");
  EXPECT_EQ(issues[1].value, 800.0);
}

TEST(SettingsValidate, HalfTheLengthIsTooFarForD) {
  Parameters p;
  p.hanging.length_mm = 1400.0;
  p.hanging.support_displacement_mm = 700.0;
  const auto issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u) << foldlab::format_issues(issues);
  EXPECT_EQ(issues[0].field, "d_mm");
  EXPECT_TRUE(
      contains(issues[0].message, "support displacement d = 700 mm must be below L/2 = 700 mm"))
      << issues[0].message;

  // Just below L/2 and d = 0 are fine; a negative d is not.
  p.hanging.support_displacement_mm = 699.9;
  EXPECT_TRUE(foldlab::validate(p).empty());
  p.hanging.support_displacement_mm = 0.0;
  EXPECT_TRUE(foldlab::validate(p).empty());
  p.hanging.support_displacement_mm = -1.0;
  const auto negative = foldlab::validate(p);
  ASSERT_EQ(negative.size(), 1u);
  EXPECT_EQ(negative[0].field, "d_mm");
}

TEST(SettingsValidate, NaNInputsAreRejected) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    const char* field;
    std::function<void(Parameters&)> set;
  };
  const std::vector<Case> cases = {
      {"t_mm", [&](Parameters& p) { p.fabric.thickness_mm = nan; }},
      {"E_MPa", [&](Parameters& p) { p.fabric.youngs_modulus_MPa = nan; }},
      {"w_N_per_mm2", [&](Parameters& p) { p.fabric.weight_N_per_mm2 = nan; }},
      {"nu", [&](Parameters& p) { p.fabric.poisson_ratio = nan; }},
      {"h_mm", [&](Parameters& p) { p.hanging.height_mm = nan; }},
      {"L_mm", [&](Parameters& p) { p.hanging.length_mm = nan; }},
      {"d_mm", [&](Parameters& p) { p.hanging.support_displacement_mm = nan; }},
      {"c", [&](Parameters& p) { p.model.load_constant_c = nan; }},
      {"length_tolerance", [&](Parameters& p) { p.model.length_tolerance = nan; }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.field);
    Parameters p;
    c.set(p);
    const auto issues = foldlab::validate(p);
    ASSERT_FALSE(issues.empty());
    bool named = false;
    for (const foldlab::ValidationIssue& issue : issues) {
      named = named || issue.field == c.field;
    }
    EXPECT_TRUE(named) << foldlab::format_issues(issues);
  }
}

TEST(SettingsValidate, InfiniteInputsAreRejected) {
  Parameters p;
  p.hanging.height_mm = std::numeric_limits<double>::infinity();
  const auto issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "h_mm");
}

TEST(SettingsValidate, OddSimpsonIntervalsAreRejected) {
  Parameters p;
  p.model.simpson_intervals = 21;
  const auto issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u) << foldlab::format_issues(issues);
  EXPECT_EQ(issues[0].field, "simpson_intervals");
  EXPECT_TRUE(contains(issues[0].message, "even")) << issues[0].message;

  p.model.simpson_intervals = 22;
  EXPECT_TRUE(foldlab::validate(p).empty());
  p.model.simpson_intervals = 0;
  EXPECT_FALSE(foldlab::validate(p).empty());
}

TEST(SettingsValidate, PoissonRatioOfOneHalfIsRejected) {
  Parameters p;
  p.fabric.poisson_ratio = 0.5;
  const auto issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "nu");
  p.fabric.poisson_ratio = 0.0;
  EXPECT_TRUE(foldlab::validate(p).empty());
}

// Values that cannot describe a cloth, each from a reported attack: refused with the range.
TEST(SettingsValidate, PhysicalRangesRefuseWhatNoClothCanBe) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"t", "1e-200"},
      {"L", "1e-320"},
      {"h", "1e-320"},
      {"p", "1e-300"},
      {"E", "1e300"},
      {"w", "1e-320"},
      {"c", "1e-300"},
      {"simpson_intervals", "1000000"},
      {"max_iterations", "1000000"},
      {"length_tolerance", "1e-300"},
  };
  for (const auto& [key, value] : cases) {
    SCOPED_TRACE(key + "=" + value);
    Parameters p;
    ASSERT_FALSE(foldlab::apply_setting(p, key, value).has_value());
    const auto issues = foldlab::validate(p);
    ASSERT_EQ(issues.size(), 1u) << foldlab::format_issues(issues);
    const foldlab::InputSpec* spec = foldlab::find_input(key);
    ASSERT_NE(spec, nullptr);
    EXPECT_EQ(issues[0].field, spec->field);
    // In the slider's words and unit: "weight per area w = 1.02e-312 g/m² must be between".
    EXPECT_TRUE(contains(issues[0].message, foldlab::input_title(*spec) + " = "))
        << issues[0].message;
    EXPECT_TRUE(contains(issues[0].message, " must be between ")) << issues[0].message;
  }
}

TEST(SettingsValidate, MessagesDoNotRoundAwayTheValueRefused) {
  Parameters p;
  p.model.stress_exponent_p = 5.0000001;
  const auto issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_TRUE(contains(issues[0].message, "p = 5.0000001")) << issues[0].message;
}

// The table is the one source of truth: check its rows against each other and against the
// parameters' defaults, which must lie inside the ranges they declare.
TEST(InputTable, RowsAreConsistent) {
  const Parameters defaults;
  for (const foldlab::InputSpec& spec : foldlab::input_table()) {
    SCOPED_TRACE(std::string(spec.key));
    EXPECT_EQ(foldlab::find_input(spec.key), &spec);
    EXPECT_FALSE(spec.help.empty());
    if (spec.kind == foldlab::InputKind::choice) {
      EXPECT_FALSE(spec.choices.empty());
      EXPECT_NE(spec.set_choice, nullptr);
      EXPECT_NE(spec.choice, nullptr);
      continue;
    }
    EXPECT_LT(spec.typical_lo, spec.typical_hi);
    if (spec.kind == foldlab::InputKind::stiffness_K) {
      continue;
    }
    EXPECT_EQ(foldlab::find_input_by_field(spec.field), &spec);
    EXPECT_TRUE(spec.valid.contains(spec.typical_lo) || spec.key == "nu") << spec.typical_lo;
    EXPECT_TRUE(spec.valid.contains(spec.typical_hi)) << spec.typical_hi;
    EXPECT_TRUE(spec.valid.contains(*spec.value(defaults)));
    if (spec.scale == foldlab::InputScale::logarithmic) {
      EXPECT_GT(spec.typical_lo, 0.0);
    }
    // A beginner's slider is a part of the expert's, around the defaults.
    if (spec.beginner_hi > spec.beginner_lo) {
      EXPECT_GE(spec.beginner_lo, spec.typical_lo);
      EXPECT_LE(spec.beginner_hi, spec.typical_hi);
      EXPECT_GE(*spec.value(defaults), spec.beginner_lo);
      EXPECT_LE(*spec.value(defaults), spec.beginner_hi);
    }
  }
}

// The beginner's sliders cover the cloths one buys: w from 10.2 (the typical range's low end,
// 1e-7 N/mm²) to 1000 g/m², chiffon's 35 and denim's 441 inside; t and E likewise. An expert's
// run over the whole typical range.
TEST(InputTable, BeginnerSlidersFitRealFabrics) {
  const foldlab::InputSpec& w = *foldlab::find_input("w");
  const foldlab::InputInterval beginner = foldlab::slider_ends(w, foldlab::SliderReach::beginner);
  EXPECT_EQ(beginner.lo, 1e-7);
  EXPECT_NEAR(foldlab::to_shown_unit(w, beginner.hi), 1000.0, 1e-9);
  const foldlab::InputInterval expert = foldlab::slider_ends(w, foldlab::SliderReach::expert);
  EXPECT_EQ(expert.lo, 1e-7);
  EXPECT_EQ(expert.hi, 1e-4);
  // The fabric presets' values (presets/FABRICS.md) on the beginner's sliders.
  const auto on_slider = [](const char* key, double value) {
    const foldlab::InputInterval ends =
        foldlab::slider_ends(*foldlab::find_input(key), foldlab::SliderReach::beginner);
    return ends.lo <= value && value <= ends.hi;
  };
  for (const double t_mm : {0.076, 0.09, 0.2, 0.8}) {
    EXPECT_TRUE(on_slider("t", t_mm)) << t_mm;
  }
  for (const double E_MPa : {9.0, 78.0, 165.0, 430.0}) {
    EXPECT_TRUE(on_slider("E", E_MPa)) << E_MPa;
  }
  // A row without a beginner's range gives both the typical one.
  const foldlab::InputSpec& h = *foldlab::find_input("h");
  EXPECT_EQ(foldlab::slider_ends(h, foldlab::SliderReach::beginner).hi, 5000.0);
  // The slider stops where validation refuses for a beginner too: d below L/2.
  Parameters p;
  p.hanging.length_mm = 1400.0;
  EXPECT_LT(
      foldlab::slider_interval(*foldlab::find_input("d"), p, foldlab::SliderReach::beginner).hi,
      700.0);
}

// A refusal speaks the slider's name and unit, with round limits in that unit.
TEST(SettingsValidate, RefusalsUseTheSlidersLabelAndUnit) {
  Parameters p;
  p.fabric.weight_N_per_mm2 = -4.905e-08;  // -5 g/m²
  std::vector<foldlab::ValidationIssue> issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "w_N_per_mm2");
  EXPECT_TRUE(issues[0].message.starts_with(
      "weight per area w = \u22125 g/m² must be between 0.1 and 1,000,000 g/m²: "))
      << issues[0].message;
  p = Parameters{};
  p.fabric.poisson_ratio = 0.5;
  issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_TRUE(
      issues[0].message.starts_with("Poisson's ratio ν = 0.5 must be at least 0 and below 0.5: "))
      << issues[0].message;
  // Twelve digits would round this onto the limit it is refused by: it is written in full.
  p.fabric.poisson_ratio = 0.50000000000001;
  issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_TRUE(contains(issues[0].message, "ν = 0.50000000000001")) << issues[0].message;
  p = Parameters{};
  p.hanging.height_mm = 2e5;
  issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_TRUE(
      issues[0].message.starts_with("height h = 200,000 mm must be between 1 and 100,000 mm: "))
      << issues[0].message;
  // The upper end that follows from L: d = 800 mm against L/2 = 700 mm.
  p = Parameters{};
  p.hanging.length_mm = 1400.0;
  p.hanging.support_displacement_mm = 800.0;
  issues = foldlab::validate(p);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].message,
            "support displacement d = 800 mm must be below L/2 = 700 mm, where the supports "
            "would meet under the span rule L-2d (kept under L-d too)");
  // The incline's interval is open at both ends.
  const foldlab::InputSpec& incline = *foldlab::find_input("incline_deg");
  EXPECT_TRUE(
      foldlab::refusal_sentence(foldlab::range_refusal(incline, 90.0, incline.valid, "why"))
          .starts_with("incline incline_deg = 90 deg must be above \u221280 and below 80 deg"));
}

}  // namespace
