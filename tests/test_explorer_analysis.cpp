// The Analysis panel's tabs: the equations, the paper's method step by step, the sweep and the
// regime map.
#include "explorer_fixture.hpp"

#include <sstream>

namespace foldlab::gui {
namespace {

// The analysis panels once chose inputs by their index in the input table, which moved when the
// table was reordered (index 3 became nu): Table 1 was swept over nu, the map's x axis was nu.
TEST_F(ExplorerTest, AnalysisPanelsSweepThePapersInputsByKey) {
  EXPECT_EQ(panel<AnalysisPanel>().sweep().key(), "h");
  EXPECT_EQ(panel<AnalysisPanel>().regime_map().x_key(), "h");
  EXPECT_EQ(panel<AnalysisPanel>().regime_map().y_key(), "w");

  ASSERT_EQ(explorer_->set_view("sweep", "table1"), std::nullopt);
  frame();                       // a tab selected now shows from the next frame on
  scroll_panel("analysis", 10);  // to the last plot, which has the x axis's title
  std::string text = frame();
  EXPECT_EQ(panel<AnalysisPanel>().sweep().key(), "h");
  EXPECT_NE(text.find("h (mm)"), std::string::npos) << "the sweep's x axis\n" << text;
  // The heights of the paper's Table 1 rows that ship as presets.
  std::vector<double> xs = panel<AnalysisPanel>().sweep().overlay_x();
  std::sort(xs.begin(), xs.end());
  EXPECT_EQ(xs, (std::vector<double>{900.0, 1400.0, 2350.0}));
  EXPECT_EQ(text.find("cannot be swept"), std::string::npos) << text;

  ASSERT_EQ(explorer_->set_view("sweep", "table2"), std::nullopt);
  text = frame();
  EXPECT_EQ(panel<AnalysisPanel>().sweep().key(), "w");
  xs = panel<AnalysisPanel>().sweep().overlay_x();
  std::sort(xs.begin(), xs.end());
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_DOUBLE_EQ(xs[0], 10e-7);
  EXPECT_DOUBLE_EQ(xs[2], 54e-7);
  // The sweep shows w as its slider does, in g/m²: the range 5e-7..8e-6 N/mm² is
  // 5e-7 / 9.81e-9 = 50.97 to 8e-6 / 9.81e-9 = 815.5 g/m², in its fields and on the axis.
  scroll_panel("analysis", -10);  // back up to the fields
  text = frame();
  EXPECT_TRUE(only_beside_w_slider(text, "N/mm²")) << text;
  EXPECT_TRUE(w_in_e_notation_only_beside_its_slider(text)) << text;
  EXPECT_NE(text.find("50.97 g/m²"), std::string::npos) << "the range's first field\n" << text;
  EXPECT_NE(text.find("815.5 g/m²"), std::string::npos) << "the range's second field\n" << text;
  // The row wraps in the panel rather than push "log" and "steps" past its edge.
  const PanelRect analysis = rect_of("analysis");
  for (const char* label : {"log", "steps"}) {
    EXPECT_LE(position_of(label).x + ImGui::CalcTextSize(label).x,
              analysis.pos.x + analysis.size.x - ImGui::GetStyle().ScrollbarSize)
        << label;
  }
  const PlotView& sweep_view = panel<AnalysisPanel>().sweep().plot_view(0);
  EXPECT_LE(sweep_view.x_lo, 50.97);
  EXPECT_GE(sweep_view.x_hi, 815.5);
  EXPECT_GT(sweep_view.x_lo, 40.0) << "not in N/mm²";
  scroll_panel("analysis", 10);
  text = frame();
  EXPECT_NE(text.find("w (g/m²)"), std::string::npos) << "the sweep's x axis\n" << text;
  EXPECT_TRUE(only_beside_w_slider(text, "N/mm²")) << text;

  open_explorer("map");
  status().set_expert_mode(true);
  frame();
  text = frame();
  EXPECT_NE(text.find("h (mm)"), std::string::npos) << "the map's x axis\n" << text;
  EXPECT_NE(text.find("w (g/m²)"), std::string::npos) << "the map's y axis";
  EXPECT_TRUE(only_beside_w_slider(text, "N/mm²")) << text;
  EXPECT_TRUE(w_in_e_notation_only_beside_its_slider(text)) << text;
  EXPECT_EQ(text.find("nu"), text.find("nu (Poisson's ratio)")) << "nu only on its slider";
}

// The paper's form of eq. 7 is one click away for a beginner too: p = 1 and K = 26.9 / 0.91.
TEST_F(ExplorerTest, ThePrintedEq7IsOneClickAwayInBothModes) {
  explorer_->load_preset_file(kPresetsDir / "default.json");
  frame();
  ASSERT_NE(document().edited().model.stress_exponent_p, 1.0) << "the default is calibrated";
  click(ParametersPanel::kPrintedEq7Label);
  const Parameters& p = document().edited();
  EXPECT_EQ(p.model.method, Method::paper);
  EXPECT_EQ(p.model.stress_exponent_p, 1.0);
  EXPECT_NEAR(stiffness_constant_K(p), 29.5604, 1e-4);
  EXPECT_TRUE(document().issues().empty());
}

TEST_F(ExplorerTest, ThePapersOverlayBelongsToItsCaseOnly) {
  ASSERT_EQ(explorer_->set_view("sweep", "table2"), std::nullopt);
  frame();
  EXPECT_EQ(panel<AnalysisPanel>().sweep().overlay_x().size(), 3u) << "Table 2's printed rows";
  explorer_->load_preset_file(kPresetsDir / "paper-table1-h900.json");
  const std::string text = frame();
  EXPECT_TRUE(panel<AnalysisPanel>().sweep().overlay_x().empty());
  EXPECT_EQ(text.find("paper, Table 2"), std::string::npos) << text;
}

// The Method tab on Table 1's h = 1400 mm row (paper method). By hand: s = 0.02147 gives
// Q7 = 1.24499; the start a_0/a_n = 101 gives n = Int[log 101 / log Q7] = Int[21.06] = 21 and
// L'/L = 0.92884 (Simpson, 20 intervals), 7.12 % short; the next iterate's L'/L = 1.00229 is
// within 5 %, so the iteration stops at its second iterate.
TEST_F(ExplorerTest, TheMethodTabStepsThroughThePapersIteration) {
  open_explorer("method");
  std::string text = frame();
  EXPECT_NE(text.find("iterate 1 of 2"), std::string::npos) << text;
  EXPECT_NE(text.find("= 101, n = Int[21.06"), std::string::npos) << text;
  // (The test's font draws ′, − and ≤ as "?": the checks read around them.)
  EXPECT_NE(text.find("= 7.12 % > 5 %: iterate again."), std::string::npos) << text;
  EXPECT_NE(text.find("0.9288"), std::string::npos) << "L′/L in the table";
  // a_0 − a_n = 1.01 h − 0.01 h = h: the a-differences alone make h, so eq. 9's root on the first
  // iterate is exactly 0, shown as such (not as a rounded 0.00) and said to come from eq. 9.
  EXPECT_EQ(panel<AnalysisPanel>().method().trace().iterates.front().z_max_mm, 0.0);
  EXPECT_NE(squeezed(text).find(squeezed("so eq. 9 gives z_max = 0 mm.")), std::string::npos)
      << text;
  EXPECT_EQ(text.find("0.00 "), std::string::npos) << text;
  click("Step");
  text = frame();
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 2);
  EXPECT_NE(text.find("iterate 2 of 2"), std::string::npos) << text;
  EXPECT_NE(squeezed(text).find(squeezed("= 0.229 % ? 5 %: stop. This is the paper method's "
                                         "answer, the one Results shows.")),
            std::string::npos)
      << text;
  click("Step");  // disabled at the end: nothing moves
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 2);
  click("Back");
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 1);
  click("Run to end");
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 2);
  click("Reset");
  EXPECT_EQ(panel<AnalysisPanel>().method().shown(), 1);
  EXPECT_EQ(shown().model.method, Method::paper) << "viewing a method edits nothing";
}

