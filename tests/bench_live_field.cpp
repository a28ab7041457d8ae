// Google Benchmark timings of the field as the explorer's view runs it (target
// foldlab_live_field_bench, not a test): a drag of d on the coarse mesh, one slice of a frame at a
// time, and the refinement when the hand rests. Counters: the frames a drag's field lags behind
// and the share of frames that showed the field of that frame's inputs.
// Run: build/tests/foldlab_live_field_bench
#include <benchmark/benchmark.h>

#include "core/field/live_field.hpp"

namespace foldlab::field {
namespace {

FieldInputs inputs(double d_mm, int cells) {
  Parameters p;
  p.hanging.support_displacement_mm = d_mm;
  FieldInputs in;
  in.outline = make_outline(p, OutlineKind::cosine);
  in.material = material_of(p.fabric);
  in.resolution.cells_x = cells;
  in.resolution.cells_y = cells;
  return in;
}

// Solves until the field is shown or given up.
void settle(LiveField& live) {
  while (live.working()) {
    live.step(0.0);
  }
}

// A drag of d by 1 % of the default's 100 mm a frame, each frame given `budget_ms` (0: solved to
// convergence), on a mesh of state.range(0) cells across: the share of frames that showed that
// frame's field and the Newton steps a frame.
void drag(benchmark::State& state, double budget_ms) {
  const int cells = static_cast<int>(state.range(0));
  LiveField live;
  live.request(inputs(100.0, cells));
  settle(live);
  double d_mm = 100.0;
  std::int64_t frames = 0;
  std::int64_t current = 0;
  std::int64_t steps = 0;
  for (auto _ : state) {
    d_mm = d_mm >= 300.0 ? 100.0 : d_mm + 1.0;
    live.request(inputs(d_mm, cells));
    if (budget_ms > 0.0) {
      live.step(budget_ms);
    } else {
      settle(live);
    }
    ++frames;
    current += live.current() ? 1 : 0;
    steps += live.iterations();
  }
  state.counters["current_share"] = static_cast<double>(current) / static_cast<double>(frames);
  state.counters["newton_steps"] = static_cast<double>(steps) / static_cast<double>(frames);
}

// One frame of a drag with the explorer's 6 ms slice.
void BM_DragFrame(benchmark::State& state) {
  drag(state, 6.0);
}
BENCHMARK(BM_DragFrame)->Arg(16)->Arg(24)->Arg(32)->Unit(benchmark::kMillisecond);

// The same drag with each frame's field solved to convergence (a warm re-solve after a 1 % change
// of d).
void BM_DragFrameWhole(benchmark::State& state) {
  drag(state, 0.0);
}
BENCHMARK(BM_DragFrameWhole)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

// The view opening on the default cloth: a cold solve on the mesh at rest, whole.
void BM_Open(benchmark::State& state) {
  const int cells = static_cast<int>(state.range(0));
  for (auto _ : state) {
    LiveField live;
    live.request(inputs(100.0, cells));
    settle(live);
    benchmark::DoNotOptimize(live.shown());
  }
}
BENCHMARK(BM_Open)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

// The hand rests after a drag: from the coarse field (half the cells) to the field at rest.
void BM_Refine(benchmark::State& state) {
  const int cells = static_cast<int>(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    LiveField live;
    live.request(inputs(100.0, cells / 2));
    settle(live);
    state.ResumeTiming();
    live.request(inputs(100.0, cells));
    settle(live);
    benchmark::DoNotOptimize(live.shown());
  }
}
BENCHMARK(BM_Refine)->Arg(32)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace foldlab::field

BENCHMARK_MAIN();
