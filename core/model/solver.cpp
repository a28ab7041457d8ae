#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "core/model/equations.hpp"
#include "core/model/root_finding.hpp"

namespace foldlab {
namespace {

// The paper's initial guesses: a_n = z_max = 0.01 h (a_0 = kLowerBoundaryFactor h).
constexpr double kInitialGuessFactor = 0.01;

// What both methods share: the inputs reduced to the quantities the equations use.
struct Setup {
  double h;
  double L;
  double l;
  double a0;
  double sag;  // A(L, l)
  double s;
  std::optional<double> Q7;  // Conci's law: the root of eq. 7
  // The law's count of eq. 10; none when it allows one fold at most (the stiff regime).
  std::optional<FoldCountRule> rule;
  bool nearest;
};

Setup make_setup(const Parameters& p) {
  Setup u{};
  u.h = p.hanging.height_mm;
  u.L = p.hanging.length_mm;
  u.l = span_mm(p);
  u.a0 = kLowerBoundaryFactor * u.h;
  u.sag = amplitude_for_upper_edge_length(u.L, u.l);
  u.s = stress_ratio(p, stiffness_constant_K(p));
  // The calibrated variant solves the law with s^p. p = 1, the printed form, skips pow so that
  // the paper's numbers stay bit for bit; Solution::stress_ratio reports s itself either way.
  const double exponent = p.model.stress_exponent_p;
  const double strength = exponent == 1.0 ? u.s : std::pow(u.s, exponent);
  u.rule = wrinkle_law(p.model.law).count_rule(strength, u.l);
  if (u.rule && u.rule->spacing == FoldSpacing::geometric) {
    u.Q7 = u.rule->ratio;
  }
  u.nearest = p.model.int_rounding == IntRounding::nearest;
  return u;
}

// n of eq. 10 at a_n; one fold when the law allows no more (Conci: eq. 7 has no root).
int count_for(const Setup& u, double an, bool& capped) {
  if (!u.rule) {
    return 1;
  }
  const int n = u.rule->count(u.a0, an, u.nearest);
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
    finish(out, u, count_for(u, u.sag, capped), u.sag, 0.0);
    out.n_capped = capped;
    return true;
  }
  return false;
}

Solution start_solution(const Parameters& p, const Setup& u) {
  Solution out;
  out.method = p.model.method;
  out.Q7 = u.Q7;
  out.count_rule = u.rule;
  out.stress_ratio = u.s;
  out.span_mm = u.l;
  out.sag_amplitude_mm = u.sag;
  return out;
}

// The argument of eq. 10's Int[] under the law; 0 when it counts no folds.
double count_argument(const Setup& u, double an) {
  return u.rule ? u.rule->argument(u.a0, an) : 0.0;
}

// `trace`, when given, receives every iterate; the loop computes nothing more without it.
Solution solve_paper(const Parameters& p, std::vector<Iterate>* trace = nullptr) {
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
    n = count_for(u, an, capped);
    const double Q = std::pow(u.a0 / an, 1.0 / n);
    z = z_max_for_fibre_length(u.a0, Q, n, u.h);
    const double amplitude = std::hypot(an, z);
    const double length =
        p.model.length_quadrature == LengthQuadrature::simpson
            ? upper_edge_length_simpson(amplitude, u.l, p.model.simpson_intervals)
            : upper_edge_length_trapezoid(amplitude, u.l, p.model.simpson_intervals);
    if (trace != nullptr) {
      if (!trace->empty()) {
        trace->back().next_n = n;
      }
      trace->push_back({n, Q, an, z, length / u.L, count_argument(u, an), n});
    }
    if (std::abs(length / u.L - 1.0) <= p.model.length_tolerance) {
      converged = true;
      break;
    }
    an = std::sqrt(std::max(u.sag * u.sag - z * z, an_floor * an_floor));
  }
  out.regime = u.rule ? Regime::wrinkled : Regime::stiff;
  out.iterations = iteration;
  out.hit_iteration_cap = !converged;
  out.stopped_at_first_iterate = converged && iteration == 1;
  out.n_capped = capped;
  finish(out, u, n, an, z);
  return out;
}

