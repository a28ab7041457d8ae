// Scripts played through the widgets, and the play button's animation of one input.
#include "explorer_fixture.hpp"

namespace foldlab::gui {
namespace {

// A play button sweeps one input while everything re-solves; pause leaves the value.
TEST_F(ExplorerTest, ThePlayButtonSweepsOneInputAndPauseLeavesItAsOneUndoStep) {
  EXPECT_FALSE(explorer_->animating());
  const std::uint64_t solves = evaluations(Stage::solution);
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "play"}}}}}, [&] { frame(); }), 0);
  EXPECT_TRUE(explorer_->animating()) << "the frame loop must keep drawing";
  std::vector<double> heights;
  for (int i = 0; i < 30; ++i) {
    frame();
    heights.push_back(height_mm());
  }
  // h's slider: 100 to 5000 mm, all valid with L = 1400 mm; one way in 4 s, at 60 frames a
  // second 240 frames, so (5000 - 100) / 240 = 20.4 mm a frame.
  for (std::size_t i = 1; i < heights.size(); ++i) {
    // (ImGui's frame time is a float: 1/60 s to 7 digits.)
    EXPECT_NEAR(heights[i] - heights[i - 1], 4900.0 / 240.0, 1e-4) << i;
  }
  EXPECT_GE(evaluations(Stage::solution), solves + 30) << "the results re-solve every frame";
  EXPECT_EQ(document().undo_depth(), 0u) << "one step, closed at pause";
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "pause"}}}}}, [&] { frame(); }), 0);
  EXPECT_FALSE(explorer_->animating());
  const double paused = height_mm();
  EXPECT_GT(paused, heights.back());
  frame();
  frame();
  EXPECT_EQ(height_mm(), paused);
  EXPECT_EQ(shown().hanging.height_mm, paused);
  EXPECT_EQ(document().undo_depth(), 1u);
  press('Z', true);
  EXPECT_EQ(height_mm(), 1400.0);

  // The range fields show their unit; a typed "to" narrows the next play to 100..1500 mm.
  EXPECT_TRUE(shows(frame(), "100 mm to 5000 mm")) << last_text_;
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "5000 mm"}},
                    {{"key", "ctrl+a"}},
                    {{"type", "1500"}},
                    {{"key", "enter"}},
                    {{"frames", 2}},
                    {{"click", "play"}}}}},
                 [&] { frame(); }),
            0);
  EXPECT_TRUE(shows(frame(), "100 mm to 1500 mm")) << last_text_;
  double highest = 0.0;
  // While it plays the views hold their frame: the fold plot's range and the camera's distance
  // only grow, so the class sees the cloth shrink as h goes down.
  double y_span = 0.0;
  float distance = 0.0f;
  // 1400 to 1500 mm and down towards 100 mm again.
  for (int i = 0; i < 3000 && !(highest > 1450.0 && height_mm() < 300.0); ++i) {
    frame();
    highest = std::max(highest, height_mm());
    const PlotView& fold = panel<FoldPlotPanel>().plot_view();
    EXPECT_GE(fold.y_hi - fold.y_lo, y_span) << "at h = " << height_mm() << " mm";
    EXPECT_GE(panel<ClothViewPanel>().camera().distance_mm, distance) << height_mm();
    y_span = fold.y_hi - fold.y_lo;
    distance = panel<ClothViewPanel>().camera().distance_mm;
  }
  EXPECT_LT(height_mm(), 300.0) << "it came back down";
  EXPECT_NEAR(highest, 1500.0, 1400.0 / 240.0 + 1e-6);
  EXPECT_LE(highest, 1500.0);
}

// A class watches the presented cloth while h plays: the Parameters panel that holds the play
// button is out of sight, and the animation goes on all the same.
TEST_F(ExplorerTest, AnAnimationGoesOnWhileAnotherViewIsPresented) {
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "play"}}}}}, [&] { frame(); }), 0);
  for (const char* presented : {"cloth", "fold_plot"}) {
    ASSERT_EQ(explorer_->set_view("present", presented), std::nullopt);
    frame();
    const double before = height_mm();
    for (int i = 0; i < 10; ++i) {
      frame();
    }
    // One way of 4900 mm in 4 s at 60 frames a second: 20.4 mm a frame.
    EXPECT_NEAR(height_mm() - before, 10.0 * 4900.0 / 240.0, 1e-3) << presented;
    EXPECT_EQ(shown().hanging.height_mm, height_mm()) << presented;
  }
}

