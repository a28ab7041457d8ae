// What follows a row of the input table or of the regime table rather than a list of its own: the
// cloth inputs in the strip's order, the caption, the stress report, the benchmark's realistic
// cloths and the help texts; the regimes' properties in the sweep's curves and the stress table.
// Each is checked against the paper's inputs and regimes as written here by hand.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli/sweep.hpp"
#include "app/gui/document.hpp"
#include "app/gui/panels/axis_inputs.hpp"
#include "app/gui/panels/parameters_panel.hpp"
#include "app/gui/picture.hpp"
#include "app/gui/ui_status.hpp"
#include "core/analysis/sweep.hpp"
#include "core/io/preset.hpp"
#include "core/model/settings.hpp"
#include "core/model/solver.hpp"
#include "core/tools/benchmark_cases.hpp"
#include "core/tools/stress.hpp"

namespace foldlab {
namespace {

// The paper's cloth, its hanging and the support displacement: t, E, w, h, L, d.
const std::vector<std::string> kPapersClothInputs = {"t", "E", "w", "h", "L", "d"};

// A cloth of the paper's kind with every input a round number, so that texts can be written out.
Parameters round_cloth() {
  Parameters p;
  p.fabric.thickness_mm = 0.25;
  p.fabric.youngs_modulus_MPa = 160.0;
  p.fabric.weight_N_per_mm2 = 1.5e-6;
  p.fabric.poisson_ratio = 0.3;
  p.hanging.height_mm = 2000.0;
  p.hanging.length_mm = 1400.0;
  p.hanging.support_displacement_mm = 100.0;
  return p;
}

TEST(InputRows, TheClothInputsAreThePapersSixInTheirOrder) {
  std::vector<std::string> keys;
  for (const InputSpec* spec : cloth_inputs()) {
    keys.emplace_back(spec->key);
  }
  EXPECT_EQ(keys, kPapersClothInputs);
}

// A cloth input is one a person sets: it has a slider in the panel's list, the stress test draws
// it (so that its report names it) and the benchmark's realistic cloths draw it.
TEST(InputRows, EveryClothInputHasASliderAStressRangeAndARealisticRange) {
  for (const InputSpec* spec : cloth_inputs()) {
    EXPECT_EQ(spec->place, InputPlace::list) << spec->key;
    EXPECT_FALSE(spec->expert) << spec->key << ": a beginner sees the cloth";
    EXPECT_TRUE(spec->sampled) << spec->key;
    EXPECT_GT(spec->realistic_lo, 0.0) << spec->key;
    EXPECT_TRUE(spec->realistic_hi > spec->realistic_lo ||
                (spec->upper_bound != nullptr && spec->realistic_part_of_upper_bound > 0.0))
        << spec->key;
  }
}

// The report names every input the test draws, the six of the cloth and ν, with its value in
// full.
TEST(InputRows, TheStressReportNamesEveryClothInputOfACase) {
  StressReport report;
  report.failures.push_back(
      {.parameters = round_cloth(), .method = Method::exact, .n = 7, .regime = Regime::wrinkled});
  const nlohmann::json inputs = stress_to_json(report).at("failures").at(0).at("inputs");
  EXPECT_EQ(inputs, (nlohmann::json{{"thickness_mm", 0.25},
                                    {"youngs_modulus_MPa", 160.0},
                                    {"weight_N_per_mm2", 1.5e-6},
                                    {"poisson_ratio", 0.3},
                                    {"height_mm", 2000.0},
                                    {"length_mm", 1400.0},
                                    {"support_displacement_mm", 100.0}}));
  const std::string table = stress_table(report);
  EXPECT_NE(table.find("FAILED: exact, 0 ms, n = 7 (wrinkled): t = 0.25 mm, E = 160 MPa, "
                       "w = 1.5e-06 N/mm², nu = 0.3, h = 2000 mm, L = 1400 mm, d = 100 mm\n"),
            std::string::npos)
      << table;
}

// The regimes whose residuals the stress test bounds are those where eqs. 8 and 9 both hold:
// every regime with folds of depth and the stiff one's single fold.
TEST(InputRows, TheStressTableNamesTheRegimesWhoseEquationsHold) {
  const std::string table = stress_table(StressReport{});
  EXPECT_NE(table.find("(residuals over wrinkled, stiff and n_cycle solutions;"), std::string::npos)
      << table;
}

// The draws as they were written before the rows carried the ranges: the benchmark's cases, and
// every figure measured on them, must not move.
TEST(InputRows, TheRealisticClothsAreDrawnAsTheyWereFromTheirOwnRanges) {
  std::mt19937_64 rows(20260412);
  std::mt19937_64 by_hand(20260412);
  for (int i = 0; i < 200; ++i) {
    const Parameters drawn = realistic_fabric(rows);
    auto log_uniform = [&by_hand](double lo, double hi) {
      std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
      return std::exp(u(by_hand));
    };
    Parameters expected;
    expected.fabric.thickness_mm = log_uniform(0.05, 1.5);
    expected.fabric.youngs_modulus_MPa = log_uniform(5.0, 2000.0);
    expected.fabric.weight_N_per_mm2 = log_uniform(3e-7, 1e-5);
    expected.hanging.height_mm = log_uniform(300.0, 3000.0);
    expected.hanging.length_mm = log_uniform(300.0, 3000.0);
    expected.hanging.support_displacement_mm = log_uniform(1.0, 0.3 * expected.hanging.length_mm);
    ASSERT_EQ(drawn, expected) << "draw " << i;
  }
}

TEST(InputRows, TheSweepsHelpNamesEachSweepableInputUnderItsScale) {
  EXPECT_EQ(sweepable_keys_on_scale(true), "t, E, w, K");
  EXPECT_EQ(sweepable_keys_on_scale(false), "nu, h, L, d");
  CLI::App app;
  cli::sweep_command::Options options;
  cli::sweep_command::declare(app, options);
  CLI::App* sweep = app.get_subcommand("sweep");
  EXPECT_EQ(sweep->get_option("--log")->get_description(),
            "logarithmic spacing (default for t, E, w, K)");
  EXPECT_EQ(sweep->get_option("--linear")->get_description(),
            "linear spacing (default for nu, h, L, d)");
}

TEST(InputRows, TheExpertBoxsHelpNamesTheClothAndTheModelsSettings) {
  EXPECT_EQ(gui::expert_mode_help(),
            "Beginners see the cloth (t, E, w, h, L, d) and its shape; experts also the model's "
            "settings (ν, K, p, method, wrinkle law, span rule, Int[]) and the 3D grid.");
}

// ν's whole range is narrow: a new axis over it runs from 0 to 0.49; the others around the value.
TEST(InputRows, ANewAxisOverNuRunsOverItsTypicalRange) {
  double from = 0.0;
  double to = 0.0;
  gui::default_range("nu", 0.3, from, to);
  EXPECT_EQ(from, 0.0);
  EXPECT_EQ(to, 0.49);
  gui::default_range("h", 1000.0, from, to);
  EXPECT_EQ(from, 300.0);
  EXPECT_EQ(to, 3000.0);
  gui::default_range("t", 0.25, from, to);
  EXPECT_DOUBLE_EQ(from, 0.025);
  EXPECT_DOUBLE_EQ(to, 2.5);
}

// w in the unit the explorer shows: 1.5e-6 N/mm² / 9.81e-9 = 152.9 g/m², "153" to 3 digits. The
// caption keeps each input whole (no-break spaces).
TEST(InputRows, ThePicturesCaptionListsEveryClothInput) {
  Preset preset = default_preset();
  preset.name = "round";
  preset.parameters = round_cloth();
  gui::UiStatus status;
  gui::Document document(preset, "", status);
  const std::vector<std::string> lines = gui::picture_caption(document);
  ASSERT_FALSE(lines.empty());
  std::string expected;
  for (const char* input :
       {"t = 0.25 mm", "E = 160 MPa", "w = 153 g/m²", "h = 2000 mm", "L = 1400 mm", "d = 100 mm"}) {
    std::string whole;
    for (const char c : std::string(input)) {
      whole += c == ' ' ? std::string("\u00A0") : std::string(1, c);
    }
    expected += (expected.empty() ? "" : "     ") + whole;
  }
  EXPECT_EQ(lines.back(), expected);
}

// The model's regimes: folds of depth that a sweep's curves join where the law counted them
// (wrinkled, and n cycling); eqs. 8 and 9 hold there and in the stiff regime's single fold.
TEST(RegimeRows, ASweepsCurvesJoinTheRegimesWithFolds) {
  std::vector<SweepPoint> points;
  for (const Regime regime : {Regime::wrinkled, Regime::n_cycle, Regime::stiff, Regime::no_slack,
                              Regime::short_cloth, Regime::negligible_slack}) {
    SweepPoint point;
    point.value = static_cast<double>(points.size());
    point.valid = true;
    point.regime = regime;
    point.n = 3;
    point.z_max_mm = 40.0;
    points.push_back(point);
  }
  const SweepCurves curves = sweep_curves(points);
  const std::vector<bool> joined = {true, true, false, false, false, false};
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(!std::isnan(curves.n[i]), joined[i]) << to_string(points[i].regime);
    EXPECT_EQ(!std::isnan(curves.z_max_mm[i]), joined[i]) << to_string(points[i].regime);
  }
  // Every regime but the plain wrinkled one is a band of its own, under its label.
  const std::vector<RegimeBand> bands = regime_bands(points, false);
  std::vector<std::string> names;
  for (const RegimeBand& band : bands) {
    names.push_back(band.name);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"n cycles", "stiff", "no slack", "short cloth",
                                             "negligible slack"}));
}

}  // namespace
}  // namespace foldlab
