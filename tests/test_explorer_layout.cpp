// The tiled window: panels refitting, moved and presented, menus, the introduction, and no
// control cut off at any size or text size.
#include "explorer_fixture.hpp"

namespace foldlab::gui {
namespace {

// The introduction for a class: from the menu bar or the View menu, closed by Escape or Close.
TEST_F(ExplorerTest, TheIntroductionOpensFromTheMenuAndClosesWithEscapeOrClose) {
  EXPECT_EQ(frame().find("A cloth hangs"), std::string::npos);
  click(IntroWindow::kTitle);
  EXPECT_TRUE(panel<IntroWindow>().is_open());
  EXPECT_NE(last_text_.find("A cloth hangs"), std::string::npos) << last_text_;
  // What it says of the folds is what the model draws: going up (i = 0 is the lowest fold line,
  // eq. 6), each arch's depth a_i is the one below's over Q.
  EXPECT_NE(squeezed(last_text_).find("eacharchisshallowerthantheonebelowitbythesameratioQ"),
            std::string::npos)
      << last_text_;
  const Solution& s = explorer_->scene().solution();
  ASSERT_GE(s.a_mm.size(), 3u);
  for (std::size_t i = 0; i + 1 < s.a_mm.size(); ++i) {
    EXPECT_NEAR(s.a_mm[i] / s.a_mm[i + 1], s.Q, 1e-9 * s.Q) << i;
  }
  press(kEscape);
  EXPECT_FALSE(panel<IntroWindow>().is_open());
  EXPECT_EQ(frame().find("A cloth hangs"), std::string::npos);

  click("View");
  click(IntroWindow::kTitle);  // the last drawn: the View menu's item
  EXPECT_TRUE(panel<IntroWindow>().is_open());
  EXPECT_NE(frame().find("A cloth hangs"), std::string::npos);
  click("Close");
  EXPECT_FALSE(panel<IntroWindow>().is_open());
  EXPECT_EQ(frame().find("A cloth hangs"), std::string::npos);
}

// The window's loop after input (gui_app.cpp): frames until the frames after input have settled
// and nothing animates, each frame's input noted as the loop notes it.
int frames_until_rest(FramesAfterInput& pacing, Explorer& explorer,
                      const std::function<void()>& frame) {
  int drawn = 0;
  while ((!pacing.settled() || explorer.animating()) && drawn < 100) {
    frame();
    pacing.frame_drawn(frame_saw_input(ImGui::GetIO()));
    ++drawn;
  }
  return drawn;
}

// The introduction's text scrolls in a child window, whose height ImGui knows only from the frame
// before: its first frame shows no scrollbar and the text cut at "Results". Opened by a click
// whose release comes in the last frame after the press, it still gets the frames that bring the
// scrollbar before the window rests.
TEST_F(ExplorerTest, TheIntroductionShowsItsScrollbarBeforeTheWindowRests) {
  ImGuiIO& io = ImGui::GetIO();
  frame();
  const ImVec2 at = position_of(IntroWindow::kTitle);
  FramesAfterInput pacing;
  pacing.woken(true);  // the press woke the window
  io.MousePos = ImVec2(at.x + 3.0f, at.y + 4.0f);
  io.MouseDown[0] = true;
  frame();
  pacing.frame_drawn(frame_saw_input(io));
  frame();
  pacing.frame_drawn(frame_saw_input(io));
  io.MouseDown[0] = false;  // the release, in the third frame after the press
  frame();
  pacing.frame_drawn(frame_saw_input(io));
  ASSERT_TRUE(panel<IntroWindow>().is_open());
  EXPECT_GE(frames_until_rest(pacing, *explorer_, [&] { frame(); }), 2);
  const ImGuiWindow* text = nullptr;
  for (const ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
    if (window->Active &&
        std::string_view(window->Name).find("##intro text") != std::string_view::npos) {
      text = window;
    }
  }
  ASSERT_NE(text, nullptr);
  EXPECT_TRUE(text->ScrollbarY) << "the frame the window rests on shows the scrollbar";
  EXPECT_GT(text->ScrollMax.y, 0.0f);
}

// Ctrl+0 at 150 %: the frame that reads the key is still laid out with the old font, which the
// next frame replaces. The window's loop draws that next frame at once, before it reads more
// input, so that a click made at once lands on the widget drawn where it was made: "play", not
// the "shape" list the new layout put there.
TEST_F(ExplorerTest, AClickRightAfterCtrl0LandsOnTheWidgetDrawnThere) {
  open_explorer("equations", kDejaVuSans);
  ASSERT_EQ(explorer_->set_view("scale", "150"), std::nullopt);
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  const ImVec2 hint_at_150 = position_of("(thickness)");
  ImGuiIO& io = ImGui::GetIO();
  io.KeyCtrl = true;
  io.KeysDown['0'] = true;
  frame();
  io.KeyCtrl = false;
  io.KeysDown['0'] = false;
  ASSERT_TRUE(explorer_->layout_pending()) << "the smaller font waits for the next frame";
  EXPECT_EQ(position_of("(thickness)").y, hint_at_150.y) << "this frame shows the old layout";
  int settling = 0;
  while (explorer_->layout_pending() && settling < 5) {
    frame();
    ++settling;
  }
  EXPECT_EQ(settling, 1);
  EXPECT_FALSE(explorer_->layout_pending());
  EXPECT_NE(position_of("(thickness)").y, hint_at_150.y) << "the layout at 100 % moved";
  // A click where the screen now shows "play" (the played click's press comes at once).
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "play"}}}}}, [&] { frame(); }), 0);
  EXPECT_TRUE(explorer_->animating()) << "play was hit";
  EXPECT_FALSE(ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) << "no list was opened";
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "pause"}}}}}, [&] { frame(); }), 0);
}