// Exact method. For one n, eq. 8 leaves one degree of freedom on the circle a_n² + z² = A²; its
// angle theta (a_n = A cos theta, z = A sin theta) is the unknown of eq. 9: a_n alone would lose
// z's digits where z << A (z = sqrt(A² - a_n²) cancels), and z alone a_n's where a_n << A.
struct UpperFold {
  double an;
  double z;
};

UpperFold on_circle(const Setup& u, double theta) {
  return {u.sag * std::cos(theta), u.sag * std::sin(theta)};
}

double angle(const UpperFold& f) {
  return std::atan2(f.z, f.an);
}

// Eq. 9's fibre length minus h at (a_n, z) with Q = (a_0/a_n)^(1/n) formed as finish() forms it,
// so that the reported residual is that of the root found.
double fibre_excess(const Setup& u, int n, const UpperFold& f) {
  return fibre_length(u.a0, std::pow(u.a0 / f.an, 1.0 / n), n, f.z) - u.h;
}

// The same with its slope in theta, summed term by term.
struct ExcessAndSlope {
  double value;
  double slope;
};

ExcessAndSlope fibre_excess_and_slope(const Setup& u, int n, const UpperFold& f) {
  const double Q = std::pow(u.a0 / f.an, 1.0 / n);
  const double shrink = 1.0 / Q;
  const double b2 = 4.0 * f.z * f.z;
  double difference = u.a0 * (Q - 1.0) * shrink;  // a_{i-1} - a_i for i = 1, as fibre_length
  double a_i = u.a0;
  double sum = 0.0;
  double sum_inverse = 0.0;
  double sum_shift = 0.0;
  for (int i = 1; i <= n; ++i) {
    a_i *= shrink;
    const double S = std::sqrt(difference * difference + b2);
    const double inverse = 1.0 / S;
    sum += S;
    sum_inverse += inverse;
    // a_i = a_0^(1-i/n) a_n^(i/n): d(a_{i-1} - a_i)/da_n = ((i-1)(a_{i-1} - a_i) - a_i) / (n a_n).
    sum_shift += difference * ((i - 1) * difference - a_i) * inverse;
    difference *= shrink;
  }
  const double dF_dan = sum_shift / (n * f.an);
  const double dF_dz = 4.0 * f.z * sum_inverse;
  // da_n/dtheta = -z, dz/dtheta = a_n.
  return {sum - u.h, -f.z * dF_dan + f.an * dF_dz};
}

constexpr int kDirectSumMax = 64;

// Int[] of eq. 10 at a_n, with every count above the cap merged into kMaxWrinkles + 1.
int count_at(const Setup& u, double an) {
  return std::min(u.rule->count(u.a0, an, u.nearest), kMaxWrinkles + 1);
}

// The a_n at the lower edge of count c's cell, where Int[x] of eq. 10 changes from c - 1 to c.
double cell_edge_an(const Setup& u, int c) {
  // wrinkle_count rounds x to nearest, or floors x (1 + 1e-9) (its guard against x = n - 1 ulp).
  const double x = u.nearest ? c - 0.5 : c / (1.0 + 1e-9);
  return u.rule->amplitude_at(u.a0, x);
}

// The root of eq. 9 for one n, inside a bracket that tightens as it is used. The fixed-point
// iteration over n needs only eq. 10's Int[] at the root, and one sign test of eq. 9 at
// the a_n where Int[] changes tells on which side of it the root lies: most visits of n are
// decided by 0-2 such tests, and only the n reported is solved to full precision.
class CountRoot {
 public:
  // The bracket comes from two closed forms around eq. 9: Minkowski's inequality gives
  // sum sqrt(delta_i² + 4z²) >= sqrt((a_0 - a_n)² + (2nz)²) and the triangle inequality gives
  // <= (a_0 - a_n) + 2nz. The fibre length falls as a_n grows along the circle, so the a_n that
  // make these equal to h bound the root from below and from above. Each z comes from its own
  // equation, not from sqrt(A² - a_n²), so that the angles keep their digits.
  CountRoot(const Setup& u, int n) : u_(&u), n_(n) {
    const double h = u.h;
    const double e = u.a0 - h;  // 0.01 h
    const double A = u.sag;
    const double nn = static_cast<double>(n) * n;
    const double C = u.a0 * u.a0 + 4.0 * nn * A * A - h * h;
    const double an_min = C / (u.a0 + std::sqrt(u.a0 * u.a0 + (4.0 * nn - 1.0) * C));
    const double an_max =
        (e + 2.0 * n * std::sqrt((4.0 * nn + 1.0) * A * A - e * e)) / (4.0 * nn + 1.0);
    // (a_0 - a_n)² + (2nz)² = h² and (a_0 - a_n) + 2nz = h respectively.
    const double z_at_min =
        std::sqrt(std::max(0.0, (an_min - e) * (h + u.a0 - an_min))) / (2.0 * n);
    const double z_at_max = std::max(0.0, an_max - e) / (2.0 * n);
    // theta grows as a_n falls.
    lo_ = {an_max, z_at_max};
    hi_ = {an_min, z_at_min};
  }

