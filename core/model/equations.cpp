#include "core/model/equations.hpp"

#include "core/model/root_finding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace foldlab {
namespace {

constexpr double kPi = std::numbers::pi;

// K(m) and E(m) from m and its complement m1 = 1 - m, passed separately so that m close to 1 keeps
// its digits (the upper edge needs 1 - m = 1 / (1 + k²)).
EllipticKE elliptic_KE_complement(double m, double m1) {
  double a = 1.0;
  double b = std::sqrt(m1);
  double c2 = m;  // c_0² = m
  double weight = 0.5;
  double sum = weight * c2;
  for (int step = 0; step < 40; ++step) {
    const double c = 0.5 * (a - b);
    const double a_next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = a_next;
    weight *= 2.0;
    sum += weight * c * c;
    // c shrinks quadratically, c_next = c² / (4 a): once c <= 1e-9 a, later steps move a by less
    // than 1e-18 a. Waiting for c = 0, which rounding may never give, cost up to 40 steps.
    if (std::abs(c) <= 1e-9 * a) {
      break;
    }
  }
  const double K = kPi / (2.0 * a);
  return {K, K * (1.0 - sum)};
}

// The upper edge in units of the span: f(k) = (2/pi) ∫_0^{pi/2} sqrt(1 + k² sin²θ) dθ = L/l, with
// k = pi A / l, and its first two derivatives. Below k = 1e-2 the closed form loses digits to
// cancellation in f - 1 and f'; its Maclaurin series is exact there to ~1e-16.
struct EdgeRatio {
  double f_minus_1;
  double derivative;
  double second_derivative;
};

EdgeRatio edge_ratio(double k) {
  const double k2 = k * k;
  if (k < 1e-2) {
    // f = 1 + k²/4 - 3k⁴/64 + 5k⁶/256 - 175k⁸/16384 + ...
    const double f_minus_1 = k2 * (0.25 + k2 * (-3.0 / 64.0 + k2 * (5.0 / 256.0)));
    const double derivative = k * (0.5 + k2 * (-3.0 / 16.0 + k2 * (15.0 / 128.0)));
    const double second = 0.5 + k2 * (-9.0 / 16.0 + k2 * (75.0 / 128.0));
    return {f_minus_1, derivative, second};
  }
  const double one_plus_k2 = 1.0 + k2;
  const double root = std::sqrt(one_plus_k2);
  const EllipticKE ke = elliptic_KE_complement(k2 / one_plus_k2, 1.0 / one_plus_k2);
  // Imaginary-modulus transformation: E(-k²) = sqrt(1+k²) E(m), K(-k²) = K(m) / sqrt(1+k²).
  const double e_neg = root * ke.E;
  const double k_neg = ke.K / root;
  // The derivatives from dE/dm = (E - K)/(2m) and dK/dm = (E - (1-m) K)/(2m(1-m)) at m = -k².
  return {2.0 / kPi * e_neg - 1.0, 2.0 / kPi * (e_neg - k_neg) / k,
          2.0 / kPi * (e_neg / one_plus_k2 - (e_neg - k_neg) / k2)};
}

double edge_integrand(double amplitude_mm, double span_mm, double x_mm) {
  const double k = kPi * amplitude_mm / span_mm;
  const double s = std::sin(kPi * x_mm / span_mm);
  return std::sqrt(1.0 + k * k * s * s);
}

}  // namespace

EllipticKE elliptic_KE(double m) {
  return elliptic_KE_complement(m, 1.0 - m);
}

double elliptic_E(double m) {
  return elliptic_KE(m).E;
}

double stress_ratio(const Parameters& p, double K) {
  const double t = p.fabric.thickness_mm;
  const double l = span_mm(p);
  return K * p.fabric.youngs_modulus_MPa * t * t * t /
         (p.fabric.weight_N_per_mm2 * p.hanging.height_mm * l * l);
}

std::optional<double> wrinkle_ratio_from_stress_ratio(double s) {
  if (!(s < 1.0) || !(s >= 0.0)) {
    return std::nullopt;
  }
  // (1-s) Q² - (2+s) Q + 1 = 0; the larger root written without cancellation for every s in [0,1).
  return (2.0 + s + std::sqrt(s * (s + 8.0))) / (2.0 * (1.0 - s));
}