// Every panel, every analysis tab, presented or tiled, with B pinned and the expert's rows, at
// sizes below any useful one and at twice the text size, then back to a laptop's size: nothing
// faults (the sanitizer build checks every access) and the tiles fill the window again.
TEST_F(ExplorerTest, EveryPanelDrawsAtAnySizeDownToOnePixelAndComesBack) {
  for (const std::string tab : {"equations", "method", "sweep", "map"}) {
    open_explorer(tab);
    status().set_expert_mode(true);
    pin_as_b(document(), status());
    std::vector<std::string> presented = {"none"};
    for (const std::unique_ptr<Panel>& panel : explorer_->panels()) {
      if (Layout::tiled(*panel)) {
        presented.push_back(panel->key());
      }
    }
    for (const std::string& present : presented) {
      ASSERT_EQ(explorer_->set_view("present", present), std::nullopt);
      for (const char* scale : {"100", "200"}) {
        ASSERT_EQ(explorer_->set_view("scale", scale), std::nullopt);
        for (const ImVec2 size : {ImVec2(200, 150), ImVec2(60, 40), ImVec2(1, 1)}) {
          show_at(size);
        }
      }
    }
    ASSERT_EQ(explorer_->set_view("present", "none"), std::nullopt);
    ASSERT_EQ(explorer_->set_view("scale", "100"), std::nullopt);
    show_at(ImVec2(1280, 800));
    EXPECT_TRUE(explorer_->layout().fills_window()) << tab;
  }
}

// Every tiled panel, as the test reads it: ImGui's own window rectangles.
using Rects = std::vector<std::pair<std::string, PanelRect>>;

// The panels cover the display below the menu bar exactly: inside it, no two overlapping, and
// their areas summing to the whole, so there is neither a gap nor a margin.
void expect_tiles_fill(const Rects& rects, ImVec2 display, float menu_height) {
  ASSERT_EQ(rects.size(), 6u);
  double area = 0.0;
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const PanelRect& a = rects[i].second;
    SCOPED_TRACE(rects[i].first);
    EXPECT_GE(a.pos.x, 0.0f);
    EXPECT_GE(a.pos.y, menu_height);
    EXPECT_LE(a.pos.x + a.size.x, display.x);
    EXPECT_LE(a.pos.y + a.size.y, display.y);
    area += static_cast<double>(a.size.x) * a.size.y;
    for (std::size_t j = i + 1; j < rects.size(); ++j) {
      const PanelRect& b = rects[j].second;
      const bool apart = a.pos.x + a.size.x <= b.pos.x || b.pos.x + b.size.x <= a.pos.x ||
                         a.pos.y + a.size.y <= b.pos.y || b.pos.y + b.size.y <= a.pos.y;
      EXPECT_TRUE(apart) << "overlaps " << rects[j].first;
    }
  }
  EXPECT_DOUBLE_EQ(area, static_cast<double>(display.x) * (display.y - menu_height));
}

TEST_F(ExplorerTest, PanelsRefitTheWindowAsItGrowsAndShrinks) {
  ImGuiIO& io = ImGui::GetIO();
  const float menu_height = ImGui::GetFrameHeight();  // the main menu bar: one frame high
  for (const ImVec2 size : {ImVec2(1024, 640), ImVec2(1920, 1080), ImVec2(1280, 800),
                            ImVec2(2560, 1440), ImVec2(1024, 640)}) {
    SCOPED_TRACE(::testing::Message() << size.x << "x" << size.y);
    io.DisplaySize = size;
    frame();
    frame();
    EXPECT_TRUE(explorer_->layout().automatic());
    expect_tiles_fill(explorer_->layout().panel_rects(), size, menu_height);
  }
}

// Widths in font sizes: the parameters column is 25 font sizes at 1024 px; at 200 % it would be
// twice as wide but stops at 40 % of the window, and the whole window is still tiled.
TEST_F(ExplorerTest, TheLayoutsWidthsFollowTheUiScale) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(1024, 640);
  frame();
  const auto width_of = [this](const std::string& name) {
    for (const auto& [n, r] : explorer_->layout().panel_rects()) {
      if (n == name) {
        return r.size.x;
      }
    }
    ADD_FAILURE() << name;
    return 0.0f;
  };
  EXPECT_FLOAT_EQ(width_of("parameters"), 25.0f * 13.0f);  // ProggyClean: 13 px
  ASSERT_EQ(explorer_->set_view("scale", "200"), std::nullopt);
  frame();
  frame();
  EXPECT_FLOAT_EQ(ImGui::GetFontSize(), 26.0f);
  // 25 font sizes would be 650 px: the column stops at 40 % of the window, 409 px (short of the
  // 20 font sizes that hold the longest label with a short slider), so that the views keep the
  // rest.
  EXPECT_FLOAT_EQ(width_of("parameters"), std::floor(0.40f * 1024.0f));
  expect_tiles_fill(explorer_->layout().panel_rects(), io.DisplaySize, ImGui::GetFrameHeight());
  io.DisplaySize = ImVec2(2560, 1440);
  frame();
  frame();
  // 30 % of 2560 px is 768 px, between 25 and 40 font sizes (650 and 1040 px).
  EXPECT_FLOAT_EQ(width_of("parameters"), 768.0f);
}