// The exact method from the same start, n = 21: eqs. 8 and 9 at n = 21 give
// Int[log(a_0/a_n(21)) / log Q7] = 8, and n = 8 maps to itself.
// The paper method's tolerance was reachable only with --set. Table 2's w = 10e-7 row with a
// tolerance of 1e-5 takes 8 iterates (the same iteration by hand in Python, as play_method_stepper
// checks with --set).
TEST_F(ExplorerTest, TheMethodTabSetsThePaperMethodsToleranceAsOneValidatedStep) {
  open_explorer("method");
  explorer_->load_preset_file(kPresetsDir / "paper-table2-w10.json");
  frame();
  frame();
  const int iterates_at_5_percent = panel<AnalysisPanel>().method().iterates();
  const std::size_t depth = document().undo_depth();  // the preset load is a step
  const std::string text = frame();
  const ImVec2 field = last_positions_[text.find("0.05", text.find("stop when"))];
  click_at(ImVec2(field.x + 3.0f, field.y + 4.0f));
  ASSERT_EQ(type_and_enter("1e-5"), 0);
  EXPECT_EQ(explorer_->edited().model.length_tolerance, 1e-5);
  EXPECT_EQ(panel<AnalysisPanel>().method().iterates(), 8);
  EXPECT_EQ(document().undo_depth(), depth + 1);

  // Beyond 0.5 the tolerance is refused with its reason, the scene keeps the last valid one.
  click_at(ImVec2(field.x + 3.0f, field.y + 4.0f));
  ASSERT_EQ(type_and_enter("0.9"), 0);
  EXPECT_EQ(explorer_->edited().model.length_tolerance, 0.9);
  EXPECT_EQ(shown().model.length_tolerance, 1e-5);
  EXPECT_NE(last_text_.find("length_tolerance"), std::string::npos) << last_text_;
  press('Z', true);
  press('Z', true);
  EXPECT_EQ(shown().model.length_tolerance, 0.05);
  frame();
  EXPECT_EQ(panel<AnalysisPanel>().method().iterates(), iterates_at_5_percent);
}

