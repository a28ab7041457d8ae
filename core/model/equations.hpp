// The model's equations 7-10 as pure functions (docs/model.md, "Equations"). Lengths in mm.
#pragma once

#include <optional>
#include <span>

#include "core/model/parameters.hpp"

namespace foldlab {

// Complete elliptic integrals of the first and second kind, K(m) and E(m), parameter m = k² in
// [0, 1), by the arithmetic-geometric mean (quadratic convergence: about 5 steps to full
// precision).
struct EllipticKE {
  double K;
  double E;
};
EllipticKE elliptic_KE(double m);
double elliptic_E(double m);

// Eq. 7: s = sigma_cr t / (w h) with sigma_cr = K E t² / l², so s = K E t³ / (w h l²), for the
// fabric, height and span (span_mm) of `p` at the constant K (stiffness_constant_K(p) as solved).
double stress_ratio(const Parameters& p, double K);
// The root Q > 1 of (Q-1)² = s Q (Q+1); none when s >= 1 (the stiff regime).
std::optional<double> wrinkle_ratio_from_stress_ratio(double s);

// Eq. 8: length of the upper edge y = a_n cos(pi x/l), z = z_max cos(pi x/l) over one span, as a
// function of the combined amplitude A = sqrt(a_n² + z_max²).
double upper_edge_length_closed_form(double amplitude_mm, double span_mm);
double upper_edge_length_simpson(double amplitude_mm, double span_mm, int intervals);
double upper_edge_length_trapezoid(double amplitude_mm, double span_mm, int intervals);
// The amplitude A >= 0 for which the closed form gives length_mm (>= span_mm); 0 when equal.
double amplitude_for_upper_edge_length(double length_mm, double span_mm);

// Eq. 9 at x = 0: length of the vertical fibre through the zig-zag of fold points a_0 > ... > a_n,
// a_i = a_0 / Q^i, with out-of-plane offsets alternating +-z_max.
double fibre_length(double a0_mm, double Q, int n, double z_max_mm);
// The z_max >= 0 for which fibre_length equals height_mm; 0 when the amplitude differences alone
// already reach it (a_0 - a_n >= h).
double z_max_for_fibre_length(double a0_mm, double Q, int n, double height_mm);

// Eq. 10: n = Int[log(a_0/a_n) / log Q], at least 1. Floor carries a relative guard of 1e-9 so
// that log(Q^n)/log Q landing an ulp below n still gives n.
int wrinkle_count(double a0_over_an, double Q, bool round_to_nearest);
// The same from log(a_0/a_n) and log Q, for a caller that counts many times with one Q.
int wrinkle_count_from_logs(double log_a0_over_an, double log_Q, bool round_to_nearest);

// Fold amplitudes a_i = a_0 / Q^i, i = 0..n.
void fold_amplitudes(double a0_mm, double Q, int n, std::span<double> out);

}  // namespace foldlab
