// Bracketed root finding shared by the solvers (private to foldlab_core).
#pragma once

#include <cmath>
#include <limits>
#include <utility>

namespace foldlab::detail {

// Brent's method: a root of f in [a, b] given f(a) and f(b) of opposite signs (or one of them 0).
// Inverse quadratic interpolation where it behaves, bisection where it does not, so it converges
// superlinearly on smooth f and never leaves the bracket. Stops when the bracket is narrower than
// relative_tolerance * |x| (plus a tiny absolute floor) or f is exactly 0.
template <class F>
double brent_root(F&& f, double a, double b, double fa, double fb, double relative_tolerance,
                  int max_iterations = 200) {
  if (fa == 0.0) {
    return a;
  }
  if (fb == 0.0) {
    return b;
  }
  double c = a;
  double fc = fa;
  double d = b - a;
  double e = d;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = b - a;
      e = d;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tolerance = 2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) +
                             0.5 * relative_tolerance * std::abs(b) +
                             std::numeric_limits<double>::min();
    const double half = 0.5 * (c - b);
    if (std::abs(half) <= tolerance || fb == 0.0) {
      return b;
    }
    if (std::abs(e) >= tolerance && std::abs(fa) > std::abs(fb)) {
      double p;
      double q;
      const double s = fb / fa;
      if (a == c) {
        p = 2.0 * half * s;  // secant
        q = 1.0 - s;
      } else {
        const double qa = fa / fc;
        const double r = fb / fc;
        p = s * (2.0 * half * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) {
        q = -q;
      } else {
        p = -p;
      }
      if (2.0 * p < std::min(3.0 * half * q - std::abs(tolerance * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = half;
        e = d;
      }
    } else {
      d = half;
      e = d;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tolerance ? d : (half > 0.0 ? tolerance : -tolerance);
    fb = f(b);
  }
  return b;
}

}  // namespace foldlab::detail
