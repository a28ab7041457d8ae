// Time per solve over the benchmark's realistic cases, for scripts/web-bench.sh to set the
// WebAssembly build (run by node) beside the desktop's: one JSON object on stdout,
// {"cases": [{"label": ..., "us_per_solve": ...}, ...]}. Each case is solved again and again for
// at least `--ms` milliseconds (default 50), after one untimed solve. Before any case is timed,
// every case is solved by turns for `--warm-up-ms` (default 500): a WebAssembly engine compiles
// the code while it first runs (V8: lazily, then again optimised on a background thread, which a
// busy machine delays), so without it the first cases timed carry that compilation, whatever
// their inputs.
// With `--field`, the tension field instead, as the explorer's field view runs it: the view
// opening on the default cloth (a cold solve on the mesh while a value is dragged, 16 cells
// across, and at rest, 32) and one frame of a drag of d (a warm re-solve after d + 1 mm, solved
// whole), so that the page's field is set beside the desktop's; warmed up by turns as the closed
// form's cases are, with the first opening's time (the engine compiling) given apart.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "core/field/live_field.hpp"
#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"
#include "core/tools/benchmark_cases.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

foldlab::field::FieldInputs field_inputs(double d_mm, int cells) {
  foldlab::Parameters p;
  p.hanging.support_displacement_mm = d_mm;
  foldlab::field::FieldInputs in;
  in.outline = foldlab::field::make_outline(p, foldlab::field::OutlineKind::cosine);
  in.material = foldlab::field::material_of(p.fabric);
  in.resolution.cells_x = cells;
  in.resolution.cells_y = cells;
  return in;
}

void settle(foldlab::field::LiveField& live) {
  while (live.working()) {
    live.step(0.0);
  }
}

// The microseconds a run of `once` takes, over at least `min_ms` and at least two runs.
template <class Once>
double us_per_run(double min_ms, Once&& once) {
  once();
  long runs = 0;
  const Clock::time_point start = Clock::now();
  double elapsed_ms = 0.0;
  while (elapsed_ms < min_ms || runs < 2) {
    once();
    ++runs;
    elapsed_ms = ms_since(start);
  }
  return 1000.0 * elapsed_ms / static_cast<double>(runs);
}

struct FieldCase {
  std::string label;
  std::function<void()> once;
};

// The first case's first run is kept apart: in a fresh page it carries the engine's compiling of
// the solver, which a student pays once, on the first opening of the view.
std::string field_cases(double min_ms, double warm_up_ms) {
  using foldlab::field::LiveField;
  std::vector<FieldCase> cases;
  for (const int cells : {16, 32}) {
    cases.push_back({"field view opening, " + std::to_string(cells) + " cells", [cells] {
                       LiveField live;
                       live.request(field_inputs(100.0, cells));
                       settle(live);
                     }});
  }
  LiveField drag;
  double d_mm = 100.0;
  cases.push_back({"field drag frame, d + 1 mm, 16 cells", [&drag, &d_mm] {
                     d_mm = d_mm >= 300.0 ? 100.0 : d_mm + 1.0;
                     drag.request(field_inputs(d_mm, 16));
                     settle(drag);
                   }});
  const Clock::time_point first_start = Clock::now();
  cases.front().once();
  const double first_run_us = 1000.0 * ms_since(first_start);
  const Clock::time_point warm_up_start = Clock::now();
  while (ms_since(warm_up_start) < warm_up_ms) {
    for (const FieldCase& c : cases) {
      c.once();
    }
  }
  std::string out =
      "{\"first_run_us\": " + foldlab::detail::shortest_number(first_run_us) + ", \"cases\": [";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    out += std::string(i == 0 ? "" : ", ") + "{\"label\": \"" + cases[i].label +
           "\", \"us_per_solve\": " +
           foldlab::detail::shortest_number(us_per_run(min_ms, cases[i].once)) + "}";
  }
  return out + "]}";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace foldlab;
  double min_ms = 50.0;
  double warm_up_ms = 500.0;
  int count = 40;
  bool field = false;
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (std::strcmp(argv[i], "--field") == 0) {
      field = true;
    } else if (has_value && std::strcmp(argv[i], "--ms") == 0) {
      min_ms = std::atof(argv[++i]);
    } else if (has_value && std::strcmp(argv[i], "--warm-up-ms") == 0) {
      warm_up_ms = std::atof(argv[++i]);
    } else if (has_value && std::strcmp(argv[i], "--cases") == 0) {
      count = std::atoi(argv[++i]);
    }
  }
  if (field) {
    std::puts(field_cases(min_ms, warm_up_ms).c_str());
    return 0;
  }
  std::string out = "{\"cases\": [";
  volatile int sink = 0;  // keeps the solves from being optimised away
  bool first = true;
  const std::vector<BenchmarkCase> cases = realistic_cases(count);
  const Clock::time_point warm_up_start = Clock::now();
  while (!cases.empty() && ms_since(warm_up_start) < warm_up_ms) {
    for (const BenchmarkCase& c : cases) {
      sink = sink + solve(c.parameters).n;
    }
  }
  for (const BenchmarkCase& c : cases) {
    sink = sink + solve(c.parameters).n;
    long solves = 0;
    const Clock::time_point start = Clock::now();
    double elapsed_ms = 0.0;
    while (elapsed_ms < min_ms) {
      sink = sink + solve(c.parameters).n;
      ++solves;
      elapsed_ms = ms_since(start);
    }
    out += std::string(first ? "" : ", ") + "{\"label\": \"" + c.label + "\", \"us_per_solve\": " +
           detail::shortest_number(1000.0 * elapsed_ms / static_cast<double>(solves)) + "}";
    first = false;
  }
  out += "]}";
  std::puts(out.c_str());
  return 0;
}
