#include "core/tools/benchmark_cases.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "core/geometry/geometry.hpp"
#include "core/geometry/parallel_grid.hpp"
#include "core/model/equations.hpp"
#include "core/model/settings.hpp"

namespace foldlab {
namespace {

using Real = long double;
constexpr Real kPiL = std::numbers::pi_v<long double>;

// --- The long-double reference. Nothing here calls the solver's equations: eq. 8 by quadrature,
// eq. 9 term by term, roots by bisection and Illinois steps. ---

// Eq. 8 by the trapezoid rule over one period of sqrt(1 + k² sin²θ) (period pi): for a smooth
// periodic integrand its error falls like exp(-2 M asinh(1/k)), below 1e-30 here for k < 20.
class EdgeQuadrature {
 public:
  static constexpr int kPoints = 2048;
  EdgeQuadrature() : sin2_(kPoints) {
    for (int j = 0; j < kPoints; ++j) {
      const Real s = std::sin(kPiL * j / kPoints);
      sin2_[static_cast<std::size_t>(j)] = s * s;
    }
  }
  // L / l for amplitude ratio k = pi A / l, and its derivative in k.
  std::pair<Real, Real> ratio(Real k) const {
    Real sum = 0.0L;
    Real slope = 0.0L;
    for (const Real s2 : sin2_) {
      const Real root = std::sqrt(1.0L + k * k * s2);
      sum += root;
      slope += k * s2 / root;
    }
    return {sum / kPoints, slope / kPoints};
  }

 private:
  std::vector<Real> sin2_;
};

const EdgeQuadrature& edge_quadrature() {
  static const EdgeQuadrature quadrature;
  return quadrature;
}

// A of eq. 8: L/l = ratio(k), by Newton from the parabola's k = 2 sqrt(L/l - 1) (ratio is convex
// and increasing in k, so from below Newton overshoots once and then descends monotonically).
Real reference_sag(Real L, Real l) {
  const Real target = L / l;
  if (!(target > 1.0L)) {
    return 0.0L;
  }
  Real k = 2.0L * std::sqrt(target - 1.0L);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const auto [value, slope] = edge_quadrature().ratio(k);
    const Real step = (value - target) / slope;
    k -= step;
    if (std::abs(step) <= 1e-11L * k) {
      break;  // quadratic convergence: the error left is about step² / k, below 1e-21 k
    }
  }
  return k * l / kPiL;
}

// Eq. 9 term by term for a_i = a_0 Q^-i.
Real reference_fibre(Real a0, Real an, int n, Real z) {
  const Real log_Q = std::log(a0 / an) / n;
  Real sum = 0.0L;
  for (int i = 1; i <= n; ++i) {
    const Real upper = a0 * std::exp(-(i - 1) * log_Q);
    const Real lower = a0 * std::exp(-i * log_Q);
    sum += std::sqrt((upper - lower) * (upper - lower) + 4.0L * z * z);
  }
  return sum;
}

// The theta in (0, pi/2) with fibre(A cos theta, A sin theta) = h: the fibre grows with theta
// (from a_0 - A < h at theta = 0 to more than a_0 > h as a_n -> 0). Bisection to a narrow
// bracket, then the Illinois variant of regula falsi to the last digit.
Real reference_theta(Real a0, Real h, Real A, int n) {
  auto F = [&](Real theta) {
    return reference_fibre(a0, A * std::cos(theta), n, A * std::sin(theta)) - h;
  };
  Real lo = 0.0L;
  Real hi = kPiL / 2 * (1.0L - 1e-12L);  // a_n = A cos theta stays positive
  // Bisect in log theta first: the root can be tiny (z << A) and plain bisection would spend its
  // digits on the wrong scale.
  Real lo_log = std::log(1e-30L);
  Real hi_log = std::log(hi);
  for (int iteration = 0; iteration < 40; ++iteration) {
    const Real mid = 0.5L * (lo_log + hi_log);
    (F(std::exp(mid)) < 0.0L ? lo_log : hi_log) = mid;
  }
  lo = std::exp(lo_log);
  hi = std::exp(hi_log);
  Real f_lo = F(lo);
  Real f_hi = F(hi);
  int side = 0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const Real x = (f_lo == f_hi) ? 0.5L * (lo + hi) : lo - f_lo * (hi - lo) / (f_hi - f_lo);
    if (!(x > lo && x < hi)) {
      break;  // lo and hi are neighbours: nothing is left between them
    }
    const Real fx = F(x);
    if (fx == 0.0L) {
      return x;
    }
    if (fx < 0.0L) {
      lo = x;
      f_lo = fx;
      if (side == -1) {
        f_hi *= 0.5L;  // Illinois: keep the stale end from pinning the false position
      }
      side = -1;
    } else {
      hi = x;
      f_hi = fx;
      if (side == 1) {
        f_lo *= 0.5L;
      }
      side = 1;
    }
  }
  return 0.5L * (lo + hi);
}

