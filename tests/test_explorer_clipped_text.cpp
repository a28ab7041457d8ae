// Text a reader cannot read whole, found from the drawn glyphs (app/gui/clipped_text.hpp), and
// the screens of a phone and a tablet emulated on any other (`device_pixel_ratio`, `pointer`).
#include "explorer_fixture.hpp"

#include "app/gui/clipped_text.hpp"

namespace foldlab::gui {
namespace {

// One frame of a bare ImGui window 120 px wide at (0, 0) that draws what `body` draws; returns
// what the detector finds in it.
std::vector<ClippedText> clipped_in_narrow_window(const std::function<void()>& body) {
  ImGuiContext* context = foldlab::testing::create_headless_imgui(ImVec2(800, 600));
  std::vector<ClippedText> found;
  for (int frame = 0; frame < 2; ++frame) {  // the window's size settles over the first frame
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(120.0f, 400.0f), ImGuiCond_Always);
    ImGui::Begin("Narrow###narrow", nullptr, ImGuiWindowFlags_NoScrollbar);
    body();
    ImGui::End();
    ImGui::Render();
    found = clipped_text(*ImGui::GetDrawData(), *ImGui::GetIO().Fonts->Fonts[0]);
  }
  ImGui::DestroyContext(context);
  return found;
}

TEST(ClippedText, TextThatFitsIsNotCounted) {
  const std::vector<ClippedText> found = clipped_in_narrow_window([] {
    ImGui::TextUnformatted("short");
    ImGui::Button("OK");
    // Wrapped at spaces, every word whole.
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted("one two three four five six seven eight nine ten");
    ImGui::PopTextWrapPos();
    // Two items, one line each: their lines stand an item spacing apart, not a wrap's line.
    ImGui::TextUnformatted("12.");
    ImGui::TextUnformatted("5 mm");
  });
  EXPECT_TRUE(found.empty()) << found.front().panel << ": " << found.front().text;
}

TEST(ClippedText, ALabelPastThePanelsEdgeIsCut) {
  // ProggyClean is 7 px a character: 36 characters are 252 px, in a window 120 px wide. (A cut
  // that falls on a space leaves no glyph across the edge, and is not seen: no space here.)
  const std::vector<ClippedText> found = clipped_in_narrow_window(
      [] { ImGui::TextUnformatted("A_label_far_too_long_for_this_panel"); });
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].panel, "narrow");
  EXPECT_EQ(found[0].how, "cut");
  EXPECT_TRUE(found[0].text.starts_with("A_label_far")) << found[0].text;
  EXPECT_LT(found[0].text.size(), std::string("A_label_far_too_long_for_this_panel").size());
}

TEST(ClippedText, AWordWiderThanTheWrapIsWrappedInsideAWord) {
  const std::vector<ClippedText> found = clipped_in_narrow_window([] {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted("Supercalifragilisticexpialidocious");
    ImGui::PopTextWrapPos();
  });
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found[0].panel, "narrow");
  EXPECT_EQ(found[0].how, "wrapped inside a word");
  EXPECT_TRUE(found[0].text.starts_with("Supercal")) << found[0].text;
  EXPECT_NE(found[0].text.find('\n'), std::string::npos) << found[0].text;
}

TEST_F(ExplorerTest, APhoneIsEmulatedByItsPixelRatioAndPointer) {
  EXPECT_FALSE(explorer_->appearance().coarse_pointer());
  EXPECT_EQ(explorer_->set_view("device_pixel_ratio", "3"), std::nullopt);
  EXPECT_EQ(explorer_->set_view("pointer", "coarse"), std::nullopt);
  ImGui::GetIO().DisplaySize = ImVec2(1170, 2532);
  frame();
  frame();
  EXPECT_FLOAT_EQ(explorer_->appearance().pixel_ratio(), 3.0f);
  EXPECT_TRUE(explorer_->appearance().coarse_pointer());
  EXPECT_NE(ImGui::GetIO().ConfigFlags & ImGuiConfigFlags_IsTouchScreen, 0);
  // A frame is 44 CSS px, 132 device pixels, tall.
  EXPECT_NEAR(ImGui::GetFrameHeight(), 132.0f, 0.5f);
  EXPECT_TRUE(shows_one_view());
  EXPECT_EQ(explorer_->presented(), "cloth");
  const nlohmann::json view = explorer_->view_settings().report();
  EXPECT_EQ(view["pointer"], "coarse");
  EXPECT_EQ(view["device_pixel_ratio"], 3.0);
  // Not a setting a session keeps, and only ratios a screen has.
  EXPECT_NE(explorer_->set_view("device_pixel_ratio", "9"), std::nullopt);
  EXPECT_NE(explorer_->set_view("pointer", "pen"), std::nullopt);
  // Back to the screen's own.
  EXPECT_EQ(explorer_->set_view("device_pixel_ratio", "0"), std::nullopt);
  EXPECT_EQ(explorer_->set_view("pointer", "screen"), std::nullopt);
  ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
  frame();
  EXPECT_FLOAT_EQ(explorer_->appearance().pixel_ratio(), 1.0f);
  EXPECT_FALSE(explorer_->appearance().coarse_pointer());
}