TEST_F(ExplorerTest, TheMethodTabShowsTheExactMethodsStaircaseToItsFixedPoint) {
  open_explorer("method");
  click("exact method");
  std::string text = frame();
  EXPECT_EQ(panel<AnalysisPanel>().method().method(), Method::exact);
  EXPECT_EQ(shown().model.method, Method::paper);
  EXPECT_NE(text.find("n = 21:"), std::string::npos) << text;
  EXPECT_NE(text.find("= Int[8.18"), std::string::npos) << text;
  EXPECT_NE(text.find("] = 8 is the next"), std::string::npos) << text;
  EXPECT_NE(text.find("n 21 ? 8: iterate again."), std::string::npos) << text;
  click("Run to end");
  text = frame();
  // The model is set to the paper method: the stepper says whose answer each is.
  EXPECT_NE(squeezed(text).find(squeezed(
                "n = 8 maps to itself: the fixed point. This is the exact method's answer; "
                "Results shows the paper method's, the method set in Parameters.")),
            std::string::npos)
      << text;
  EXPECT_EQ(panel<AnalysisPanel>().method().trace().solution.n, 8);
}

// At t = 0.9 mm, Table 1's cloth is stiff (s >= 1) below h = K E t³ / (w l²) =
// 29.56 × 165 × 0.9³ / (1.5e-6 × 1300²) = 1402.6 mm (by hand). The sweep over h shows that
// stretch as a named band, and Q's curve holds no single-fold value (a_0/a_1 = 101) there.
TEST_F(ExplorerTest, TheSweepShowsAStiffStretchAsABandNotASpike) {
  open_explorer("sweep");
  ASSERT_EQ(explorer_->set_input("t", 0.9), std::nullopt);
  frame();
  const std::string text = frame();
  const SweepPanel& sweep_panel = panel<AnalysisPanel>().sweep();
  ASSERT_EQ(sweep_panel.key(), "h");
  ASSERT_FALSE(sweep_panel.bands().empty());
  const RegimeBand& stiff = sweep_panel.bands().front();
  EXPECT_EQ(stiff.name, "stiff");
  EXPECT_DOUBLE_EQ(stiff.from, 500.0);
  EXPECT_NEAR(stiff.to, 1402.6, 2500.0 / 199.0);  // within one step of the sweep
  EXPECT_NE(text.find("stiff"), std::string::npos) << "the band's name is drawn\n" << text;
  // A key above the plots says what each shade is: a band one sample wide has no room for its
  // name.
  EXPECT_NE(squeezed(text).find(
                squeezed(std::string("stiff: ") + std::string(regime_info(Regime::stiff).plain))),
            std::string::npos)
      << text;
  // The largest Q with two or more folds, from the same sweep solved here.
  double wrinkled_max_Q = 0.0;
  double stiff_max_Q = 0.0;
  for (const SweepPoint& p : sweep(shown(), SweepAxis{"h", 500.0, 3000.0, 200, false})) {
    if (p.regime == Regime::wrinkled && p.n >= 2) {
      wrinkled_max_Q = std::max(wrinkled_max_Q, p.Q);
    } else if (p.regime == Regime::stiff) {
      stiff_max_Q = std::max(stiff_max_Q, p.Q);
    }
  }
  EXPECT_NEAR(stiff_max_Q, 101.0, 1e-9) << "the spike the Q curve used to show";
  ASSERT_GT(wrinkled_max_Q, 1.0);
  for (double Q : sweep_panel.curves().Q) {
    EXPECT_TRUE(std::isnan(Q) || Q <= wrinkled_max_Q) << Q;
  }
  // The three plots share the sweep's x range, so that the current value lines up in all three:
  // the Q plot, with no Q over the stiff band, once fitted its own. (The z_max plot is below
  // the panel's fold, not drawn.)
  for (int which = 0; which < 2; ++which) {
    EXPECT_LE(sweep_panel.plot_view(which).x_lo, 500.0) << which;
    EXPECT_GE(sweep_panel.plot_view(which).x_hi, 3000.0) << which;
    EXPECT_EQ(sweep_panel.plot_view(which).x_lo, sweep_panel.plot_view(0).x_lo) << which;
    EXPECT_EQ(sweep_panel.plot_view(which).x_hi, sweep_panel.plot_view(0).x_hi) << which;
  }
  // And their data areas start at one x: n's short tick labels ("2") left n's area 4 px left of
  // Q's ("1.25"), so the same value sat 4 px apart, as seen in the window.
  frame();
  const PlotView& n_view = sweep_panel.plot_view(0);
  const PlotView& Q_view = sweep_panel.plot_view(1);
  EXPECT_EQ(n_view.min.x, Q_view.min.x);
  EXPECT_EQ(n_view.max.x, Q_view.max.x);
}

