#include "core/tools/stress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>

#include <nlohmann/json.hpp>

#include "core/geometry/geometry.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

constexpr std::size_t kMaxFailuresKept = 10;
// A busy machine can stall any one solve for milliseconds: the slowest few of each thread are
// timed again after the run, and the slowest case is the one whose best time is worst.
constexpr std::size_t kSlowCandidates = 32;

void keep_slow_candidate(std::vector<StressCase>& candidates, const StressCase& c) {
  candidates.push_back(c);
  std::sort(candidates.begin(), candidates.end(),
            [](const StressCase& a, const StressCase& b) { return a.seconds > b.seconds; });
  if (candidates.size() > kSlowCandidates) {
    candidates.pop_back();
  }
}

// The best of three timings of a case.
double best_time(const StressCase& c) {
  double best = 1e300;
  Parameters p = c.parameters;
  p.model.method = c.method;
  for (int i = 0; i < 3; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const Solution s = solve(p);
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (s.n < 0) {
      break;  // never: keeps the solve from being optimized away
    }
  }
  return best;
}

bool finite(double v) {
  return std::isfinite(v);
}

// Every number a solution reports.
bool all_finite(const Solution& s) {
  bool ok = finite(s.Q) && finite(s.stress_ratio) && finite(s.z_max_mm) && finite(s.span_mm) &&
            finite(s.sag_amplitude_mm) && finite(s.residual_length) && finite(s.residual_height) &&
            (!s.Q7 || finite(*s.Q7));
  for (double a : s.a_mm) {
    ok = ok && finite(a);
  }
  return ok;
}

bool all_finite(const DeformedGrid& g) {
  bool ok = finite(g.worst_fibre_error);
  for (const Eigen::Vector3f& v : g.positions_mm) {
    ok = ok && v.allFinite();
  }
  for (const Eigen::Vector3f& v : g.normals) {
    ok = ok && v.allFinite();
  }
  return ok;
}

void merge(MethodStress& into, const MethodStress& from) {
  for (const auto& [regime, count] : from.regimes) {
    into.regimes[regime] += count;
  }
  into.non_finite += from.non_finite;
  into.hangs += from.hangs;
  into.iteration_cap_hits += from.iteration_cap_hits;
  into.n_capped += from.n_capped;
  into.max_residual_length = std::max(into.max_residual_length, from.max_residual_length);
  into.max_residual_height = std::max(into.max_residual_height, from.max_residual_height);
  into.max_n = std::max(into.max_n, from.max_n);
  into.seconds += from.seconds;
  for (const StressCase& c : from.slow_candidates) {
    keep_slow_candidate(into.slow_candidates, c);
  }
}

void merge(StressReport& into, const StressReport& from) {
  merge(into.paper, from.paper);
  merge(into.exact, from.exact);
  into.n_cycles += from.n_cycles;
  into.grids += from.grids;
  into.grid_non_finite += from.grid_non_finite;
  into.worst_grid_fibre_error = std::max(into.worst_grid_fibre_error, from.worst_grid_fibre_error);
  into.worst_resolved_grid_fibre_error =
      std::max(into.worst_resolved_grid_fibre_error, from.worst_resolved_grid_fibre_error);
  for (const StressCase& c : from.failures) {
    if (into.failures.size() < kMaxFailuresKept) {
      into.failures.push_back(c);
    }
  }
}