double upper_edge_length_closed_form(double amplitude_mm, double span_mm) {
  const double k = kPi * amplitude_mm / span_mm;
  return span_mm * (1.0 + edge_ratio(k).f_minus_1);
}

double upper_edge_length_simpson(double amplitude_mm, double span_mm, int intervals) {
  const int n = std::max(2, intervals + (intervals % 2));
  const double step = span_mm / n;
  const double x0 = -0.5 * span_mm;
  double sum = edge_integrand(amplitude_mm, span_mm, x0) +
               edge_integrand(amplitude_mm, span_mm, x0 + span_mm);
  for (int i = 1; i < n; ++i) {
    sum += (i % 2 == 1 ? 4.0 : 2.0) * edge_integrand(amplitude_mm, span_mm, x0 + i * step);
  }
  return sum * step / 3.0;
}

double upper_edge_length_trapezoid(double amplitude_mm, double span_mm, int intervals) {
  const int n = std::max(1, intervals);
  const double step = span_mm / n;
  const double x0 = -0.5 * span_mm;
  double sum = 0.5 * (edge_integrand(amplitude_mm, span_mm, x0) +
                      edge_integrand(amplitude_mm, span_mm, x0 + span_mm));
  for (int i = 1; i < n; ++i) {
    sum += edge_integrand(amplitude_mm, span_mm, x0 + i * step);
  }
  return sum * step;
}

double amplitude_for_upper_edge_length(double length_mm, double span_mm) {
  const double excess = length_mm / span_mm - 1.0;  // f(k) - 1 must equal this
  if (!(excess > 0.0)) {
    return 0.0;
  }
  const double r = 1.0 + excess;
  // Bounds on k: Jensen gives f <= sqrt(1 + k²/2), so k >= sqrt(2(r²-1)); f >= 2k/pi gives k <= pi
  // r/2.
  double lo = std::sqrt(2.0 * excess * (r + 1.0));
  double hi = std::max(lo, 0.5 * kPi * r);
  // Start from the inverted series k² = 4x + 3x² - x³/2 + O(x⁴) (x = f - 1) where it is close,
  // from the lower bound otherwise.
  double k = excess < 0.25 ? std::sqrt(excess * (4.0 + excess * (3.0 - 0.5 * excess))) : lo;
  k = std::clamp(k, lo, hi);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const EdgeRatio e = edge_ratio(k);
    const double g = e.f_minus_1 - excess;
    if (g == 0.0) {
      break;
    }
    if (g > 0.0) {
      hi = std::min(hi, k);
    } else {
      lo = std::max(lo, k);
    }
    // Halley's step: cubic convergence, and f, f' and f'' all come from one K, E pair.
    const double denominator = 2.0 * e.derivative * e.derivative - g * e.second_derivative;
    const double step = denominator > 0.0 ? -2.0 * g * e.derivative / denominator : 0.0;
    if (step != 0.0 && std::abs(step) <= 1e-6 * k) {
      // The error left after this step is about step³ / k² < 1e-18 k. Waiting for a smaller step
      // can take long: f - 1 carries a rounding error of about 1e-16, which puts a floor of about
      // 1e-16 / k² under the step for small k.
      k += step;
      break;
    }
    double next = k + step;
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
    }
    k = next;
  }
  return k * span_mm / kPi;
}