// The paper's Table 1 beside the model: the printed n, Q, z_max of each row and the model's at
// the same h (the paper's form of eq. 7 in these presets gives n = 5, 8, 14).
TEST_F(ExplorerTest, TheSweepListsThePapersTableBesideTheModel) {
  ASSERT_EQ(explorer_->set_view("sweep", "table1"), std::nullopt);
  frame();
  frame();
  click("Paper vs model (table)");
  const std::string text = frame();
  for (const char* printed :
       {"n paper", "n model", "1.31", "1.29", "1.34", "54 mm", "48 mm", "60 mm"}) {
    EXPECT_NE(text.find(printed), std::string::npos) << printed << "\n" << text;
  }
  EXPECT_NE(text.find("43.4 mm"), std::string::npos) << "the model's z_max at h = 1400\n" << text;
}

// The Equations tab at twice the text size and in a 1024 x 640 window: every equation wraps
// before an operator instead of running past the panel, so that each number is drawn whole
// (ImGui leaves out a glyph wholly past a clip edge: a cut line loses its last numbers).
TEST_F(ExplorerTest, TheEquationsCutNoNumberAtTwiceTheTextSizeOrInASmallWindow) {
  open_explorer("equations", kDejaVuSans);
  explorer_->load_preset_file(kPresetsDir / "default.json");  // calibrated: s^p, p != 1
  const Solution& s = explorer_->scene().solution();
  const double p = explorer_->scene().parameters().model.stress_exponent_p;
  ASSERT_NE(p, 1.0);
  ASSERT_TRUE(s.Q7.has_value());
  // As the tab writes them: what a reader must see whole, spaces and line breaks aside.
  const std::string s_power =
      detail::printf_string("s^p=%.5g^%.6g=%.5g", s.stress_ratio, p, std::pow(s.stress_ratio, p));
  const std::string q7 = detail::printf_string("->Q7=%.5f", *s.Q7);
  const std::string h_line = detail::printf_string("h=%.1fmm", 1400.0);
  const std::string q = detail::printf_string("Q=(a_0/a_n)^(1/n)=%.4f", s.Q);
  // At 200 % a 1024 x 640 window leaves the tiled panel a few lines high: there it is presented.
  struct Case {
    const char* scale;
    ImVec2 size;
    const char* present;
  };
  for (const Case c :
       {Case{"100", ImVec2(1024, 640), "none"}, Case{"150", ImVec2(1024, 640), "none"},
        Case{"200", ImVec2(1024, 640), "analysis"}, Case{"200", ImVec2(1280, 800), "none"},
        Case{"200", ImVec2(1920, 1080), "none"}}) {
    SCOPED_TRACE(::testing::Message() << c.scale << " % at " << c.size.x << "x" << c.size.y
                                      << ", presented: " << c.present);
    ASSERT_EQ(explorer_->set_view("present", c.present), std::nullopt);
    ASSERT_EQ(explorer_->set_view("scale", c.scale), std::nullopt);
    show_at(c.size);
    // The wheel over the equations (the tab's own child window scrolls, not the panel).
    const auto turn_wheel = [&](float notches) {
      const PanelRect r = rect_of("analysis");
      ImGuiIO& io = ImGui::GetIO();
      io.MousePos = ImVec2(r.pos.x + 0.5f * r.size.x, r.pos.y + 0.75f * r.size.y);
      io.MouseWheel = notches;
      frame();
      io.MouseWheel = 0.0f;
      frame();
    };
    turn_wheel(50.0f);
    bool seen[4] = {};
    const std::string wanted[4] = {s_power, q7, h_line, q};
    for (int scroll = 0; scroll < 30; ++scroll) {
      const PanelRect r = rect_of("analysis");
      const std::vector<std::string> cut =
          cut_glyphs(r.pos, ImVec2(r.pos.x + r.size.x, r.pos.y + r.size.y));
      EXPECT_TRUE(cut.empty()) << cut.size() << " glyphs cut, first "
                               << (cut.empty() ? "" : cut.front());
      const std::string text = squeezed(last_text_);
      for (int i = 0; i < 4; ++i) {
        seen[i] = seen[i] || text.find(wanted[i]) != std::string::npos;
      }
      turn_wheel(-1.0f);
    }
    for (int i = 0; i < 4; ++i) {
      EXPECT_TRUE(seen[i]) << wanted[i] << " never drawn whole\n" << last_text_;
    }
  }
}

