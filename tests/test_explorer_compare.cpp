// Comparing two fabrics: B pinned beside A in the results, the fold plot, the 3D view and the
// sweep, and kept with the session.
#include "explorer_fixture.hpp"

namespace foldlab::gui {
namespace {

// A/B comparison. B is pinned with the Results panel's button and A is changed through a slider
// drag, as a designer would; every number B shows is checked against a direct solve of B's
// parameters, and A − B (the change since the pin) against two independent solves.
TEST_F(ExplorerTest, PinnedBKeepsItsNumbersWhileADragChangesAAndTheTableShowsTheChangeAMinusB) {
  open_explorer("equations", kDejaVuSans);
  explorer_->load_preset_file(kPresetsDir / "default.json");  // calibrated: intervals shown
  frame();
  frame();
  EXPECT_EQ(last_text_.find("A − B"), std::string::npos) << "no table before a pin";
  // The proportional font's spaces are found by the player's reading of the glyphs.
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Pin as B"}}}}}, [&] { frame(); }), 0);
  ASSERT_TRUE(document().compare().pinned());
  const Parameters b = shown();
  EXPECT_EQ(document().compare().b().parameters, b);
  const std::string default_name = load_preset(kPresetsDir / "default.json").name;
  EXPECT_EQ(document().compare().b().name, default_name);

  ASSERT_EQ(play(*explorer_, {{"steps", {{{"drag", "h"}, {"dx", 80}}}}}, [&] { frame(); }), 0);
  const Parameters a = shown();
  ASSERT_GT(a.hanging.height_mm, b.hanging.height_mm + 50.0) << "the drag moved h";
  EXPECT_EQ(document().compare().b().parameters, b) << "B is not an edit of A";
  const Solution solved_a = solve(a);
  const Solution solved_b = solve(b);
  const Solution& shown_b = document().compare().solution();
  EXPECT_EQ(shown_b.n, solved_b.n);
  EXPECT_DOUBLE_EQ(shown_b.Q, solved_b.Q);
  EXPECT_DOUBLE_EQ(shown_b.z_max_mm, solved_b.z_max_mm);
  ASSERT_NE(solved_a.z_max_mm, solved_b.z_max_mm);

  // Each quantity's row of the table: the symbol, A, B and A − B, and under A and B their
  // intervals, from the calibration the preset carries.
  frame();
  const std::string text = frame();
  const auto rows_of = [](const Parameters& p) {
    const Solution s = solve(p);
    const PredictionRange r = *model_standing(p, default_preset().calibration).range;
    return std::array<std::pair<std::string, std::string>, 3>{
        std::pair{detail::printf_string("%d", s.n),
                  detail::printf_string("%d–%d", r.n_min, r.n_max)},
        std::pair{detail::printf_string("%.4f", s.Q),
                  detail::printf_string("%.4f–%.4f", r.Q_min, r.Q_max)},
        std::pair{detail::printf_string("%.2f mm", s.z_max_mm),
                  detail::printf_string("%.1f–%.1f mm", r.z_max_min_mm, r.z_max_max_mm)}};
  };
  const auto a_cells = rows_of(a);
  const auto b_cells = rows_of(b);
  // The change since B was pinned: A − B.
  const std::array<std::string, 3> differences = {
      detail::printf_string("%+d", solved_a.n - solved_b.n),
      detail::printf_string("%+.4f", solved_a.Q - solved_b.Q),
      detail::printf_string("%+.2f mm", solved_a.z_max_mm - solved_b.z_max_mm)};
  const char* const symbols[] = {"n", "Q", "z_max"};
  for (int i = 0; i < 3; ++i) {
    const std::string rows = std::string("\n") + symbols[i] + a_cells[i].first + b_cells[i].first +
                             differences[i] + "\n" + a_cells[i].second + b_cells[i].second + "\n";
    EXPECT_TRUE(shows(text, rows)) << rows << "\n" << text;
  }
  EXPECT_TRUE(shows(text, "A − B\nsince pinned")) << text;
  // The labels wrap in the panel: read without the line breaks.
  std::string unwrapped = text;
  std::erase(unwrapped, '\n');
  EXPECT_TRUE(shows(unwrapped, "A: " + default_name + " (edited)")) << text;
  EXPECT_TRUE(shows(unwrapped, "B: " + default_name)) << text;
  EXPECT_FALSE(shows(unwrapped, "B: " + default_name + " (edited)")) << text;

  // Undo moves A back to where B was pinned and leaves B alone.
  press('Z', true);
  EXPECT_EQ(shown(), b);
  EXPECT_EQ(document().compare().b().parameters, b);
}

TEST_F(ExplorerTest, TheFoldPlotDrawsBsFoldLinesDashedBesideAs) {
  EXPECT_EQ(panel<FoldPlotPanel>().compare_lines_drawn(), 0);
  const int legend_without_b = panel<FoldPlotPanel>().plot_view().legend_entries;
  click("Pin as B");
  const Parameters b = shown();
  ASSERT_EQ(explorer_->set_input("h", 2350.0), std::nullopt);
  frame();
  // B's lines as the core lays them out, each sample a point (the gaps of a dash are NaN points).
  Scene direct(b);
  const FoldLines& lines = direct.fold_lines();
  std::size_t points = 0;
  for (const FoldLine& line : lines.lines) {
    points += line.points_mm.size();
  }
  ASSERT_GT(lines.lines.size(), 1u);
  EXPECT_EQ(panel<FoldPlotPanel>().compare_lines_drawn(), static_cast<int>(lines.lines.size()));
  EXPECT_EQ(panel<FoldPlotPanel>().compare_points_drawn(), points);
  // "A positive fold", "A negative fold", "B positive fold (dashed)", "B negative fold (dashed)"
  // in place of the two fold entries, none cut at the plot's edge.
  EXPECT_EQ(panel<FoldPlotPanel>().plot_view().legend_entries, legend_without_b + 2);
  const std::string text = frame();
  for (const char* entry : {"A positive fold", "A negative fold", "B positive fold (dashed)",
                            "B negative fold (dashed)"}) {
    EXPECT_NE(text.find(entry), std::string::npos) << entry << "\n" << text;
  }
  const PanelRect plot = rect_of("fold_plot");
  EXPECT_EQ(cut_glyphs(plot.pos, ImVec2(plot.pos.x + plot.size.x, plot.pos.y + plot.size.y)),
            std::vector<std::string>{});
  click("Clear B");
  EXPECT_FALSE(document().compare().pinned());
  EXPECT_EQ(panel<FoldPlotPanel>().compare_lines_drawn(), 0);
  EXPECT_EQ(panel<FoldPlotPanel>().plot_view().legend_entries, legend_without_b);
}

TEST_F(ExplorerTest, TheThreeDViewDrawsBBesideAOnlyWhilePinned) {
  frame();
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).frames, 0u) << "no B: nothing drawn for it";
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).mesh_uploads, 0u);
  click("Pin as B");
  const RenderCounters pinned = renderer_.cloth_counters(panel<ClothViewPanel>().b_view());
  EXPECT_GE(pinned.mesh_uploads, 1u);
  EXPECT_GE(pinned.frames, 1u);
  const std::uint64_t a_frames = renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).frames;
  for (int i = 0; i < 3; ++i) {
    frame();
  }
  // Both cloths every frame, and B's picture kept while nothing it shows changes.
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().a_view()).frames, a_frames + 3);
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).frames, pinned.frames + 3);
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).view_cache_hits, pinned.view_cache_hits + 3);
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).mesh_uploads, pinned.mesh_uploads);
  // Each half is named. In the tiled half view a preset's long name would wrap over the cloth
  // and its supports: the letter alone; presented, the view is wide enough for the name.
  const auto drawn_in_cloth_view = [&](const std::string& words) {
    const PanelRect view = rect_of("cloth");
    const auto boundary = [&](std::size_t at) {
      return at >= last_text_.size() || last_text_[at] == ' ' || last_text_[at] == '\n';
    };
    for (std::size_t at = last_text_.find(words); at != std::string::npos;
         at = last_text_.find(words, at + 1)) {
      const ImVec2 p = last_positions_[at];
      if ((at == 0 || boundary(at - 1)) && boundary(at + words.size()) && p.x >= view.pos.x &&
          p.x < view.pos.x + view.size.x && p.y >= view.pos.y && p.y < view.pos.y + view.size.y) {
        return true;
      }
    }
    return false;
  };
  click("Clear B");
  click("Default: the Table 1 cloth");
  click("Pin as B");
  ASSERT_EQ(explorer_->set_input("h", 2000.0), std::nullopt);
  frame();
  EXPECT_TRUE(drawn_in_cloth_view("A")) << last_text_;
  EXPECT_TRUE(drawn_in_cloth_view("B")) << last_text_;
  EXPECT_FALSE(drawn_in_cloth_view("B: Default:")) << last_text_;
  ASSERT_EQ(explorer_->set_view("present", "cloth"), std::nullopt);
  frame();
  frame();
  EXPECT_TRUE(drawn_in_cloth_view("B: Default: the Table 1 cloth,")) << last_text_;
  // The read-out over the presented view gives both fabrics' numbers.
  // (Drawn larger, its glyphs' offsets no longer read as one line: compared squeezed.)
  const std::string read_out = squeezed(last_text_);
  EXPECT_NE(read_out.find(detail::printf_string("A:n=%d", explorer_->scene().solution().n)),
            std::string::npos)
      << last_text_;
  EXPECT_NE(read_out.find(detail::printf_string("B:n=%d", document().compare().solution().n)),
            std::string::npos)
      << last_text_;
  // At the view's foot, below the cloth and its supports.
  const PanelRect presented = rect_of("cloth");
  EXPECT_GT(position_of("B: Default: the Table 1 cloth,").y,
            presented.pos.y + 0.8f * presented.size.y);
  ASSERT_EQ(explorer_->set_view("present", "none"), std::nullopt);
  frame();
  click("Clear B");
  const std::uint64_t cleared = renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).frames;
  frame();
  frame();
  EXPECT_EQ(renderer_.cloth_counters(panel<ClothViewPanel>().b_view()).frames, cleared);
}

