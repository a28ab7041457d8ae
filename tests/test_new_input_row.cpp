// A new input is one row of the input table: a throw-away row (the thickness in micrometres, a
// second view of t) is added at run time, before anything reads the table, and every front end
// takes it with no other edit: --set, presets, sweeps, the stress sampler, the explorer's sliders
// and a played script's expects. Its own process (ctest runs each test alone), so that the row
// never reaches another suite.
#include <gtest/gtest.h>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "app/gui/explorer.hpp"
#include "app/gui/input_player.hpp"
#include "app/gui/renderer.hpp"
#include "core/analysis/sweep.hpp"
#include "core/io/preset.hpp"
#include "core/model/settings.hpp"
#include "core/model/settings_testing.hpp"
#include "core/model/solver.hpp"
#include "core/tools/stress.hpp"
#include "headless_imgui.hpp"
#include "temp_dir.hpp"

namespace foldlab {
namespace {

namespace fs = std::filesystem;

// 20 to 2000 µm: narrower than t's own typical range (0.01 to 5 mm), so that the stress
// sampler's draws show which row set the thickness last.
const InputSpec kMicrometres{
    .key = "t_um",
    .name = "thickness in micrometres",
    .unit = "µm",
    .field = "t_um",
    .preset = "/fabric/thickness_um",
    .help = "fabric thickness in micrometres",
    .valid = {1.0, 50000.0, false, false},
    .why = "from 1 micrometre to 50 mm",
    .typical_lo = 20.0,
    .typical_hi = 2000.0,
    .scale = InputScale::logarithmic,
    .format = "%.4g",
    .place = InputPlace::list,
    .sampled = true,
    .access = {[](const Parameters& p) { return 1000.0 * p.fabric.thickness_mm; },
               [](Parameters& p, double um) { p.fabric.thickness_mm = um / 1000.0; }},
};

class NewInputRow : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { add_input_row_for_testing(kMicrometres); }
};

TEST_F(NewInputRow, IsSetByKeyWithItsUnitAndRefusedOutsideItsRange) {
  Parameters p;
  EXPECT_TRUE(apply_assignments(p, {"t_um=300"}).empty());
  EXPECT_DOUBLE_EQ(p.fabric.thickness_mm, 0.3);
  EXPECT_DOUBLE_EQ(*numeric_setting(p, "t_um"), 300.0);
  EXPECT_TRUE(apply_assignments(p, {"t_um=0.5"}).empty());  // kept as typed, refused by validate
  const std::vector<ValidationIssue> issues = validate(p);
  EXPECT_TRUE(std::any_of(issues.begin(), issues.end(), [](const ValidationIssue& issue) {
    return issue.field == "t_um" &&
           issue.message.starts_with(
               "thickness in micrometres t_um = 0.5 µm must be between 1 and 50,000 µm: from 1 "
               "micrometre");
  })) << format_issues(issues);
}

TEST_F(NewInputRow, IsWrittenToAndReadFromAPreset) {
  Preset preset = default_preset();
  set_input(preset.parameters, "t", 0.42);
  const nlohmann::json written = preset_to_json(preset);
  EXPECT_DOUBLE_EQ(written.at("fabric").at("thickness_um").get<double>(), 420.0);

  nlohmann::json edited = written;
  edited["fabric"]["thickness_um"] = 250.0;  // the later row wins, as a later --set does
  const Preset read = preset_from_json(edited, "edited.json");
  EXPECT_DOUBLE_EQ(read.parameters.fabric.thickness_mm, 0.25);
}

TEST_F(NewInputRow, IsASweepAxis) {
  const auto& keys = sweepable_keys();
  ASSERT_NE(std::find(keys.begin(), keys.end(), "t_um"), keys.end());
  const std::vector<SweepPoint> points =
      sweep(default_preset().parameters, {"t_um", 100.0, 1000.0, 3, false});
  ASSERT_EQ(points.size(), 3u);
  for (const auto& [point, t_mm] :
       {std::pair{points.front(), 0.1}, std::pair{points.back(), 1.0}}) {
    Parameters p = default_preset().parameters;
    p.fabric.thickness_mm = t_mm;
    const Solution s = solve(p);
    EXPECT_TRUE(point.valid);
    EXPECT_EQ(point.n, s.n) << t_mm;
    EXPECT_DOUBLE_EQ(point.z_max_mm, s.z_max_mm) << t_mm;
  }
}

TEST_F(NewInputRow, IsDrawnByTheStressSamplerOverItsTypicalRange) {
  double lo = 1e9;
  double hi = 0.0;
  for (int i = 1; i < 2000; ++i) {
    const double t = stress_sample(5, i).fabric.thickness_mm;
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  // Log-uniform over 20-2000 µm: 2000 draws come within 1 % (in log) of both ends.
  EXPECT_GE(lo, 0.02);
  EXPECT_LT(lo, 0.02 * std::pow(100.0, 0.01));
  EXPECT_LE(hi, 2.0);
  EXPECT_GT(hi, 2.0 / std::pow(100.0, 0.01));
}

class NewInputRowInTheExplorer : public foldlab::testing::TempDirTest {
 protected:
  NewInputRowInTheExplorer() : TempDirTest("foldlab_new_row_") {}
  static void SetUpTestSuite() { add_input_row_for_testing(kMicrometres); }
};

TEST_F(NewInputRowInTheExplorer, HasASliderThatAPlayedScriptDragsAndExpects) {
  ImGuiContext* context = foldlab::testing::create_headless_imgui(ImVec2(1280, 800));
  const fs::path presets = FOLDLAB_PRESETS_DIR;
  gui::NullRenderer renderer;
  auto explorer = std::make_unique<gui::Explorer>(
      load_preset(presets / "paper-table1-h1400.json"),
      (presets / "paper-table1-h1400.json").string(), false,
      gui::ExplorerOptions{
          presets, dir_ / "user-presets", {}, "equations", {}, dir_ / "measurements.csv", dir_},
      renderer);
  const auto frame = [&] {
    explorer->prepare_frame();
    ImGui::NewFrame();
    explorer->frame();
    ImGui::Render();
  };
  frame();
  frame();
  EXPECT_TRUE(explorer->report().at("sliders").contains("t_um"));
  // 0.25 mm is 250 µm; a drag to the right thickens the cloth, seen by both rows.
  const nlohmann::json script = {
      {"steps",
       {{{"expect", {{"parameters.t_um", 250.0}}}},
        {{"drag", "t_um"}, {"dx", 40}},
        {{"expect", {{"parameters.t_um", {260.0, 2000.0}}, {"parameters.t_mm", {0.26, 2.0}}}}}}}};
  gui::InputPlayer player(script, "new row script");
  while (player.before_new_frame(ImGui::GetIO(), *explorer)) {
    frame();
  }
  EXPECT_EQ(player.exit_status(), 0) << player.failure();
  // A value set through the new row is the cloth's thickness in the old row's unit: 300 µm is
  // 0.3 mm.
  ASSERT_EQ(explorer->set_input("t_um", 300.0), std::nullopt);
  EXPECT_DOUBLE_EQ(explorer->edited().fabric.thickness_mm, 0.3);
  EXPECT_DOUBLE_EQ(*numeric_setting(explorer->edited(), "t"), 0.3);
  explorer.reset();
  ImGui::DestroyContext(context);
}

}  // namespace
}  // namespace foldlab