// A student recomputing eq. 7's s from the numbers the tab prints gets the s it prints: every
// input carries the digits the result does (306 g/m² was "3e-06" N/mm², and s came out 2 % off).
TEST_F(ExplorerTest, EquationsCarryTheDigitsToReproduceTheirResult) {
  ASSERT_EQ(explorer_->set_input("w", 306.0 * 9.81e-9), std::nullopt);
  const std::string text = squeezed(frame());
  const std::string start = "s=KEt³/(whl²)=";
  const std::size_t at = text.find(start);
  ASSERT_NE(at, std::string::npos) << text;
  // "K×E×t³/(w×h×l²)=s", read back as a person would: six numbers, then s.
  std::string numbers = text.substr(at + start.size(), 160);
  for (const char* mark : {"×", "³", "²", "/", "(", ")", "="}) {
    for (std::size_t i = numbers.find(mark); i != std::string::npos; i = numbers.find(mark)) {
      numbers.replace(i, std::string(mark).size(), " ");
    }
  }
  std::istringstream in(numbers);
  double K = 0, E = 0, t = 0, w = 0, h = 0, l = 0, s_printed = 0;
  ASSERT_TRUE(in >> K >> E >> t >> w >> h >> l >> s_printed) << numbers;
  const double s_recomputed = K * E * t * t * t / (w * h * l * l);
  // s is printed with 5 significant digits: the recomputed one agrees to its last digit.
  EXPECT_NEAR(s_recomputed / s_printed, 1.0, 1e-4) << numbers;

  // The calibrated form's exponent too: s^p from the printed s and p is the printed s^p.
  explorer_->load_preset_file(kPresetsDir / "default.json");
  const std::string calibrated = squeezed(frame());
  const std::size_t power = calibrated.find("s^p=");
  ASSERT_NE(power, std::string::npos) << calibrated;
  std::string line = calibrated.substr(power + 4, 60);
  for (char& c : line) {
    c = (c == '^' || c == '=') ? ' ' : c;
  }
  std::istringstream parts(line);
  double base = 0, exponent = 0, result = 0;
  ASSERT_TRUE(parts >> base >> exponent >> result) << line;
  EXPECT_NEAR(std::pow(base, exponent) / result, 1.0, 1e-4) << line;
}

