// The scene recomputes a stage only when one of its inputs changed and somebody asks for it.
#include <gtest/gtest.h>

#include "core/geometry/scene.hpp"

namespace foldlab {
namespace {

std::uint64_t evaluations(const Scene& scene, Stage stage) {
  return scene.stats(stage).evaluations;
}

TEST(Scene, SolvingBuildsNoGeometry) {
  Scene scene;
  const Solution& s = scene.solution();
  EXPECT_GT(s.n, 0);
  EXPECT_EQ(evaluations(scene, Stage::solution), 1u);
  EXPECT_EQ(evaluations(scene, Stage::fold_lines), 0u);
  EXPECT_EQ(evaluations(scene, Stage::grid), 0u);
  EXPECT_EQ(evaluations(scene, Stage::normals), 0u);
  scene.solution();  // asked again, nothing changed
  EXPECT_EQ(evaluations(scene, Stage::solution), 1u);
}

TEST(Scene, GridResolutionDoesNotResolve) {
  Scene scene;
  scene.normals();
  scene.set_grid_resolution(64, 32);
  const DeformedGrid& grid = scene.grid();
  EXPECT_EQ(grid.nx, 64);
  EXPECT_EQ(grid.positions_mm.size(), 64u * 32u);
  EXPECT_EQ(evaluations(scene, Stage::solution), 1u);
  EXPECT_EQ(evaluations(scene, Stage::grid), 2u);
  EXPECT_EQ(evaluations(scene, Stage::normals), 1u);  // not asked for since
  EXPECT_EQ(scene.normals().size(), 64u * 32u);
  EXPECT_EQ(evaluations(scene, Stage::normals), 2u);
  scene.set_grid_resolution(64, 32);  // the same again: nothing to do
  scene.normals();
  EXPECT_EQ(evaluations(scene, Stage::grid), 2u);
  EXPECT_EQ(evaluations(scene, Stage::normals), 2u);
}

TEST(Scene, AHiddenViewCostsNothing) {
  // The 3D view hidden: only the plot asks, for the fold lines, while a parameter moves.
  Scene scene;
  Parameters p = scene.parameters();
  for (int step = 0; step < 10; ++step) {
    p.hanging.height_mm = 900.0 + 50.0 * step;
    scene.set_parameters(p);
    scene.fold_lines();
  }
  EXPECT_EQ(evaluations(scene, Stage::solution), 10u);
  EXPECT_EQ(evaluations(scene, Stage::fold_lines), 10u);
  EXPECT_EQ(evaluations(scene, Stage::grid), 0u);
  EXPECT_EQ(evaluations(scene, Stage::normals), 0u);
  // The view shown again: one grid for the current parameters, not ten.
  scene.normals();
  EXPECT_EQ(evaluations(scene, Stage::grid), 1u);
  EXPECT_EQ(scene.grid().positions_mm.size(), 128u * 128u);
}

TEST(Scene, UnchangedParametersRecomputeNothing) {
  Scene scene;
  scene.normals();
  scene.fold_lines();
  const std::uint64_t grid_version = scene.version(Stage::grid);
  scene.set_parameters(scene.parameters());  // e.g. a colour changed in the GUI: no model input
  scene.normals();
  scene.fold_lines();
  EXPECT_EQ(evaluations(scene, Stage::solution), 1u);
  EXPECT_EQ(evaluations(scene, Stage::fold_lines), 1u);
  EXPECT_EQ(scene.version(Stage::grid), grid_version);
}

TEST(Scene, ParameterChangeInvalidatesEverythingDownstream) {
  Scene scene;
  const int n_before = scene.solution().n;
  scene.fold_lines();
  scene.normals();
  Parameters p = scene.parameters();
  p.hanging.height_mm = 2350.0;  // Table 1's tallest row: more folds
  scene.set_parameters(p);
  EXPECT_GT(scene.solution().n, n_before);
  EXPECT_EQ(scene.fold_lines().lines.size(), static_cast<std::size_t>(scene.solution().n) + 1);
  scene.normals();
  for (Stage stage : {Stage::solution, Stage::fold_lines, Stage::grid, Stage::normals}) {
    EXPECT_EQ(evaluations(scene, stage), 2u) << to_string(stage);
  }
}

TEST(Scene, FoldLineSamplesTouchOnlyFoldLines) {
  Scene scene;
  scene.fold_lines();
  scene.normals();
  scene.set_fold_line_samples(17);
  EXPECT_EQ(scene.fold_lines().lines.front().points_mm.size(), 17u);
  scene.normals();
  EXPECT_EQ(evaluations(scene, Stage::solution), 1u);
  EXPECT_EQ(evaluations(scene, Stage::fold_lines), 2u);
  EXPECT_EQ(evaluations(scene, Stage::grid), 1u);
}

TEST(Scene, ResetStatsKeepsVersions) {
  Scene scene;
  scene.normals();
  const std::uint64_t version = scene.version(Stage::normals);
  scene.reset_stats();
  EXPECT_EQ(evaluations(scene, Stage::normals), 0u);
  EXPECT_EQ(scene.version(Stage::normals), version);
}

}  // namespace
}  // namespace foldlab

namespace foldlab {
namespace {

TEST(Scene, ShapeChangesRedrawWithoutResolving) {
  Scene scene;
  scene.normals();
  scene.fold_lines();
  Parameters p = scene.parameters();
  p.shape.kind = ShapeKind::strip;
  p.shape.supports = 3;
  scene.set_parameters(p);
  EXPECT_EQ(scene.fold_lines().lines.size(), 2u * (scene.solution().n + 1));
  scene.normals();
  EXPECT_EQ(scene.stats(Stage::solution).evaluations, 1u);
  EXPECT_EQ(scene.stats(Stage::fold_lines).evaluations, 2u);
  EXPECT_EQ(scene.stats(Stage::grid).evaluations, 2u);
}

}  // namespace
}  // namespace foldlab
