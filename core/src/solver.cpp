#include "foldlab/solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "foldlab/equations.hpp"
#include "root_finding.hpp"

namespace foldlab {
namespace {

// The paper's initial guesses (MODEL.md): a_0 = 1.01 h, a_n = z_max = 0.01 h.
constexpr double kLowerBoundaryFactor = 1.01;
constexpr double kInitialGuessFactor = 0.01;

// What both methods share: the inputs reduced to the quantities the equations use.
struct Setup {
  double h;
  double L;
  double l;
  double a0;
  double sag;  // A(L, l)
  double s;
  std::optional<double> Q7;
  bool nearest;
};

Setup make_setup(const Parameters& p) {
  Setup u{};
  u.h = p.hanging.height_mm;
  u.L = p.hanging.length_mm;
  u.l = span_mm(p);
  u.a0 = kLowerBoundaryFactor * u.h;
  u.sag = amplitude_for_upper_edge_length(u.L, u.l);
  u.s = stress_ratio(stiffness_constant_K(p), p.fabric.youngs_modulus_MPa, p.fabric.thickness_mm,
                     p.fabric.weight_N_per_mm2, u.h, u.l);
  u.Q7 = wrinkle_ratio_from_stress_ratio(u.s);
  u.nearest = p.model.int_rounding == IntRounding::nearest;
  return u;
}

// n of eq. 10 for a given a_0/a_n; one fold when eq. 7 has no root (Q7 infinite).
int count_for(const Setup& u, double a0_over_an, bool& capped) {
  if (!u.Q7) {
    return 1;
  }
  const int n = wrinkle_count(a0_over_an, *u.Q7, u.nearest);
  capped = capped || n > kMaxWrinkles;
  return std::min(n, kMaxWrinkles);
}

// Fills n, Q, a_i, z_max and the residuals from a_n and z_max.
void finish(Solution& out, const Setup& u, int n, double an, double z) {
  out.n = n;
  out.Q = std::pow(u.a0 / an, 1.0 / n);
  out.z_max_mm = z;
  out.a_mm.assign(static_cast<std::size_t>(n) + 1, 0.0);
  fold_amplitudes(u.a0, out.Q, n, out.a_mm);
  out.a_mm.back() = an;
  out.residual_length = upper_edge_length_closed_form(std::hypot(an, z), u.l) / u.L - 1.0;
  out.residual_height = fibre_length(u.a0, out.Q, n, z) / u.h - 1.0;
}

// Regimes decided before any iteration; true when `out` is complete.
bool settle_degenerate(Solution& out, const Setup& u) {
  if (u.sag <= 0.0) {
    out.regime = Regime::no_slack;
    out.residual_length = u.l / u.L - 1.0;
    return true;
  }
  if (u.sag >= u.a0) {
    out.regime = Regime::short_cloth;
    return true;
  }
  if (u.sag <= kInitialGuessFactor * u.h) {
    // The nearest meaningful answer: flat folds (z = 0) with the upper edge carrying the whole sag.
    out.regime = Regime::negligible_slack;
    bool capped = false;
    finish(out, u, count_for(u, u.a0 / u.sag, capped), u.sag, 0.0);
    out.n_capped = capped;
    return true;
  }
  return false;
}

Solution start_solution(const Parameters& p, const Setup& u) {
  Solution out;
  out.method = p.model.method;
  out.Q7 = u.Q7;
  out.stress_ratio = u.s;
  out.span_mm = u.l;
  out.sag_amplitude_mm = u.sag;
  return out;
}

Solution solve_paper(const Parameters& p) {
  const Setup u = make_setup(p);
  Solution out = start_solution(p, u);
  if (settle_degenerate(out, u)) {
    return out;
  }
  const double an_floor = kInitialGuessFactor * u.h;
  double an = an_floor;
  double z = kInitialGuessFactor * u.h;
  int n = 1;
  bool capped = false;
  bool converged = false;
  int iteration = 0;
  while (iteration < p.model.max_iterations) {
    ++iteration;
    n = count_for(u, u.a0 / an, capped);
    const double Q = std::pow(u.a0 / an, 1.0 / n);
    z = z_max_for_fibre_length(u.a0, Q, n, u.h);
    const double length =
        upper_edge_length_simpson(std::hypot(an, z), u.l, p.model.simpson_intervals);
    if (std::abs(length / u.L - 1.0) <= p.model.length_tolerance) {
      converged = true;
      break;
    }
    an = std::sqrt(std::max(u.sag * u.sag - z * z, an_floor * an_floor));
  }
  out.regime = u.Q7 ? Regime::wrinkled : Regime::stiff;
  out.iterations = iteration;
  out.hit_iteration_cap = !converged;
  out.n_capped = capped;
  finish(out, u, n, an, z);
  return out;
}

// Exact method: for a given n, a_n in (0, A) with z² = A² - a_n² such that eq. 9 holds.
// F(a_n) = fibre length - h is positive as a_n -> 0 (a_0 > h) and equals 0.01 h - A < 0 at a_n = A,
// so a root is bracketed and Brent's method finds it.
double upper_amplitude_for_count(const Setup& u, int n) {
  const double A2 = u.sag * u.sag;
  auto F = [&](double an) {
    const double Q = std::exp(std::log(u.a0 / an) / n);
    return fibre_length(u.a0, Q, n, std::sqrt(std::max(0.0, A2 - an * an))) - u.h;
  };
  // Near a_n -> 0, Q blows up; start the bracket where Q^n = 1e12 (F is still positive there).
  const double lo = u.a0 * 1e-12 < u.sag ? u.a0 * 1e-12 : 0.5 * u.sag;
  const double hi = u.sag;
  return detail::brent_root(F, lo, hi, F(lo), F(hi), 1e-15);
}

Solution solve_exact(const Parameters& p) {
  const Setup u = make_setup(p);
  Solution out = start_solution(p, u);
  if (settle_degenerate(out, u)) {
    return out;
  }
  bool capped = false;
  if (!u.Q7) {
    out.regime = Regime::stiff;
    out.iterations = 1;
    const double an = upper_amplitude_for_count(u, 1);
    finish(out, u, 1, an, std::sqrt(u.sag * u.sag - an * an));
    return out;
  }
  // Fixed point of n -> Int[log(a_0/a_n(n)) / log Q7], starting from the paper's initial guess.
  struct Visit {
    int n;
    double an;
  };
  std::vector<Visit> visited;
  int n = count_for(u, 1.0 / kInitialGuessFactor * kLowerBoundaryFactor, capped);
  constexpr int kMaxSteps = 64;
  std::size_t chosen = 0;
  bool settled = false;
  for (int step = 0; step < kMaxSteps && !settled; ++step) {
    const double an = upper_amplitude_for_count(u, n);
    visited.push_back({n, an});
    const int next = count_for(u, u.a0 / an, capped);
    for (std::size_t i = 0; i < visited.size(); ++i) {
      if (visited[i].n != next) {
        continue;
      }
      settled = true;
      chosen = i;
      // A cycle: every visit from i on; report the smallest n among them.
      for (std::size_t j = i; j < visited.size(); ++j) {
        out.n_cycle.push_back(visited[j].n);
        if (visited[j].n < visited[chosen].n) {
          chosen = j;
        }
      }
      break;
    }
    n = next;
  }
  out.iterations = static_cast<int>(visited.size());
  if (!settled) {
    out.hit_iteration_cap = true;
    chosen = visited.size() - 1;
  }
  std::sort(out.n_cycle.begin(), out.n_cycle.end());
  if (out.n_cycle.size() <= 1) {
    out.n_cycle.clear();
    out.regime = Regime::wrinkled;
  } else {
    out.regime = Regime::n_cycle;
  }
  out.n_capped = capped;
  const Visit& v = visited[chosen];
  finish(out, u, v.n, v.an, std::sqrt(std::max(0.0, u.sag * u.sag - v.an * v.an)));
  return out;
}

std::string format(const char* pattern, double a, double b = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, a, b);
  return buffer;
}

}  // namespace

