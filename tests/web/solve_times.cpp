// Time per solve over the benchmark's realistic cases, for scripts/web-bench.sh to set the
// WebAssembly build (run by node) beside the desktop's: one JSON object on stdout,
// {"cases": [{"label": ..., "us_per_solve": ...}, ...]}. Each case is solved again and again for
// at least `--ms` milliseconds (default 50), after one untimed solve. Before any case is timed,
// every case is solved by turns for `--warm-up-ms` (default 500): a WebAssembly engine compiles
// the code while it first runs (V8: lazily, then again optimised on a background thread, which a
// busy machine delays), so without it the first cases timed carry that compilation, whatever
// their inputs.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"
#include "core/tools/benchmark_cases.hpp"

int main(int argc, char** argv) {
  using namespace foldlab;
  using Clock = std::chrono::steady_clock;
  double min_ms = 50.0;
  double warm_up_ms = 500.0;
  int count = 40;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--ms") == 0) {
      min_ms = std::atof(argv[i + 1]);
    } else if (std::strcmp(argv[i], "--warm-up-ms") == 0) {
      warm_up_ms = std::atof(argv[i + 1]);
    } else if (std::strcmp(argv[i], "--cases") == 0) {
      count = std::atoi(argv[i + 1]);
    }
  }
  std::string out = "{\"cases\": [";
  volatile int sink = 0;  // keeps the solves from being optimised away
  bool first = true;
  const std::vector<BenchmarkCase> cases = realistic_cases(count);
  const Clock::time_point warm_up_start = Clock::now();
  while (!cases.empty() &&
         std::chrono::duration<double, std::milli>(Clock::now() - warm_up_start).count() <
             warm_up_ms) {
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
      elapsed_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }
    out += std::string(first ? "" : ", ") + "{\"label\": \"" + c.label + "\", \"us_per_solve\": " +
           detail::shortest_number(1000.0 * elapsed_ms / static_cast<double>(solves)) + "}";
    first = false;
  }
  out += "]}";
  std::puts(out.c_str());
  return 0;
}