// Each frames step is bounded, and so is their sum: 5000 steps of 1000 frames each once ran for
// hours.
TEST(PlayScript, ItsFramesAddUpToAtMostTheCap) {
  nlohmann::json steps = nlohmann::json::array();
  for (int i = 0; i < 100; ++i) {
    steps.push_back({{"frames", 1000}});
  }
  EXPECT_TRUE(play_script_problems({{"steps", steps}}).empty());
  steps.push_back({{"frames", 1}});
  const std::vector<std::string> problems = play_script_problems({{"steps", steps}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("add up to 100001, more than the 100000"), std::string::npos)
      << problems[0];
}

TEST(AnimatedInput, MovesOverTheSlidersRangeWhereTheModelAcceptsIt) {
  const Parameters base = load_preset(kPresetsDir / "paper-table1-h1400.json").parameters;
  // h: the table's typical range, 100 to 5000 mm, all valid with L = 1400 mm.
  const AnimatedInput h("h", base);
  EXPECT_DOUBLE_EQ(h.lo(), 100.0);
  EXPECT_DOUBLE_EQ(h.hi(), 5000.0);
  EXPECT_DOUBLE_EQ(h.value(0), 100.0);    // the first frame starts at the low end
  EXPECT_DOUBLE_EQ(h.value(60), 5000.0);  // 60 frames a way
  // d: its slider reaches 2500 mm, but d < L/2 = 700 mm with L = 1400 mm.
  const AnimatedInput d("d", base);
  EXPECT_DOUBLE_EQ(d.lo(), 0.0);
  EXPECT_LT(d.hi(), 700.0);
  EXPECT_GT(d.hi(), 680.0);
  EXPECT_THROW(AnimatedInput("method", base), app::InputError);
}

TEST_F(ExplorerTest, APlayedScriptFailsAtTheFirstExpectThatDoesNotHold) {
  InputPlayer player({{"steps",
                       {{{"expect", {{"parameters.h_mm", 1400}}}},
                        {{"expect", {{"parameters.h_mm", {100, 200}}}}},
                        {{"expect", {{"parameters.h_mm", 1400}}}}}}},
                     "test script");
  int frames = 0;
  while (player.before_new_frame(ImGui::GetIO(), *explorer_)) {
    frame();
    ++frames;
  }
  EXPECT_LT(frames, 10);
  EXPECT_EQ(player.exit_status(), 1);
  EXPECT_NE(player.failure().find("step 2 "), std::string::npos) << player.failure();
}

// A slider below the edge of a small window cannot be pressed by a person, so a script that drags
// or clicks it fails, saying where it is, rather than pass with the value unchanged.
TEST_F(ExplorerTest, APlayedScriptFailsOnASliderOutOfSight) {
  show_at(ImVec2(400, 300));
  for (const char* step : {"drag", "click"}) {
    SCOPED_TRACE(step);
    InputPlayer player(
        {{"steps",
          {{{"frames", 1}},
           {{"frames", 1}},
           step == std::string("drag") ? nlohmann::json{{"drag", "h"}, {"dx", 50}}
                                       : nlohmann::json{{"click", "h"}, {"at", 0.9}}}}},
        "test script");
    while (player.before_new_frame(ImGui::GetIO(), *explorer_)) {
      frame();
    }
    EXPECT_EQ(player.exit_status(), 1);
    EXPECT_NE(player.failure().find("step 3 "), std::string::npos) << player.failure();
    EXPECT_NE(player.failure().find("the slider h is out of sight"), std::string::npos)
        << player.failure();
    EXPECT_EQ(height_mm(), 1400.0);
  }
}

TEST_F(ExplorerTest, AMalformedScriptNamesEveryProblem) {
  try {
    InputPlayer player({{"steps",
                         {{{"drag", "q"}, {"dx", 1}},
                          {{"click", "w"}, {"at", 2}},
                          {{"frames", 3}},
                          {{"type", 5}}}}},
                       "test script");
    FAIL() << "accepted";
  } catch (const app::InputError& e) {
    const std::string message = e.what();
    for (const char* step : {"step 1:", "step 2:", "step 4:"}) {
      EXPECT_NE(message.find(step), std::string::npos) << message;
    }
    EXPECT_EQ(message.find("step 3:"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace foldlab::gui
