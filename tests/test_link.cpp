// The fabric as a link (core/io/link.hpp): written, read back through `--set`'s path, and the
// percent-encoding between.
#include "core/io/link.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/preset.hpp"
#include "core/model/settings.hpp"

namespace {

namespace fs = std::filesystem;
using foldlab::LinkAssignment;
using foldlab::Parameters;

// (memcpy rather than std::bit_cast, which the browser build's libc++ lacks)
std::uint64_t bits(double v) {
  std::uint64_t out = 0;
  std::memcpy(&out, &v, sizeof out);
  return out;
}

// Every field of Parameters, listed here rather than read from the input table: a field the link
// left out shows up as a difference.
void expect_bit_identical(const Parameters& got, const Parameters& want, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(bits(got.fabric.thickness_mm), bits(want.fabric.thickness_mm));
  EXPECT_EQ(bits(got.fabric.youngs_modulus_MPa), bits(want.fabric.youngs_modulus_MPa));
  EXPECT_EQ(bits(got.fabric.weight_N_per_mm2), bits(want.fabric.weight_N_per_mm2));
  EXPECT_EQ(bits(got.fabric.poisson_ratio), bits(want.fabric.poisson_ratio));
  EXPECT_EQ(bits(got.hanging.height_mm), bits(want.hanging.height_mm));
  EXPECT_EQ(bits(got.hanging.length_mm), bits(want.hanging.length_mm));
  EXPECT_EQ(bits(got.hanging.support_displacement_mm), bits(want.hanging.support_displacement_mm));
  EXPECT_EQ(got.model.method, want.model.method);
  EXPECT_EQ(got.model.law, want.model.law);
  EXPECT_EQ(bits(got.model.load_constant_c), bits(want.model.load_constant_c));
  EXPECT_EQ(got.model.span_rule, want.model.span_rule);
  EXPECT_EQ(got.model.int_rounding, want.model.int_rounding);
  EXPECT_EQ(got.model.simpson_intervals, want.model.simpson_intervals);
  EXPECT_EQ(bits(got.model.length_tolerance), bits(want.model.length_tolerance));
  EXPECT_EQ(got.model.max_iterations, want.model.max_iterations);
  EXPECT_EQ(got.model.length_quadrature, want.model.length_quadrature);
  EXPECT_EQ(bits(got.model.stress_exponent_p), bits(want.model.stress_exponent_p));
  EXPECT_EQ(got.shape.kind, want.shape.kind);
  EXPECT_EQ(got.shape.supports, want.shape.supports);
  EXPECT_EQ(bits(got.shape.incline_deg), bits(want.shape.incline_deg));
  EXPECT_TRUE(got == want);
}

std::vector<std::string> as_set(const std::vector<LinkAssignment>& link) {
  std::vector<std::string> out;
  for (const LinkAssignment& a : link) {
    out.push_back(a.set_text());
  }
  return out;
}

// A link applied to the built-in defaults, as `--set` applies its values; the errors it gives.
std::vector<std::string> apply_link(Parameters& p, const std::string& link) {
  return foldlab::apply_assignments(p, as_set(foldlab::parse_fabric_link(link)));
}

std::vector<std::string> messages(const Parameters& p) {
  std::vector<std::string> out;
  for (const foldlab::ValidationIssue& issue : foldlab::validate(p)) {
    out.push_back(issue.message);
  }
  return out;
}

TEST(Link, EveryPresetComesBackBitForBitOverTheDefaults) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(FOLDLAB_PRESETS_DIR)) {
    if (entry.path().extension() == ".json") {
      files.push_back(entry.path());
    }
  }
  ASSERT_GE(files.size(), 17u);  // default, 7 paper cases, 9 fabrics
  for (const fs::path& file : files) {
    const Parameters want = foldlab::load_preset(file).parameters;
    const std::string link = foldlab::fabric_link(want);
    Parameters got;  // the built-in defaults, which differ from every preset somewhere
    EXPECT_TRUE(apply_link(got, link).empty()) << link;
    expect_bit_identical(got, want, file.filename().string() + ": " + link);
  }
}