  // Int[] of eq. 10 at the root, capped as count_at().
  int count() {
    if (solved_) {
      return count_at(*u_, root_.an);
    }
    // a_n falls as theta grows, so the count grows with theta.
    int c_min = count_at(*u_, lo_.an);
    int c_max = count_at(*u_, hi_.an);
    while (c_min < c_max) {
      const int c = c_min + (c_max - c_min + 1) / 2;
      const double an = std::max(hi_.an, std::min(lo_.an, cell_edge_an(*u_, c)));
      const UpperFold edge{an, std::sqrt(std::max(0.0, (u_->sag - an) * (u_->sag + an)))};
      if (fibre_excess(*u_, n_, edge) <= 0.0) {  // the root lies at or beyond the edge
        lo_ = edge;
        c_min = c;
      } else {
        hi_ = edge;
        c_max = c - 1;
      }
    }
    return c_min;
  }

  UpperFold solve() {
    if (solved_) {
      return root_;
    }
    solved_ = true;
    // Widened by far more than the rounding of the bounds' closed forms.
    double lo = std::max(0.0, angle(lo_) * (1.0 - 1e-9));
    double hi = std::min(0.5 * std::numbers::pi, angle(hi_) * (1.0 + 1e-9));
    // fibre_length sums term by term for n <= 64 and for steep progressions (log Q >= 0.01);
    // otherwise its sums are O(1) and the root is found from values alone.
    if (n_ > kDirectSumMax && std::log(u_->a0 / lo_.an) < 0.01 * n_) {
      auto F = [&](double theta) { return fibre_excess(*u_, n_, on_circle(*u_, theta)); };
      root_ = on_circle(*u_, detail::brent_root(F, lo, hi, F(lo), F(hi), 1e-15));
      return root_;
    }
    // Safeguarded Newton from near the Minkowski end, where the root sits (exactly on it for
    // n = 1, where the inequality is an equality).
    double theta = hi;
    double previous_theta = -1.0;  // none yet
    double previous_slope = 0.0;
    if (n_ > 1) {
      theta = std::clamp(theta - spread_correction(), lo, hi);
    }
    for (int iteration = 0; iteration < 200; ++iteration) {
      const ExcessAndSlope e = fibre_excess_and_slope(*u_, n_, on_circle(*u_, theta));
      if (e.value == 0.0) {
        break;
      }
      (e.value < 0.0 ? lo : hi) = theta;  // the excess grows with theta
      const double step = -e.value / e.slope;
      if (previous_theta >= 0.0 && std::abs(step) <= 1e-6 * theta) {
        // Close enough for one Halley step with the curvature from the last two slopes: it
        // leaves an error of about (curvature's error) x step², below 1e-15 theta, and saves
        // the Newton step that would bring 1e-12 to 1e-24 (measured: the same agreement with
        // the long-double references, 12 % fewer evaluations).
        const double curvature = (e.slope - previous_slope) / (theta - previous_theta);
        const double denominator = 2.0 * e.slope * e.slope - e.value * curvature;
        theta += denominator > 0.0 ? -2.0 * e.value * e.slope / denominator : step;
        break;
      }
      previous_theta = theta;
      previous_slope = e.slope;
      if (std::abs(step) <= 1e-9 * theta) {
        // Quadratic convergence: after a step this small the error is below rounding.
        theta += step;
        break;
      }
      theta = (theta + step > lo && theta + step < hi) ? theta + step : 0.5 * (lo + hi);
      if (hi - lo <= 4e-16 * theta) {
        break;
      }
    }
    root_ = on_circle(*u_, theta);
    return root_;
  }