// An equation breaks before "=" first, then before an arithmetic operator, then at a space; a
// line after a break is indented.
TEST_F(ExplorerTest, AnEquationWrapsBeforeItsOperators) {
  frame();
  const auto width = [](const char* text) { return ImGui::CalcTextSize(text).x; };
  EXPECT_EQ(wrap_equation("s^p = 0.0012247^0.522 = 0.030123", 1000.0f),
            "s^p = 0.0012247^0.522 = 0.030123");
  EXPECT_EQ(wrap_equation("s^p = 0.0012247^0.522 = 0.030123", width("s^p = 0.0012247^0.522")),
            "s^p = 0.0012247^0.522\n    = 0.030123");
  EXPECT_EQ(wrap_equation("a = 12 × 345 / 6789 = 2", width("    = 12 × 345")),
            "a\n    = 12 × 345\n    / 6789\n    = 2");
  // The leading spaces of a "  = value" line are its own, not a place to break.
  EXPECT_EQ(wrap_equation("  = 1.25", 1000.0f), "  = 1.25");
  // No operator left: at spaces, never inside a number.
  EXPECT_EQ(wrap_equation("check 0.0012247 0.522", width("    0.0012247")),
            "check\n    0.0012247\n    0.522");
}

// Each of the Sweep tab's three plots keeps a data area of a few lines at 150 % in a small
// window: the panel scrolls instead of squeezing a plot to a few pixels.
TEST_F(ExplorerTest, EachSweepPlotKeepsItsHeightAtALargeUiScale) {
  open_explorer("sweep", kDejaVuSans);
  ASSERT_EQ(explorer_->set_view("scale", "150"), std::nullopt);
  for (const ImVec2 size : {ImVec2(1280, 800), ImVec2(1024, 640)}) {
    SCOPED_TRACE(::testing::Message() << size.x << "x" << size.y);
    show_at(size);
    // The panel scrolls (the wheel over its tabs, not over a plot, which it would zoom) to show
    // each plot in turn.
    const PanelRect analysis = rect_of("analysis");
    bool seen[3] = {};
    for (int scroll = 0; scroll < 12; ++scroll) {
      for (int which = 0; which < 3; ++which) {
        const PlotView& view = panel<AnalysisPanel>().sweep().plot_view(which);
        if (view.max.y > analysis.pos.y && view.min.y < analysis.pos.y + analysis.size.y) {
          seen[which] = true;
          EXPECT_GE(view.max.y - view.min.y, 3.0f * ImGui::GetFontSize()) << "plot " << which;
        }
      }
      scroll_panel("analysis", 1);
    }
    EXPECT_TRUE(seen[0] && seen[1] && seen[2]);
  }
}

// The regime map's colours explained beside it: a colour bar with n's scale on the map's right
// and the regimes without n named under it.
TEST_F(ExplorerTest, TheRegimeMapHasAColourBarAndNamesItsRegimes) {
  open_explorer("map");
  while (explorer_->busy()) {
    frame();
  }
  const std::string text = frame();
  for (const char* name : {"no slack", "short cloth", "negligible slack", "invalid inputs"}) {
    EXPECT_NE(text.find(name), std::string::npos) << name << "\n" << text;
  }
  // The bar's scale, 1 at the bottom to 200 at the top, right of the map's x range (3000).
  const ImVec2 top = position_of("\n200\n");
  const ImVec2 bottom = position_of("\n1\n");
  const ImVec2 x_to = position_of("3000");
  EXPECT_LT(top.y, bottom.y);
  EXPECT_GT(top.x, x_to.x);
  EXPECT_GT(bottom.x, x_to.x);
  // The bar's title above it, clear of the x labels' line (under the bar "3000" ran into it).
  const ImVec2 title = position_of("\nn\n");
  EXPECT_LT(title.y + ImGui::GetFontSize(), top.y);
}

