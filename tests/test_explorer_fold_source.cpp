// The 3D view's fold source: the cloth drawn with the closed form's folds or with those read from
// the tension field, the field solved only for a view that asks for it, Results' two columns, and
// a preset's own cut in the field view, the field view's scale while an input moves. The expected
// folds come from the core calls `foldlab
// field --json` makes (mesh, cold solve, field_folds), never from the panels.
#include "explorer_fixture.hpp"

#include <regex>
#include "outline_area.hpp"

#include "app/gui/panels/field_panel.hpp"
#include "app/gui/picture.hpp"
#include "core/field/field_case.hpp"
#include "core/field/field_folds.hpp"

namespace foldlab::gui {
namespace {

using nlohmann::json;

// The field's folds as `foldlab field --json` finds them for `p` on the explorer's mesh at rest:
// FieldPanel::kDefaultCells across the shape's cut (or `cells_x`) and as many down as keep the
// cells square.
field::FieldFolds folds_as_the_command_finds_them(const Parameters& p,
                                                  int cells_x = FieldPanel::kDefaultCells) {
  const field::Outline outline = field::make_outline(p, field::outline_kind_of(p.shape));
  double top = outline.top_mm.front().y();
  double bottom = outline.bottom_mm.front().y();
  for (const Eigen::Vector2d& v : outline.top_mm) {
    top = std::min(top, v.y());
  }
  for (const Eigen::Vector2d& v : outline.bottom_mm) {
    bottom = std::max(bottom, v.y());
  }
  field::MeshResolution resolution;
  resolution.cells_x = cells_x;
  resolution.cells_y =
      std::clamp(static_cast<int>(std::lround(resolution.cells_x * (bottom - top) /
                                              (outline.right_mm() - outline.left_mm()))),
                 4, 2 * resolution.cells_x);
  field::Solver solver(field::make_mesh(outline, resolution));
  const field::Solution solution =
      field::solve_cold(solver, outline, field::material_of(p.fabric), resolution);
  EXPECT_TRUE(solution.converged);
  return field::field_folds(solver.mesh(), solution, field::support_targets(outline), p);
}

using foldlab::testing::shoelace_area_mm2;

class FoldSourceTest : public ExplorerTest {
 protected:
  // Frames until the field (if any is asked for) has settled on the mesh at rest.
  void settle() {
    for (int i = 0; i < 30; ++i) {
      frame();  // past the rest time after the last change, 0.3 s at 60 frames a second
    }
    for (int i = 0; i < 600 && explorer_->busy(); ++i) {
      frame();
    }
    frame();
  }
  json report() { return explorer_->report(); }
};

// Table 1's h = 1400 mm cloth at L = 4000 mm, where the field counts other folds than the closed
// form: switched to the field, the 3D view's scene has the field's n, z_max and a_i; switched
// back, the closed form's.
TEST_F(FoldSourceTest, TheFieldsFoldsAreDrawnInTheThreeDViewWhenChosen) {
  ASSERT_EQ(explorer_->set_input("L", 4000.0), std::nullopt);
  settle();
  const Parameters p = shown();
  const field::FieldFolds expected = folds_as_the_command_finds_them(p);
  const Solution closed = solve(p);
  ASSERT_GE(expected.n, 1);
  ASSERT_TRUE(expected.n != closed.n ||
              std::abs(expected.z_max_mm - closed.z_max_mm) > 0.05 * closed.z_max_mm)
      << "a case where the two agree shows nothing: field n " << expected.n << " z_max "
      << expected.z_max_mm << ", closed form n " << closed.n << " z_max " << closed.z_max_mm;

  ClothViewPanel& view = panel<ClothViewPanel>();
  EXPECT_EQ(view.fold_source(), FoldSource::closed_form);
  EXPECT_FALSE(view.drawn_field_folds());
  EXPECT_EQ(report().at("fold_source").at("n"), closed.n);

  ASSERT_EQ(explorer_->set_view("fold_source", "field"), std::nullopt);
  const std::string first = frame();
  // Asked for before the view draws, the field is solved in the same frame (a cold solve climbs
  // its ladder in one slice): the first frame already draws its folds, and says so.
  EXPECT_NE(first.find("Folds from the tension field: n = "), std::string::npos) << first;
  EXPECT_EQ(report().at("fold_source").at("drawn"), "field");
  settle();

  ASSERT_TRUE(view.drawn_field_folds());
  const FoldOverride& drawn = *view.drawn_field_folds();
  EXPECT_EQ(drawn.n, expected.n);
  EXPECT_NEAR(drawn.z_max_mm, expected.z_max_mm, 1e-6 * expected.z_max_mm);
  ASSERT_EQ(drawn.a_mm.size(), expected.a_mm.size());
  for (std::size_t i = 0; i < drawn.a_mm.size(); ++i) {
    EXPECT_NEAR(drawn.a_mm[i], expected.a_mm[i], 1e-6 * expected.a_mm.front()) << "a_" << i;
  }
  const json source = report().at("fold_source");
  EXPECT_EQ(source.at("source"), "field");
  EXPECT_EQ(source.at("drawn"), "field");
  EXPECT_EQ(source.at("n"), expected.n);
  EXPECT_NEAR(source.at("z_max_mm").get<double>(), expected.z_max_mm, 1e-6 * expected.z_max_mm);
  EXPECT_EQ(report().at("view").at("fold_source"), "field");
  // The document's scene, which Results and the fold plot read, keeps the closed form's.
  EXPECT_EQ(explorer_->scene().solution().n, closed.n);
  EXPECT_EQ(explorer_->scene().solution().z_max_mm, closed.z_max_mm);
  // The renderer was given the field's cloth: the grid the view uploaded last is a new one.
  EXPECT_NE(frame().find("Folds from the tension field: n = " + std::to_string(expected.n)),
            std::string::npos);

  ASSERT_EQ(explorer_->set_view("fold_source", "closed_form"), std::nullopt);
  settle();
  EXPECT_FALSE(view.drawn_field_folds());
  EXPECT_EQ(report().at("fold_source").at("n"), closed.n);
  EXPECT_EQ(report().at("fold_source").at("z_max_mm").get<double>(), closed.z_max_mm);
  EXPECT_TRUE(report().at("fold_source").at("words").is_null());
}

// With the closed form's folds and the field view closed, nothing asks for the field: no request,
// no Newton step, however the inputs move; Results offers to solve it.
TEST_F(FoldSourceTest, NoFieldSolveIsRequestedWhileNoViewAsksForIt) {
  for (const double d : {120.0, 140.0, 160.0}) {
    ASSERT_EQ(explorer_->set_input("d", d), std::nullopt);
    frame();
  }
  settle();
  const json view = report().at("field");
  EXPECT_TRUE(view.at("solving_for").empty()) << view.dump();
  EXPECT_FALSE(view.at("working").get<bool>());
  EXPECT_FALSE(view.at("current").get<bool>()) << "a field was requested";
  EXPECT_FALSE(view.contains("converged")) << "a field was solved";
  EXPECT_EQ(view.at("slice_ms").get<double>(), 0.0);
  EXPECT_TRUE(panel<FieldPanel>().consumers().empty());
  const json results = report().at("results").at("field_column");
  EXPECT_FALSE(results.at("shown").get<bool>());
  EXPECT_EQ(results.at("state"), "not_solved");

  // Results' offer opens the field view, which solves it; then the two columns are shown.
  frame();
  click("with the tension field");  // the button "compare with the tension field"

  settle();
  EXPECT_EQ(report().at("field").at("solving_for"), json::array({"view"}));
  const json column = report().at("results").at("field_column");
  EXPECT_TRUE(column.at("shown").get<bool>());
  EXPECT_EQ(column.at("state"), "converged");
  const field::FieldFolds expected = folds_as_the_command_finds_them(shown());
  const json& rows = column.at("rows");
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows[0], json({"n", std::to_string(explorer_->scene().solution().n),
                           std::to_string(expected.n)}));
  EXPECT_EQ(rows[2][0], "z_max");
  EXPECT_EQ(rows[2][2], detail::printf_string("%.1f mm", expected.z_max_mm));
  EXPECT_EQ(rows.size(),
            3u + static_cast<std::size_t>(std::max(expected.n, explorer_->scene().solution().n)));
}

// The fold source alone asks for the field (its view closed): Results shows both columns; before
// the first solve the field's column says why it has no numbers.
TEST_F(FoldSourceTest, ResultsShowsTheFieldBesideTheClosedFormForTheFoldSource) {
  ASSERT_EQ(explorer_->set_view("fold_source", "field"), std::nullopt);
  frame();
  frame();
  settle();
  EXPECT_FALSE(report().at("field").at("open").get<bool>());
  EXPECT_EQ(report().at("field").at("solving_for"), json::array({"fold_source"}));
  const json column = report().at("results").at("field_column");
  EXPECT_TRUE(column.at("shown").get<bool>());
  EXPECT_EQ(column.at("state"), "converged");
  EXPECT_EQ(column.at("rows")[0][0], "n");
  const json cloth_cut = column.at("rows");
  // Another cut in the field view is not the cloth's: the 3D view keeps its folds from a solve of
  // the cloth's own cut, the same as before, and Results' column with it.
  ASSERT_EQ(explorer_->set_view("field_cut", "wedge"), std::nullopt);
  frame();
  settle();
  const json other = report();
  EXPECT_EQ(other.at("fold_source").at("drawn"), "field");
  EXPECT_EQ(other.at("field").at("cut"), "wedge");
  EXPECT_EQ(other.at("field").at("fold_source_solve").at("cut"), "shape");
  EXPECT_TRUE(other.at("field").at("fold_source_solve").at("converged").get<bool>());
  EXPECT_EQ(other.at("results").at("field_column").at("state"), "converged");
  EXPECT_EQ(other.at("results").at("field_column").at("rows"), cloth_cut);
  // The view closed, its own cut is not solved: one solve, the cloth's, and the view's last
  // field is still the cloth's cut of before (the wedge's area would be w L (h + h/4) / 2).
  EXPECT_FALSE(other.at("field").at("working").get<bool>());
  EXPECT_EQ(other.at("field").at("outline_area_mm2"),
            other.at("field").at("fold_source_solve").at("outline_area_mm2"));

  // With the view open on the wedge and the closed form's folds in the 3D view, Results has no
  // cloth's field to show: it says the view shows another cut.
  ASSERT_EQ(explorer_->set_view("fold_source", "closed_form"), std::nullopt);
  ASSERT_EQ(explorer_->set_view("field", "1"), std::nullopt);
  settle();
  const json wedge = report();
  EXPECT_EQ(wedge.at("results").at("field_column").at("state"), "other_cut");
  EXPECT_EQ(wedge.at("results").at("field_column").at("rows")[0][2],
            wedge.at("results").at("field_column").at("words"));
  EXPECT_EQ(wedge.at("field").at("solving_for"), json::array({"view"}));
  EXPECT_NE(wedge.at("field").at("outline_area_mm2"), other.at("field").at("outline_area_mm2"));
}

// d changed before every frame, as `render --animate d` plays it: the field is requested and
// stepped before the 3D view draws, so that most frames draw the field of the inputs on show; a
// frame whose slice runs out draws the last converged field's folds, said to be of the previous
// inputs; none falls back to the closed form's.
TEST_F(FoldSourceTest, TheFieldsFoldsFollowAnInputChangedEveryFrame) {
  ASSERT_EQ(explorer_->set_view("fold_source", "field"), std::nullopt);
  settle();
  const json before = report().at("fold_source").at("frames");
  constexpr int kFrames = 60;
  int from_field = 0;
  int from_previous = 0;
  for (int i = 1; i <= kFrames; ++i) {
    ASSERT_EQ(explorer_->set_input("d", 100.0 + 2.0 * i), std::nullopt);
    frame();
    const json source = report().at("fold_source");
    const std::string drawn = source.at("drawn");
    if (drawn == "field") {
      ++from_field;
    } else {
      ASSERT_EQ(drawn, "previous_field") << "frame " << i << ": " << source.dump();
      ++from_previous;
      EXPECT_NE(source.at("words").get<std::string>().find("of the previous inputs"),
                std::string::npos);
    }
  }
  EXPECT_GE(from_field, kFrames / 2) << from_previous << " frames drew the previous inputs' field";
  const json frames = report().at("fold_source").at("frames");
  EXPECT_EQ(frames.at("field").get<int>() - before.at("field").get<int>(), from_field);
  EXPECT_EQ(frames.at("previous_field").get<int>() - before.at("previous_field").get<int>(),
            from_previous);
  EXPECT_EQ(frames.at("closed_form"), before.at("closed_form"));
  // While d moves the field is solved on half the mesh: the last frame's folds are those of the
  // last d on 16 cells, as the command finds them.
  if (report().at("fold_source").at("drawn") == "field") {
    const field::FieldFolds expected =
        folds_as_the_command_finds_them(shown(), FieldPanel::kDefaultCells / 2);
    const json source = report().at("fold_source");
    EXPECT_EQ(source.at("n"), expected.n);
    EXPECT_NEAR(source.at("z_max_mm").get<double>(), expected.z_max_mm, 1e-3 * expected.z_max_mm);
  }
}

// While h shrinks frame by frame the field view keeps its scale, so that the cloth is seen to
// shrink; at rest it is fitted to its canvas again, larger.
TEST_F(FoldSourceTest, TheFieldViewKeepsItsScaleWhileAnInputMoves) {
  panel<FieldPanel>().open();
  settle();
  const double at_rest = report().at("field").at("canvas_px_per_mm").get<double>();
  ASSERT_GT(at_rest, 0.0);
  EXPECT_EQ(report().at("field").at("mesh").at("cells_x"), FieldPanel::kDefaultCells);
  const double h_mm = shown().hanging.height_mm;
  // h shrinks by 40 % over 10 frames, then keeps moving by a little until the field of half the
  // cells has been shown (how many frames that takes depends on the machine).
  bool coarse_shown = false;
  double h_now_mm = h_mm;
  for (int i = 1; i <= 400 && !(coarse_shown && i > 10); ++i) {
    h_now_mm = i <= 10 ? h_mm * (1.0 - 0.04 * i) : h_now_mm * (1.0 - 1e-4);
    ASSERT_EQ(explorer_->set_input("h", h_now_mm), std::nullopt);
    frame();
    EXPECT_LE(report().at("field").at("canvas_px_per_mm").get<double>(), at_rest * (1.0 + 1e-9))
        << "frame " << i;
    coarse_shown = coarse_shown ||
                   report().at("field").at("mesh").at("cells_x") == FieldPanel::kDefaultCells / 2;
  }
  // While the hand moves the field is solved on half the cells; at rest on all of them.
  EXPECT_TRUE(coarse_shown);
  settle();
  EXPECT_EQ(report().at("field").at("mesh").at("cells_x"), FieldPanel::kDefaultCells);
  // The cloth 40 % shorter: fitted by its height, a scale larger by up to 1 / 0.6.
  EXPECT_GT(report().at("field").at("canvas_px_per_mm").get<double>(), 1.1 * at_rest);
}

// The closed form's fold lines over the field hang from the field's supports on every cut whose
// supports the closed form knows: inclined supports too, whose lines the scene has already
// sheared. Each line's ends are the supports where the field's cut is pinned (from the core's
// outline), and a line halfway across is below the line through them.
TEST(FieldOverlay, TheClosedFormsLinesHangFromTheFieldsSupports) {
  for (const ShapeKind kind :
       {ShapeKind::cosine_membrane, ShapeKind::rectangular, ShapeKind::inclined}) {
    Parameters p;
    p.shape.kind = kind;
    p.shape.incline_deg = 15.0;
    const Solution solution = solve(p);
    ASSERT_GE(solution.n, 1);
    const FoldLines lines = fold_lines(solution, p, 33);
    const std::vector<Eigen::Vector2d> targets =
        field::support_targets(field::make_outline(p, field::outline_kind_of(p.shape)));
    ASSERT_EQ(targets.size(), 2u);
    const auto overlay = cosines_on_field(lines, targets);
    ASSERT_EQ(overlay.size(), lines.lines.size());
    for (const std::vector<Eigen::Vector2d>& line : overlay) {
      SCOPED_TRACE(static_cast<int>(kind));
      EXPECT_NEAR((line.front() - targets[0]).norm(), 0.0, 1e-6);
      EXPECT_NEAR((line.back() - targets[1]).norm(), 0.0, 1e-6);
      const Eigen::Vector2d& middle = line[line.size() / 2];
      EXPECT_GT(middle.y(), 0.5 * (targets[0].y() + targets[1].y()));
    }
  }
}

// A cut that folds onto itself (the wedge with its supports moved far in) is seen: the legend
// gives the share turned over, as the solve finds it; and a force that statics makes zero (the
// middle support of a strip across) is written 0, not as round-off.
TEST_F(FoldSourceTest, TheFieldViewShowsACutTurnedOverAndZeroForcesAsZero) {
  ASSERT_EQ(explorer_->set_view("field_cut", "wedge"), std::nullopt);
  ASSERT_EQ(explorer_->set_input("d", 453.0), std::nullopt);
  panel<FieldPanel>().open();
  settle();
  std::string refusal;
  const std::optional<field::SolvedField> solved = field::solve_field(
      field_inputs(shown(), FieldPanel::kDefaultCells, FieldCut::wedge), refusal);
  ASSERT_TRUE(solved.has_value()) << refusal;
  const double share = solved->report.solution.folded_share;
  ASSERT_GT(share, 0.0);
  EXPECT_NE(frame().find(detail::printf_string("turned over %.1f %%", 100.0 * share)),
            std::string::npos)
      << last_text_;

  ASSERT_EQ(explorer_->set_view("field_cut", "shape"), std::nullopt);
  ASSERT_EQ(explorer_->set_input("d", 100.0), std::nullopt);
  ASSERT_EQ(explorer_->document().apply(Edit::choose("shape", "strip")), std::nullopt);
  settle();
  const std::string text = frame();
  EXPECT_EQ(text.find("turned over"), std::string::npos);
  EXPECT_NE(text.find("N up, 0.00 N across"), std::string::npos) << text;
  EXPECT_FALSE(std::regex_search(text, std::regex("[0-9.]+e[-+][0-9]+ N (up|across)"))) << text;
}

// A cloth too thick to fold at the rays' tension (t = 3 mm): the field counts no fold, as the
// command finds it, and the view says why rather than "n = 0" under a wrinkled cloth.
TEST_F(FoldSourceTest, TheFieldViewSaysWhyItCountsNoFold) {
  ASSERT_EQ(explorer_->set_input("t", 3.0), std::nullopt);
  ASSERT_EQ(folds_as_the_command_finds_them(shown()).n, 0);
  panel<FieldPanel>().open();
  settle();
  const std::string text = frame();
  EXPECT_NE(text.find("folds from the field: none: under the wrinkle law"), std::string::npos)
      << text;
  EXPECT_EQ(text.find("folds from the field: n = 0"), std::string::npos);
}

// The colour bar beside the 3D view and a picture's caption give the folds drawn: the field's n
// and z_max, said to be the tension field's, and the closed form's when they are drawn.
TEST_F(FoldSourceTest, TheColourBarAndCaptionGiveTheFoldsDrawn) {
  ASSERT_EQ(explorer_->set_input("L", 4000.0), std::nullopt);
  ASSERT_EQ(explorer_->set_view("colour_by", "z"), std::nullopt);
  ASSERT_EQ(explorer_->set_view("fold_source", "field"), std::nullopt);
  settle();
  const field::FieldFolds expected = folds_as_the_command_finds_them(shown());
  const Solution closed = solve(shown());
  ASSERT_NE(expected.n, closed.n);
  json bar = report().at("fold_source").at("colour_bar");
  EXPECT_EQ(bar.at("title"), "z\ntension field");
  EXPECT_NEAR(bar.at("z_max_mm").get<double>(), expected.z_max_mm, 1e-6 * expected.z_max_mm);
  PictureSpec spec;
  spec.view = PictureView::cloth;
  spec.caption = true;
  const auto caption = [&] {
    const std::vector<std::string> lines = picture_caption(
        picture_source(document(), explorer_->panels(), kNoClothView, kNoClothView, {}), spec);
    // Read as plain spaces: the caption keeps each value with its name by no-break spaces.
    std::string line = lines.size() > 1 ? lines[1] : std::string();
    for (std::size_t at = line.find("\u00A0"); at != std::string::npos;
         at = line.find("\u00A0", at)) {
      line.replace(at, std::string_view("\u00A0").size(), " ");
    }
    return line;
  };
  std::string numbers = caption();
  EXPECT_NE(numbers.find("n = " + std::to_string(expected.n)), std::string::npos) << numbers;
  EXPECT_NE(numbers.find(detail::printf_string("z_max = %.2f mm", expected.z_max_mm)),
            std::string::npos)
      << numbers;
  EXPECT_NE(numbers.find("(folds from the tension field)"), std::string::npos) << numbers;
  EXPECT_EQ(numbers.find("n = " + std::to_string(closed.n)), std::string::npos) << numbers;

  // Presented, the read-out over the view gives them too. Its large text is read back glyph by
  // glyph with gaps of its own: compared without any spaces.
  ASSERT_EQ(explorer_->set_view("present", "cloth"), std::nullopt);
  settle();
  std::string text = squeezed(frame());
  EXPECT_NE(text.find(detail::printf_string("n=%dQ=%.4fz_max=%.2fmm(foldsfromthetensionfield)",
                                            expected.n, expected.Q, expected.z_max_mm)),
            std::string::npos)
      << text;

  ASSERT_EQ(explorer_->set_view("fold_source", "closed_form"), std::nullopt);
  settle();
  text = squeezed(frame());
  EXPECT_NE(text.find(detail::printf_string("n=%d", closed.n)), std::string::npos) << text;
  EXPECT_EQ(text.find("tensionfield"), std::string::npos) << text;
  bar = report().at("fold_source").at("colour_bar");
  EXPECT_EQ(bar.at("title"), "z");
  EXPECT_EQ(bar.at("z_max_mm").get<double>(), closed.z_max_mm);
  numbers = caption();
  EXPECT_NE(numbers.find("n = " + std::to_string(closed.n)), std::string::npos) << numbers;
  EXPECT_EQ(numbers.find("tension field"), std::string::npos) << numbers;
}

// The shipped curtain panel carries its own cut: loaded, the field view solves that cut (its
// area by the shoelace formula over the file's vertices, its three hooks), not the shape's.
TEST_F(FoldSourceTest, APresetsOwnCutIsTheFieldViewsCut) {
  const fs::path file = kPresetsDir / "shaped-curtain-curved-hem.json";
  const json text = json::parse(std::ifstream(file));
  document().load_preset_file(file);
  ASSERT_EQ(explorer_->set_view("field", "1"), std::nullopt);
  settle();
  const json view = report().at("field");
  EXPECT_EQ(view.at("cut"), "preset");
  EXPECT_TRUE(view.at("converged").get<bool>());
  EXPECT_NEAR(view.at("outline_area_mm2").get<double>(), shoelace_area_mm2(text.at("outline")),
              1e-9 * shoelace_area_mm2(text.at("outline")));
  const double weight = text.at("fabric").at("weight_N_per_mm2").get<double>() *
                        shoelace_area_mm2(text.at("outline"));
  // The mesh follows the hem by chords between its 32 columns: its weight is short of w times the
  // file's area by 2.7e-5 of it (docs/field.md, "The outlines"; `foldlab field --preset
  // shaped-curtain-curved-hem --cells-x 32` gives 2.2526467 N against 2.2527074 N).
  EXPECT_NEAR(1.0 - view.at("weight_N").get<double>() / weight, 2.69e-5, 0.05e-5);
  ASSERT_EQ(view.at("supports").size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(view.at("supports")[i].at("at_mm"), text.at("outline").at("supports")[i].at("at"));
    EXPECT_EQ(view.at("supports")[i].at("to_mm"), text.at("outline").at("supports")[i].at("to"));
  }
  // Saved under another name, the cut goes with it.
  const fs::path saved = dir_ / "my-curtain.json";
  save_preset(preset_to_save(document(), "My curtain"), saved);
  EXPECT_EQ(json::parse(std::ifstream(saved)).at("outline"), text.at("outline"));
}

// A preset whose cut hangs from a point inside the cloth is not loaded: the state before is kept
// and the refusal says which support, as for any preset that does not read.
TEST_F(FoldSourceTest, APresetWithABadCutIsRefusedAndTheStateKept) {
  json text = json::parse(std::ifstream(kPresetsDir / "shaped-curtain-curved-hem.json"));
  text["outline"]["supports"][1]["at"] = {600.0, 700.0};
  const fs::path bad = dir_ / "hook-inside.json";
  std::ofstream(bad) << text.dump(2);
  const std::string before = document().loaded().name;
  document().load_preset_file(bad);
  frame();
  EXPECT_EQ(document().loaded().name, before);
  EXPECT_FALSE(document().loaded().outline.has_value());
  EXPECT_NE(status().message().find("/outline: support 2 at (600, 700) mm is off the outline"),
            std::string::npos)
      << status().message();
  // Said where it is seen too: the status line is at the foot of the Presets panel's list.
  EXPECT_NE(status().toast().find("Not loaded"), std::string::npos) << status().toast();
  EXPECT_NE(status().toast().find("off the outline"), std::string::npos) << status().toast();
}

}  // namespace
}  // namespace foldlab::gui