// Samples [first, last) into `report`.
void run_range(const StressOptions& options, int first, int last, StressReport& report) {
  using Clock = std::chrono::steady_clock;
  for (int i = first; i < last; ++i) {
    Parameters p = stress_sample(options.seed, i);
    for (Method m : {Method::paper, Method::exact}) {
      p.model.method = m;
      MethodStress& stats = m == Method::paper ? report.paper : report.exact;
      const auto start = Clock::now();
      const Solution s = solve(p);
      const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      const StressCase here{p, m, seconds, s.n, s.regime};
      stats.seconds += seconds;
      ++stats.regimes[std::string(to_string(s.regime))];
      const bool ok = all_finite(s);
      // A solve over the bound counts as a hang only if it is that slow again (not a stall of the
      // machine); a real hang never returns for either timing.
      const bool hung = seconds > options.hang_seconds && best_time(here) > options.hang_seconds;
      stats.non_finite += !ok;
      stats.hangs += hung;
      if ((!ok || hung) && report.failures.size() < kMaxFailuresKept) {
        report.failures.push_back(here);
      }
      stats.iteration_cap_hits += s.hit_iteration_cap;
      stats.n_capped += s.n_capped;
      stats.max_n = std::max(stats.max_n, s.n);
      if (stats.slow_candidates.size() < kSlowCandidates ||
          seconds > stats.slow_candidates.back().seconds) {
        keep_slow_candidate(stats.slow_candidates, here);
      }
      if (m == Method::exact && s.regime == Regime::n_cycle) {
        ++report.n_cycles;
      }
      if (regime_info(s.regime).equations_hold) {
        stats.max_residual_length =
            std::max(stats.max_residual_length, std::abs(s.residual_length));
        stats.max_residual_height =
            std::max(stats.max_residual_height, std::abs(s.residual_height));
      }
      if (options.grid_every > 0 && i % options.grid_every == 0) {
        const DeformedGrid grid = deformed_grid(s, p, options.grid_nx, options.grid_ny);
        ++report.grids;
        if (!all_finite(grid)) {
          ++report.grid_non_finite;
          if (report.failures.size() < kMaxFailuresKept) {
            report.failures.push_back(here);
          }
        }
        report.worst_grid_fibre_error =
            std::max(report.worst_grid_fibre_error, grid.worst_fibre_error);
        if (options.grid_ny >= 4 * s.n) {
          report.worst_resolved_grid_fibre_error =
              std::max(report.worst_resolved_grid_fibre_error, grid.worst_fibre_error);
        }
      }
    }
  }
}

// The inputs the test draws (`sampled`), by the last part of their preset pointer:
// "thickness_mm".
nlohmann::json parameters_json(const Parameters& p) {
  nlohmann::json out = nlohmann::json::object();
  for (const InputSpec& spec : input_table()) {
    if (spec.sampled) {
      out[std::string(spec.preset.substr(spec.preset.rfind('/') + 1))] = *spec.value(p);
    }
  }
  return out;
}

nlohmann::json case_json(const StressCase& c) {
  return {{"method", to_string(c.method)},
          {"seconds", c.seconds},
          {"n", c.n},
          {"regime", to_string(c.regime)},
          {"inputs", parameters_json(c.parameters)}};
}

nlohmann::json method_json(const MethodStress& m) {
  return {{"regimes", m.regimes},
          {"non_finite", m.non_finite},
          {"hangs", m.hangs},
          {"iteration_cap_hits", m.iteration_cap_hits},
          {"n_capped", m.n_capped},
          {"max_residual_length", m.max_residual_length},
          {"max_residual_height", m.max_residual_height},
          {"max_n", m.max_n},
          {"solve_seconds", m.seconds},
          {"slowest", case_json(m.slowest)}};
}

// "wrinkled, stiff and n_cycle": the regimes whose residuals the test bounds.
std::string equations_hold_regimes() {
  std::vector<std::string_view> keys;
  for (const RegimeInfo& info : kRegimes) {
    if (info.equations_hold) {
      keys.push_back(info.key);
    }
  }
  std::string out;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == keys.size() ? " and " : ", ") + std::string(keys[i]);
  }
  return out;
}

