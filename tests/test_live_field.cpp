// The field that follows its inputs a slice at a time: it ends where a whole solve ends, keeps
// the last converged field on show (marked as older) while it works, and keeps it when a cut is
// refused. Statics and the cut's area come from hand formulas, not from the solver.
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "core/field/live_field.hpp"

namespace foldlab::field {
namespace {

// The Table 1 cloth on the rectangle hung from its top corners: 1400 x 1400 mm (or h_mm tall, a
// new cut and so a new mesh at each h), w = 1.5e-6 N/mm².
FieldInputs rectangle(double d_mm, int cells_x = 16, double h_mm = 1400.0) {
  Parameters p;
  p.hanging.support_displacement_mm = d_mm;
  p.hanging.height_mm = h_mm;
  FieldInputs in;
  in.outline = make_outline(p, OutlineKind::rectangular);
  in.material = material_of(p.fabric);
  in.resolution.cells_x = cells_x;
  in.resolution.cells_y = cells_x;
  return in;
}

// Runs slices of `budget_ms` until the field is shown or given up; the slices taken.
int run(LiveField& live, double budget_ms) {
  int slices = 0;
  while (live.working() && slices < 100000) {
    live.step(budget_ms);
    ++slices;
  }
  return slices;
}

TEST(LiveField, SlicedSolveHoldsTheWeightOnItsSupportsByStatics) {
  LiveField live;
  live.request(rectangle(100.0));
  run(live, 0.0);
  ASSERT_TRUE(live.current());
  const SolvedField& first = *live.shown();
  const Solution& s = first.report.solution;
  ASSERT_TRUE(s.converged);
  // w h L of the flat rectangle, by hand: 1.5e-6 x 1400 x 1400 = 2.94 N.
  EXPECT_NEAR(s.weight_N, 2.94, 1e-9);
  // Symmetric supports: each carries half of it, and the thrusts balance.
  ASSERT_EQ(s.reactions_N.size(), 2u);
  EXPECT_NEAR(s.reactions_N[0].y() + s.reactions_N[1].y(), -2.94, 1e-6 * 2.94);
  EXPECT_NEAR(s.reactions_N[0].y(), -1.47, 1e-6 * 2.94);
  EXPECT_NEAR(s.reactions_N[0].x() + s.reactions_N[1].x(), 0.0, 1e-6 * 2.94);

  // d moves 1 %: the re-solve in slices of 0.2 ms (many slices, each a step or two) ends on the
  // field a whole solve from the same start reaches, and shows the old field until then.
  live.request(rectangle(101.0));
  EXPECT_FALSE(live.current());
  ASSERT_NE(live.shown(), nullptr);
  EXPECT_EQ(live.shown()->inputs, rectangle(100.0));
  const int slices = run(live, 0.2);
  ASSERT_TRUE(live.current());
  EXPECT_GE(slices, 1);
  const Solution& moved = live.shown()->report.solution;
  EXPECT_TRUE(moved.converged);
  EXPECT_LE(moved.relative_residual, 1e-8);
  EXPECT_NEAR(moved.reactions_N[0].y() + moved.reactions_N[1].y(), -2.94, 1e-6 * 2.94);
  // The pinned supports are 2 mm closer: the span l = L - d, by the model's span rule.
  EXPECT_NEAR(live.shown()->inputs.outline.supports[1].to_mm.x() -
                  live.shown()->inputs.outline.supports[0].to_mm.x(),
              1400.0 - 101.0, 1e-9);
  std::string refusal;
  const std::optional<SolvedField> whole = solve_field(rectangle(101.0), refusal);
  ASSERT_TRUE(whole.has_value()) << refusal;
  EXPECT_NEAR(moved.reactions_N[0].x(), whole->report.solution.reactions_N[0].x(),
              1e-6 * std::abs(whole->report.solution.reactions_N[0].x()));
}

TEST(LiveField, ANewMeshStartsFromTheFieldOnShowAndRefinesIt) {
  LiveField live;
  live.request(rectangle(100.0, 8));
  run(live, 0.0);
  ASSERT_TRUE(live.current());
  const int coarse_iterations = live.iterations();
  // The hand rests: the finer mesh starts from the coarse field carried over.
  live.request(rectangle(100.0, 16));
  run(live, 0.0);
  ASSERT_TRUE(live.current());
  EXPECT_EQ(live.shown()->inputs.resolution.cells_x, 16);
  EXPECT_LT(live.iterations(), coarse_iterations);
  EXPECT_NEAR(live.shown()->report.solution.weight_N, 2.94, 1e-9);
}

// h played: a new cut every slice, each slice too short to finish a solve. Each solve under way
// is finished before the newer inputs are taken, so fields of inputs a solve behind keep being
// shown; restarted at every slice, none would end and the first field would stay on show.
TEST(LiveField, InputsChangedEverySliceAreShownASolveBehind) {
  LiveField live;
  live.request(rectangle(100.0, 12, 1400.0));
  run(live, 0.0);
  ASSERT_TRUE(live.current());
  const std::uint64_t first = live.shown_count();
  for (int i = 1; i <= 200; ++i) {
    live.request(rectangle(100.0, 12, 1400.0 + 10.0 * i));
    live.step(1e-3);  // one Newton step a slice
  }
  EXPECT_GE(live.shown_count() - first, 3u) << "fields shown while h moved";
  const double shown_h = live.shown()->inputs.outline.bottom_mm.front().y() -
                         live.shown()->inputs.outline.top_mm.front().y();
  EXPECT_GT(shown_h, 1400.0 + 10.0 * 100) << "the field on show is of h far behind";
  // At rest the newest inputs are solved and shown.
  run(live, 0.0);
  EXPECT_TRUE(live.current());
  EXPECT_EQ(live.shown()->inputs, rectangle(100.0, 12, 1400.0 + 10.0 * 200));
}

// A cold start given short slices goes on from where each ended and lands where a whole solve
// does: a very stiff cloth, whose ladder takes many steps, in slices of a step or so.
TEST(LiveField, AColdStartInShortSlicesEndsWhereAWholeSolveDoes) {
  FieldInputs stiff = rectangle(100.0, 12);
  stiff.material.stiffness_N_per_mm *= 1000.0;
  std::string refusal;
  const std::optional<SolvedField> whole = solve_field(stiff, refusal);
  ASSERT_TRUE(whole.has_value()) << refusal;
  LiveField live;
  live.request(stiff);
  live.step(1e-3, 1e-3);  // the first field's longer first slice as short as the rest
  EXPECT_TRUE(live.working()) << "the whole ladder ran in the first slice";
  const int slices = 1 + run(live, 1e-3);
  ASSERT_TRUE(live.current()) << live.refusal();
  EXPECT_GT(slices, 3);
  const Solution& s = live.shown()->report.solution;
  EXPECT_TRUE(s.converged);
  EXPECT_NEAR(s.reactions_N[0].x(), whole->report.solution.reactions_N[0].x(),
              1e-6 * std::abs(whole->report.solution.reactions_N[0].x()));
  EXPECT_NEAR(s.reactions_N[0].y(), -0.5 * s.weight_N, 1e-6 * s.weight_N);
}

TEST(LiveField, ARefusedCutKeepsTheLastFieldAndSaysWhy) {
  LiveField live;
  live.request(rectangle(100.0, 8));
  run(live, 0.0);
  ASSERT_TRUE(live.current());
  FieldInputs bad = rectangle(100.0, 8);
  bad.outline.supports[1].at_mm = {0.0, 700.0};  // inside the cloth, on neither edge
  live.request(bad);
  EXPECT_FALSE(live.working());
  EXPECT_FALSE(live.current());
  EXPECT_FALSE(live.refusal().empty());
  ASSERT_NE(live.shown(), nullptr);
  EXPECT_EQ(live.shown()->inputs, rectangle(100.0, 8));
  // Back to a valid cut: solved again, the refusal gone.
  live.request(rectangle(120.0, 8));
  run(live, 0.0);
  EXPECT_TRUE(live.current());
  EXPECT_TRUE(live.refusal().empty());
}

}  // namespace
}  // namespace foldlab::field