TEST(Link, AFabricReadsAsItsKeysAndUnits) {
  Parameters p;
  p.fabric.weight_N_per_mm2 = 150 * 9.81e-9;  // 150 g/m² at g = 9.81 m/s²
  p.fabric.thickness_mm = 0.25;
  p.model.method = foldlab::Method::exact;
  p.model.law = foldlab::WrinkleLawKind::cerda_mahadevan;
  p.shape.incline_deg = -12.5;
  EXPECT_EQ(foldlab::fabric_link(p),
            "t=0.25&E=165&w=150gsm&nu=0.3&h=1400&L=1400&d=100&c=26.9&p=1&method=exact"
            "&law=cerda-mahadevan&span_rule=L-d&int_rounding=nearest&simpson_intervals=20"
            "&length_tolerance=0.05&max_iterations=200&length_quadrature=simpson&shape=cosine"
            "&supports=3&incline_deg=-12.5");
}

TEST(Link, RandomFabricsComeBackBitForBit) {
  std::mt19937_64 random(20240527);
  const auto log_uniform = [&](double lo, double hi) {
    return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(random));
  };
  int weights_in_grams = 0;
  constexpr int kFabrics = 3000;
  for (int i = 0; i < kFabrics; ++i) {
    Parameters want;
    want.fabric.thickness_mm = log_uniform(0.01, 5.0);
    want.fabric.youngs_modulus_MPa = log_uniform(1.0, 1e4);
    want.fabric.weight_N_per_mm2 = log_uniform(1e-7, 1e-4);
    want.fabric.poisson_ratio = std::uniform_real_distribution<double>(0.0, 0.49)(random);
    want.hanging.height_mm = log_uniform(100.0, 5000.0);
    want.hanging.length_mm = log_uniform(100.0, 5000.0);
    want.hanging.support_displacement_mm = log_uniform(1.0, 2500.0);
    want.model.load_constant_c = log_uniform(0.5, 300.0);
    want.model.stress_exponent_p = log_uniform(0.2, 2.0);
    want.model.length_tolerance = log_uniform(1e-4, 0.1);
    want.model.method = i % 2 == 0 ? foldlab::Method::exact : foldlab::Method::paper;
    want.shape.kind = i % 3 == 0 ? foldlab::ShapeKind::inclined : foldlab::ShapeKind::strip;
    want.shape.incline_deg = std::uniform_real_distribution<double>(-45.0, 45.0)(random);
    want.shape.supports = 2 + i % 7;
    const std::string link = foldlab::fabric_link(want);
    Parameters got;
    ASSERT_TRUE(apply_link(got, link).empty()) << link;
    expect_bit_identical(got, want, link);
    if (::testing::Test::HasFailure()) {
      return;
    }
    weights_in_grams += link.find("gsm&") != std::string::npos;
  }
  // The shown unit where it reads back exactly, N/mm² where not: both occur.
  EXPECT_GT(weights_in_grams, 0);
  EXPECT_LT(weights_in_grams, kFabrics);
}

TEST(Link, ARefusedValueIsKeptAndNamedAsSetNamesIt) {
  // d beyond L/2 (L = 1400 mm by default) and a negative weight: stored as typed, refused by
  // validate() with the same words as the same values after --set.
  Parameters linked;
  EXPECT_TRUE(apply_link(linked, "#d=900&w=-5").empty());
  Parameters set;
  EXPECT_TRUE(foldlab::apply_assignments(set, {"d=900", "w=-5"}).empty());
  EXPECT_EQ(linked.hanging.support_displacement_mm, 900.0);
  EXPECT_EQ(linked.fabric.weight_N_per_mm2, -5.0);
  const std::vector<std::string> problems = messages(linked);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems, messages(set));
  EXPECT_NE(problems[0].find("weight per area w = −5.09683995923e8 g/m²"), std::string::npos)
      << problems[0];
  EXPECT_NE(problems[1].find("support displacement d = 900 mm"), std::string::npos) << problems[1];
  // What cannot be stored at all is named as --set names it.
  Parameters a;
  Parameters b;
  EXPECT_EQ(apply_link(a, "t=abc&zz=1&t&method=fast"),
            foldlab::apply_assignments(b, {"t=abc", "zz=1", "t", "method=fast"}));
  EXPECT_EQ(apply_link(a, "t=abc&zz=1&t&method=fast").size(), 4u);
  EXPECT_TRUE(a == Parameters{});
}

