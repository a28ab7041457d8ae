// Google Benchmark timings of the tension-field solver (target foldlab_field_bench, not a test):
// cold solves (mesh, coarse-to-fine ladder, Newton) and warm re-solves after a 1 % change of d
// on the same mesh, per mesh size, with the thrust H and the potential beside those of the
// finest mesh as counters. Run: build/tests/foldlab_field_bench
#include <cmath>
#include <map>
#include <utility>

#include <benchmark/benchmark.h>

#include "core/field/field_case.hpp"

namespace foldlab::field {
namespace {

constexpr int kFinestCells = 80;

OutlineKind kind_of(std::int64_t arg) {
  return arg == 0 ? OutlineKind::rectangular : OutlineKind::cosine;
}

MeshResolution resolution(std::int64_t cells_x) {
  const int cx = static_cast<int>(cells_x);
  return {cx, cx * 7 / 10, MeshSplit::union_jack};
}

// The finest mesh's thrust and potential, solved once per outline.
std::pair<double, double> finest(OutlineKind kind) {
  static std::map<OutlineKind, std::pair<double, double>> cache;
  const auto found = cache.find(kind);
  if (found != cache.end()) {
    return found->second;
  }
  const Parameters p;
  const FieldReport r =
      solve_outline(make_outline(p, kind), material_of(p.fabric), resolution(kFinestCells), {}, 0);
  return cache[kind] = {r.thrust_N, r.solution.potential_Nmm};
}

void report_errors(benchmark::State& state, OutlineKind kind, const FieldReport& r) {
  const auto [thrust, potential] = finest(kind);
  state.counters["iterations"] = r.solution.iterations;
  state.counters["converged"] = r.solution.converged ? 1 : 0;
  state.counters["H_N"] = r.thrust_N;
  state.counters["H_error_vs_finest"] = std::abs(r.thrust_N / thrust - 1.0);
  state.counters["potential_error_vs_finest"] =
      std::abs(r.solution.potential_Nmm / potential - 1.0);
}

// Args: cells across, outline (0 rectangle, Conci's set-up; 1 cosine, the default preset's).
void BM_FieldCold(benchmark::State& state) {
  const Parameters p;
  const OutlineKind kind = kind_of(state.range(1));
  const Outline outline = make_outline(p, kind);
  const Material material = material_of(p.fabric);
  FieldReport last;
  for (auto _ : state) {
    last = solve_outline(outline, material, resolution(state.range(0)), {}, 0);
    benchmark::DoNotOptimize(last.thrust_N);
  }
  report_errors(state, kind, last);
}
BENCHMARK(BM_FieldCold)
    ->ArgNames({"cells", "cosine"})
    ->ArgsProduct({{10, 20, 30, 40, 60}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// A drag: d moves by 1 % back and forth, each solve starting from the last on the same mesh.
void BM_FieldWarm(benchmark::State& state) {
  Parameters p;
  const OutlineKind kind = kind_of(state.range(1));
  const MeshResolution res = resolution(state.range(0));
  const Material material = material_of(p.fabric);
  Outline outline = make_outline(p, kind);
  Solver solver(make_mesh(outline, res));
  Solution previous = solve_cold(solver, outline, material, res);
  const double d = p.hanging.support_displacement_mm;
  bool moved = false;
  int iterations = 0;
  int solves = 0;
  for (auto _ : state) {
    moved = !moved;
    p.hanging.support_displacement_mm = moved ? 1.01 * d : d;
    const Outline next = make_outline(p, kind);
    previous = solver.solve(material, support_targets(next), {}, &previous);
    iterations += previous.iterations;
    ++solves;
  }
  state.counters["iterations_per_solve"] = static_cast<double>(iterations) / solves;
  state.counters["converged"] = previous.converged ? 1 : 0;
}
BENCHMARK(BM_FieldWarm)
    ->ArgNames({"cells", "cosine"})
    ->ArgsProduct({{20, 30, 40}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace foldlab::field

BENCHMARK_MAIN();
