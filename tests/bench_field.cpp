// Google Benchmark timings of the tension-field solver (target foldlab_field_bench, not a test):
// cold solves (mesh, coarse-to-fine ladder, Newton) and warm re-solves after a 1 % change of d
// on the same mesh, per mesh size, with the error of the thrust H and of the strain energy
// against a Richardson extrapolation from the three finest nested meshes as counters; and a sheet
// hung from its whole top edge, whose T_yy far from the sides is w (h - Y) exactly, per mesh size.
// The curve of run time against error that docs/performance.md and docs/field.md tabulate.
// Run: build/tests/foldlab_field_bench
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include <benchmark/benchmark.h>

#include "core/field/field_case.hpp"

namespace foldlab::field {
namespace {

// The nested meshes the extrapolation uses: each halves the last's cells (cells_y = 0.7 cells_x
// keeps them nested: 20 x 14, 40 x 28, 80 x 56). Not 160 x 112: Conci's rectangle there stops at
// the iteration cap with a residual of 9e-7 after five minutes (docs/field.md, Run time).
constexpr std::array<int, 3> kRichardsonCells = {20, 40, 80};

OutlineKind kind_of(std::int64_t arg) {
  return arg == 0 ? OutlineKind::rectangular : OutlineKind::cosine;
}

MeshResolution resolution(std::int64_t cells_x) {
  const int cx = static_cast<int>(cells_x);
  return {cx, cx * 7 / 10, MeshSplit::union_jack};
}

// Richardson's extrapolation of f(h) = f* + C h^p from three meshes halving h, with the observed
// order p = log2((f1 - f2) / (f2 - f3)). Where the differences do not shrink (p <= 0.1: a
// logarithmic drift, as the point supports' H has) there is no limit to extrapolate to, and the
// finest value stands in, its order said.
struct Extrapolation {
  double limit = 0.0;
  double order = 0.0;
};
Extrapolation richardson(double f1, double f2, double f3) {
  const double ratio = (f1 - f2) / (f2 - f3);
  const double order = ratio > 0.0 ? std::log2(ratio) : 0.0;
  if (!(order > 0.1)) {
    return {f3, order};
  }
  return {f3 + (f3 - f2) / (std::pow(2.0, order) - 1.0), order};
}

struct Reference {
  Extrapolation thrust;
  Extrapolation energy;
};

// Solved once per outline on the nested meshes, and printed, since the orders are a result.
Reference reference(OutlineKind kind) {
  static std::map<OutlineKind, Reference> cache;
  const auto found = cache.find(kind);
  if (found != cache.end()) {
    return found->second;
  }
  const Parameters p;
  std::array<double, 3> thrust{};
  std::array<double, 3> energy{};
  for (std::size_t i = 0; i < kRichardsonCells.size(); ++i) {
    const FieldReport r = solve_outline(make_outline(p, kind), material_of(p.fabric),
                                        resolution(kRichardsonCells[i]), {}, 0);
    thrust[i] = r.thrust_N;
    energy[i] = r.solution.energy_Nmm;
    std::fprintf(stderr, "%s %d cells: H = %.8g N, strain energy = %.8g N mm, converged %d\n",
                 std::string(to_string(kind)).c_str(), kRichardsonCells[i], r.thrust_N,
                 r.solution.energy_Nmm, r.solution.converged ? 1 : 0);
  }
  const Reference ref{richardson(thrust[0], thrust[1], thrust[2]),
                      richardson(energy[0], energy[1], energy[2])};
  std::fprintf(stderr,
               "%s: H -> %.8g N (observed order %.2f), strain energy -> %.8g N mm (order %.2f)\n",
               std::string(to_string(kind)).c_str(), ref.thrust.limit, ref.thrust.order,
               ref.energy.limit, ref.energy.order);
  return cache[kind] = ref;
}

void report_errors(benchmark::State& state, OutlineKind kind, const FieldReport& r) {
  const Reference ref = reference(kind);
  state.counters["iterations"] = r.solution.iterations;
  state.counters["converged"] = r.solution.converged ? 1 : 0;
  state.counters["H_N"] = r.thrust_N;
  state.counters["H_error"] = std::abs(r.thrust_N / ref.thrust.limit - 1.0);
  state.counters["energy_error"] = std::abs(r.solution.energy_Nmm / ref.energy.limit - 1.0);
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
    ->ArgsProduct({{10, 20, 30, 40, 60, 80}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// The batch anchor's size: the coarse mesh of Chen et al.'s draped dress carries about 1 400
// degrees of freedom (docs/field.md, Run time). The mesh of each cut whose free unknowns (two a
// node) come nearest to that, solved cold as BM_FieldCold does; counters give its size.
constexpr int kAnchorUnknowns = 1400;

MeshResolution anchor_resolution(const Outline& outline) {
  MeshResolution best = resolution(8);
  int best_gap = 1 << 30;
  for (int cells = 8; cells <= 80; ++cells) {
    const MeshResolution r = resolution(cells);
    const Mesh mesh = make_mesh(outline, r);
    const int unknowns = 2 * static_cast<int>(mesh.nodes_mm.size() - mesh.support_nodes.size());
    if (std::abs(unknowns - kAnchorUnknowns) < best_gap) {
      best_gap = std::abs(unknowns - kAnchorUnknowns);
      best = r;
    }
  }
  return best;
}

// Arg: outline (0 rectangle, 1 cosine).
void BM_FieldColdAnchorSize(benchmark::State& state) {
  const Parameters p;
  const OutlineKind kind = kind_of(state.range(0));
  const Outline outline = make_outline(p, kind);
  const Material material = material_of(p.fabric);
  const MeshResolution res = anchor_resolution(outline);
  const Mesh mesh = make_mesh(outline, res);
  FieldReport last;
  for (auto _ : state) {
    last = solve_outline(outline, material, res, {}, 0);
    benchmark::DoNotOptimize(last.thrust_N);
  }
  state.counters["cells_x"] = res.cells_x;
  state.counters["nodes"] = static_cast<double>(mesh.nodes_mm.size());
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
  state.counters["unknowns"] =
      2.0 * static_cast<double>(mesh.nodes_mm.size() - mesh.support_nodes.size());
  state.counters["iterations"] = last.solution.iterations;
  state.counters["converged"] = last.solution.converged ? 1 : 0;
}
BENCHMARK(BM_FieldColdAnchorSize)->ArgName("cosine")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// A sheet L x h = 1200 x 300 mm hung from a support at every node of its top edge, cells across
// and half as many down: in the middle half of its width, from 0.35 h to 0.85 h down, the weight
// below is carried straight up, T_yy = w (h - Y). Counters: the largest and the rms relative error
// of the larger principal tension there.
void BM_FieldHungSheet(benchmark::State& state) {
  const double L = 1200.0;
  const double h = 300.0;
  const int nx = static_cast<int>(state.range(0));
  Outline o;
  o.top_mm = {{-0.5 * L, 0.0}, {0.5 * L, 0.0}};
  o.bottom_mm = {{-0.5 * L, h}, {0.5 * L, h}};
  for (int i = 0; i <= nx; ++i) {
    const Eigen::Vector2d at(-0.5 * L + L * i / nx, 0.0);
    o.supports.push_back({at, at});
  }
  // nu = 0: with nu > 0 the pinned top restrains the Poisson contraction and the shear this sets
  // up moves T_yy off w (h - Y) by up to about 1 % whatever the mesh (docs/field.md, Checks), an
  // elastic effect that would hide the discretisation's error.
  const Material material{Parameters{}.fabric.youngs_modulus_MPa * Parameters{}.fabric.thickness_mm,
                          0.0, Parameters{}.fabric.weight_N_per_mm2};
  const MeshResolution res{nx, nx / 2, MeshSplit::union_jack};
  FieldReport last;
  for (auto _ : state) {
    last = solve_outline(o, material, res, {}, 0);
    benchmark::DoNotOptimize(last.thrust_N);
  }
  const Mesh mesh = make_mesh(o, res);
  double worst = 0.0;
  double squares = 0.0;
  int count = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (int n : mesh.triangles[t]) {
      centroid += mesh.nodes_mm[n] / 3.0;
    }
    if (std::abs(centroid.x()) > 0.25 * L || centroid.y() < 0.35 * h || centroid.y() > 0.85 * h) {
      continue;
    }
    const double expected = material.weight_N_per_mm2 * (h - centroid.y());
    const double error = last.solution.triangles[t].tension_N_per_mm / expected - 1.0;
    worst = std::max(worst, std::abs(error));
    squares += error * error;
    ++count;
  }
  state.counters["iterations"] = last.solution.iterations;
  state.counters["converged"] = last.solution.converged ? 1 : 0;
  state.counters["Tyy_max_error"] = worst;
  state.counters["Tyy_rms_error"] = count > 0 ? std::sqrt(squares / count) : 0.0;
}
BENCHMARK(BM_FieldHungSheet)
    ->ArgName("cells")
    ->Arg(10)
    ->Arg(20)
    ->Arg(40)
    ->Arg(80)
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