namespace {

// Sum of sqrt(delta_i² + b²) for i = first..last with delta_i = c exp(-beta i), by Euler-Maclaurin
// with the closed-form integral. The remainder after the third-derivative term is about
// 3e-5 beta^6 times the largest term: below 1e-16 of the sum for beta < 0.01.
double zigzag_sum_euler_maclaurin(double c, double beta, double b, int first, int last) {
  const double b2 = b * b;
  struct Point {
    double u, S, d1, d3;
  };
  auto at = [&](int i) {
    const double u = c * std::exp(-beta * i);
    const double g = u * u;
    const double S = std::sqrt(g + b2);
    const double S2 = S * S;
    const double d1 = -beta * g / S;
    const double d3 =
        -beta * beta * beta * g * (g * g + 2.0 * g * b2 + 4.0 * b2 * b2) / (S2 * S2 * S);
    return Point{u, S, d1, d3};
  };
  const Point p = at(first);
  const Point q = at(last);
  // ∫ sqrt(c² e^{-2 beta x} + b²) dx = (G(u_first) - G(u_last)) / beta with
  // G(u) = S - b ln((b + S)/u), written without the cancellation of the two logarithms:
  // ln(u_first/u_last) = beta (last - first).
  const double s_difference = (p.u - q.u) * (p.u + q.u) / (p.S + q.S);
  double integral = s_difference / beta;
  if (b > 0.0) {
    integral +=
        b * (static_cast<double>(last - first) - std::log1p(s_difference / (b + q.S)) / beta);
  }
  return integral + 0.5 * (p.S + q.S) + (q.d1 - p.d1) / 12.0 - (q.d3 - p.d3) / 720.0;
}

}  // namespace

double fibre_length(double a0_mm, double Q, int n, double z_max_mm) {
  const double b = 2.0 * z_max_mm;
  const double beta = std::log(Q);
  const double c = a0_mm * (Q - 1.0);  // delta_i = c Q^-i = a_{i-1} - a_i
  if (n > 64 && beta < 0.01 && beta > 0.0) {
    return zigzag_sum_euler_maclaurin(c, beta, b, 1, n);
  }
  const double shrink = 1.0 / Q;
  double difference = c * shrink;
  double sum = 0.0;
  for (int i = 1; i <= n; ++i) {
    // Once delta_i < 1e-5 b the remaining terms are b sqrt(1 + r²) with r < 1e-5: two terms of
    // that series, summed over the geometric sequence in closed form.
    if (n - i > 64 && difference < 1e-5 * b) {
      const double m = n - i + 1;
      const double r2 = difference * difference / (b * b);
      const double sum_r2 = std::expm1(-2.0 * beta * m) / std::expm1(-2.0 * beta);
      const double sum_r4 = std::expm1(-4.0 * beta * m) / std::expm1(-4.0 * beta);
      return sum + b * (m + 0.5 * r2 * sum_r2 - 0.125 * r2 * r2 * sum_r4);
    }
    sum += std::sqrt(difference * difference + b * b);
    difference *= shrink;
  }
  return sum;
}

double z_max_for_fibre_length(double a0_mm, double Q, int n, double height_mm) {
  const double drop = -a0_mm * std::expm1(-n * std::log(Q));  // sum of the a-differences
  if (drop >= height_mm) {
    return 0.0;
  }
  // The fibre length lies between max(drop, 2nz) and drop + 2nz, so (h - drop)/(2n) <= z <= h/(2n).
  const double lo = (height_mm - drop) / (2.0 * n);
  const double hi = height_mm / (2.0 * n);
  auto excess = [&](double z) { return fibre_length(a0_mm, Q, n, z) - height_mm; };
  return detail::brent_root(excess, lo, hi, excess(lo), excess(hi), 1e-15);
}

int wrinkle_count(double a0_over_an, double Q, bool round_to_nearest) {
  return wrinkle_count_from_logs(std::log(a0_over_an), std::log(Q), round_to_nearest);
}

int wrinkle_count_from_logs(double log_a0_over_an, double log_Q, bool round_to_nearest) {
  constexpr double kMax = 1e9;
  double x = log_a0_over_an / log_Q;
  if (!(x < kMax)) {
    x = kMax;  // Q so close to 1 (or a_0/a_n so large) that n exceeds what an int holds
  }
  const double count = round_to_nearest ? std::nearbyint(x) : std::floor(x * (1.0 + 1e-9));
  return std::max(1, static_cast<int>(count));
}

void fold_amplitudes(double a0_mm, double Q, int n, std::span<double> out) {
  double a = a0_mm;
  const double shrink = 1.0 / Q;
  for (int i = 0; i <= n && i < static_cast<int>(out.size()); ++i) {
    out[static_cast<std::size_t>(i)] = a;
    a *= shrink;
  }
}

}  // namespace foldlab