int reference_count(Real a0_over_an, Real Q7, bool nearest) {
  const Real x = std::log(a0_over_an) / std::log(Q7);
  return std::max(1, static_cast<int>(nearest ? std::nearbyint(x) : std::floor(x)));
}

Real relative_error(Real value, Real reference) {
  if (reference == 0.0L) {
    return value == 0.0L ? 0.0L : std::numeric_limits<Real>::infinity();
  }
  return std::abs(value / reference - 1.0L);
}

double median_of(std::vector<double> values) {
  if (values.empty()) {
    return 0.0;
  }
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle),
                   values.end());
  return values[middle];
}

double quantile_of(std::vector<double> values, double q) {
  if (values.empty()) {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const auto index =
      static_cast<std::size_t>(std::lround(q * static_cast<double>(values.size() - 1)));
  return values[std::min(index, values.size() - 1)];
}

}  // namespace

Parameters realistic_fabric(std::mt19937_64& random) {
  auto log_uniform = [&random](double lo, double hi) {
    std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
    return std::exp(u(random));
  };
  Parameters p;
  // One draw per cloth input in table order (t, E, w, h, L, d): the cases, and every figure
  // measured on them, stay put as long as the rows keep their order and ranges. An upper end
  // that follows from other inputs (d's, from L) comes from those drawn before.
  for (const InputSpec* spec : cloth_inputs()) {
    double hi = spec->realistic_hi;
    if (spec->realistic_part_of_upper_bound > 0.0) {
      const std::optional<double> bound = spec->upper_bound ? spec->upper_bound(p) : std::nullopt;
      if (!bound) {
        throw std::logic_error("no upper bound to draw " + std::string(spec->key) + " below");
      }
      hi = spec->realistic_part_of_upper_bound * *bound;
    }
    if (!(spec->realistic_lo > 0.0 && hi > spec->realistic_lo)) {
      throw std::logic_error("the cloth input " + std::string(spec->key) +
                             " has no realistic range to draw from");
    }
    set_input(p, spec->key, log_uniform(spec->realistic_lo, hi));
  }
  return p;
}

std::vector<BenchmarkCase> realistic_cases(int count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<BenchmarkCase> cases;
  cases.reserve(static_cast<std::size_t>(std::max(0, count)));
  for (int i = 0; i < count; ++i) {
    cases.push_back({"random " + std::to_string(i), realistic_fabric(random)});
  }
  return cases;
}

std::vector<Measurement> calibration_rows(const std::vector<Measurement>& base, int count) {
  std::vector<Measurement> rows;
  for (int i = 0; i < count && !base.empty(); ++i) {
    const auto size = static_cast<int>(base.size());
    Measurement m = base[static_cast<std::size_t>(i % size)];
    // Rounds 0, 1, 2, 3, 4, ... move by 0, -3 %, +3 %, -6 %, +6 %, ...
    const int round = i / size;
    const double step = (round % 2 == 0 ? 1.0 : -1.0) * 0.03 * ((round + 1) / 2);
    m.inputs.hanging.height_mm = std::round(m.inputs.hanging.height_mm * (1.0 + step));
    m.inputs.fabric.weight_N_per_mm2 *= 1.0 - 0.5 * step;
    m.observed.z_max_mm = *m.observed.z_max_mm * (1.0 + 0.7 * step);
    m.observed.Q = 1.0 + (*m.observed.Q - 1.0) * (1.0 - 0.4 * step);
    m.name = "row " + std::to_string(i + 1);
    m.row = i + 1;
    rows.push_back(std::move(m));
  }
  return rows;
}