 private:
  // Minkowski's bound treats the a-differences as equal. To second order in their spread,
  // sum f(delta_i) = n f(mean) + f''(mean)/2 sum (delta_i - mean)² with f = sqrt(delta² + 4z²),
  // and n f(mean) is Minkowski's sqrt((a_0 - a_n)² + (2nz)²). One Newton step on that model from
  // hi_ moves the start about as far as a Newton step on eq. 9 would (4.1 -> 3.3 evaluations).
  double spread_correction() const {
    const UpperFold& m = hi_;
    const double D = u_->a0 - m.an;
    const double b = 2.0 * m.z;
    const double mean = D / n_;
    const double q = std::pow(m.an / u_->a0, 1.0 / n_);  // 1/Q
    const double first = u_->a0 * (1.0 - q);
    const double ratio = m.an / u_->a0;  // q^n
    const double sum_of_squares = first * first * (1.0 - ratio * ratio) / (1.0 - q * q);
    const double S2 = mean * mean + b * b;
    const double spread = 0.5 * b * b / (S2 * std::sqrt(S2)) * (sum_of_squares - D * mean);
    const double M = std::sqrt(D * D + n_ * n_ * b * b);  // = h while hi_ is Minkowski's bound
    const double slope = (D * m.z + 4.0 * n_ * n_ * m.z * m.an) / M;  // dM/dtheta
    return slope > 0.0 ? (M - u_->h + spread) / slope : 0.0;
  }

  const Setup* u_;
  int n_;
  UpperFold lo_{};  // the root's theta is at or above lo_'s, at or below hi_'s
  UpperFold hi_{};
  bool solved_ = false;
  UpperFold root_{};
};

// The iterate of the exact method at n, whose a_n and z_max are the root of eqs. 8 and 9.
Iterate exact_iterate(const Setup& u, int n, const UpperFold& f, int next) {
  const double Q = std::pow(u.a0 / f.an, 1.0 / n);
  const double length = upper_edge_length_closed_form(std::hypot(f.an, f.z), u.l);
  return {n, Q, f.an, f.z, length / u.L, count_argument(u, f.an), next};
}

Solution solve_exact(const Parameters& p, std::vector<Iterate>* trace = nullptr) {
  const Setup u = make_setup(p);
  Solution out = start_solution(p, u);
  if (settle_degenerate(out, u)) {
    return out;
  }
  if (!u.rule) {
    out.regime = Regime::stiff;
    out.iterations = 1;
    const UpperFold f = CountRoot(u, 1).solve();
    finish(out, u, 1, f.an, f.z);
    if (trace != nullptr) {
      trace->push_back(exact_iterate(u, 1, f, 1));
    }
    return out;
  }
  // Fixed point of n -> eq. 10's Int[] at a_n(n), starting from the paper's initial guess.
  bool capped = false;
  constexpr int kMaxSteps = 64;
  std::array<int, kMaxSteps> visited{};
  int visits = 0;
  std::optional<CountRoot> last;  // the latest visit's bracket: usually the n reported
  int n = count_for(u, kInitialGuessFactor * u.h, capped);
  int chosen = 0;
  bool settled = false;
  while (visits < kMaxSteps && !settled) {
    visited[static_cast<std::size_t>(visits++)] = n;
    last.emplace(u, n);
    int next = last->count();
    if (next > kMaxWrinkles) {
      capped = true;
      next = kMaxWrinkles;
    }
    if (trace != nullptr) {
      // Solving after count() only narrows the bracket count() left: the reported root is the same.
      trace->push_back(exact_iterate(u, n, last->solve(), next));
    }
    for (int i = 0; i < visits && !settled; ++i) {
      if (visited[static_cast<std::size_t>(i)] != next) {
        continue;
      }
      settled = true;
      chosen = i;
      // A cycle: every visit from i on; report the smallest n among them.
      for (int j = i; j < visits; ++j) {
        if (visits - i > 1) {
          out.n_cycle.push_back(visited[static_cast<std::size_t>(j)]);
        }
        if (visited[static_cast<std::size_t>(j)] < visited[static_cast<std::size_t>(chosen)]) {
          chosen = j;
        }
      }
    }
    n = next;
  }
  out.iterations = visits;
  if (!settled) {
    out.hit_iteration_cap = true;
    chosen = visits - 1;
  }
  std::sort(out.n_cycle.begin(), out.n_cycle.end());
  out.regime = out.n_cycle.empty() ? Regime::wrinkled : Regime::n_cycle;
  out.n_capped = capped;
  const int n_reported = visited[static_cast<std::size_t>(chosen)];
  const UpperFold fold = chosen == visits - 1 ? last->solve() : CountRoot(u, n_reported).solve();
  finish(out, u, n_reported, fold.an, fold.z);
  return out;
}