TEST_F(ExplorerTest, TheSweepDrawsBsCurveBesideAs) {
  open_explorer("sweep");
  EXPECT_EQ(panel<AnalysisPanel>().sweep().curves_drawn(), 1);
  EXPECT_EQ(panel<AnalysisPanel>().sweep().compare_curves(), nullptr);
  click("Pin as B");
  const Parameters b = shown();
  ASSERT_EQ(explorer_->set_input("w", 2.0 * b.fabric.weight_N_per_mm2), std::nullopt);
  frame();
  EXPECT_EQ(panel<AnalysisPanel>().sweep().curves_drawn(), 2);
  const SweepCurves* drawn = panel<AnalysisPanel>().sweep().compare_curves();
  ASSERT_NE(drawn, nullptr);
  // The sweep's own axis (h from 500 to 3000 mm, 200 steps) over B's parameters, from the core.
  const SweepCurves direct = sweep_curves(sweep(b, SweepAxis{"h", 500.0, 3000.0, 200, false}));
  EXPECT_EQ(drawn->x, direct.x);
  EXPECT_EQ(drawn->n, direct.n);
  EXPECT_EQ(drawn->z_max_mm, direct.z_max_mm);
  EXPECT_NE(panel<AnalysisPanel>().sweep().curves().z_max_mm, direct.z_max_mm) << "A moved";
}