ReferenceSolution reference_solution(const Parameters& p) {
  Parameters exact_parameters = p;
  exact_parameters.model.method = Method::exact;
  const Solution exact = solve(exact_parameters);

  ReferenceSolution ref;
  ref.regime = exact.regime;
  ref.n = exact.n;
  const Real h = p.hanging.height_mm;
  const Real L = p.hanging.length_mm;
  const Real l = span_mm(p);
  const Real a0 = 1.01L * h;
  ref.sag_mm = reference_sag(L, l);
  if (ref.n == 0) {
    return ref;  // no slack or short cloth: no folds to compare
  }
  const Real A = ref.sag_mm;
  Real theta = 0.0L;
  const RegimeInfo& regime = regime_info(exact.regime);
  if (!regime.equations_hold) {
    ref.an_mm = A;  // the solver's flat-fold answer: a_n = A, z = 0
  } else {
    theta = reference_theta(a0, h, A, ref.n);
    ref.an_mm = A * std::cos(theta);
    ref.z_max_mm = A * std::sin(theta);
  }
  ref.Q = std::exp(std::log(a0 / ref.an_mm) / ref.n);
  const Real edge =
      l * edge_quadrature().ratio(kPiL * std::hypot(ref.an_mm, ref.z_max_mm) / l).first;
  ref.residual_length = std::abs(edge / L - 1.0L);
  if (regime.equations_hold) {
    ref.residual_height = std::abs(reference_fibre(a0, ref.an_mm, ref.n, ref.z_max_mm) / h - 1.0L);
  }
  if (regime.n_fixed_point && exact.Q7) {
    ref.n_is_fixed_point = reference_count(a0 / ref.an_mm, *exact.Q7,
                                           p.model.int_rounding == IntRounding::nearest) == ref.n;
  }
  return ref;
}

std::vector<BenchmarkMethod> benchmark_methods() {
  std::vector<BenchmarkMethod> methods;
  for (LengthQuadrature rule : {LengthQuadrature::simpson, LengthQuadrature::trapezoid}) {
    for (double tolerance : {0.05, 0.01, 0.001}) {
      for (int intervals : {4, 8, 16, 20, 32, 64, 128}) {
        char name[96];
        std::snprintf(name, sizeof name, "paper %s N=%d tol=%g%%",
                      std::string(to_string(rule)).c_str(), intervals, 100.0 * tolerance);
        methods.push_back({name, Method::paper, rule, intervals, tolerance});
      }
    }
  }
  methods.push_back({"exact", Method::exact, LengthQuadrature::simpson, 20, 0.05});
  return methods;
}

Parameters with_method(Parameters p, const BenchmarkMethod& m) {
  p.model.method = m.method;
  p.model.length_quadrature = m.quadrature;
  p.model.simpson_intervals = m.intervals;
  p.model.length_tolerance = m.tolerance;
  return p;
}