Solution solve(const Parameters& p) {
  return p.model.method == Method::paper ? solve_paper(p) : solve_exact(p);
}

std::string_view to_string(Regime r) {
  switch (r) {
    case Regime::wrinkled:
      return "wrinkled";
    case Regime::no_slack:
      return "no_slack";
    case Regime::stiff:
      return "stiff";
    case Regime::short_cloth:
      return "short_cloth";
    case Regime::negligible_slack:
      return "negligible_slack";
    case Regime::n_cycle:
      return "n_cycle";
  }
  return "unknown";
}

std::string describe(const Solution& s, const Parameters& p) {
  std::string text;
  switch (s.regime) {
    case Regime::wrinkled:
      break;
    case Regime::no_slack:
      text =
          "No slack: d = 0 so the supports span the whole upper edge (l = L); the cloth hangs "
          "flat.";
      break;
    case Regime::stiff:
      text = format(
          "Stiff: s = %.3g >= 1, eq. 7 has no root (buckling stress above the weight's); at most "
          "one fold.",
          s.stress_ratio);
      break;
    case Regime::short_cloth:
      text = format(
          "Short cloth: the upper edge needs a sag A = %.4g mm, more than a_0 = 1.01 h = %.4g mm; "
          "no folds fit.",
          s.sag_amplitude_mm, kLowerBoundaryFactor * p.hanging.height_mm);
      break;
    case Regime::negligible_slack:
      text = format(
          "Negligible slack: the sag A = %.3g mm is below 0.01 h = %.3g mm, so eq. 9 has no root; "
          "showing flat folds (z_max = 0) with a_n = A.",
          s.sag_amplitude_mm, kInitialGuessFactor * p.hanging.height_mm);
      break;
    case Regime::n_cycle: {
      text = "n cycles under eq. 10 between";
      for (int n : s.n_cycle) {
        text += ' ';
        text += std::to_string(n);
      }
      text += "; the smallest is reported.";
      break;
    }
  }
  auto append = [&text](const std::string& more) {
    if (!text.empty()) {
      text += ' ';
    }
    text += more;
  };
  if (s.hit_iteration_cap) {
    append(s.method == Method::paper
               ? format("The paper iteration stopped after %.0f iterations without reaching "
                        "|L'/L - 1| <= %.3g; the last iterate is shown.",
                        s.iterations, p.model.length_tolerance)
               : "The n iteration did not settle; the last n is shown.");
  }
  if (s.n_capped) {
    append(format("Eq. 10 asks for more than %.0f folds; n is capped there.", kMaxWrinkles));
  }
  return text;
}

}  // namespace foldlab