TEST_F(ExplorerTest, APlayedScriptPinsSwapsAndClearsB) {
  const nlohmann::json script = {
      {"steps",
       {{{"expect", {{"compare", nullptr}}}},
        {{"click", "Pin as B"}},
        {{"expect", {{"compare.parameters.h_mm", 1400}}}},
        {{"drag", "h"}, {"dx", 80}},
        {{"expect", {{"parameters.h_mm", {1500, 5000}}, {"compare.parameters.h_mm", 1400}}}},
        {{"click", "Swap A and B"}},
        {{"expect", {{"parameters.h_mm", 1400}, {"compare.parameters.h_mm", {1500, 5000}}}}},
        {{"expect", {{"renderer.compare.frames", {1, 1e9}}}}},
        {{"click", "Clear B"}},
        {{"expect", {{"compare", nullptr}, {"parameters.h_mm", 1400}}}}}}};
  InputPlayer player(script, "test script");
  while (player.before_new_frame(ImGui::GetIO(), *explorer_)) {
    frame();
  }
  EXPECT_EQ(player.exit_status(), 0) << player.failure() << "\n" << frame();
  // Each of pin, swap and clear is one undo step that restores A and B together: the first undo
  // brings B back, the second the fabrics as they were before the swap, the third A before the
  // drag, the fourth no B.
  EXPECT_FALSE(document().compare().pinned());
  EXPECT_EQ(height_mm(), 1400.0);
  press('Z', true);
  ASSERT_TRUE(document().compare().pinned());
  const double dragged = document().compare().b().parameters.hanging.height_mm;
  EXPECT_GT(dragged, 1500.0);
  EXPECT_EQ(height_mm(), 1400.0);
  press('Z', true);
  EXPECT_EQ(height_mm(), dragged);
  ASSERT_TRUE(document().compare().pinned());
  EXPECT_EQ(document().compare().b().parameters.hanging.height_mm, 1400.0) << "B as pinned";
  press('Z', true);
  EXPECT_EQ(height_mm(), 1400.0);
  EXPECT_TRUE(document().compare().pinned());
  press('Z', true);
  EXPECT_FALSE(document().compare().pinned());
  press('Y', true);  // redo
  EXPECT_TRUE(document().compare().pinned());
}

