// Equations 7-10 against closed forms, published constants and an independent quadrature.
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/io/preset.hpp"
#include "core/model/equations.hpp"
#include "core/model/solver.hpp"

namespace foldlab {
namespace {

constexpr long double kPiL = std::numbers::pi_v<long double>;

// Independent reference: Gauss-Legendre-free, long-double composite trapezoid over a whole period
// of a smooth periodic integrand (exponentially convergent), written here and not in the library.
long double periodic_trapezoid(long double (*f)(long double, long double), long double param,
                               int points) {
  long double sum = 0.0L;
  for (int i = 0; i < points; ++i) {
    sum += f(2.0L * kPiL * i / points, param);
  }
  return sum * 2.0L * kPiL / points;
}

// ∫_0^{2pi} sqrt(1 - m sin²θ) dθ = 4 E(m).
long double e_integrand(long double theta, long double m) {
  const long double s = std::sin(theta);
  return std::sqrt(1.0L - m * s * s);
}

TEST(EllipticIntegral, MatchesPublishedValues) {
  // Abramowitz & Stegun, Table 17.1 / DLMF 19.6: E(0) = pi/2, E(1/2), K(1/2) to 16 digits.
  EXPECT_NEAR(elliptic_E(0.0), std::numbers::pi / 2, 1e-16);
  EXPECT_NEAR(elliptic_E(0.5), 1.3506438810476755, 4.5e-16);  // 2 ulp
  EXPECT_NEAR(elliptic_KE(0.5).K, 1.8540746773013719, 4e-16);
  EXPECT_NEAR(elliptic_E(1.0 - 1e-12), 1.0, 1e-10);  // E(1) = 1, approached from below
}

TEST(EllipticIntegral, MatchesIndependentQuadratureTo1e13) {
  for (double m : {0.0, 1e-8, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.95, 0.99}) {
    const long double reference = periodic_trapezoid(e_integrand, m, 4096) / 4.0L;
    EXPECT_NEAR(elliptic_E(m), static_cast<double>(reference),
                1e-13 * static_cast<double>(reference))
        << "m = " << m;
  }
}

// Integrand of eq. 8 over a whole period of its square: with theta = pi x / l over [-pi/2, pi/2],
// sqrt(1 + k² sin²θ) has period pi, so the trapezoid over [0, 2pi) gives 2x the span integral.
long double edge_integrand(long double theta, long double k) {
  const long double s = std::sin(theta);
  return std::sqrt(1.0L + k * k * s * s);
}

long double reference_edge_length(double amplitude_mm, double span_mm) {
  const long double k = kPiL * amplitude_mm / span_mm;
  // L = (l/pi) ∫_{-pi/2}^{pi/2} ... = (l/pi) * (1/2) ∫_0^{2pi} ...
  return span_mm / kPiL * 0.5L * periodic_trapezoid(edge_integrand, k, 8192);
}

TEST(UpperEdgeLength, ClosedFormMatchesIndependentQuadratureTo1e13) {
  const double span = 1300.0;
  for (double amplitude : {0.0, 1e-3, 1.0, 10.0, 100.0, 236.0, 500.0, 1300.0, 5000.0, 40000.0}) {
    const double reference = static_cast<double>(reference_edge_length(amplitude, span));
    EXPECT_NEAR(upper_edge_length_closed_form(amplitude, span), reference, 1e-13 * reference)
        << "A = " << amplitude;
  }
}

TEST(UpperEdgeLength, SmallAmplitudeFollowsTheSeries) {
  // L/l = 1 + k²/4 - 3k⁴/64 + ... : for k = 1e-4 the first term is exact to 1e-16.
  const double span = 1000.0;
  const double amplitude = 1e-4 * span / std::numbers::pi;
  const double excess = upper_edge_length_closed_form(amplitude, span) / span - 1.0;
  // L/l - 1 is formed from L/l ≈ 1, so it carries an absolute rounding error of a few 1e-16.
  EXPECT_NEAR(excess, 0.25e-8, 4.5e-16);
}

TEST(UpperEdgeLength, SimpsonAndTrapezoidConvergeToTheClosedForm) {
  const double span = 1300.0;
  const double amplitude = 236.0;  // A(L = 1400, l = 1300): the default preset
  const double exact = upper_edge_length_closed_form(amplitude, span);
  double previous_error = 1.0;
  for (int n : {4, 8, 16, 32}) {
    const double error = std::abs(upper_edge_length_simpson(amplitude, span, n) / exact - 1.0);
    EXPECT_LT(error, previous_error) << "N = " << n;
    previous_error = error;
  }
  EXPECT_LT(std::abs(upper_edge_length_simpson(amplitude, span, 64) / exact - 1.0), 1e-12);
  // The integrand is smooth and periodic: at equal N the trapezoid rule beats Simpson.
  for (int n : {4, 8, 16, 20}) {
    EXPECT_LT(std::abs(upper_edge_length_trapezoid(amplitude, span, n) / exact - 1.0),
              std::abs(upper_edge_length_simpson(amplitude, span, n) / exact - 1.0))
        << "N = " << n;
  }
}

TEST(UpperEdgeLength, SimpsonWithTwoIntervalsByHand) {
  // Two panels over [-l/2, l/2] sample the integrand at the supports, sqrt(1 + k²), and at the
  // centre, 1: L' = (l/6) (2 sqrt(1 + k²) + 4).
  const double span = 1300.0;
  const double amplitude = 236.0;
  const double k = std::numbers::pi * amplitude / span;
  const double by_hand = span / 6.0 * (2.0 * std::sqrt(1.0 + k * k) + 4.0);
  EXPECT_NEAR(upper_edge_length_simpson(amplitude, span, 2), by_hand, 1e-9);
  // Simpson with N = 2 under-estimates L' by about 3 % (here -2.5 %).
  EXPECT_NEAR(by_hand / upper_edge_length_closed_form(amplitude, span) - 1.0, -0.025, 0.005);
}

TEST(UpperEdgeAmplitude, InvertsTheClosedForm) {
  const double span = 1300.0;
  for (double ratio :
       {1.0 + 1e-12, 1.0 + 1e-9, 1.0 + 1e-6, 1.0001, 1.01, 1.0769, 1.5, 2.0, 10.0, 100.0}) {
    const double length = ratio * span;
    const double amplitude = amplitude_for_upper_edge_length(length, span);
    EXPECT_GT(amplitude, 0.0);
    EXPECT_NEAR(upper_edge_length_closed_form(amplitude, span) / length - 1.0, 0.0, 1e-14)
        << "L/l = " << ratio;
  }
  EXPECT_EQ(amplitude_for_upper_edge_length(span, span), 0.0);
  // Tiny slack: L/l - 1 = k²/4, so A = (l/pi) 2 sqrt(L/l - 1) to first order.
  const double excess = 1e-10;
  EXPECT_NEAR(amplitude_for_upper_edge_length(span * (1.0 + excess), span),
              span / std::numbers::pi * 2.0 * std::sqrt(excess), 1e-9);
}

TEST(Eq7, RootSatisfiesTheQuadratic) {
  for (double s : {1e-12, 1e-8, 1e-4, 0.01, 0.0284, 0.1, 0.5, 0.9, 0.999999}) {
    const auto Q = wrinkle_ratio_from_stress_ratio(s);
    ASSERT_TRUE(Q.has_value()) << "s = " << s;
    EXPECT_GT(*Q, 1.0);
    // (Q-1)² = s Q (Q+1), checked as a relative residual.
    // Q - 1 formed in the test from Q ≈ 1 keeps only eps/(Q-1) relative accuracy.
    const double lhs = (*Q - 1.0) * (*Q - 1.0);
    const double rhs = s * *Q * (*Q + 1.0);
    const double tolerance = 1e-13 + 4.0 * 2.3e-16 / (*Q - 1.0);
    EXPECT_NEAR(lhs, rhs, tolerance * rhs) << "s = " << s;
  }
}

TEST(Eq7, PaperRatioFromItsStressRatio) {
  // Table 1 prints Q = 1.29; the s that gives it by eq. 7 is (Q-1)²/(Q(Q+1)), computed by hand.
  const double Q = 1.29;
  const double s = (Q - 1.0) * (Q - 1.0) / (Q * (Q + 1.0));
  EXPECT_NEAR(*wrinkle_ratio_from_stress_ratio(s), 1.29, 1e-12);
  // Small s: Q ≈ 1 + sqrt(2s).
  EXPECT_NEAR(*wrinkle_ratio_from_stress_ratio(1e-10), 1.0 + std::sqrt(2e-10), 1e-9);
}

TEST(Eq7, NoRootAtOrAboveOne) {
  EXPECT_FALSE(wrinkle_ratio_from_stress_ratio(1.0).has_value());
  EXPECT_FALSE(wrinkle_ratio_from_stress_ratio(3.0).has_value());
  EXPECT_FALSE(wrinkle_ratio_from_stress_ratio(std::nan("")).has_value());
  EXPECT_DOUBLE_EQ(*wrinkle_ratio_from_stress_ratio(0.0), 1.0);
}

// Eq. 7 as the paper writes it, sigma_cr = c E t² / (l² (1 - nu²)) and s = sigma_cr t / (w h),
// evaluated here in SI units (Pa, m, N/m²) from c and nu, against the library's one formula in mm
// and MPa from K = c / (1 - nu²): a slipped unit or power on either side shows. Table 1's
// h = 1400 mm row (c = 26.9, nu = 0.3, l = L - d = 1300 mm), worked on paper: s = 0.02147.
TEST(Eq7, StressRatioAgreesWithThePapersCriticalStressInSIUnits) {
  const double c = 26.9;
  const double nu = 0.3;
  const double E_Pa = 165e6;
  const double t_m = 0.25e-3;
  const double l_m = 1.3;
  const double w_N_per_m2 = 1.5;  // 1.5e-6 N/mm²
  const double h_m = 1.4;
  const double sigma_cr_Pa = c * E_Pa * t_m * t_m / (l_m * l_m * (1.0 - nu * nu));
  const double s_si = sigma_cr_Pa * t_m / (w_N_per_m2 * h_m);
  EXPECT_NEAR(s_si, 0.02147, 5e-6);
  const Parameters p =
      load_preset(std::filesystem::path(FOLDLAB_PRESETS_DIR) / "paper-table1-h1400.json")
          .parameters;
  EXPECT_NEAR(stress_ratio(p, c / (1.0 - nu * nu)), s_si, 1e-12 * s_si);

  // The preset of that row solves with this s, and its Q7 makes eq. 7's left-hand side,
  // w h (Q - 1)² / (t Q (Q + 1)), the critical stress in Pa.
  const Solution solution = solve(p);
  EXPECT_NEAR(solution.stress_ratio, s_si, 1e-12 * s_si);
  ASSERT_TRUE(solution.Q7.has_value());
  const double Q = *solution.Q7;
  EXPECT_NEAR(w_N_per_m2 * h_m * (Q - 1.0) * (Q - 1.0) / (t_m * Q * (Q + 1.0)), sigma_cr_Pa,
              1e-10 * sigma_cr_Pa);
}

TEST(Eq9, FibreLengthOfOneFoldIsTheHypotenuse) {
  const double a0 = 1010.0;
  const double Q = 2.0;
  EXPECT_NEAR(fibre_length(a0, Q, 1, 30.0), std::hypot(505.0, 60.0), 1e-12);
  // z = 0: the fibre is the sum of the a-differences, a_0 (1 - Q^-n).
  EXPECT_NEAR(fibre_length(a0, 1.3, 7, 0.0), a0 * (1.0 - std::pow(1.3, -7)), 1e-10);
  // Equal differences in the limit Q -> 1 are not special-cased: n terms of 2z each.
  EXPECT_NEAR(fibre_length(a0, 1.0 + 1e-15, 5, 10.0), 100.0, 1e-9);
}

TEST(Eq9, ZMaxInvertsTheFibreLength) {
  for (int n : {1, 2, 7, 40, 500}) {
    const double a0 = 1414.0;
    const double Q = std::pow(6.0, 1.0 / n);
    const double h = 1400.0;
    const double z = z_max_for_fibre_length(a0, Q, n, h);
    EXPECT_GT(z, 0.0);
    EXPECT_NEAR(fibre_length(a0, Q, n, z), h, 1e-11 * h) << "n = " << n;
  }
  // The differences alone reach h: no out-of-plane depth is needed.
  EXPECT_EQ(z_max_for_fibre_length(1010.0, 101.0, 1, 1000.0), 0.0);
}

// Eq. 9 summed term by term in long double: the reference for the library's fast paths (Euler-
// Maclaurin for many small steps, a closed-form tail once the steps are tiny against 2 z).
long double direct_fibre_length(long double a0, long double Q, int n, long double z) {
  long double sum = 0.0L;
  long double previous = a0;
  long double a = a0;
  for (int i = 1; i <= n; ++i) {
    // A running product, re-anchored by pow every 256 steps so rounding cannot accumulate.
    a = (i % 256 == 0) ? a0 * std::pow(Q, -static_cast<long double>(i)) : a / Q;
    sum += std::sqrt((previous - a) * (previous - a) + 4.0L * z * z);
    previous = a;
  }
  return sum;
}

TEST(Eq9, FastSumsMatchTermByTermSummation) {
  // The grid reaches both ends of eq. 9: fibres that are almost all drop (a_0 - a_n, z small
  // against the steps) and fibres that are almost all zig-zag (2 n z, the steps small against
  // z), where the fast paths take over; each end is counted by what the reference sum gives.
  int drop_dominated = 0;
  int zigzag_dominated = 0;
  for (int n : {1, 7, 64, 65, 100, 700, 5000, 100000, 1000000}) {
    for (double ratio : {1.5, 6.0, 101.0, 1e4}) {  // a_0 / a_n
      for (double z : {0.0, 1e-3, 1.0, 50.0, 1000.0}) {
        const double a0 = 1414.0;
        const double Q = std::pow(ratio, 1.0 / n);
        const long double reference = direct_fibre_length(a0, Q, n, z);
        EXPECT_NEAR(fibre_length(a0, Q, n, z), static_cast<double>(reference),
                    2e-14 * static_cast<double>(reference))
            << "n = " << n << ", a0/an = " << ratio << ", z = " << z;
        const double drop = a0 - a0 / ratio;
        const double zigzag = 2.0 * n * z;
        drop_dominated += std::abs(static_cast<double>(reference) / drop - 1.0) < 1e-3;
        zigzag_dominated +=
            zigzag > 0.0 && std::abs(static_cast<double>(reference) / zigzag - 1.0) < 1e-3;
      }
    }
  }
  EXPECT_GE(drop_dominated, 10);
  EXPECT_GE(zigzag_dominated, 10);
}

TEST(Eq10, FloorAndNearest) {
  EXPECT_EQ(wrinkle_count(std::pow(1.3, 6.4), 1.3, false), 6);
  EXPECT_EQ(wrinkle_count(std::pow(1.3, 6.4), 1.3, true), 6);
  EXPECT_EQ(wrinkle_count(std::pow(1.3, 6.6), 1.3, false), 6);
  EXPECT_EQ(wrinkle_count(std::pow(1.3, 6.6), 1.3, true), 7);
  EXPECT_EQ(wrinkle_count(1.01, 1.3, false), 1);  // at least one fold
}

TEST(Eq10, IntegerBoundaryIsNotLostToRounding) {
  // log(Q^n)/log Q lands below n for some Q, n; floor must still give n.
  int below_n = 0;  // cases where a plain floor would lose a fold
  for (int n = 1; n <= 60; ++n) {
    for (double Q : {1.1, 1.29, 1.31, 1.7, 3.0}) {
      const double ratio = std::pow(Q, n);
      EXPECT_EQ(wrinkle_count(ratio, Q, false), n) << "Q = " << Q;
      below_n += std::log(ratio) / std::log(Q) < n;
    }
  }
  EXPECT_GT(below_n, 0) << "no case where the guard is needed: the test would not see it go";
}

// Eq. 8 over one span by the trapezoid rule on its whole period in long double: the length of the
// upper edge y = a_n cos(pi x/l), z = z_max cos(pi x/l), written here and not in the library.
long double upper_edge_length(long double a_n, long double z_max, long double span) {
  constexpr int kPoints = 2048;
  const long double k2 = kPiL * kPiL * (a_n * a_n + z_max * z_max) / (span * span);  // (pi A/l)²
  long double sum = 0.0L;
  for (int j = 0; j < kPoints; ++j) {
    const long double s = std::sin(kPiL * j / kPoints);
    sum += std::sqrt(1.0L + k2 * s * s);
  }
  return span * sum / kPoints;
}

// What the user reads off a solution: the fold amplitudes start at a_0 = 1.01 h and fall by the
// reported Q from one line to the next; with the alternating +-z_max they make a vertical fibre
// of length h (eq. 9) and an upper edge of length L (eq. 8); and n is eq. 10's count for them
// with Q7, the root of eq. 7 (the exact method's fixed point). Summed and integrated here, in
// long double, from the solution's numbers only.
TEST(FoldAmplitudes, FallByTheReportedRatioAndMakeTheFibreAndTheEdge) {
  for (const char* name : {"paper-table1-h900", "paper-table1-h1400", "paper-table2-w33",
                           "paper-table2-w54", "default"}) {
    for (const Method method : {Method::exact, Method::paper}) {
      Parameters p =
          load_preset(std::filesystem::path(FOLDLAB_PRESETS_DIR) / (std::string(name) + ".json"))
              .parameters;
      p.model.method = method;
      const Solution s = solve(p);
      SCOPED_TRACE(std::string(name) + " " + std::string(to_string(method)));
      ASSERT_EQ(s.regime, Regime::wrinkled);
      ASSERT_EQ(s.a_mm.size(), static_cast<std::size_t>(s.n) + 1);
      const double h = p.hanging.height_mm;
      EXPECT_NEAR(s.a_mm.front(), 1.01 * h, 1e-9 * h);
      long double fibre = 0.0L;
      for (std::size_t i = 1; i < s.a_mm.size(); ++i) {
        EXPECT_NEAR(s.a_mm[i - 1] / s.a_mm[i], s.Q, 1e-12 * s.Q) << "line " << i;
        const long double drop = static_cast<long double>(s.a_mm[i - 1]) - s.a_mm[i];
        fibre += std::sqrt(drop * drop + 4.0L * s.z_max_mm * s.z_max_mm);
      }
      EXPECT_NEAR(static_cast<double>(fibre), h, 1e-10 * h);
      const double L = p.hanging.length_mm;
      const double span = L - p.hanging.support_displacement_mm;  // the presets' l = L - d
      ASSERT_EQ(p.model.span_rule, SpanRule::L_minus_d);
      const double edge = static_cast<double>(upper_edge_length(s.a_mm.back(), s.z_max_mm, span));
      if (method == Method::exact) {
        EXPECT_NEAR(edge, L, 1e-10 * L);
        ASSERT_TRUE(s.Q7.has_value());
        const double count = std::log(s.a_mm.front() / s.a_mm.back()) / std::log(*s.Q7);
        EXPECT_EQ(s.n, p.model.int_rounding == IntRounding::nearest
                           ? std::lround(count)
                           : static_cast<long>(std::floor(count)));
      } else {
        // The paper's iteration stops once L' is within its tolerance (5 %) by Simpson's rule.
        EXPECT_NEAR(edge, L, (p.model.length_tolerance + 1e-3) * L);
      }
    }
  }
}

}  // namespace
}  // namespace foldlab
