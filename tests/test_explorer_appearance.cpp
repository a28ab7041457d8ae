// How things read: colour contrast in both themes, wrapped text, and the fonts' Greek.
#include "app/gui/input_words.hpp"
#include "explorer_fixture.hpp"

namespace foldlab::gui {
namespace {

TEST(Contrast, MatchesHandComputedWcagRatios) {
  const ImVec4 black(0, 0, 0, 1);
  const ImVec4 white(1, 1, 1, 1);
  EXPECT_NEAR(contrast_ratio(black, white), 21.0, 1e-9);
  EXPECT_NEAR(contrast_ratio(white, black), 21.0, 1e-9);
  EXPECT_NEAR(contrast_ratio(white, white), 1.0, 1e-12);
  // #767676 on white: 118/255 = 0.46275 -> ((0.46275 + 0.055) / 1.055)^2.4 = 0.18116 (grey, so
  // that is L), and 1.05 / 0.23116 = 4.542: the lightest grey that passes 4.5:1 on white.
  const float grey = 118.0f / 255.0f;
  EXPECT_NEAR(contrast_ratio(ImVec4(grey, grey, grey, 1), white), 4.542, 0.001);
  // Pure red: L = 0.2126, so 1.05 / 0.2626 = 3.998 on white and 0.2626 / 0.05 = 5.252 on black.
  EXPECT_NEAR(contrast_ratio(ImVec4(1, 0, 0, 1), white), 3.998, 0.001);
  EXPECT_NEAR(contrast_ratio(ImVec4(1, 0, 0, 1), black), 5.252, 0.001);
  // Half-transparent white over black is the grey 0.5: L = 0.21404, 0.26404 / 0.05 = 5.281.
  EXPECT_NEAR(contrast_ratio(blend_over(ImVec4(1, 1, 1, 0.5f), black), black), 5.281, 0.001);
}

TEST(Contrast, FoldColoursReadOnThePlotBackgroundInBothThemes) {
  for (const bool light : {false, true}) {
    const ImVec4 background = plot_background(light);
    const FoldColours colours = fold_colours(light);
    EXPECT_GE(contrast_ratio(colours.positive, background), 4.5) << "light " << light;
    EXPECT_GE(contrast_ratio(colours.negative, background), 4.5) << "light " << light;
  }
  // The blue the plot used before on the dark theme's plot: the 1.3:1 a projector washes out.
  const ImVec4 old_blue(31 / 255.0f, 58 / 255.0f, 147 / 255.0f, 1.0f);
  EXPECT_NEAR(contrast_ratio(old_blue, plot_background(false)), 1.3, 0.1);
}

// The text colours that read weakly on a light background before (yellow supports, the green
// success tag, amber notes): each at least 4.5:1 against what it is drawn on, in both themes.
TEST(Contrast, TextAndMarkerColoursReadInBothThemes) {
  const struct {
    const char* name;
    const ThemedColour* colour;
  } texts[] = {{"error", &kErrorText},
               {"success", &kOkText},
               {"note", &kNoteText},
               {"dim", &kDimText},
               {"section", &kSectionText}};
  for (const bool light : {false, true}) {
    SCOPED_TRACE(light ? "light theme" : "dark theme");
    for (const auto& t : texts) {
      EXPECT_GE(contrast_ratio(t.colour->get(light), window_background(light)), 4.5) << t.name;
    }
    for (const ThemedColour* mark : {&kSupportMarker, &kSweepCurve, &kPaperPoint, &kCurrentValue}) {
      EXPECT_GE(contrast_ratio(mark->get(light), plot_background(light)), 4.5);
    }
  }
  // What the light theme showed before: the dark theme's amber on its 0.94 grey, about 1.6:1.
  EXPECT_LT(contrast_ratio(kNoteText.get(false), window_background(true)), 2.0);
  EXPECT_NEAR(relative_luminance(0.94, 0.94, 0.94), 0.8689, 1e-4);  // ((0.94 + 0.055) / 1.055)^2.4
  EXPECT_NEAR(window_background(true).x, 0.94f, 1e-6);
}

// Marks that are not text need 3:1 (WCAG 1.4.11). On the light theme the 3D view's yellow supports
// on its light grey backdrop were about 1.3:1, and an unchecked checkbox (near-white on the panel's
// grey) had no edge to see.
TEST(Contrast, NonTextMarksReadAtThreeToOneInBothThemes) {
  for (const bool light : {false, true}) {
    SCOPED_TRACE(light ? "light theme" : "dark theme");
    const ImGuiStyle style = theme_style(light);
    const ImVec4 window = window_background(light);
    // A checkbox's edge: its outline against the panel, and against the box's own fill.
    const ImVec4 frame = blend_over(style.Colors[ImGuiCol_FrameBg], window);
    const ImVec4 edge =
        style.FrameBorderSize > 0.0f ? blend_over(style.Colors[ImGuiCol_Border], frame) : frame;
    EXPECT_GE(std::max(contrast_ratio(edge, window), contrast_ratio(frame, window)), 3.0);
  }
  // The 3D view's backdrops (ClothViewPanel) and the supports' colour drawn on them.
  const ImVec4 light_backdrop(0.90f, 0.91f, 0.93f, 1.0f);
  const ImVec4 dark_backdrop(0.16f, 0.17f, 0.20f, 1.0f);
  // A slider's handle on its field in the light theme (pale blue on white was 1.7:1 and hard to
  // find on a projector).
  {
    const ImGuiStyle style = theme_style(true);
    const ImVec4 field = blend_over(style.Colors[ImGuiCol_FrameBg], window_background(true));
    EXPECT_GE(contrast_ratio(blend_over(style.Colors[ImGuiCol_SliderGrab], field), field), 3.0);
    EXPECT_GE(contrast_ratio(blend_over(style.Colors[ImGuiCol_SliderGrabActive], field), field),
              3.0);
  }
  EXPECT_GE(contrast_ratio(kSupportMarker.get(true), light_backdrop), 3.0);
  EXPECT_GE(contrast_ratio(kSupportMarker.get(false), dark_backdrop), 3.0);
  // What it was: the dark theme's yellow on the light backdrop.
  EXPECT_LT(contrast_ratio(ImVec4(0.95f, 0.85f, 0.25f, 1.0f), light_backdrop), 1.5);
}

// Every themed colour a user must read, against what it is drawn on, in both themes; and
// ImGui's own hint grey and slider handle, which the themes change.
TEST(Contrast, EveryThemedColourReadsOnWhatItIsDrawnOn) {
  ASSERT_GE(themed_colours().size(), 14u);
  for (const bool light : {false, true}) {
    SCOPED_TRACE(light ? "light theme" : "dark theme");
    const ImVec4 window = window_background(light);
    const ImVec4 plot = plot_background(light);
    const ImGuiStyle style = theme_style(light);
    const ImVec4 text = style.Colors[ImGuiCol_Text];
    for (const ThemedColourUse& use : themed_colours()) {
      const ImVec4 colour = use.colour->get(light);
      switch (use.on) {
        case Backdrop::window:
          EXPECT_GE(contrast_ratio(colour, window), 4.5) << use.name;
          break;
        case Backdrop::plot:
          EXPECT_GE(contrast_ratio(colour, plot), 4.5) << use.name;
          break;
        case Backdrop::window_and_plot:
          EXPECT_GE(contrast_ratio(colour, window), 4.5) << use.name;
          EXPECT_GE(contrast_ratio(colour, plot), 4.5) << use.name;
          break;
        case Backdrop::under_text:
          EXPECT_GE(contrast_ratio(text, blend_over(colour, window)), 4.5) << use.name;
          break;
        case Backdrop::under_dim_text:
          EXPECT_GE(contrast_ratio(kDimText.get(light), blend_over(colour, plot)), 4.5) << use.name;
          break;
      }
    }
    // Hints and help markers (ImGui's disabled text) on the window and on a plot.
    EXPECT_GE(contrast_ratio(style.Colors[ImGuiCol_TextDisabled], window), 4.5);
    EXPECT_GE(contrast_ratio(style.Colors[ImGuiCol_TextDisabled], plot), 4.5);
    // A slider's value over its handle: the handle blended over the frame over the window.
    const ImVec4 frame = blend_over(style.Colors[ImGuiCol_FrameBg], window);
    EXPECT_GE(contrast_ratio(text, blend_over(style.Colors[ImGuiCol_SliderGrab], frame)), 4.5);
    EXPECT_GE(contrast_ratio(text, blend_over(style.Colors[ImGuiCol_SliderGrabActive], frame)),
              4.5);
  }
  // What the light theme showed before, by hand: the staircase's orange (255, 120, 60) on the
  // 0.94 grey, L = 0.2126 × 1 + 0.7152 × 0.1878 + 0.0722 × 0.0452 = 0.3502, so
  // (0.8689 + 0.05) / (0.3502 + 0.05) = 2.30; ImGui's hint grey 0.6 (L = 0.3185): 2.49.
  const ImVec4 old_staircase(1.0f, 120 / 255.0f, 60 / 255.0f, 1.0f);
  EXPECT_NEAR(contrast_ratio(old_staircase, window_background(true)), 2.30, 0.01);
  EXPECT_NEAR(contrast_ratio(ImVec4(0.6f, 0.6f, 0.6f, 1.0f), window_background(true)), 2.49, 0.01);
}

// The paper's symbols where the font has them, their ASCII names where it has not (the built-in
// font of the headless tests): ν on its slider and in K's name, λ in the results.
// The Results panel's model line once read "p = 0." / "5216" at 150 %: ImGui wraps after a '.'.
TEST_F(ExplorerTest, WrappedTextBreaksOnlyAtSpacesSoNoNumberIsCutInTwo) {
  frame();
  const std::string text =
      "model: calibrated on Conci's Tables 1–2 (K = 1.686, p = 0.5216, 6 rows, exact method)";
  // From the widest word's width on: below it a word is cut, as ImGui cuts it.
  float widest_word = 0.0f;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find(' ', at), text.size());
    widest_word = std::max(widest_word, ImGui::CalcTextSize(text.substr(at, end - at).c_str()).x);
    at = end + 1;
  }
  int wraps = 0;
  for (float width = std::ceil(widest_word); width <= 700.0f; width += 1.0f) {
    const std::string wrapped = wrap_at_spaces(text, width);
    std::string joined = wrapped;
    std::replace(joined.begin(), joined.end(), '\n', ' ');
    ASSERT_EQ(joined, text) << "a break other than at a space, at " << width << " px";
    std::size_t start = 0;
    for (std::size_t end = wrapped.find('\n'); start <= wrapped.size();
         end = wrapped.find('\n', start)) {
      const std::string line = wrapped.substr(start, end == std::string::npos ? end : end - start);
      if (line.find(' ') != std::string::npos) {  // a lone word may be wider than the line
        EXPECT_LE(ImGui::CalcTextSize(line.c_str()).x, width) << line;
      }
      // Greedy: the next line's first word did not fit after this one.
      if (end != std::string::npos) {
        const std::size_t next_space = wrapped.find_first_of(" \n", end + 1);
        const std::string next_word = wrapped.substr(end + 1, next_space - end - 1);
        EXPECT_GT(ImGui::CalcTextSize((line + " " + next_word).c_str()).x, width) << line;
        ++wraps;
      }
      if (end == std::string::npos) {
        break;
      }
      start = end + 1;
    }
  }
  EXPECT_GT(wraps, 100);
  // Lines begin with their own spaces (the Equations tab indents its "= value" lines).
  EXPECT_EQ(wrap_at_spaces("  = 0.0012247\n  = 1.5", 1000.0f), "  = 0.0012247\n  = 1.5");
  // A word wider than the line is cut between characters, so that nothing sticks out.
  const float two_digits = ImGui::CalcTextSize("00").x;
  EXPECT_EQ(wrap_at_spaces("0123456789", two_digits), "01\n23\n45\n67\n89");
  // A path is cut after a folder's '/' ("Saved to …/presets/chiffon.js" over "on" was drawn).
  const float path_width = ImGui::CalcTextSize("/tmp/cfg/presets/chif").x;
  EXPECT_EQ(wrap_at_spaces("Saved to /tmp/cfg/presets/chiffon.json", path_width),
            "Saved to\n/tmp/cfg/presets/\nchiffon.json");
}