// At 200 % the views keep their share of the window: the fold plot's data and the 3D panel are
// each a sizeable part of it, on a laptop and on a projector's 1920 x 1080.
TEST_F(ExplorerTest, AtTwiceTheTextSizeThePlotsKeepTheirShareOfTheWindow) {
  open_explorer("equations", kDejaVuSans);
  ASSERT_EQ(explorer_->set_view("scale", "200"), std::nullopt);
  for (const ImVec2 size : {ImVec2(1280, 800), ImVec2(1920, 1080)}) {
    SCOPED_TRACE(::testing::Message() << size.x << "x" << size.y);
    show_at(size);
    const double window = static_cast<double>(size.x) * size.y;
    const PlotView& plot = panel<FoldPlotPanel>().plot_view();
    const double plot_share = (plot.max.x - plot.min.x) * (plot.max.y - plot.min.y) / window;
    const PanelRect cloth = rect_of("cloth");
    const double cloth_share = static_cast<double>(cloth.size.x) * cloth.size.y / window;
    // At true scale the data frame has the cloth's own proportions (1400 x 1400 mm here), narrower
    // than the tile: 2.9 % of 1920 x 1080 at 200 %.
    EXPECT_GT(plot_share, 0.025) << "the fold plot's data";
    EXPECT_GT(cloth_share, 0.175) << "the 3D view's panel";
    EXPECT_TRUE(explorer_->layout().fills_window());
  }
}

// The button at the right of a panel's title fills the window with that panel under a large
// read-out of n, Q and z_max; Escape (or the menu bar's button) brings the tiles back. A
// double-click on a title does the same as the button.
TEST_F(ExplorerTest, APanelIsPresentedByItsTitleButtonAndEscapeReturnsToTheTiles) {
  ImGuiIO& io = ImGui::GetIO();
  const ImVec2 display = io.DisplaySize;
  const float menu_height = ImGui::GetFrameHeight();
  const float title_height = ImGui::GetFontSize() + 2.0f * ImGui::GetStyle().FramePadding.y;
  const auto title_button = [&](const std::string& key) {
    const PanelRect r = rect_of(key);
    return ImVec2(r.pos.x + r.size.x - 0.5f * title_height, r.pos.y + 0.5f * title_height);
  };
  const auto expect_presented = [&](const std::string& key) {
    const Rects rects = explorer_->layout().panel_rects();
    ASSERT_EQ(rects.size(), 1u) << "the other tiles are hidden";
    EXPECT_EQ(rects[0].first, key);
    const PanelRect& r = rects[0].second;
    EXPECT_FLOAT_EQ(r.pos.x, 0.0f);
    EXPECT_FLOAT_EQ(r.size.x, display.x);
    EXPECT_FLOAT_EQ(r.pos.y + r.size.y, display.y);
    // Under the menu bar and the read-out: most of the window.
    EXPECT_GT(r.size.y, 0.85f * (display.y - menu_height));
  };
  click_at(title_button("fold_plot"));
  expect_presented("fold_plot");
  const Solution& s = explorer_->scene().solution();
  // Drawn larger, its glyphs' offsets no longer read as one line of text: compare without
  // spaces and line breaks.
  std::string text = frame();
  std::erase(text, ' ');
  std::erase(text, '\n');
  EXPECT_NE(text.find(detail::printf_string("n=%d", s.n)), std::string::npos) << text;
  EXPECT_NE(text.find(detail::printf_string("z_max=%.2fmm", s.z_max_mm)), std::string::npos)
      << text;
  EXPECT_FALSE(explorer_->layout().fills_window());
  press(kEscape);
  frame();
  expect_tiles_fill(explorer_->layout().panel_rects(), display, menu_height);
  EXPECT_TRUE(explorer_->layout().automatic());

  // A double-click on the 3D view's title, then the menu bar's button back.
  const PanelRect cloth = rect_of("cloth");
  io.MousePos = ImVec2(cloth.pos.x + 0.3f * cloth.size.x, cloth.pos.y + 0.5f * title_height);
  frame();
  for (int i = 0; i < 2; ++i) {
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
  }
  frame();
  expect_presented("cloth");
  click("Back to the tiles (Esc)");
  expect_tiles_fill(explorer_->layout().panel_rects(), display, menu_height);
  // A script names the panel.
  ASSERT_EQ(explorer_->set_view("present", "analysis"), std::nullopt);
  frame();
  frame();
  expect_presented("analysis");
  EXPECT_TRUE(explorer_->set_view("present", "nothing").has_value());
  // The introduction opened over a presented panel takes the first Escape; the next one returns
  // to the tiles.
  click(IntroWindow::kTitle);
  ASSERT_TRUE(panel<IntroWindow>().is_open());
  press(kEscape);
  EXPECT_FALSE(panel<IntroWindow>().is_open());
  frame();
  expect_presented("analysis");
  press(kEscape);
  frame();
  expect_tiles_fill(explorer_->layout().panel_rects(), display, menu_height);
}

