// Run time against error: a fixed set of realistic cases, a reference solution
// per case that does not share code with the solver, the method variants to compare, and the
// measurements (time per solve, error in n, Q and z_max) that `foldlab bench`, docs/bench.csv and
// docs/bench.svg report.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/io/measurements.hpp"
#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

inline constexpr std::uint64_t kBenchmarkSeed = 20240604;

struct BenchmarkCase {
  std::string label;  // "random 17" or a preset's name
  Parameters parameters;
};

// One fabric drawn log-uniformly from the clothes and curtains a designer tunes: each cloth input
// over its row's realistic range, narrower than the typical ranges the stress test covers (d from
// 1 mm to 0.3 L), with the default model settings (calibrated K, l = L - d, Int[] to nearest).
Parameters realistic_fabric(std::mt19937_64& random);
// `count` realistic fabrics from a fixed seed, so that every run sees the same cases.
std::vector<BenchmarkCase> realistic_cases(int count, std::uint64_t seed = kBenchmarkSeed);

// `count` measured rows for timing a calibration and its coverage check: row i is `base[i %
// base.size()]` (e.g. the paper's fit rows) with h, w and the observed z_max and Q moved by fixed
// steps of 3 % per round through `base`, so that every row differs and a run is the same
// everywhere. Precondition: every base row observes n, z_max and Q.
std::vector<Measurement> calibration_rows(const std::vector<Measurement>& base, int count);

// The reference of one case: n as the exact method finds it, and a_n, z_max and Q re-solved
// for that n in long double with code of its own: eq. 8 by a 2048-point periodic trapezoid
// quadrature (spectrally accurate for this integrand), eq. 9 summed term by term, roots by
// bisection and Illinois steps.
struct ReferenceSolution {
  Regime regime = Regime::no_slack;
  int n = 0;
  long double Q = 1.0L;
  long double z_max_mm = 0.0L;
  long double an_mm = 0.0L;
  long double sag_mm = 0.0L;  // A of eq. 8
  // The long-double solution's own residuals, |eq. 8 length / L - 1| and |eq. 9 length / h - 1|,
  // recomputed in long double after the solve.
  long double residual_length = 0.0L;
  long double residual_height = 0.0L;
  // Eq. 10 applied to the long-double a_n gives back n (a fixed point; false for n cycles).
  bool n_is_fixed_point = true;
  bool has_folds() const { return n >= 1 && z_max_mm > 0.0L; }
};

// Precondition: validate(p) is empty and n of the exact method is at most 1e5 (term-by-term sums).
ReferenceSolution reference_solution(const Parameters& p);

// A method variant on the chart: the solver settings that select it.
struct BenchmarkMethod {
  std::string name;  // e.g. "paper simpson N=20 tol=5%", "exact"
  Method method = Method::paper;
  LengthQuadrature quadrature = LengthQuadrature::simpson;
  int intervals = 20;
  double tolerance = 0.05;
};

// The paper method with Simpson and with the trapezoid rule, N in {4, 8, 16, 20, 32, 64, 128} and
// tolerance in {5%, 1%, 0.1%}, then the exact method.
std::vector<BenchmarkMethod> benchmark_methods();
// `p` with the method's settings in place of its own.
Parameters with_method(Parameters p, const BenchmarkMethod& m);

// Error of one method over a case set, against the references. Q and z_max errors are relative
// (|value / reference - 1|) over the cases whose reference has folds.
struct MethodAccuracy {
  int cases = 0;              // cases whose reference has folds
  int n_exact = 0;            // of those, how many got the reference's n
  int max_abs_n_error = 0;    // max |n - n_ref|
  double median_Q_error = 0;  // relative
  double max_Q_error = 0;
  double median_z_error = 0;
  double max_z_error = 0;
};
MethodAccuracy method_accuracy(const std::vector<Solution>& solutions,
                               const std::vector<ReferenceSolution>& references);

// Nanoseconds per solve: each case is solved `repeats` times, each solve timed alone (the clock's
// own cost, measured, is subtracted); a case's time is the median of its repeats; the summary is
// over cases.
struct TimingSummary {
  double median_ns = 0;
  double p10_ns = 0;
  double p90_ns = 0;
  double mean_ns = 0;  // total time / solves, as a throughput figure
};
TimingSummary time_solves(const std::vector<Parameters>& cases, int repeats);
// The same for several methods (one case list each), taking turns pass by pass so that a busy
// spell of the machine is shared among them.
std::vector<TimingSummary> time_methods(const std::vector<std::vector<Parameters>>& methods,
                                        int repeats);

struct BenchmarkRow {
  BenchmarkMethod method;
  TimingSummary timing;
  MethodAccuracy accuracy;
  bool pareto = false;  // no other row is both at most as slow and at most as wrong (z_max)
};

// Marks the rows on the Pareto front of (median ns per solve, median z_max error).
void mark_pareto_front(std::vector<BenchmarkRow>& rows);

// How far the double-precision exact method lands from the long-double references.
struct ReferenceCheck {
  int cases = 0;                      // cases with folds
  double max_Q_difference = 0;        // max |Q_exact / Q_ref - 1|
  double max_z_difference = 0;        // max |z_exact / z_ref - 1|
  double max_an_difference = 0;       // max |a_n exact / a_n ref - 1|
  double max_reference_residual = 0;  // max of the references' own residuals (eqs. 8 and 9)
  int n_not_fixed_point = 0;          // wrinkled cases whose long-double a_n gives another n
};
ReferenceCheck check_references(const std::vector<Solution>& exact,
                                const std::vector<ReferenceSolution>& references);

// The rest of the pipeline for one solution, milliseconds per call (median of `repeats`).
struct PipelineTiming {
  int grid_size = 0;             // vertices per side
  double fold_lines_ms = 0;      // fold_lines(s, p, 201)
  double grid_serial_ms = 0;     // deformed_grid: positions, triangles, normals, one thread
  double normals_serial_ms = 0;  // of which vertex_normals
  double grid_parallel_ms = 0;   // deformed_grid_parallel with `threads` threads
  int threads = 1;
};
std::vector<PipelineTiming> time_pipeline(const Solution& s, const Parameters& p,
                                          const std::vector<int>& grid_sizes, int repeats,
                                          int threads);

// docs/bench.csv: one row per method, with a header.
std::string benchmark_csv(const std::vector<BenchmarkRow>& rows);
// docs/bench.svg: run time against error on log-log axes, the Pareto front joined and labelled.
std::string benchmark_svg(const std::vector<BenchmarkRow>& rows, const std::string& subtitle);

}  // namespace foldlab