// Each fabric carries the preset it came from through pin, swap, reset, undo and the session: a
// swap once left A tied to B's preset (the header said "Silk chiffon" over linen's values, and
// "Reset to preset" then made A chiffon too).
TEST_F(ExplorerTest, EachFabricKeepsItsOwnPresetThroughPinSwapResetUndoAndTheSession) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  const Preset linen = load_preset(kPresetsDir / "fabric-linen-medium.json");
  const Preset chiffon = load_preset(kPresetsDir / "fabric-silk-chiffon.json");
  explorer_->load_preset_file(kPresetsDir / "fabric-linen-medium.json");
  frame();
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Pin as B"}}}}}, [&] { frame(); }), 0);
  explorer_->load_preset_file(kPresetsDir / "fabric-silk-chiffon.json");
  frame();
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Swap A and B"}}}}}, [&] { frame(); }), 0);
  const auto expect_a_is = [&](const Preset& a, const Preset& b, const char* when) {
    SCOPED_TRACE(when);
    EXPECT_EQ(document().loaded().name, a.name);
    EXPECT_EQ(fabric_label(document()), a.name);
    EXPECT_EQ(shown(), a.parameters);
    EXPECT_FALSE(document().unsaved());
    ASSERT_TRUE(document().compare().pinned());
    EXPECT_EQ(document().compare().b().name, b.name);
    EXPECT_EQ(document().compare().b_origin().name, b.name);
    EXPECT_EQ(document().compare().b().parameters, b.parameters);
  };
  expect_a_is(linen, chiffon, "after the swap");
  const std::string header = squeezed(frame());
  EXPECT_NE(header.find(squeezed(linen.name)), std::string::npos) << header;
  EXPECT_EQ(header.find(squeezed(chiffon.name + " (unsaved changes)")), std::string::npos);

  // Reset to preset, after a change, gives linen back, not chiffon.
  ASSERT_EQ(explorer_->set_input("h", 2400.0), std::nullopt);
  frame();
  EXPECT_EQ(fabric_label(document()), linen.name + " (edited)");
  click("Reset to preset");
  expect_a_is(linen, chiffon, "after reset");

  // Undo the reset, the change and the swap: chiffon is A again, with linen as B.
  press('Z', true);
  press('Z', true);
  press('Z', true);
  expect_a_is(chiffon, linen, "before the swap");
  press('Y', true);  // redo the swap
  expect_a_is(linen, chiffon, "redone");

  // The session keeps B's preset with it.
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  expect_a_is(linen, chiffon, "restored");
  ASSERT_EQ(play(*explorer_, {{"steps", {{{"click", "Swap A and B"}}}}}, [&] { frame(); }), 0);
  expect_a_is(chiffon, linen, "swapped back after a restart");
}

TEST_F(ExplorerTest, BIsRestoredWithTheSession) {
  const fs::path session = dir_ / "session.json";
  open_explorer("equations", {}, session);
  click("Pin as B");
  const Parameters b = shown();
  ASSERT_EQ(explorer_->set_input("h", 2000.0), std::nullopt);
  frame();
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  ASSERT_TRUE(document().compare().pinned());
  EXPECT_EQ(document().compare().b().parameters, b);
  EXPECT_EQ(shown().hanging.height_mm, 2000.0);
  click("Clear B");
  explorer_->save_session_now();
  open_explorer("equations", {}, session, true);
  EXPECT_FALSE(document().compare().pinned());
}

}  // namespace
}  // namespace foldlab::gui