// The map's axes carry round ticks in the sliders' units: h over 300..3000 mm 1, 2 or 5 × 10^k
// apart, w over 3e-7..1e-5 N/mm² = 30.6..1019 g/m² (log scale) at 1, 2 or 5 × 10^k g/m², written
// out and no two labels overlapping.
TEST_F(ExplorerTest, TheRegimeMapsAxesHaveRoundTicksInTheSlidersUnits) {
  open_explorer("map");
  while (explorer_->busy()) {
    frame();
  }
  const std::string text = frame();
  // The x labels: the line above the x title, evenly spaced by a round step.
  const std::size_t title = text.find("\nh (mm)\n");
  ASSERT_NE(title, std::string::npos) << text;
  const std::size_t line = text.rfind('\n', title - 1) + 1;
  const std::string x_labels = text.substr(line, title - line);
  EXPECT_EQ(x_labels.find('e'), std::string::npos) << x_labels;
  std::vector<double> x_ticks;
  for (const char* at = x_labels.c_str(); *at != '\0';) {
    char* end = nullptr;
    x_ticks.push_back(std::strtod(at, &end));
    ASSERT_NE(end, at) << x_labels;
    at = end;
  }
  ASSERT_GE(x_ticks.size(), 2u) << x_labels;
  const double step = x_ticks[1] - x_ticks[0];
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
  EXPECT_TRUE(mantissa == 1.0 || mantissa == 2.0 || mantissa == 5.0) << x_labels;
  for (std::size_t k = 1; k < x_ticks.size(); ++k) {
    EXPECT_EQ(x_ticks[k] - x_ticks[k - 1], step) << x_labels;
    EXPECT_GE(x_ticks[k - 1], 300.0);
    EXPECT_LE(x_ticks[k], 3000.0);
    // Drawn apart: the next label starts right of where this one ends.
    const ImVec2 here = position_of(" " + format_tick(x_ticks[k], step));
    EXPECT_GT(here.x, 0.0f);
  }
  // The y labels: one a line between the y title and the x labels, 1, 2 or 5 × 10^k g/m² inside
  // 30.6..1019, ascending, each at least a line above the one before.
  const std::size_t y_title = text.find("\nw (g/m²)\n");
  ASSERT_NE(y_title, std::string::npos) << text;
  const std::size_t first_y = y_title + std::string("\nw (g/m²)\n").size();
  std::vector<double> y_ticks;
  float last_y = -1e9f;
  for (std::size_t at = first_y; at < line;) {
    const std::size_t end = text.find('\n', at);
    const std::string label = text.substr(at, end - at);
    const double value = std::strtod(label.c_str(), nullptr);
    EXPECT_EQ(label.find('e'), std::string::npos) << label;
    const double leading = value / std::pow(10.0, std::floor(std::log10(value) + 1e-9));
    EXPECT_TRUE(std::abs(leading - 1) < 1e-9 || std::abs(leading - 2) < 1e-9 ||
                std::abs(leading - 5) < 1e-9)
        << label;
    EXPECT_GT(value, 30.58);
    EXPECT_LT(value, 1019.4);
    if (!y_ticks.empty()) {  // drawn from the bottom up
      EXPECT_GT(value, y_ticks.back());
      EXPECT_GE(last_y - last_positions_[at].y, ImGui::GetFontSize()) << label;
    }
    y_ticks.push_back(value);
    last_y = last_positions_[at].y;
    at = end + 1;
  }
  ASSERT_GE(y_ticks.size(), 2u) << text;
  EXPECT_TRUE(w_in_e_notation_only_beside_its_slider(text)) << text;

  // The hover reads in the same units, at the ticks it is over.
  const ImVec2 w_100 = position_of("\n100\n");  // a decade on a log axis is always labelled
  const std::string x_tick = format_tick(x_ticks.back(), step);
  const ImVec2 x_at = position_of(x_tick);
  ImGui::GetIO().MousePos = ImVec2(x_at.x + 0.5f * ImGui::CalcTextSize(x_tick.c_str()).x - 2.0f,
                                   w_100.y + 0.5f * ImGui::GetFontSize());
  frame();
  const std::string hovered = frame();
  // Within a cell (2700 mm / 256 = 11 mm; a w cell is 1/256 of 1.52 decades, 1.4 %) and the
  // 2 px the mouse stays left of the map's edge.
  const std::string first_tick = format_tick(x_ticks.front(), step);
  const float first_centre =
      position_of(first_tick).x + 0.5f * ImGui::CalcTextSize(first_tick.c_str()).x;
  const float last_centre = x_at.x + 0.5f * ImGui::CalcTextSize(x_tick.c_str()).x;
  const double mm_per_px = (x_ticks.back() - x_ticks.front()) / (last_centre - first_centre);
  EXPECT_NEAR(number_after(hovered, ", w = "), 100.0, 3.0) << hovered;
  EXPECT_NEAR(number_after(hovered, "\nh = "), x_ticks.back(), 11.0 + 3.0 * mm_per_px) << hovered;
  EXPECT_NE(hovered.find(" g/m²\n"), std::string::npos) << hovered;
}

