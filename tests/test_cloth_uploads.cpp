// The 3D view's upload rule (app/gui/cloth_uploads.hpp), which the GL cloth renderer and the
// NullRenderer both run: hand-written sequences of what the buffers should show, and the uploads
// each step must make.
#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>
#include <vector>

#include "app/gui/cloth_uploads.hpp"
#include "app/gui/renderer.hpp"
#include "core/io/preset.hpp"

namespace foldlab::gui {
namespace {

const std::filesystem::path kPresetsDir = FOLDLAB_PRESETS_DIR;

DrawnLattice lattice(int columns, int rows, int first_row = 0) {
  DrawnLattice l;
  l.columns.resize(static_cast<std::size_t>(columns));
  std::iota(l.columns.begin(), l.columns.end(), 0);
  l.rows.resize(static_cast<std::size_t>(rows));
  std::iota(l.rows.begin(), l.rows.end(), first_row);
  return l;
}

// The scene's stages as Scene numbers them: solution -> fold lines / grid -> normals.
ClothBufferSources sources(std::uint64_t normals, std::uint64_t fold_lines, std::uint64_t grid) {
  ClothBufferSources s;
  s.normals_version = normals;
  s.fold_lines_version = fold_lines;
  s.grid_version = grid;
  s.fold_lines_shown = true;
  s.z_scale = 1.0f;
  s.positive_fold_colour = {0.1f, 0.2f, 0.6f};
  s.negative_fold_colour = {0.8f, 0.1f, 0.1f};
  s.lattice = lattice(40, 60);
  return s;
}

struct Expect {
  bool mesh, mesh_indices, fold_lines, decorations;
};

void expect(const ClothUploads& got, Expect want, const char* step) {
  EXPECT_EQ(got.mesh, want.mesh) << step;
  EXPECT_EQ(got.mesh_indices, want.mesh_indices) << step;
  EXPECT_EQ(got.fold_lines, want.fold_lines) << step;
  EXPECT_EQ(got.decorations, want.decorations) << step;
}

TEST(ClothUploadRule, FirstFrameUploadsEverythingThenNothingUntilAVersionMoves) {
  ClothUploadRule rule;
  expect(rule.next(sources(1, 1, 1)), {true, true, true, true}, "first frame");
  expect(rule.next(sources(1, 1, 1)), {false, false, false, false}, "same versions");
  expect(rule.next(sources(1, 1, 1)), {false, false, false, false}, "and again");
}

TEST(ClothUploadRule, EachStageVersionReUploadsOnlyItsBuffers) {
  ClothUploadRule rule;
  rule.next(sources(1, 1, 1));
  // A new grid resolution: grid and normals are made again, the solution and fold lines are not.
  expect(rule.next(sources(2, 1, 2)), {true, false, false, true}, "grid resolution");
  // A new h: every stage reruns.
  expect(rule.next(sources(3, 2, 3)), {true, false, true, true}, "new h");
  // Normals alone (not a sequence the scene makes, but the rule reads each version on its own).
  expect(rule.next(sources(4, 2, 3)), {true, false, false, false}, "normals only");
  expect(rule.next(sources(4, 3, 3)), {false, false, true, false}, "fold lines only");
  expect(rule.next(sources(4, 3, 4)), {false, false, false, true}, "grid only");
  expect(rule.next(sources(4, 3, 4)), {false, false, false, false}, "unchanged");
}

TEST(ClothUploadRule, HiddenFoldLinesAreNotUploadedAndComeBackOnlyIfTheyChanged) {
  ClothUploadRule rule;
  ClothBufferSources s = sources(1, 1, 1);
  rule.next(s);
  s.fold_lines_shown = false;
  s.fold_lines_version = 2;  // the scene may move on while they are hidden
  expect(rule.next(s), {false, false, false, false}, "hidden, version moved");
  s.fold_lines_version = 1;
  s.fold_lines_shown = true;
  expect(rule.next(s), {false, false, false, false}, "shown again as uploaded");
  s.fold_lines_shown = false;
  s.fold_lines_version = 3;
  expect(rule.next(s), {false, false, false, false}, "hidden again");
  s.fold_lines_shown = true;
  expect(rule.next(s), {false, false, true, false}, "shown again, changed meanwhile");
}

TEST(ClothUploadRule, TheStyleBakedIntoVerticesCountsAsWellAsTheVersions) {
  ClothUploadRule rule;
  ClothBufferSources s = sources(5, 5, 5);
  rule.next(s);
  s.z_scale = 4.0f;  // positions of the cloth and of the lines on it
  expect(rule.next(s), {true, false, true, false}, "z exaggeration");
  s.positive_fold_colour.x() = 0.5f;  // per-vertex colours of the lines only
  expect(rule.next(s), {false, false, true, false}, "positive colour");
  s.negative_fold_colour.y() = 0.5f;
  expect(rule.next(s), {false, false, true, false}, "negative colour");
  s.fold_lines_shown = false;
  s.z_scale = 2.0f;
  expect(rule.next(s), {true, false, false, false}, "z with the lines hidden");
  s.fold_lines_shown = true;
  expect(rule.next(s), {false, false, true, false}, "the lines catch up when shown");
}

TEST(ClothUploadRule, ADifferentLatticeReUploadsTheMeshAndItsTrianglesOnlyWhenItsSizeChanged) {
  ClothUploadRule rule;
  ClothBufferSources s = sources(1, 1, 1);
  rule.next(s);
  s.lattice = lattice(40, 60, 1);  // the camera moved: other rows, as many of them
  expect(rule.next(s), {true, false, false, false}, "other rows, same count");
  s.lattice = lattice(40, 80, 1);  // zoomed in: more rows
  expect(rule.next(s), {true, true, false, false}, "more rows");
  s.lattice = lattice(50, 80, 1);
  expect(rule.next(s), {true, true, false, false}, "more columns");
  expect(rule.next(s), {false, false, false, false}, "unchanged");
}

// The NullRenderer counts what the rule asks for, on a real scene: a new z exaggeration
// re-uploads the mesh and the fold lines (a rule of its own once counted neither).
TEST(ClothUploadRule, TheNullRendererCountsTheRulesUploads) {
  Scene scene(load_preset(kPresetsDir / "paper-table1-h1400.json").parameters);
  NullRenderer renderer;
  const ClothView view = renderer.create_cloth_view();
  OrbitCamera camera;
  const FrameSize size{400, 300};
  ClothStyle style;
  const auto draw = [&] {
    renderer.draw_cloth(view, nullptr, ImVec2(0, 0), cloth_buffers(scene, style), camera, size,
                        style);
  };
  draw();
  EXPECT_EQ(renderer.cloth_counters(view).mesh_uploads, 1u);
  EXPECT_EQ(renderer.cloth_counters(view).fold_line_uploads, 1u);
  EXPECT_GT(renderer.cloth_counters(view).drawn_rows, 0u);
  EXPECT_GT(renderer.cloth_counters(view).drawn_columns, 0u);
  draw();
  EXPECT_EQ(renderer.cloth_counters(view).mesh_uploads, 1u);
  style.z_exaggeration = 4.0f;
  draw();
  EXPECT_EQ(renderer.cloth_counters(view).mesh_uploads, 2u);
  EXPECT_EQ(renderer.cloth_counters(view).fold_line_uploads, 2u);
  style.positive_fold_colour.x() = 0.5f;
  draw();
  EXPECT_EQ(renderer.cloth_counters(view).mesh_uploads, 2u);
  EXPECT_EQ(renderer.cloth_counters(view).fold_line_uploads, 3u);
  style.wireframe = true;  // every vertex
  draw();
  EXPECT_EQ(renderer.cloth_counters(view).mesh_uploads, 3u);
  EXPECT_EQ(renderer.cloth_counters(view).drawn_rows, static_cast<std::uint64_t>(scene.grid().ny));
  EXPECT_EQ(renderer.cloth_counters(view).drawn_columns,
            static_cast<std::uint64_t>(scene.grid().nx));
  Parameters p = scene.parameters();
  p.hanging.height_mm = 1500.0;
  scene.set_parameters(p);
  draw();
  EXPECT_EQ(renderer.cloth_counters(view).mesh_uploads, 4u);
  EXPECT_EQ(renderer.cloth_counters(view).fold_line_uploads, 4u);
}

}  // namespace
}  // namespace foldlab::gui