TEST(Link, AnAddressAFragmentAndTheBarePiecesReadAlike) {
  const auto keys = [](const std::string& link) {
    std::vector<std::string> out = as_set(foldlab::parse_fabric_link(link));
    return out;
  };
  const std::vector<std::string> want = {"h=2000", "w=200gsm"};
  EXPECT_EQ(keys("https://example.org/foldlab/index.html?preset=paper-fig4#h=2000&w=200gsm"), want);
  EXPECT_EQ(keys("#h=2000&w=200gsm"), want);
  EXPECT_EQ(keys("h=2000&w=200gsm"), want);
  EXPECT_EQ(keys("&&h=2000&&w=200gsm&"), want);
  EXPECT_TRUE(keys("https://example.org/foldlab/").empty());
  EXPECT_TRUE(keys("#").empty());
  // Only the first '=' splits: the value keeps the rest.
  EXPECT_EQ(keys("#t=1=2"), std::vector<std::string>{"t=1=2"});
  Parameters p;
  ASSERT_TRUE(apply_link(p, "https://example.org/x#h=2000&w=200gsm").empty());
  EXPECT_EQ(p.hanging.height_mm, 2000.0);
  EXPECT_EQ(p.fabric.weight_N_per_mm2, 200 * 9.81e-9);
}

TEST(Link, AnHtmlEscapedAmpersandReadsAsTheAmpersand) {
  // A link pasted through e-mail or a chat that escapes HTML, once or twice.
  const std::vector<std::string> want = {"t=0.4", "E=200", "w=600gsm"};
  EXPECT_EQ(as_set(foldlab::parse_fabric_link("#t=0.4&amp;E=200&amp;w=600gsm")), want);
  EXPECT_EQ(as_set(foldlab::parse_fabric_link("t=0.4&amp;amp;E=200&w=600gsm")), want);
  Parameters p;
  ASSERT_TRUE(apply_link(p, "https://example.org/x#h=2000&amp;w=200gsm").empty());
  EXPECT_EQ(p.hanging.height_mm, 2000.0);
  EXPECT_EQ(p.fabric.weight_N_per_mm2, 200 * 9.81e-9);
  // An escaped '&' inside a value is not a separator: it stays, and the value is no number.
  Parameters q;
  EXPECT_EQ(apply_link(q, "h=2000%26amp%3B").size(), 1u);
}

TEST(Link, PercentEncodingRoundTripsEveryByte) {
  std::string every;
  for (int b = 0; b < 256; ++b) {
    every += static_cast<char>(b);
  }
  const std::string encoded = foldlab::percent_encode(every);
  for (const char c : encoded) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ||
                       c == '_' || c == '~' || c == '%';
    EXPECT_TRUE(plain) << static_cast<int>(c);
  }
  EXPECT_EQ(encoded.size(), 66u + 3u * (256u - 66u));  // 66 unreserved characters
  EXPECT_EQ(foldlab::percent_decode(encoded), every);
  EXPECT_EQ(foldlab::percent_encode("150 g/m²"), "150%20g%2Fm%C2%B2");
  EXPECT_EQ(foldlab::percent_encode("1e+20"), "1e%2B20");
  // Lower-case hex reads too; a '%' that starts no escape and '+' stay as they are.
  EXPECT_EQ(foldlab::percent_decode("%c2%b2%2b"), "²+");
  EXPECT_EQ(foldlab::percent_decode("100%"), "100%");
  EXPECT_EQ(foldlab::percent_decode("%zz%4"), "%zz%4");
  EXPECT_EQ(foldlab::percent_decode("1000+400"), "1000+400");
}

TEST(Link, EncodedUnitsAndArithmeticReadAsTyped) {
  Parameters encoded;
  ASSERT_TRUE(
      apply_link(encoded, "#w=150%20g%2Fm%C2%B2&h=1000%2B400&L=2*700&E=0.165%20GPa").empty());
  EXPECT_EQ(encoded.fabric.weight_N_per_mm2, 150 * 9.81e-9);
  EXPECT_EQ(encoded.hanging.height_mm, 1400.0);
  EXPECT_EQ(encoded.hanging.length_mm, 1400.0);
  EXPECT_EQ(encoded.fabric.youngs_modulus_MPa, 0.165 * 1000.0);
  Parameters plus;
  ASSERT_TRUE(apply_link(plus, "h=1000+400").empty());
  EXPECT_EQ(plus.hanging.height_mm, 1400.0);
}