// The regime map in its tile at 200 % in 1280 x 800: its axes and cells took the whole tile and
// the map was out of sight. They fold behind "map settings..." as the views' settings do, the
// line of timing goes with them, and they work from the popup.
TEST_F(ExplorerTest, AtALargeTextSizeTheRegimeMapsSettingsFoldAndStillWork) {
  open_explorer("map");
  ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
  frame();
  frame();
  const auto report = [&] { return panel<AnalysisPanel>().regime_map().report(); };
  EXPECT_FALSE(report().at("settings_folded").get<bool>());
  EXPECT_NE(last_text_.find("show z_max instead of n"), std::string::npos) << last_text_;
  explorer_->appearance().request(200, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_TRUE(report().at("settings_folded").get<bool>());
  EXPECT_EQ(last_text_.find("show z_max instead of n"), std::string::npos) << last_text_;
  EXPECT_EQ(last_text_.find("solves in"), std::string::npos) << last_text_;
  click("map settings...");
  EXPECT_NE(last_text_.find("solves in"), std::string::npos) << last_text_;
  EXPECT_EQ(report().at("shows"), "n");
  click("show z_max instead of n");
  EXPECT_EQ(report().at("shows"), "z_max");
  EXPECT_TRUE(report().at("settings_folded").get<bool>()) << "a setting does not unfold the row";
  press(kEscape);
  explorer_->appearance().request(100, false);
  for (int i = 0; i < 4; ++i) {
    frame();
  }
  EXPECT_FALSE(report().at("settings_folded").get<bool>());
}

// A click on the regime map moves both of its inputs, and one undo brings both back.
TEST_F(ExplorerTest, ARegimeMapClickIsOneUndoStep) {
  open_explorer("map");
  while (explorer_->busy()) {
    frame();
  }
  frame();
  const Parameters before = shown();
  const std::size_t depth = document().undo_depth();
  // The middle of the map as the panel reports where it drew it.
  DrawingAreas areas;
  panel<AnalysisPanel>().drawing_areas(areas);
  const auto map = std::find_if(areas.begin(), areas.end(),
                                [](const auto& area) { return area.first == "regime_map"; });
  ASSERT_NE(map, areas.end());
  const ImVec2 middle(map->second.pos.x + 0.5f * map->second.size.x,
                      map->second.pos.y + 0.5f * map->second.size.y);
  click_at(middle);
  EXPECT_NE(shown().hanging.height_mm, before.hanging.height_mm);
  EXPECT_NE(shown().fabric.weight_N_per_mm2, before.fabric.weight_N_per_mm2);
  EXPECT_EQ(document().undo_depth(), depth + 1) << "x and y in one step";
  ASSERT_TRUE(document().undo());
  EXPECT_EQ(shown().hanging.height_mm, before.hanging.height_mm);
  EXPECT_EQ(shown().fabric.weight_N_per_mm2, before.fabric.weight_N_per_mm2);
}

// "n changed from" tells the change the fabric made, wherever it was made: edits made while
// another view is presented (the Equations tab not drawn) count, so after t = 0.4 mm then 0.3 mm
// the tab says the last change, from n at 0.4 mm to n at 0.3 mm, not from the n it last drew.
TEST_F(ExplorerTest, WhyNChangedTracksTheFabricNotThePanel) {
  open_explorer("equations");
  ImGui::GetIO().DisplaySize = ImVec2(1920, 1600);  // the tab's last line in sight
  explorer_->load_preset_file(kPresetsDir / "paper-table1-h1400.json");
  frame();
  const int first = explorer_->scene().solution().n;
  ASSERT_EQ(explorer_->set_view("present", "fold_plot"), std::nullopt);
  frame();
  ASSERT_EQ(explorer_->set_input("t", 0.4), std::nullopt);
  frame();
  const int at_04 = explorer_->scene().solution().n;
  ASSERT_EQ(explorer_->set_input("t", 0.3), std::nullopt);
  frame();
  const int at_03 = explorer_->scene().solution().n;
  ASSERT_NE(first, at_04);
  ASSERT_NE(at_04, at_03);
  ASSERT_EQ(explorer_->set_view("present", "none"), std::nullopt);
  frame();
  const std::string text = frame();
  const std::string said =
      "n changed from " + std::to_string(at_04) + " to " + std::to_string(at_03);
  EXPECT_NE(text.find(said), std::string::npos) << said << "\n" << text;
}

}  // namespace
}  // namespace foldlab::gui