// A window squeezed below a word's width (a tiling window manager, xdotool, a phone) once made the
// cut of a long word step past its end: each character still gets a line of its own.
TEST_F(ExplorerTest, WrappingIntoNoWidthPutsEachCharacterOnALine) {
  frame();
  for (const float width : {-50.0f, 0.0f, 1.0f}) {
    EXPECT_EQ(wrap_at_spaces("ab c", width), "a\nb\nc") << width;
    EXPECT_EQ(wrap_at_spaces("", width), "") << width;
    EXPECT_EQ(wrap_at_spaces("ν", width), "ν") << width;  // one character: nothing to cut
  }
}

TEST_F(ExplorerTest, GreekShowsWithDejaVuAndSpeltOutWithTheBuiltInFont) {
  status().set_expert_mode(true);
  frame();
  std::string text = frame();
  EXPECT_NE(text.find("nu (Poisson's ratio)"), std::string::npos) << text;
  EXPECT_NE(text.find("K (eq. 7 constant c/(1-nu²))"), std::string::npos) << text;
  EXPECT_EQ(readable("ν σ λ π Σ ∫ −"), "nu sigma lambda pi Sum Int -");

  open_explorer("map", kDejaVuSans);
  status().set_expert_mode(true);
  frame();
  text = frame();
  // (Spaces in DejaVu's proportional text are not told from narrow gaps: compared without.)
  EXPECT_NE(squeezed(text).find("ν(Poisson'sratio)"), std::string::npos) << text;
  EXPECT_NE(squeezed(text).find("K(eq.7constantc/(1-ν²))"), std::string::npos) << text;
  EXPECT_EQ(squeezed(text).find("nu("), std::string::npos) << text;
  const ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
  for (const unsigned used : {0x03BDu, 0x03C3u, 0x03BBu, 0x03C0u, 0x03A3u, 0x222Bu, 0x2212u}) {
    EXPECT_NE(font->FindGlyphNoFallback(static_cast<ImWchar>(used)), nullptr) << used;
  }
  EXPECT_EQ(readable("ν σ λ π Σ ∫ −"), "ν σ λ π Σ ∫ −");
}