// A value a slider left: written as the slider shows it (t at three significant digits, w in
// g/m² at the gsm unit's digits), so that a drag leaves no 17-digit noise in a link.
TEST(Link, DraggedValuesAreWrittenWithTheSlidersDigits) {
  Parameters p;
  p.fabric.thickness_mm = 0.23761827878721103;
  p.fabric.weight_N_per_mm2 = 999.9999999999991 * 9.81e-9;
  const Parameters base;
  const std::string dragged = foldlab::fabric_link(p, {&base, {"t", "w"}, ""});
  EXPECT_EQ(dragged, "t=0.238&w=1000gsm");
  // Read back: the values the slider showed, not the ones under the mouse.
  Parameters read = base;
  ASSERT_TRUE(apply_link(read, dragged).empty());
  EXPECT_EQ(read.fabric.thickness_mm, 0.238);
  EXPECT_EQ(read.fabric.weight_N_per_mm2, 1000 * 9.81e-9);
  // Typed (not dragged): exact, and read back bit for bit.
  const std::string typed = foldlab::fabric_link(p, {&base, {}, ""});
  EXPECT_EQ(typed.substr(0, typed.find('&')), "t=0.23761827878721103");
  Parameters exact = base;
  ASSERT_TRUE(apply_link(exact, typed).empty());
  expect_bit_identical(exact, p, typed);
}

// K (c/(1-ν²)) is stored as c: a dragged K writes c with the fewest digits that still give the K
// the slider showed ("%.3g"), and a typed c after it is written exactly again.
TEST(Link, ADraggedKWritesAShortCThatShowsTheSameK) {
  Parameters p;
  ASSERT_FALSE(foldlab::assign_text(p, "K", "37.123456789"));
  const double nu = p.fabric.poisson_ratio;
  const Parameters base;
  const std::string link = foldlab::fabric_link(p, {&base, {"K"}, ""});
  ASSERT_EQ(link.rfind("c=", 0), 0u) << link;
  const std::string c_text = link.substr(2, link.find('&') - 2);
  EXPECT_LE(c_text.size(), 6u) << link;  // not 0.3356... to 17 digits
  Parameters read = base;
  ASSERT_TRUE(apply_link(read, link).empty());
  char shown[32];
  std::snprintf(shown, sizeof shown, "%.3g", read.model.load_constant_c / (1.0 - nu * nu));
  EXPECT_STREQ(shown, "37.1");
  const std::string typed = foldlab::fabric_link(p, {&base, {}, ""});
  Parameters exact = base;
  ASSERT_TRUE(apply_link(exact, typed).empty());
  expect_bit_identical(exact, p, typed);
}

// Keys equal to the preset the reader starts from stay out; B's keys carry their prefix, and a
// link of two fabrics reads back as both.
TEST(Link, KeysEqualToTheBaseAreLeftOutAndBsCarryItsPrefix) {
  const Parameters base =
      foldlab::load_preset(fs::path(FOLDLAB_PRESETS_DIR) / "paper-table1-h1400.json").parameters;
  EXPECT_EQ(foldlab::fabric_link(base, {&base, {}, ""}), "");
  Parameters a = base;
  a.hanging.height_mm = 2000;
  a.model.method = foldlab::Method::exact;
  Parameters b = base;
  b.fabric.thickness_mm = 0.4;
  const std::string link = foldlab::fabric_link(a, {&base, {}, ""}) + "&" +
                           foldlab::fabric_link(b, {&base, {}, foldlab::kLinkBPrefix});
  EXPECT_EQ(link, "h=2000&method=exact&b.t=0.4");
  Parameters read_a = base;
  Parameters read_b = base;
  std::vector<std::string> a_pieces;
  std::vector<std::string> b_pieces;
  for (const LinkAssignment& piece : foldlab::parse_fabric_link(link)) {
    if (piece.key.starts_with(foldlab::kLinkBPrefix)) {
      b_pieces.push_back(piece.key.substr(2) + "=" + piece.text);
    } else {
      a_pieces.push_back(piece.set_text());
    }
  }
  EXPECT_TRUE(foldlab::apply_assignments(read_a, a_pieces).empty());
  EXPECT_TRUE(foldlab::apply_assignments(read_b, b_pieces).empty());
  expect_bit_identical(read_a, a, "A");
  expect_bit_identical(read_b, b, "B");
}

}  // namespace