// Presenting, a teacher answers "what if it were twice as heavy?" without leaving the view: the
// strip under the read-out holds t, E, w, h, L and d, driven as the panel's sliders are (a click,
// arrow keys with Shift for a tenth of the step, a value typed with its unit, a refused one with
// its reason under the strip), while the view stays presented. "Hide inputs" in the menu bar
// takes the strip away, and the choice is kept with the session.
TEST_F(ExplorerTest, ThePresentedViewsStripOfInputsChangesTheFabricWithoutLeavingIt) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  const auto script = [&](nlohmann::json steps) {
    return play(*explorer_, {{"steps", std::move(steps)}}, [&] { frame(); });
  };
  ASSERT_EQ(explorer_->set_view("present", "fold_plot"), std::nullopt);
  frame();
  frame();
  const PanelRect with_strip = rect_of("fold_plot");
  std::vector<std::string> keys;
  for (const auto& [key, place] : panel<ParametersPanel>().slider_places()) {
    keys.push_back(key);
    EXPECT_LE(place.max.y, with_strip.pos.y) << key << ": above the presented view";
    EXPECT_GE(place.max.x - place.min.x, 7.0f * ImGui::GetFontSize()) << key;
  }
  EXPECT_EQ(keys, (std::vector<std::string>{"E", "L", "d", "h", "t", "w"}));

  // A click focuses w; each arrow key moves it by 1 % of the slider, Shift+arrow by 0.1 %: of
  // the beginner's 1e-7 N/mm² (10.2 g/m²) to 1000 g/m², log10(1000 x 9.81e-9 / 1e-7) = 1.99
  // decades on a log scale.
  const double slider_decades = std::log10(1000.0 * 9.81e-9 / 1e-7);
  ASSERT_EQ(script({{{"click", "w"}, {"at", 0.5}}}), 0);
  const double w0 = explorer_->edited().fabric.weight_N_per_mm2;
  ASSERT_EQ(script({{{"key", "right"}}}), 0);
  const double w1 = explorer_->edited().fabric.weight_N_per_mm2;
  EXPECT_NEAR(std::log10(w1 / w0), 0.01 * slider_decades, 1e-9);
  ASSERT_EQ(script({{{"key", "shift+right"}}, {{"key", "shift+left"}}, {{"key", "shift+left"}}}),
            0);
  EXPECT_NEAR(std::log10(explorer_->edited().fabric.weight_N_per_mm2 / w1), -0.001 * slider_decades,
              1e-9);
  EXPECT_EQ(explorer_->presented(), "fold_plot");

  // Twice as heavy, typed with its unit.
  ASSERT_EQ(script({{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", "306 gsm"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}),
            0);
  const InputSpec& w = *find_input("w");
  EXPECT_EQ(panel<ParametersPanel>().shown(document(), w), "306 g/m²");
  EXPECT_TRUE(document().issues().empty());
  EXPECT_EQ(explorer_->presented(), "fold_plot");

  // Refused: the reason under the strip, above the view, as at the panel's foot.
  ASSERT_EQ(script({{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", "-5 gsm"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}),
            0);
  ASSERT_FALSE(document().issues().empty());
  const PanelRect refused = rect_of("fold_plot");
  EXPECT_LE(position_of("must be between").y, refused.pos.y) << last_text_;
  EXPECT_GT(refused.pos.y, with_strip.pos.y) << "the strip grew by the reason's lines";
  EXPECT_EQ(explorer_->presented(), "fold_plot");
  ASSERT_EQ(script({{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", "heavy"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}),
            0);
  EXPECT_LE(position_of("is not a number").y, rect_of("fold_plot").pos.y) << last_text_;
  press('Z', true);
  frame();
  EXPECT_EQ(panel<ParametersPanel>().shown(document(), w), "306 g/m²");

  // Hidden from the menu bar: no slider to press, the view a strip taller, and so on the next
  // start.
  ASSERT_EQ(script({{{"click", MenuBar::kHideInputsLabel}}, {{"frames", 2}}}), 0);
  EXPECT_TRUE(panel<ParametersPanel>().slider_places().empty());
  EXPECT_LT(rect_of("fold_plot").pos.y, with_strip.pos.y);
  EXPECT_EQ(explorer_->presented(), "fold_plot");
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  EXPECT_FALSE(explorer_->layout().presents_inputs());
  ASSERT_EQ(explorer_->set_view("present", "fold_plot"), std::nullopt);
  frame();
  frame();
  EXPECT_TRUE(panel<ParametersPanel>().slider_places().empty());
  ASSERT_EQ(script({{{"click", MenuBar::kShowInputsLabel}}, {{"frames", 2}}}), 0);
  EXPECT_EQ(panel<ParametersPanel>().slider_places().size(), 6u);
}

// A drag that missed w's handle and started on the line of text under it carried the whole
// Parameters panel away from its tile.
TEST_F(ExplorerTest, APanelMovesByItsTitleOnlyNotByADragInsideIt) {
  frame();
  const PanelRect before = rect_of("parameters");
  const ImVec2 start = position_of("oz/yd²");
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = start;
  frame();
  io.MouseDown[0] = true;
  frame();
  for (int i = 1; i <= 10; ++i) {
    io.MousePos =
        ImVec2(start.x + 10.0f * static_cast<float>(i), start.y + 5.0f * static_cast<float>(i));
    frame();
  }
  io.MouseDown[0] = false;
  frame();
  frame();
  EXPECT_EQ(rect_of("parameters").pos.x, before.pos.x);
  EXPECT_EQ(rect_of("parameters").pos.y, before.pos.y);
  EXPECT_TRUE(explorer_->layout().automatic());
  EXPECT_EQ(document().undo_depth(), 0u) << "nothing changed";
}

// Dragging the corner shared by the fold plot, the 3D view and the lower panels moves those
// edges: the neighbours follow, nothing overlaps and no hole opens. "Reset layout" puts the
// edges back.
TEST_F(ExplorerTest, DraggingAPanelsCornerMovesTheNeighboursEdgesWithIt) {
  ImGuiIO& io = ImGui::GetIO();
  io.BackendFlags |= ImGuiBackendFlags_HasMouseCursors;  // as the GLFW backend: edges resize
  frame();
  frame();
  const PanelRect fold = rect_of("fold_plot");
  const PanelRect cloth = rect_of("cloth");
  const PanelRect results = rect_of("results");
  // The resize grip in the fold plot's lower right corner, 80 px left and 40 px down.
  const ImVec2 grip(fold.pos.x + fold.size.x - 3.0f, fold.pos.y + fold.size.y - 3.0f);
  io.MousePos = grip;
  frame();
  io.MouseDown[0] = true;
  frame();
  for (float step = 1.0f; step <= 4.0f; step += 1.0f) {
    io.MousePos = ImVec2(grip.x - 20.0f * step, grip.y + 10.0f * step);
    frame();
  }
  io.MouseDown[0] = false;
  frame();
  frame();
  EXPECT_TRUE(explorer_->layout().fills_window());
  expect_tiles_fill(explorer_->layout().panel_rects(), io.DisplaySize, ImGui::GetFrameHeight());
  EXPECT_FLOAT_EQ(rect_of("fold_plot").size.x, fold.size.x - 80.0f);
  EXPECT_FLOAT_EQ(rect_of("fold_plot").size.y, fold.size.y + 40.0f);
  EXPECT_FLOAT_EQ(rect_of("cloth").pos.x, cloth.pos.x - 80.0f);
  EXPECT_FLOAT_EQ(rect_of("cloth").size.y, cloth.size.y + 40.0f);
  EXPECT_FLOAT_EQ(rect_of("results").pos.y, results.pos.y + 40.0f);
  EXPECT_FLOAT_EQ(rect_of("results").size.x, results.size.x) << "the lower edge stays";
  // A bigger window keeps the user's proportions and still tiles it.
  io.DisplaySize = ImVec2(1600, 1000);
  frame();
  frame();
  EXPECT_TRUE(explorer_->layout().fills_window());
  click("Reset layout");
  frame();
  EXPECT_FLOAT_EQ(rect_of("fold_plot").size.x, rect_of("results").size.x);
  EXPECT_TRUE(explorer_->layout().fills_window());
}

// Escape closes an open menu and an open combo, as elsewhere on the desktop.
TEST_F(ExplorerTest, EscapeClosesAnOpenMenuOrCombo) {
  click("View");
  ASSERT_NE(frame().find("Larger text"), std::string::npos) << "the View menu is open";
  press(kEscape);
  EXPECT_EQ(frame().find("Larger text"), std::string::npos) << last_text_;
  click("fabric");  // the 3D view's "colour by" combo
  ASSERT_NE(frame().find("fold sign"), std::string::npos) << "the combo is open";
  press(kEscape);
  EXPECT_EQ(frame().find("fold sign"), std::string::npos) << last_text_;
}

TEST_F(ExplorerTest, APanelTheUserMovesStaysUntilResetLayout) {
  ImGuiIO& io = ImGui::GetIO();
  frame();
  const auto results_pos = [this] {
    for (const auto& [n, r] : explorer_->layout().panel_rects()) {
      if (n == "results") {
        return r.pos;
      }
    }
    return ImVec2(-1, -1);
  };
  const ImVec2 before = results_pos();
  // Drag the Results panel by its title bar, 60 px right and 40 px down.
  const ImVec2 title = position_of("Results");
  const ImVec2 grab(title.x + 80.0f, title.y + 4.0f);
  io.MousePos = grab;
  frame();
  io.MouseDown[0] = true;
  frame();
  for (float step = 1.0f; step <= 4.0f; step += 1.0f) {
    io.MousePos = ImVec2(grab.x + 15.0f * step, grab.y + 10.0f * step);
    frame();
  }
  io.MouseDown[0] = false;
  frame();
  frame();
  EXPECT_FALSE(explorer_->layout().automatic());
  EXPECT_FLOAT_EQ(results_pos().x, before.x + 60.0f);
  EXPECT_FLOAT_EQ(results_pos().y, before.y + 40.0f);
  // A bigger window no longer moves the user's panel.
  io.DisplaySize = ImVec2(1600, 1000);
  frame();
  frame();
  EXPECT_FLOAT_EQ(results_pos().x, before.x + 60.0f);
  EXPECT_FLOAT_EQ(results_pos().y, before.y + 40.0f);
  // "Reset layout" stands in the menu bar while the user's arrangement is shown.
  click("Reset layout");
  EXPECT_TRUE(explorer_->layout().automatic());
  expect_tiles_fill(explorer_->layout().panel_rects(), io.DisplaySize, ImGui::GetFrameHeight());
  EXPECT_EQ(frame().find("Reset layout"), std::string::npos) << "only shown when it would act";
}

// A session remembers whether the user arranged the panels (imgui.ini keeps where), so that the
// next start does not tile over their arrangement.
TEST_F(ExplorerTest, TheUsersArrangementIsRememberedWithTheSession) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  EXPECT_TRUE(explorer_->layout().automatic());
  const ImVec2 title = position_of("Results");
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(title.x + 80.0f, title.y + 4.0f);
  frame();
  io.MouseDown[0] = true;
  frame();
  io.MousePos.x += 50.0f;
  frame();
  io.MouseDown[0] = false;
  frame();
  ASSERT_FALSE(explorer_->layout().automatic());
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  EXPECT_FALSE(explorer_->layout().automatic());
  explorer_->layout().reset();
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  EXPECT_TRUE(explorer_->layout().automatic());
}

// At the smallest supported window the controls of each panel are drawn inside it, not cut off
// at its right edge: the rows wrap.
TEST_F(ExplorerTest, At1024x640NoControlIsCutOff) {
  ImGui::GetIO().DisplaySize = ImVec2(1024, 640);
  frame();
  frame();
  const Rects rects = explorer_->layout().panel_rects();
  const auto right_of = [&](const std::string& name) {
    for (const auto& [n, r] : rects) {
      if (n == name) {
        return r.pos.x + r.size.x;
      }
    }
    return 0.0f;
  };
  const struct {
    const char* label;
    const char* panel;
  } controls[] = {{"reset camera", "cloth"},   {"breeze", "cloth"},
                  {"z exaggeration", "cloth"}, {"Save as...", "presets"},
                  {"autoscale", "fold_plot"},  {"Reset to preset", "parameters"},
                  {"Regime map", "analysis"}};
  for (const auto& c : controls) {
    const ImVec2 at = position_of(c.label);
    EXPECT_LE(at.x + ImGui::CalcTextSize(c.label).x, right_of(c.panel)) << c.label;
  }
}

// At 200 % in a 1280 x 800 window the views' settings took most of their panels (the cloth was
// drawn 85 px high): they fold behind one button and the views keep the room; a click opens them,
// and they work as in the row. At 100 % they stay in the row.
TEST_F(ExplorerTest, AtALargeTextSizeTheViewsSettingsFoldAndTheViewsKeepTheirRoom) {
  ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
  frame();
  frame();
  EXPECT_FALSE(panel<ClothViewPanel>().toolbar_folded());
  EXPECT_FALSE(panel<FoldPlotPanel>().toolbar_folded());
  explorer_->appearance().request(200, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_TRUE(panel<ClothViewPanel>().toolbar_folded());
  EXPECT_TRUE(panel<FoldPlotPanel>().toolbar_folded());
  EXPECT_EQ(last_text_.find("wireframe"), std::string::npos) << last_text_;
  // The least useful height of the cloth: twelve lines of text.
  EXPECT_GE(panel<ClothViewPanel>().view_rect().size.y, 12.0f * ImGui::GetFontSize());
  const bool wireframe = panel<ClothViewPanel>().style().wireframe;
  click("view settings...");
  click("wireframe");
  EXPECT_NE(panel<ClothViewPanel>().style().wireframe, wireframe);
  EXPECT_TRUE(panel<ClothViewPanel>().toolbar_folded()) << "a setting does not unfold the row";
  press(kEscape);
  explorer_->appearance().request(100, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_FALSE(panel<ClothViewPanel>().toolbar_folded());
  EXPECT_NE(last_text_.find("wireframe"), std::string::npos) << last_text_;
}

// A message on the status line while a view is presented ("Undone.", a refusal) went between the
// read-out and the strip and moved the strip's sliders under the pointer; a typed text's reason
// was said twice, over and under the strip. The message goes under the strip, and once.
TEST_F(ExplorerTest, APresentedMessageNeverMovesTheStripAndIsSaidOnce) {
  ASSERT_EQ(explorer_->set_view("present", "fold_plot"), std::nullopt);
  frame();
  frame();
  const float w_y = panel<ParametersPanel>().slider_places().at("w").min.y;
  status().notify("Undone.", false);
  frame();
  EXPECT_NE(last_text_.find("Undone."), std::string::npos) << last_text_;
  EXPECT_EQ(panel<ParametersPanel>().slider_places().at("w").min.y, w_y);
  ASSERT_EQ(play(*explorer_,
                 {{"steps",
                   {{{"click", "w"}, {"at", 0.5}, {"ctrl", true}},
                    {{"type", "heavy"}},
                    {{"key", "enter"}},
                    {{"frames", 2}}}}},
                 [&] { frame(); }),
            0);
  EXPECT_EQ(panel<ParametersPanel>().slider_places().at("w").min.y, w_y);
  const std::size_t first = last_text_.find("is not a number");
  ASSERT_NE(first, std::string::npos) << last_text_;
  EXPECT_EQ(last_text_.find("is not a number", first + 1), std::string::npos) << last_text_;
}

// Presented at 200 % in 1024 x 640: the read-out wraps between n, Q and z_max, never inside one
// ("z_max = 48.96 (30.5–78." over "6) mm" was drawn), and the menu bar's last item stays on it.
// Outside the wrinkled regime the presented read-out names the regime and gives no range: at
// t = 3 mm and h = 1000 mm the default cloth's s = K E t³ / (w h l²) is above 1 (by hand, with
// the default's K = 1.686: 1.686 x 165 x 27 / (1.5e-6 x 1000 x 1300²) = 2.96): stiff, one fold.
TEST_F(ExplorerTest, APresentedReadOutNamesARegimeWithoutFoldsAndGivesNoRange) {
  open_explorer("equations", kDejaVuSans);  // the explorer's own font, as the read-out uses
  document().load_preset_file(kPresetsDir / "default.json");  // calibrated: its values have ranges
  ASSERT_EQ(explorer_->set_view("present", "cloth"), std::nullopt);
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  // (The read-out's large text reads with odd gaps in the test's text: it is read squeezed.)
  std::string text = squeezed(last_text_);
  EXPECT_NE(text.find("n=7(4"), std::string::npos)
      << "a wrinkled cloth's n has its range: " << text;
  ASSERT_EQ(explorer_->set_input("t", 3.0), std::nullopt);
  ASSERT_EQ(explorer_->set_input("h", 1000.0), std::nullopt);
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  text = squeezed(last_text_);
  ASSERT_EQ(explorer_->scene().solution().regime, Regime::stiff);
  const std::size_t stiff = text.find("stiff:n=");
  ASSERT_NE(stiff, std::string::npos) << text;
  const std::size_t mm = text.find("mm", stiff);
  ASSERT_NE(mm, std::string::npos) << text;
  EXPECT_EQ(text.substr(stiff, mm - stiff).find('('), std::string::npos)
      << text.substr(stiff, mm - stiff);
}

TEST_F(ExplorerTest, APresentedReadOutWrapsBetweenItsValuesAndTheMenuBarKeepsItsItems) {
  open_explorer("equations", kDejaVuSans);  // the explorer's own font: the bar's widths are its
  // The default preset: its calibration gives each value a range, which makes the line long.
  document().load_preset_file(kPresetsDir / "default.json");
  ImGui::GetIO().DisplaySize = ImVec2(1024, 640);
  explorer_->appearance().request(200, false);
  ASSERT_EQ(explorer_->set_view("present", "cloth"), std::nullopt);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  // (DejaVu's narrow gaps read as spaces or not: "z_m ax", "m m".)
  const std::size_t z = last_text_.find("z_");
  ASSERT_NE(z, std::string::npos) << last_text_;
  const std::size_t mm = last_text_.find('m', last_text_.find(')', z));
  ASSERT_NE(mm, std::string::npos) << last_text_;
  EXPECT_EQ(last_positions_[z].y, last_positions_[mm].y) << "z_max's value and unit on one line";
  const std::size_t q = last_text_.find("Q");
  ASSERT_LT(q, z);
  EXPECT_GT(last_positions_[z].y, last_positions_[q].y) << "this width needs two lines";
  const std::size_t range_end = last_text_.find(")", q);
  EXPECT_EQ(last_positions_[range_end].y, last_positions_[q].y) << "Q's range on Q's line";
  const float right =
      position_of(MenuBar::kHideInputsLabel).x + ImGui::CalcTextSize(MenuBar::kHideInputsLabel).x;
  EXPECT_LE(right, 1024.0f);
  // The presented view's menu (its title bar's items, and "Back to the tiles") stays; the bar's
  // own way back goes where it would push "Hide inputs" off (Esc, and that menu, remain).
  EXPECT_TRUE(shows(last_text_, "Cloth (3D)")) << last_text_;
  EXPECT_FALSE(shows(last_text_, MenuBar::kBackToTilesShortLabel)) << last_text_;
  // At 100 % the bar has room for the long wording.
  explorer_->appearance().request(100, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_TRUE(shows(last_text_, MenuBar::kBackToTilesLabel)) << last_text_;
}

// The panels are one list: each has a title and a key of its own, and the report's panels are
// the tiled ones of that list, by key, in its order.
TEST_F(ExplorerTest, EveryPanelHasADistinctNameAndTheReportNamesComeFromTheList) {
  std::vector<std::string> names;
  std::vector<std::string> keys;
  std::vector<std::string> tiled;
  for (const std::unique_ptr<Panel>& panel : explorer_->panels()) {
    ASSERT_NE(panel->name(), nullptr);
    ASSERT_NE(panel->key(), nullptr);
    EXPECT_FALSE(std::string(panel->name()).empty());
    EXPECT_FALSE(std::string(panel->key()).empty());
    names.emplace_back(panel->name());
    keys.emplace_back(panel->key());
    if (Layout::tiled(*panel)) {
      tiled.emplace_back(panel->key());
    }
  }
  EXPECT_GE(names.size(), 8u);
  for (std::vector<std::string>* list : {&names, &keys}) {
    std::vector<std::string> sorted = *list;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  }
  EXPECT_EQ(tiled.size(), static_cast<std::size_t>(kTileCount));
  frame();
  std::vector<std::string> reported;
  for (const auto& [key, rect] : explorer_->layout().panel_rects()) {
    reported.push_back(key);
  }
  EXPECT_EQ(reported, tiled);
  const nlohmann::json state = explorer_state_json(*explorer_);
  for (const std::string& key : tiled) {
    EXPECT_TRUE(state.at("layout").at("panels").contains(key)) << key;
  }
  // Each title is the one its window shows.
  const std::string text = frame();
  for (const std::unique_ptr<Panel>& panel : explorer_->panels()) {
    if (Layout::tiled(*panel)) {
      EXPECT_NE(text.find(panel->name()), std::string::npos) << panel->name();
    }
  }
}

// The colour that the last frame's untextured fills give the point `at`, blended in drawing
// order over `under` (what the renderer shows beneath ImGui). Text and other textured triangles
// are left out: the question is what the fills let through.
ImVec4 composited_fill(ImVec2 at, ImVec4 under) {
  const ImDrawData& data = *ImGui::GetDrawData();
  const ImVec2 white = ImGui::GetIO().Fonts->TexUvWhitePixel;
  ImVec4 out = under;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList& list = *data.CmdLists[l];
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      if (cmd.UserCallback != nullptr || at.x < cmd.ClipRect.x || at.y < cmd.ClipRect.y ||
          at.x >= cmd.ClipRect.z || at.y >= cmd.ClipRect.w) {
        continue;
      }
      for (unsigned k = 0; k + 2 < cmd.ElemCount; k += 3) {
        const ImDrawVert* v[3];
        bool textured = false;
        for (unsigned j = 0; j < 3; ++j) {
          v[j] = &list.VtxBuffer[static_cast<int>(
              cmd.VtxOffset + list.IdxBuffer[static_cast<int>(cmd.IdxOffset + k + j)])];
          textured = textured || v[j]->uv.x != white.x || v[j]->uv.y != white.y;
        }
        // Barycentric coordinates of `at`; outside the triangle when any is negative.
        const auto cross = [](ImVec2 a, ImVec2 b, ImVec2 c) {
          return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        };
        const float area = cross(v[0]->pos, v[1]->pos, v[2]->pos);
        if (textured || area == 0.0f) {
          continue;
        }
        const float b0 = cross(v[1]->pos, v[2]->pos, at) / area;
        const float b1 = cross(v[2]->pos, v[0]->pos, at) / area;
        const float b2 = 1.0f - b0 - b1;
        if (b0 < 0.0f || b1 < 0.0f || b2 < 0.0f) {
          continue;
        }
        ImVec4 colour(0, 0, 0, 0);
        for (unsigned j = 0; j < 3; ++j) {
          const ImVec4 c = ImGui::ColorConvertU32ToFloat4(v[j]->col);
          const float b = j == 0 ? b0 : j == 1 ? b1 : b2;
          colour = ImVec4(colour.x + b * c.x, colour.y + b * c.y, colour.z + b * c.z,
                          colour.w + b * c.w);
        }
        out = ImVec4(colour.x * colour.w + out.x * (1.0f - colour.w),
                     colour.y * colour.w + out.y * (1.0f - colour.w),
                     colour.z * colour.w + out.z * (1.0f - colour.w), 1.0f);
      }
    }
  }
  return out;
}

// Menus hide what is under them: panel text showing through a menu reads as one of its items.
// The View menu, opened by a click, is drawn over the panels; a point of its background comes out
// the same colour whether black or white is under the whole frame, in both themes.
TEST_F(ExplorerTest, AnOpenMenuLetsNothingUnderItShowThrough) {
  for (const char* theme : {"dark", "light"}) {
    SCOPED_TRACE(std::string(theme) + " theme");
    ASSERT_EQ(explorer_->set_view("theme", theme), std::nullopt);
    frame();
    click("View");
    const ImGuiWindow* menu = nullptr;
    for (const ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
      if (window->Active && (window->Flags & ImGuiWindowFlags_Popup) != 0) {
        menu = window;
      }
    }
    ASSERT_NE(menu, nullptr) << "the View menu did not open";
    // Beside its items' text, halfway down, and inside the panels' area below the menu bar.
    const ImVec2 at(menu->Pos.x + menu->Size.x - 3.0f, menu->Pos.y + 0.5f * menu->Size.y);
    const ImVec4 over_black = composited_fill(at, ImVec4(0, 0, 0, 1));
    const ImVec4 over_white = composited_fill(at, ImVec4(1, 1, 1, 1));
    for (const auto& [black, white] :
         {std::pair{over_black.x, over_white.x}, std::pair{over_black.y, over_white.y},
          std::pair{over_black.z, over_white.z}}) {
      EXPECT_NEAR(black, white, 1.0f / 255.0f);
    }
    press(kEscape);
  }
}

// A finger's grip on the edge between the 2D plot and the 3D view: a press on its middle and a
// drag of 120 px moves that edge by 120 px (the plot wider, the 3D view narrower by as much), and
// the edge is kept with the session. A mouse has none.
TEST_F(ExplorerTest, AFingersGripOnATilesEdgeDragsItAndTheSessionKeepsIt) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  ASSERT_FALSE(explorer_->set_view("pointer", "coarse"));
  frame();
  frame();
  const auto grip_of = [this](const std::string& edge) -> std::optional<PanelRect> {
    for (const auto& [key, rect] : explorer_->layout().handle_rects()) {
      if (key == edge) {
        return rect;
      }
    }
    return std::nullopt;
  };
  const std::optional<PanelRect> grip = grip_of("layout_fold_plot");
  ASSERT_TRUE(grip.has_value());
  EXPECT_EQ(explorer_->layout().handle_rects().size(), 5u) << "one grip on each inner edge";
  EXPECT_GE(std::min(grip->size.x, grip->size.y), 44.0f);
  const PanelRect fold = rect_of("fold_plot");
  const PanelRect cloth = rect_of("cloth");
  // The grip straddles the edge between the two tiles.
  EXPECT_LT(grip->pos.x, cloth.pos.x);
  EXPECT_GT(grip->pos.x + grip->size.x, cloth.pos.x);
  ImGuiIO& io = ImGui::GetIO();
  const ImVec2 middle(grip->pos.x + 0.5f * grip->size.x, grip->pos.y + 0.5f * grip->size.y);
  io.MousePos = middle;
  frame();
  io.MouseDown[0] = true;
  frame();
  for (float step = 1.0f; step <= 4.0f; step += 1.0f) {
    io.MousePos = ImVec2(middle.x + 30.0f * step, middle.y + 5.0f * step);
    frame();
  }
  io.MouseDown[0] = false;
  frame();
  frame();
  EXPECT_FLOAT_EQ(rect_of("fold_plot").size.x, fold.size.x + 120.0f);
  EXPECT_FLOAT_EQ(rect_of("cloth").pos.x, cloth.pos.x + 120.0f);
  EXPECT_FLOAT_EQ(rect_of("cloth").size.x, cloth.size.x - 120.0f);
  EXPECT_FLOAT_EQ(rect_of("fold_plot").size.y, fold.size.y) << "only the dragged edge moves";
  EXPECT_TRUE(explorer_->layout().fills_window());
  EXPECT_TRUE(explorer_->layout().automatic());

  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  ASSERT_FALSE(explorer_->set_view("pointer", "coarse"));
  frame();
  frame();
  EXPECT_FLOAT_EQ(rect_of("cloth").pos.x, cloth.pos.x + 120.0f);

  // With a mouse there is no grip.
  ASSERT_FALSE(explorer_->set_view("pointer", "fine"));
  frame();
  frame();
  EXPECT_TRUE(explorer_->layout().handle_rects().empty());
}

}  // namespace
}  // namespace foldlab::gui