TEST_F(ExplorerTest, TheFontHasGreekAndFallsBackWhenMissing) {
  constexpr ImWchar kNu = 0x03BD;
  constexpr ImWchar kCapitalSigma = 0x03A3;
  open_explorer("equations", kDejaVuSans);
  const ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
  EXPECT_NE(font->FindGlyphNoFallback(kNu), nullptr);
  EXPECT_NE(font->FindGlyphNoFallback(kCapitalSigma), nullptr);
  EXPECT_NE(font->FindGlyphNoFallback(0x03C0), nullptr);  // π
  EXPECT_TRUE(explorer_->appearance().notice().empty()) << explorer_->appearance().notice();
  // The equations read as in the paper, drawn with the font's own glyphs.
  EXPECT_NE(frame().find("(2l/π)"), std::string::npos);

  open_explorer("equations", dir_ / "no-such-font.ttf");
  EXPECT_NE(explorer_->appearance().notice().find("no-such-font.ttf"), std::string::npos);
  EXPECT_NE(frame().find("is missing"), std::string::npos) << "the notice is shown";
  EXPECT_NE(ImGui::GetIO().Fonts->Fonts[0]->FindGlyphNoFallback('a'), nullptr);
}

TEST(Contrast, TheComparedFabricsFoldsAreAnotherHueThanAs) {
  // Their contrast is in the table of themed colours, read by
  // EveryThemedColourReadsOnWhatItIsDrawnOn.
  for (const bool light : {false, true}) {
    SCOPED_TRACE(light ? "light theme" : "dark theme");
    // B reads apart from A's folds of the same sign: another hue, not a shade of it.
    const FoldColours a = fold_colours(light);
    const auto apart = [](ImVec4 p, ImVec4 q) {
      return std::abs(p.x - q.x) + std::abs(p.y - q.y) + std::abs(p.z - q.z);
    };
    EXPECT_GT(apart(kCompareB.get(light), a.positive), 0.5f);
    EXPECT_GT(apart(kCompareBNegative.get(light), a.negative), 0.5f);
  }
}