// Each drawn input in full (shortest_number), so that a failure can be solved again with --set.
std::string describe_case(const StressCase& c) {
  char text[128];
  std::snprintf(text, sizeof text,
                "%s, %.3g ms, n = %d (%s):", std::string(to_string(c.method)).c_str(),
                1e3 * c.seconds, c.n, std::string(to_string(c.regime)).c_str());
  std::string out = text;
  const char* separator = " ";
  for (const InputSpec& spec : input_table()) {
    if (spec.sampled) {
      out += separator + std::string(spec.key) + " = " +
             detail::shortest_number(*spec.value(c.parameters)) +
             (spec.unit.empty() ? "" : " " + std::string(spec.unit));
      separator = ", ";
    }
  }
  return out;
}

}  // namespace

std::string stress_sampled_ranges() {
  std::string out;
  for (const InputSpec& spec : input_table()) {
    if (!spec.sampled) {
      continue;
    }
    out += (out.empty() ? "" : ", ") + std::string(spec.key) + " " +
           detail::shortest_number(spec.typical_lo) + " to " +
           detail::shortest_number(spec.typical_hi) +
           (spec.unit.empty() ? "" : " " + std::string(spec.unit));
    if (spec.upper_bound != nullptr) {
      out += " (below " + std::string(spec.upper_bound_name) + ")";
    }
  }
  return out;
}

Parameters stress_sample(std::uint64_t seed, int index) {
  // One generator per sample, seeded from (seed, index): a sample does not depend on which
  // thread draws it or on the samples before it.
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(index)};
  std::mt19937_64 random(sequence);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Every sampled row of the input table over its typical range (where the fabrics one meets
  // lie), in table order: log-uniformly when the range is positive (it spans decades of fabrics,
  // whatever the slider's scale), else uniformly. A row with an upper bound that follows from
  // others (d < L/2) is drawn below it, and unit() < 1 keeps it open. Every 100th sample puts rows
  // whose typical range starts at their closed valid end on that end (d = 0, nu = 0), an edge a
  // uniform draw never hits.
  Parameters p;
  for (const InputSpec& spec : input_table()) {
    if (!spec.sampled) {
      continue;
    }
    const double lo = spec.typical_lo;
    const std::optional<double> bound = spec.upper_bound ? spec.upper_bound(p) : std::nullopt;
    const double hi = bound ? std::min(spec.typical_hi, *bound) : spec.typical_hi;
    const double u = unit(random);
    const bool at_edge = index % 100 == 0 && lo == spec.valid.lo && !spec.valid.lo_open;
    const double value = at_edge    ? lo
                         : lo > 0.0 ? std::exp(std::log(lo) + u * (std::log(hi) - std::log(lo)))
                                    : lo + u * (hi - lo);
    spec.access.set(p, value);
  }
  // Every law by turns, each with its published constant.
  const std::span<const WrinkleLaw* const> laws = wrinkle_laws();
  const WrinkleLaw& law = *laws[static_cast<std::size_t>(index) % laws.size()];
  p.model.law = law.kind();
  p.model.load_constant_c = law.published_load_constant_c();
  return p;
}