using detail::printf_string;
using detail::shortest_number;

}  // namespace

Solution solve(const Parameters& p) {
  return p.model.method == Method::paper ? solve_paper(p) : solve_exact(p);
}

IterationTrace trace_iterations(const Parameters& p) {
  IterationTrace trace;
  trace.solution = p.model.method == Method::paper ? solve_paper(p, &trace.iterates)
                                                   : solve_exact(p, &trace.iterates);
  return trace;
}

std::vector<CountMapPoint> count_map(const Parameters& p, int n_from, int n_to) {
  std::vector<CountMapPoint> out;
  const Setup u = make_setup(p);
  Solution probe;
  if (!u.rule || settle_degenerate(probe, u)) {
    return out;
  }
  for (int n = std::max(1, n_from); n <= std::min(n_to, kMaxWrinkles); ++n) {
    CountRoot root(u, n);
    const int count = root.count();
    out.push_back({n, count_argument(u, root.solve().an), count});
  }
  return out;
}

FoldSummary fold_summary(const Solution& s) {
  return {.n = s.n, .Q = s.Q, .z_max_mm = s.z_max_mm, .regime = s.regime, .n_capped = s.n_capped};
}

const RegimeInfo& regime_info(Regime r) {
  for (const RegimeInfo& info : kRegimes) {
    if (info.regime == r) {
      return info;
    }
  }
  throw std::logic_error("a regime missing from kRegimes");
}

std::string_view to_string(Regime r) {
  return regime_info(r).key;
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
      // Eq. 7 sees s^p: with p != 1 that, not s, is what reached 1.
      text = p.model.stress_exponent_p == 1.0
                 ? printf_string("Stiff: s = %.3g >= 1", s.stress_ratio)
                 : printf_string("Stiff: s^p = %.3g^%s = %.3g >= 1", s.stress_ratio,
                                 shortest_number(p.model.stress_exponent_p).c_str(),
                                 std::pow(s.stress_ratio, p.model.stress_exponent_p));
      text += ", eq. 7 has no root (buckling stress above the weight's); at most one fold.";
      break;
    case Regime::short_cloth:
      text = printf_string(
          "Short cloth: the upper edge needs a sag A = %.4g mm, more than a_0 = 1.01 h = %.4g mm; "
          "no folds fit.",
          s.sag_amplitude_mm, kLowerBoundaryFactor * p.hanging.height_mm);
      break;
    case Regime::negligible_slack:
      text = printf_string(
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
               ? printf_string("The paper iteration stopped after %d iterations without reaching "
                               "|L'/L - 1| <= %.3g; the last iterate is shown and its z_max is "
                               "not a prediction.",
                               s.iterations, p.model.length_tolerance)
               : "The n iteration did not settle; the last n is shown.");
  }
  if (s.stopped_at_first_iterate) {
    append(printf_string(
        "The paper iteration stopped at its first iterate: the initial guess a_n = 0.01 h already "
        "meets |L'/L - 1| <= %.3g, so z_max is eq. 9 at that guess, not a prediction (the exact "
        "method solves eq. 8).",
        p.model.length_tolerance));
  }
  if (s.n_capped) {
    append(printf_string("Eq. 10 asks for more than %d folds; n is capped there.", kMaxWrinkles));
  }
  return text;
}

}  // namespace foldlab