TEST_F(ExplorerTest, APhoneHeldSidewaysShowsOneViewATabletItsTiles) {
  ASSERT_EQ(explorer_->set_view("device_pixel_ratio", "3"), std::nullopt);
  ASSERT_EQ(explorer_->set_view("pointer", "coarse"), std::nullopt);
  // 844 x 360 CSS px: lower than 30 lines of the tests' built-in 13 px font (DejaVu's 15 px
  // lines make 844 x 390 one view too).
  ImGui::GetIO().DisplaySize = ImVec2(2532, 1080);
  frame();
  frame();
  EXPECT_TRUE(shows_one_view());
  ASSERT_EQ(explorer_->set_view("device_pixel_ratio", "2"), std::nullopt);
  ImGui::GetIO().DisplaySize = ImVec2(2048, 1536);  // 1024 x 768 CSS px
  frame();
  frame();
  EXPECT_FALSE(shows_one_view());
}

TEST_F(ExplorerTest, AFingersChangeOfAnInputIsSaidInTheToast) {
  // A mouse's change shows where the mouse is: no toast.
  ASSERT_EQ(explorer_->set_input("h", 1500.0), std::nullopt);
  frame();
  EXPECT_EQ(explorer_->status().toast(), "");
  ASSERT_EQ(explorer_->set_view("pointer", "coarse"), std::nullopt);
  frame();
  frame();
  EXPECT_EQ(explorer_->status().toast(), "");  // nothing changed since
  ASSERT_EQ(explorer_->set_input("h", 1600.0), std::nullopt);
  frame();
  const std::string toast = explorer_->status().toast();
  EXPECT_NE(toast.find("height h = 1600 mm (was 1500 mm)"), std::string::npos) << toast;
  // A drag's value with the digits its slider shows (w in whole g/m²: 1.9613299999999999e-06
  // N/mm² is 199.9317 g/m² at g = 9.81, shown 200), not the 12 of the number stored.
  ASSERT_EQ(explorer_->set_input("w", 1.9613299999999999e-06), std::nullopt);
  frame();
  EXPECT_NE(explorer_->status().toast().find("w = 200 g/m² (was "), std::string::npos)
      << explorer_->status().toast();
  // Two values the slider shows alike are told apart with all their digits.
  ASSERT_EQ(explorer_->set_input("w", 1.9614e-06), std::nullopt);
  frame();
  EXPECT_NE(explorer_->status().toast().find("w = 199.93883792 g/m² (was 199.931702345 g/m²)"),
            std::string::npos)
      << explorer_->status().toast();
  // Several inputs at once are named by their symbols.
  explorer_->document().apply(Edit::inputs({{"h", 1700.0}, {"L", 3000.0}}));
  frame();
  EXPECT_NE(explorer_->status().toast().find("Changed h, L"), std::string::npos)
      << explorer_->status().toast();
}

TEST_F(ExplorerTest, EveryTargetIsAFingersHeightOnACoarsePointer) {
  ASSERT_EQ(explorer_->set_view("pointer", "coarse"), std::nullopt);
  frame();
  frame();
  EXPECT_GE(smallest_target().height_px, kTouchTargetPx - 0.5f) << smallest_target().what;
  const nlohmann::json state = explorer_state_json(*explorer_);
  EXPECT_GE(state["layout"]["smallest_target"]["height_css_px"].get<double>(), 43.5)
      << state["layout"]["smallest_target"].dump();
}

}  // namespace
}  // namespace foldlab::gui
