// A tension field picture's caption: the field's own figures (its cut, weight, thrust and folds)
// beside the closed form's, and why the closed form's cosines asked for are not drawn, there and
// under the field view's figures. The expected figures come from the core calls `foldlab field
// --json` makes (mesh, cold solve, report, field_folds) and the cut's area from the shoelace
// formula over its vertices, never from the panels.
#include "explorer_fixture.hpp"
#include "outline_area.hpp"

#include "app/gui/panels/field_panel.hpp"
#include "app/gui/picture.hpp"
#include "core/field/field_case.hpp"
#include "core/field/field_folds.hpp"
#include "core/field/rays.hpp"

namespace foldlab::gui {
namespace {

using nlohmann::json;

// The caption's text with its no-break spaces read as plain ones, one line to a string.
std::vector<std::string> plain(std::vector<std::string> lines) {
  for (std::string& line : lines) {
    for (std::size_t at = line.find("\u00A0"); at != std::string::npos;
         at = line.find("\u00A0", at)) {
      line.replace(at, std::string_view("\u00A0").size(), " ");
    }
  }
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) {
    out += line + "\n";
  }
  return out;
}

class FieldPictureTest : public ExplorerTest {
 protected:
  std::vector<std::string> caption() {
    PictureSpec spec;
    spec.view = PictureView::field;
    spec.caption = true;
    return plain(picture_caption(
        picture_source(document(), explorer_->panels(), kNoClothView, kNoClothView, {}), spec));
  }
};

// The triangle cut of the default cloth, 32 cells across and as many down as keep them square
// (the caption says the mesh): its weight is w times the triangle's area, and its thrust and n are
// those the command finds on that mesh.
TEST_F(FieldPictureTest, TheCaptionGivesTheFieldsWeightThrustAndFolds) {
  ASSERT_EQ(explorer_->set_view("field_cut", "triangle"), std::nullopt);
  ASSERT_EQ(explorer_->set_view("field_cells", "32"), std::nullopt);
  const Parameters p = shown();
  const field::Outline outline = field::make_outline(p, field::OutlineKind::triangle);
  json cut = {{"top", json::array()}, {"bottom", json::array()}};
  for (const Eigen::Vector2d& v : outline.top_mm) {
    cut["top"].push_back({v.x(), v.y()});
  }
  for (const Eigen::Vector2d& v : outline.bottom_mm) {
    cut["bottom"].push_back({v.x(), v.y()});
  }
  const double weight_N = p.fabric.weight_N_per_mm2 * testing::shoelace_area_mm2(cut);
  ASSERT_GT(weight_N, 0.1);

  const std::vector<std::string> lines = caption();
  const std::string text = joined(lines);
  ASSERT_NE(text.find("Tension field on the triangle cut, mesh 32 x 32 cells"), std::string::npos)
      << text;
  EXPECT_NEAR(number_after(text, "weight "), weight_N, 1e-3 * weight_N) << text;

  // As `foldlab field --shape triangle --cells-x 32 --cells-y 32 --json` finds them.
  field::MeshResolution resolution;
  resolution.cells_x = 32;
  resolution.cells_y = 32;
  field::Solver solver(field::make_mesh(outline, resolution));
  const field::Material material = field::material_of(p.fabric);
  field::Solution solution = field::solve_cold(solver, outline, material, resolution);
  ASSERT_TRUE(solution.converged);
  const field::FieldReport report =
      field::report_field(solver, std::move(solution), outline, material);
  const field::FieldFolds folds =
      field::field_folds(solver.mesh(), report.solution, field::support_targets(outline), p);
  EXPECT_NEAR(number_after(text, "thrust H "), report.thrust_N, 1e-3 * report.thrust_N) << text;
  EXPECT_NEAR(number_after(text, "through the supports: "), report.pencil_thrust_N,
              1e-3 * report.pencil_thrust_N)
      << text;
  EXPECT_NE(text.find("the field's folds: n = " + std::to_string(folds.n) + ","), std::string::npos)
      << text;
  EXPECT_NE(text.find("converged (relative force residual"), std::string::npos) << text;
  // The closed form's figures stay, said to be the closed form's.
  const Solution closed = solve(p);
  EXPECT_NE(text.find("the closed form's folds: n = " + std::to_string(closed.n)),
            std::string::npos)
      << text;
  // No cosines asked for: nothing said of them.
  EXPECT_EQ(text.find("cosines"), std::string::npos) << text;
}

// Asked for on the triangle cut, which the closed form does not solve, the cosines are not drawn
// and the caption and the field view both say why; on the shape's own cut nothing is said.
TEST_F(FieldPictureTest, CosinesNotDrawnOnTheTriangleAreSaidSo) {
  ASSERT_EQ(explorer_->set_view("field_cut", "triangle"), std::nullopt);
  ASSERT_EQ(explorer_->set_view("field_cosines", "1"), std::nullopt);
  const std::string why =
      "The closed form's cosines are not drawn: the closed form solves the rectangular, cosine, "
      "strip and inclined cloths, not the triangle cut.";
  std::string text = joined(caption());
  EXPECT_NE(text.find(why), std::string::npos) << text;

  ASSERT_EQ(explorer_->set_view("field", "1"), std::nullopt);
  std::string drawn;
  for (int i = 0; i < 600 && squeezed(drawn).find(squeezed(why)) == std::string::npos; ++i) {
    drawn = frame();
  }
  EXPECT_NE(squeezed(drawn).find(squeezed(why)), std::string::npos) << drawn;

  ASSERT_EQ(explorer_->set_view("field_cut", "shape"), std::nullopt);
  text = joined(caption());
  EXPECT_EQ(text.find("cosines are not drawn"), std::string::npos) << text;
  for (int i = 0; i < 60; ++i) {
    drawn = frame();
  }
  EXPECT_EQ(squeezed(drawn).find("cosinesarenotdrawn"), std::string::npos) << drawn;
}

// At d = 0 the closed form has no folds: asked for, its cosines are not drawn, and said so.
TEST_F(FieldPictureTest, CosinesAtNoDisplacementAreSaidNotDrawn) {
  ASSERT_EQ(explorer_->set_input("d", 0.0), std::nullopt);
  ASSERT_EQ(explorer_->set_view("field_cosines", "1"), std::nullopt);
  ASSERT_EQ(solve(shown()).n, 0);
  const std::string text = joined(caption());
  EXPECT_NE(text.find("The closed form's cosines are not drawn: at d = 0 the supports are not "
                      "moved in, and the closed form has no folds."),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace foldlab::gui
