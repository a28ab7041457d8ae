// Google Benchmark timings of the solver and the pipeline (target foldlab_bench, not a test):
// a second, independent harness beside `foldlab bench`. Run: build/tests/foldlab_bench
#include <cstdint>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/analysis/calibration.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/geometry/geometry.hpp"
#include "core/geometry/parallel_grid.hpp"
#include "core/geometry/scene.hpp"
#include "core/model/equations.hpp"
#include "core/tools/benchmark_cases.hpp"

namespace foldlab {
namespace {

const std::vector<BenchmarkCase>& cases() {
  static const std::vector<BenchmarkCase> set = realistic_cases(1000);
  return set;
}

// One solve per iteration, walking through the case set so that no single case dominates.
void solve_cases(benchmark::State& state, const BenchmarkMethod& method) {
  std::vector<Parameters> inputs;
  for (const BenchmarkCase& c : cases()) {
    inputs.push_back(with_method(c.parameters, method));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solve(inputs[i]));
    i = i + 1 == inputs.size() ? 0 : i + 1;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_SolveExact(benchmark::State& state) {
  solve_cases(state, {"exact", Method::exact, LengthQuadrature::simpson, 20, 0.05});
}
BENCHMARK(BM_SolveExact);

// Args: intervals, tolerance in 1e-4, 0 = Simpson / 1 = trapezoid.
void BM_SolvePaper(benchmark::State& state) {
  const BenchmarkMethod method{
      "paper", Method::paper,
      state.range(2) == 0 ? LengthQuadrature::simpson : LengthQuadrature::trapezoid,
      static_cast<int>(state.range(0)), static_cast<double>(state.range(1)) * 1e-4};
  solve_cases(state, method);
}
BENCHMARK(BM_SolvePaper)
    ->ArgNames({"N", "tol_1e-4", "trapezoid"})
    ->Args({20, 500, 0})  // the paper's own: Simpson, 20 intervals, 5 %
    ->Args({4, 500, 1})
    ->Args({8, 10, 1})
    ->Args({128, 10, 0});

void BM_EllipticE(benchmark::State& state) {
  double m = 0.3;
  for (auto _ : state) {
    benchmark::DoNotOptimize(elliptic_E(m));
    m = m < 0.9 ? m + 1e-3 : 0.3;
  }
}
BENCHMARK(BM_EllipticE);

void BM_AmplitudeForUpperEdgeLength(benchmark::State& state) {
  double length = 1400.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(amplitude_for_upper_edge_length(length, 1300.0));
    length = length < 1600.0 ? length + 0.01 : 1301.0;
  }
}
BENCHMARK(BM_AmplitudeForUpperEdgeLength);

const Parameters& default_parameters() {
  static const Parameters p = [] {
    Parameters exact;
    exact.model.method = Method::exact;
    return exact;
  }();
  return p;
}

const Solution& default_solution() {
  static const Solution s = solve(default_parameters());
  return s;
}

void BM_FoldLines(benchmark::State& state) {
  for (auto _ : state) {
    benchmark::DoNotOptimize(fold_lines(default_solution(), default_parameters(), 201));
  }
}
BENCHMARK(BM_FoldLines);

void BM_GridOneThread(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(deformed_grid(default_solution(), Parameters{}, size, size));
  }
  state.SetItemsProcessed(state.iterations() * size * size);
}
BENCHMARK(BM_GridOneThread)->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);

void BM_GridParallel(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(deformed_grid_parallel(default_solution(), Parameters{}, size, size));
  }
  state.SetItemsProcessed(state.iterations() * size * size);
}
BENCHMARK(BM_GridParallel)->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);

// The scene stages of one explorer frame while a slider drags h: a new solve, fold lines, grid
// and normals, all through Scene as the 3D view pulls them (the explorer's default grid is 128).
void BM_SceneDraggedFrame(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  Scene scene(default_parameters());
  scene.set_grid_resolution(size, size);
  Parameters p = default_parameters();
  const double h_mm = p.hanging.height_mm;
  int frame = 0;
  for (auto _ : state) {
    p.hanging.height_mm = h_mm * (1.0 + 0.001 * (frame++ % 100));
    scene.set_parameters(p);
    benchmark::DoNotOptimize(scene.fold_lines());
    benchmark::DoNotOptimize(scene.normals());
  }
}
BENCHMARK(BM_SceneDraggedFrame)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond);

// `foldlab calibrate --fit K,p --coverage` on 6, 12 and 24 rows near the paper's (the rows of
// calibration_rows): the in-sample fit with leave-one-out and group splits, then the coverage
// check's nested fits, on every core. Its time grows about as m³.
void BM_CalibrateWithCoverage(benchmark::State& state) {
  MeasurementSet data;
  data.origin = "bench";
  std::vector<Measurement> paper;
  for (const Measurement& m : load_measurements(FOLDLAB_DATA_DIR "/paper-measurements.csv").rows) {
    if (m.role == MeasurementRole::fit) {
      paper.push_back(m);
    }
  }
  data.rows = calibration_rows(paper, static_cast<int>(state.range(0)));
  Parameters base = default_parameters();
  CalibrationOptions options;
  options.fit = FitConstants::K_and_p;
  for (auto _ : state) {
    benchmark::DoNotOptimize(calibrate(data, base, options));
    benchmark::DoNotOptimize(cross_validated_coverage(data, base, options));
  }
}
BENCHMARK(BM_CalibrateWithCoverage)
    ->Arg(6)
    ->Arg(12)
    ->Arg(24)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
}  // namespace foldlab

BENCHMARK_MAIN();