TEST(TouchTargets, AFingersStyleMakesEveryFrameFortyFourPixelsTall) {
  // The default style's frames are the font and 3 px above and below it: 15 + 6 = 21 px. For a
  // finger they grow to 44 px (WCAG 2.5.5), so 14.5 px above and below 15 px of text; rows stand
  // 8 px apart.
  const ImGuiStyle fine = theme_style(false);
  ASSERT_FLOAT_EQ(fine.FramePadding.y, 3.0f);
  const ImGuiStyle touch = touch_style(fine, 15.0f, 44.0f, 8.0f);
  EXPECT_FLOAT_EQ(touch.FramePadding.y, 14.5f);
  EXPECT_FLOAT_EQ(15.0f + 2.0f * touch.FramePadding.y, 44.0f);
  EXPECT_FLOAT_EQ(touch.ItemSpacing.y, 8.0f);
  EXPECT_FLOAT_EQ(touch.FramePadding.x, fine.FramePadding.x);
  EXPECT_FLOAT_EQ(touch.GrabMinSize, 22.0f);
  // At 200 % text on a screen of ratio 2: 60 px of text in a target of 88 device px (44 CSS px).
  ImGuiStyle scaled = fine;
  scaled.ScaleAllSizes(4.0f);
  EXPECT_FLOAT_EQ(touch_style(scaled, 60.0f, 88.0f, 16.0f).FramePadding.y, 14.0f);
  // Text larger than the target: the style's own padding (12 px at that scale) stays.
  EXPECT_FLOAT_EQ(touch_style(scaled, 90.0f, 88.0f, 16.0f).FramePadding.y, 12.0f);
}