StressReport run_stress(const StressOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  int threads = options.threads > 0
                    ? options.threads
                    : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::max(1, std::min(threads, options.samples));
  std::vector<StressReport> parts(static_cast<std::size_t>(threads));
  std::vector<std::thread> workers;
  const int samples = std::max(0, options.samples);
  for (int t = 0; t < threads; ++t) {
    const int first = static_cast<int>(static_cast<long long>(samples) * t / threads);
    const int last = static_cast<int>(static_cast<long long>(samples) * (t + 1) / threads);
    workers.emplace_back(run_range, std::cref(options), first, last,
                         std::ref(parts[static_cast<std::size_t>(t)]));
  }
  for (std::thread& w : workers) {
    w.join();
  }
  StressReport report;
  for (const StressReport& part : parts) {
    merge(report, part);
  }
  for (MethodStress* m : {&report.paper, &report.exact}) {
    for (StressCase& c : m->slow_candidates) {
      c.seconds = best_time(c);
      if (c.seconds >= m->slowest.seconds) {
        m->slowest = c;
      }
    }
  }
  report.samples = samples;
  report.seed = options.seed;
  report.threads = threads;
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

nlohmann::json stress_to_json(const StressReport& r) {
  nlohmann::json exact = method_json(r.exact);
  exact["n_cycles"] = r.n_cycles;
  nlohmann::json failures = nlohmann::json::array();
  for (const StressCase& c : r.failures) {
    failures.push_back(case_json(c));
  }
  return {{"samples", r.samples},
          {"seed", r.seed},
          {"threads", r.threads},
          {"wall_seconds", r.wall_seconds},
          {"passed", r.passed()},
          {"paper", method_json(r.paper)},
          {"exact", exact},
          {"grids",
           {{"built", r.grids},
            {"non_finite", r.grid_non_finite},
            {"worst_fibre_error", r.worst_grid_fibre_error},
            {"worst_resolved_fibre_error", r.worst_resolved_grid_fibre_error}}},
          {"failures", failures}};
}

std::string stress_table(const StressReport& r) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line,
                "FoldLab stress test: %d samples x 2 methods, seed %llu, %d threads, %.2f s\n\n",
                r.samples, static_cast<unsigned long long>(r.seed), r.threads, r.wall_seconds);
  out += line;
  std::vector<std::string> regimes;
  for (const MethodStress* m : {&r.paper, &r.exact}) {
    for (const auto& [name, count] : m->regimes) {
      if (std::find(regimes.begin(), regimes.end(), name) == regimes.end()) {
        regimes.push_back(name);
      }
    }
  }
  std::snprintf(line, sizeof line, "%-28s %14s %14s\n", "", "paper", "exact");
  out += line;
  auto count_row = [&](const std::string& label, int paper, int exact) {
    std::snprintf(line, sizeof line, "%-28s %14d %14d\n", label.c_str(), paper, exact);
    out += line;
  };
  auto number_row = [&](const std::string& label, double paper, double exact) {
    std::snprintf(line, sizeof line, "%-28s %14.3g %14.3g\n", label.c_str(), paper, exact);
    out += line;
  };
  for (const std::string& name : regimes) {
    auto get = [&name](const MethodStress& m) {
      const auto it = m.regimes.find(name);
      return it == m.regimes.end() ? 0 : it->second;
    };
    count_row("regime " + name, get(r.paper), get(r.exact));
  }
  count_row("NaN or inf in any output", r.paper.non_finite, r.exact.non_finite);
  count_row("hangs (solve > 1 s)", r.paper.hangs, r.exact.hangs);
  count_row("iteration cap hits", r.paper.iteration_cap_hits, r.exact.iteration_cap_hits);
  count_row("n capped at " + std::to_string(kMaxWrinkles), r.paper.n_capped, r.exact.n_capped);
  count_row("largest n", r.paper.max_n, r.exact.max_n);
  number_row("max |residual| eq. 8", r.paper.max_residual_length, r.exact.max_residual_length);
  number_row("max |residual| eq. 9", r.paper.max_residual_height, r.exact.max_residual_height);
  number_row("solve time total (s)", r.paper.seconds, r.exact.seconds);
  out += "  (residuals over " + equations_hold_regimes() +
         " solutions; the paper method stops at its\n   5% tolerance on eq. 8 by design)\n";
  std::snprintf(line, sizeof line,
                "\nexact method n cycles: %d\ngrids built: %d, non-finite: %d, worst fibre "
                "error %.3g (%.3g where ny >= 4n)\n",
                r.n_cycles, r.grids, r.grid_non_finite, r.worst_grid_fibre_error,
                r.worst_resolved_grid_fibre_error);
  out += line;
  out += "slowest paper solve: " + describe_case(r.paper.slowest) + "\n";
  out += "slowest exact solve: " + describe_case(r.exact.slowest) + "\n";
  for (const StressCase& c : r.failures) {
    out += "FAILED: " + describe_case(c) + "\n";
  }
  out += r.passed() ? "\nPASSED: no NaN, no inf, no hang\n" : "\nFAILED\n";
  return out;
}

}  // namespace foldlab