MethodAccuracy method_accuracy(const std::vector<Solution>& solutions,
                               const std::vector<ReferenceSolution>& references) {
  MethodAccuracy out;
  std::vector<double> Q_errors;
  std::vector<double> z_errors;
  for (std::size_t i = 0; i < solutions.size() && i < references.size(); ++i) {
    const ReferenceSolution& ref = references[i];
    if (!ref.has_folds()) {
      continue;
    }
    const Solution& s = solutions[i];
    ++out.cases;
    out.n_exact += s.n == ref.n;
    out.max_abs_n_error = std::max(out.max_abs_n_error, std::abs(s.n - ref.n));
    Q_errors.push_back(static_cast<double>(relative_error(s.Q, ref.Q)));
    z_errors.push_back(static_cast<double>(relative_error(s.z_max_mm, ref.z_max_mm)));
  }
  out.median_Q_error = median_of(Q_errors);
  out.median_z_error = median_of(z_errors);
  out.max_Q_error = Q_errors.empty() ? 0.0 : *std::max_element(Q_errors.begin(), Q_errors.end());
  out.max_z_error = z_errors.empty() ? 0.0 : *std::max_element(z_errors.begin(), z_errors.end());
  return out;
}

TimingSummary time_solves(const std::vector<Parameters>& cases, int repeats) {
  return time_methods({cases}, repeats).front();
}

std::vector<TimingSummary> time_methods(const std::vector<std::vector<Parameters>>& methods,
                                        int repeats) {
  using Clock = std::chrono::steady_clock;
  repeats = std::max(1, repeats);
  // The cost of reading the clock twice, which every timed solve below also pays.
  std::vector<double> empty(1001);
  for (double& t : empty) {
    const auto start = Clock::now();
    t = std::chrono::duration<double, std::nano>(Clock::now() - start).count();
  }
  const double clock_ns = median_of(empty);

  // times[method][case][repeat]
  std::vector<std::vector<std::vector<double>>> times;
  times.reserve(methods.size());
  for (const std::vector<Parameters>& cases : methods) {
    times.emplace_back(cases.size(), std::vector<double>(static_cast<std::size_t>(repeats)));
  }
  std::vector<double> total_ns(methods.size(), 0.0);
  volatile double sink = 0.0;  // keeps the solves from being optimized away
  // Whole passes over the set, so that a case is not timed with its own inputs still warm in the
  // branch predictors (as a user's next solve would not be); the methods take turns pass by pass,
  // so that a busy spell of the machine is shared among them instead of hitting one.
  for (int r = 0; r < repeats; ++r) {
    for (std::size_t m = 0; m < methods.size(); ++m) {
      for (std::size_t i = 0; i < methods[m].size(); ++i) {
        const auto start = Clock::now();
        const Solution s = solve(methods[m][i]);
        const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count();
        sink = sink + s.z_max_mm;
        times[m][i][static_cast<std::size_t>(r)] = std::max(0.0, ns - clock_ns);
        total_ns[m] += ns - clock_ns;
      }
    }
  }
  std::vector<TimingSummary> out;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::vector<double> medians;
    medians.reserve(times[m].size());
    for (const std::vector<double>& repeats_of_case : times[m]) {
      medians.push_back(median_of(repeats_of_case));
    }
    TimingSummary t;
    t.median_ns = median_of(medians);
    t.p10_ns = quantile_of(medians, 0.1);
    t.p90_ns = quantile_of(medians, 0.9);
    const double solves = static_cast<double>(methods[m].size()) * repeats;
    t.mean_ns = solves > 0 ? total_ns[m] / solves : 0.0;
    out.push_back(t);
  }
  return out;
}

void mark_pareto_front(std::vector<BenchmarkRow>& rows) {
  for (BenchmarkRow& row : rows) {
    row.pareto = true;
    for (const BenchmarkRow& other : rows) {
      const bool no_slower = other.timing.median_ns <= row.timing.median_ns;
      const bool no_worse = other.accuracy.median_z_error <= row.accuracy.median_z_error;
      const bool better = other.timing.median_ns < row.timing.median_ns ||
                          other.accuracy.median_z_error < row.accuracy.median_z_error;
      if (&other != &row && no_slower && no_worse && better) {
        row.pareto = false;
        break;
      }
    }
  }
}

