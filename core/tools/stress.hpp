// The numerical stress test: both methods over inputs far wider than real fabrics, counting what
// the solver promises never happens (NaN, inf, hangs) and what it reports instead (regimes,
// iteration caps, n cycles, residuals).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

struct StressOptions {
  int samples = 100000;
  std::uint64_t seed = 1;
  // A solve slower than this counts as a hang (far above the slowest honest solve, ~0.1 s at the
  // cap of 1e7 folds).
  double hang_seconds = 1.0;
  // Every grid_every-th sample also builds a grid_nx x grid_ny deformed grid (both methods).
  int grid_every = 50;
  int grid_nx = 16;
  int grid_ny = 256;
  int threads = 0;  // <= 0: std::thread::hardware_concurrency()
};

// Sample i of the stress test, the same for any thread count: t, E, w, h and L log-uniform over
// the input table's typical ranges; d uniform in [0, L/2) and exactly 0 for every 100th sample; nu
// uniform over its typical range; the default c.
Parameters stress_sample(std::uint64_t seed, int index);
// What stress_sample draws, from the input table: "t 0.01 to 5 mm, ..., d 0 to 2500 mm
// (below L/2), ...", for help texts.
std::string stress_sampled_ranges();

struct StressCase {
  Parameters parameters;
  Method method = Method::paper;
  double seconds = 0.0;
  int n = 0;
  Regime regime = Regime::no_slack;
};

struct MethodStress {
  std::map<std::string, int> regimes;  // solutions per regime name
  int non_finite = 0;                  // solutions with a NaN or inf in any output
  int hangs = 0;                       // solves slower than hang_seconds
  int iteration_cap_hits = 0;
  int n_capped = 0;  // eq. 10 asked for more than kMaxWrinkles folds
  // Max |residual| of eqs. 8 and 9 over the regimes where both equations hold
  // (RegimeInfo::equations_hold); negligible_slack misses eq. 9 by design (it has no root there).
  double max_residual_length = 0.0;
  double max_residual_height = 0.0;
  int max_n = 0;
  double seconds = 0.0;  // total solve time
  // The slowest case, by the best of three timings of the slowest few (a busy machine can stall
  // any single solve).
  StressCase slowest;
  std::vector<StressCase> slow_candidates;
};

struct StressReport {
  int samples = 0;
  std::uint64_t seed = 0;
  MethodStress paper;
  MethodStress exact;
  int n_cycles = 0;  // exact method: eq. 10 cycled
  int grids = 0;     // deformed grids built (both methods)
  int grid_non_finite = 0;
  double worst_grid_fibre_error = 0.0;           // over every grid built
  double worst_resolved_grid_fibre_error = 0.0;  // over grids with ny >= 4 n (folds resolved)
  double wall_seconds = 0.0;
  int threads = 1;
  std::vector<StressCase> failures;  // the first few non-finite or hung cases
  bool passed() const {
    return paper.non_finite + exact.non_finite + grid_non_finite == 0 &&
           paper.hangs + exact.hangs == 0;
  }
};

StressReport run_stress(const StressOptions& options);

nlohmann::json stress_to_json(const StressReport& report);
std::string stress_table(const StressReport& report);

}  // namespace foldlab
