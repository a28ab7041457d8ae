// The wrinkle laws behind the solver: Cerda and Mahadevan's wavelength against its published
// closed form, the count each law gives against the fold amplitudes it returns, and a calibration
// that finds a law's planted constant on rows that law "measured".
#include <array>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/analysis/calibration.hpp"
#include "core/io/preset.hpp"
#include "core/model/settings.hpp"
#include "core/model/solver.hpp"
#include "core/model/wrinkle_law.hpp"

namespace foldlab {
namespace {

Parameters table1_h1400(WrinkleLawKind law) {
  Parameters p = load_preset(std::filesystem::path(FOLDLAB_PRESETS_DIR) / "paper-table1-h1400.json")
                     .parameters;
  p.model.method = Method::exact;
  p.model.law = law;
  p.model.load_constant_c = wrinkle_law(law).published_load_constant_c();
  p.model.stress_exponent_p = 1.0;
  return p;
}

// lambda = (2 pi L t)^(1/2) / (3 (1 - nu²) gamma)^(1/4) with L -> l and gamma = w h / (E t),
// written out as Cerda and Mahadevan print it, not through s.
double published_wavelength_mm(const Parameters& p) {
  const double t = p.fabric.thickness_mm;
  const double nu = p.fabric.poisson_ratio;
  const double gamma =
      p.fabric.weight_N_per_mm2 * p.hanging.height_mm / (p.fabric.youngs_modulus_MPa * t);
  return std::sqrt(2.0 * std::numbers::pi * span_mm(p) * t) /
         std::pow(3.0 * (1.0 - nu * nu) * gamma, 0.25);
}

// The keys a user types (docs/model.md's table of laws) and each law's constant: Conci printed
// none, so FoldLab's calibrated c = 26.9 (docs/calibration.md); Cerda and Mahadevan's is
// 4 pi² / 3 = 39.478 / 3 = 13.159.
TEST(WrinkleLaw, EveryLawHasAKeyThatParsesBackAndATitle) {
  struct Row {
    const char* key;
    WrinkleLawKind kind;
    double c;
  };
  const Row rows[] = {{"conci", WrinkleLawKind::conci, 26.9},
                      {"cerda-mahadevan", WrinkleLawKind::cerda_mahadevan, 13.159}};
  ASSERT_EQ(wrinkle_laws().size(), std::size(rows));
  for (const Row& row : rows) {
    WrinkleLawKind parsed{};
    ASSERT_TRUE(parse_wrinkle_law(row.key, parsed)) << row.key;
    EXPECT_EQ(parsed, row.kind);
    const WrinkleLaw& law = wrinkle_law(row.kind);
    EXPECT_EQ(law.key(), row.key);
    EXPECT_FALSE(law.title().empty());
    EXPECT_NEAR(law.published_load_constant_c(), row.c, 5e-4) << row.key;
  }
  WrinkleLawKind untouched = WrinkleLawKind::cerda_mahadevan;
  EXPECT_FALSE(parse_wrinkle_law("Conci", untouched));
  EXPECT_EQ(untouched, WrinkleLawKind::cerda_mahadevan);
}

TEST(WrinkleLaw, CerdaMahadevanSpacingIsThePublishedWavelength) {
  for (double h : {900.0, 1400.0, 2350.0}) {
    Parameters p = table1_h1400(WrinkleLawKind::cerda_mahadevan);
    p.hanging.height_mm = h;
    const Solution s = solve(p);
    ASSERT_TRUE(s.count_rule) << h;
    EXPECT_EQ(s.count_rule->spacing, FoldSpacing::even);
    EXPECT_NEAR(s.count_rule->step, published_wavelength_mm(p), 1e-9 * s.count_rule->step) << h;
    EXPECT_FALSE(s.Q7);  // Q7 is Conci's
  }
  // By hand for Table 1, h = 1400 mm: gamma = 1.5e-6 x 1400 / (165 x 0.25) = 5.0909e-5,
  // lambda = sqrt(2 pi 1300 0.25) / (2.73 gamma)^(1/4) = 45.19 / 0.10858 = 416.2 mm.
  EXPECT_NEAR(solve(table1_h1400(WrinkleLawKind::cerda_mahadevan)).count_rule->step, 416.2, 0.1);
}

// Whatever the law, the reported n is eq. 10's Int[] at the reported a_n (the exact method's fixed
// point), and eqs. 8 and 9 hold to 1e-10.
TEST(WrinkleLaw, EachLawsNIsItsOwnCountAtTheReportedAmplitudes) {
  for (const WrinkleLaw* law : wrinkle_laws()) {
    for (double h : {900.0, 1400.0, 2350.0, 4000.0}) {
      Parameters p = table1_h1400(law->kind());
      p.hanging.height_mm = h;
      const Solution s = solve(p);
      ASSERT_EQ(s.regime, Regime::wrinkled) << law->key() << " h " << h;
      ASSERT_TRUE(s.count_rule);
      const double a0 = s.a_mm.front();
      const double an = s.a_mm.back();
      const double x = law->kind() == WrinkleLawKind::conci
                           ? std::log(a0 / an) / std::log(*s.Q7)
                           : (a0 - an) / published_wavelength_mm(p);
      EXPECT_EQ(s.n, std::max(1, static_cast<int>(std::nearbyint(x)))) << law->key() << " " << h;
      EXPECT_LT(std::abs(s.residual_length), 1e-10);
      EXPECT_LT(std::abs(s.residual_height), 1e-10);
    }
  }
}

// The laws differ where they should: with h the wavelength law's count grows as h/lambda with
// lambda ~ h^(-1/4), faster than the tables (5 -> 8 folds for h 900 -> 2350 mm).
TEST(WrinkleLaw, TheWavelengthLawsCountGrowsFasterWithHeight) {
  auto n_at = [](WrinkleLawKind law, double h) {
    Parameters p = table1_h1400(law);
    p.hanging.height_mm = h;
    return solve(p).n;
  };
  const int cm_low = n_at(WrinkleLawKind::cerda_mahadevan, 900.0);
  const int cm_high = n_at(WrinkleLawKind::cerda_mahadevan, 2350.0);
  EXPECT_GE(cm_high, 2 * cm_low);
  EXPECT_GT(cm_high, cm_low);
}

TEST(WrinkleLaw, IsAnInputOfTheTableAndAPresetField) {
  Parameters p;
  EXPECT_FALSE(apply_setting(p, "law", "cerda-mahadevan"));
  EXPECT_EQ(p.model.law, WrinkleLawKind::cerda_mahadevan);
  const auto error = apply_setting(p, "law", "hooke");
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("conci, cerda-mahadevan"), std::string::npos) << *error;
  EXPECT_EQ(p.model.law, WrinkleLawKind::cerda_mahadevan);
  // A preset file holds it as model.law, by the key a user types.
  Preset wavelength = default_preset();
  wavelength.parameters.model.law = WrinkleLawKind::cerda_mahadevan;
  EXPECT_EQ(preset_to_json(wavelength).at("model").at("law"), "cerda-mahadevan");
  nlohmann::json file = preset_to_json(default_preset());
  file["model"]["law"] = "cerda-mahadevan";
  EXPECT_EQ(preset_from_json(file, "wavelength.json").parameters.model.law,
            WrinkleLawKind::cerda_mahadevan);
}

// Rows measured by the wavelength law at a planted K: the same search that fits Conci's law finds
// it (the scan starts at the law's own ceiling, above s = 1).
TEST(WrinkleLaw, CalibrationFindsAPlantedConstantOfTheWavelengthLaw) {
  const Parameters base = table1_h1400(WrinkleLawKind::cerda_mahadevan);
  const double planted_K = 2.0;
  std::vector<Measurement> rows;
  for (const auto& [t, E, w, h, L, d] :
       std::vector<std::array<double, 6>>{{0.25, 165, 1.5e-6, 900, 1400, 100},
                                          {0.25, 165, 1.5e-6, 2350, 1400, 100},
                                          {0.35, 150, 1.0e-6, 1450, 900, 85},
                                          {0.35, 150, 5.4e-6, 1450, 900, 85},
                                          {0.15, 80, 1.2e-6, 1800, 1600, 150},
                                          {0.45, 200, 6e-6, 1100, 1100, 70}}) {
    Measurement m;
    m.inputs.fabric = {t, E, w, base.fabric.poisson_ratio};
    m.inputs.hanging = {h, L, d};
    const Solution s = solve(with_constants(parameters_for(m, base), planted_K, 1.0));
    m.observed = {s.n, s.z_max_mm, s.Q};
    rows.push_back(m);
  }
  CalibrationOptions options;
  options.fit = FitConstants::K;
  const std::optional<FittedConstants> fit = fit_constants(rows, base, options);
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->score.n_missed, 0);
  EXPECT_LT(fit->score.mean_relative_error, 1e-9);
  EXPECT_LE(fit->K_low, planted_K);
  EXPECT_GT(fit->K_high, planted_K);
}

}  // namespace
}  // namespace foldlab