ReferenceCheck check_references(const std::vector<Solution>& exact,
                                const std::vector<ReferenceSolution>& references) {
  ReferenceCheck out;
  for (std::size_t i = 0; i < exact.size() && i < references.size(); ++i) {
    const ReferenceSolution& ref = references[i];
    if (!ref.has_folds()) {
      continue;
    }
    ++out.cases;
    const Solution& s = exact[i];
    out.max_Q_difference =
        std::max(out.max_Q_difference, static_cast<double>(relative_error(s.Q, ref.Q)));
    out.max_z_difference = std::max(out.max_z_difference,
                                    static_cast<double>(relative_error(s.z_max_mm, ref.z_max_mm)));
    out.max_an_difference = std::max(out.max_an_difference,
                                     static_cast<double>(relative_error(s.a_mm.back(), ref.an_mm)));
    out.max_reference_residual =
        std::max({out.max_reference_residual, static_cast<double>(ref.residual_length),
                  static_cast<double>(ref.residual_height)});
    out.n_not_fixed_point += !ref.n_is_fixed_point;
  }
  return out;
}

std::vector<PipelineTiming> time_pipeline(const Solution& s, const Parameters& p,
                                          const std::vector<int>& grid_sizes, int repeats,
                                          int threads) {
  using Clock = std::chrono::steady_clock;
  auto ms_since = [](Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  };
  repeats = std::max(1, repeats);
  volatile std::size_t kept = 0;  // keeps the results from being optimized away
  std::vector<PipelineTiming> out;
  for (int size : grid_sizes) {
    std::vector<double> lines_ms;
    std::vector<double> serial_ms;
    std::vector<double> normals_ms;
    std::vector<double> parallel_ms;
    for (int r = 0; r < repeats; ++r) {
      auto start = Clock::now();
      const FoldLines lines = fold_lines(s, p, 201);
      lines_ms.push_back(ms_since(start));
      start = Clock::now();
      const DeformedGrid serial = deformed_grid(s, p, size, size);
      serial_ms.push_back(ms_since(start));
      start = Clock::now();
      const std::vector<Eigen::Vector3f> normals =
          vertex_normals(serial.positions_mm, serial.triangle_indices);
      normals_ms.push_back(ms_since(start));
      start = Clock::now();
      const DeformedGrid parallel = deformed_grid_parallel(s, p, size, size, threads);
      parallel_ms.push_back(ms_since(start));
      kept = kept + lines.stride + normals.size() + parallel.normals.size();
    }
    PipelineTiming t;
    t.grid_size = size;
    t.fold_lines_ms = median_of(lines_ms);
    t.grid_serial_ms = median_of(serial_ms);
    t.normals_serial_ms = median_of(normals_ms);
    t.grid_parallel_ms = median_of(parallel_ms);
    t.threads = threads;
    out.push_back(t);
  }
  return out;
}

std::string benchmark_csv(const std::vector<BenchmarkRow>& rows) {
  std::string out =
      "method,kind,quadrature,intervals,tolerance,median_ns,p10_ns,p90_ns,mean_ns,cases,"
      "n_exact_percent,max_abs_n_error,median_Q_error,max_Q_error,median_z_error,max_z_error,"
      "pareto\n";
  for (const BenchmarkRow& row : rows) {
    const BenchmarkMethod& m = row.method;
    const MethodAccuracy& a = row.accuracy;
    char line[512];
    std::snprintf(
        line, sizeof line, "%s,%s,%s,%d,%g,%.0f,%.0f,%.0f,%.0f,%d,%.2f,%d,%.3e,%.3e,%.3e,%.3e,%d\n",
        m.name.c_str(), std::string(to_string(m.method)).c_str(),
        m.method == Method::paper ? std::string(to_string(m.quadrature)).c_str() : "",
        m.method == Method::paper ? m.intervals : 0, m.method == Method::paper ? m.tolerance : 0.0,
        row.timing.median_ns, row.timing.p10_ns, row.timing.p90_ns, row.timing.mean_ns, a.cases,
        a.cases ? 100.0 * a.n_exact / a.cases : 0.0, a.max_abs_n_error, a.median_Q_error,
        a.max_Q_error, a.median_z_error, a.max_z_error, row.pareto ? 1 : 0);
    out += line;
  }
  return out;
}

}  // namespace foldlab