TEST(HintWords, AFingersHintsNameNoMouseGestureAndTheMousesKeepTheirs) {
  const Hint all[] = {Hint::type_value, Hint::parameters_intro, Hint::cloth_view,
                      Hint::fold_plot,  Hint::interval_details, Hint::present_view};
  for (const Hint hint : all) {
    const std::string finger = hint_words(hint, true);
    const std::string mouse = hint_words(hint, false);
    EXPECT_FALSE(finger.empty());
    EXPECT_NE(finger, mouse);
    for (const char* word : {"Ctrl", "click", "right-drag", "wheel", "hover", "Esc"}) {
      EXPECT_EQ(finger.find(word), std::string::npos) << finger << " says " << word;
    }
  }
  EXPECT_EQ(std::string(hint_words(Hint::type_value, false)), "Ctrl+click a slider to type");
  EXPECT_EQ(std::string(hint_words(Hint::type_value, true)), "long press a slider to type");
  EXPECT_EQ(std::string(hint_words(Hint::cloth_view, false)),
            "drag: orbit, right-drag: pan, wheel: zoom");
  EXPECT_EQ(std::string(hint_words(Hint::fold_plot, true)),
            "pinch: zoom, drag: pan, double tap: autoscale");
}

TEST(HintWords, FollowImGuisTouchScreenFlag) {
  ImGuiContext* context = testing::create_headless_imgui(ImVec2(800, 600));
  ImGuiIO& io = ImGui::GetIO();
  io.ConfigFlags &= ~ImGuiConfigFlags_IsTouchScreen;
  EXPECT_EQ(std::string(hint_words(Hint::type_value)), "Ctrl+click a slider to type");
  io.ConfigFlags |= ImGuiConfigFlags_IsTouchScreen;
  EXPECT_EQ(std::string(hint_words(Hint::type_value)), "long press a slider to type");
  ImGui::DestroyContext(context);
}

TEST(FingerDrag, IsWholeNearTheSliderAndSlowerTheFartherTheFingerStrays) {
  // A slider 44 px tall: within 44 px of its middle the finger's whole movement; at 88 px half,
  // at 176 px a quarter; never below the tenth of the mouse's Shift drag.
  EXPECT_DOUBLE_EQ(finger_drag_speed(0.0f, 44.0f, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(finger_drag_speed(30.0f, 44.0f, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(finger_drag_speed(44.0f, 44.0f, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(finger_drag_speed(88.0f, 44.0f, 0.1), 0.5);
  EXPECT_DOUBLE_EQ(finger_drag_speed(176.0f, 44.0f, 0.1), 0.25);
  EXPECT_DOUBLE_EQ(finger_drag_speed(1000.0f, 44.0f, 0.1), 0.1);
  EXPECT_DOUBLE_EQ(finger_drag_speed(NAN, 44.0f, 0.1), 1.0);
}

}  // namespace
}  // namespace foldlab::gui
