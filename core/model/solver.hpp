// The two solution methods (docs/model.md): `paper` (the paper's 5%-tolerance iteration as we read
// it) and `exact` (eqs. 8 and 9 to machine precision, n as the fixed point of eq. 10).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/parameters.hpp"

namespace foldlab {

// Every outcome is a regime with a message; none is an error and none yields NaN, so
// a sweep, a slider or a batch never stops at an awkward input.
enum class Regime {
  wrinkled,          // n >= 1 folds, all equations hold
  no_slack,          // d = 0: L = l, flat cloth, n = 0
  stiff,             // s >= 1: eq. 7 has no root, a single fold at most
  short_cloth,       // the upper edge needs a sag A(L, l) >= a_0 = 1.01 h: no folds fit
  negligible_slack,  // A(L, l) <= 0.01 h: eq. 9 has no root; flat folds (z_max = 0) shown
  n_cycle,           // exact method: eq. 10 cycles between values of n; the smallest is used
};

// What each front end says of a regime: its key in reports and JSON, its words in plot bands and
// legends, the colour a regime map gives a cell that has no n to show (0xRRGGBB; absent for
// the regimes coloured by n), and what it means for the cloth in words without the model's
// symbols, for a beginner's one line; and what the front ends ask of it.
struct RegimeInfo {
  Regime regime = Regime::wrinkled;
  std::string_view key{};
  std::string_view label{};
  std::optional<std::uint32_t> map_rgb{};
  std::string_view plain{};
  // The law counted the folds (n >= 1, with depth): a sweep's n and z_max curves run through it.
  bool has_folds = false;
  // Eqs. 8 and 9 hold at the solution: the stress test bounds their residuals there, and the
  // benchmark's reference solves them (elsewhere the folds it has are flat, a_n = A, z_max = 0).
  bool equations_hold = false;
  // n is a fixed point of eq. 10, which the benchmark's reference checks.
  bool n_fixed_point = false;
  // Nothing to remark: no band on a sweep, the results' message dim rather than a note, no
  // regimes line under a comparison.
  bool unremarkable = false;
};
inline constexpr RegimeInfo kRegimes[] = {
    {.regime = Regime::wrinkled,
     .key = "wrinkled",
     .label = "wrinkled",
     .plain = "the cloth hangs in folds under its own weight",
     .has_folds = true,
     .equations_hold = true,
     .n_fixed_point = true,
     .unremarkable = true},
    {.regime = Regime::no_slack,
     .key = "no_slack",
     .label = "no slack",
     .map_rgb = 0x3c3c3c,
     .plain = "the supports span the whole edge, so the cloth hangs flat"},
    {.regime = Regime::stiff,
     .key = "stiff",
     .label = "stiff",
     .plain = "too stiff for its weight to buckle it: one fold at most",
     .equations_hold = true},
    {.regime = Regime::short_cloth,
     .key = "short_cloth",
     .label = "short cloth",
     .map_rgb = 0x781e1e,
     .plain = "too short for the sag of its upper edge: no folds fit"},
    {.regime = Regime::negligible_slack,
     .key = "negligible_slack",
     .label = "negligible slack",
     .map_rgb = 0x5a5a78,
     .plain = "so little slack that the folds stay flat"},
    {.regime = Regime::n_cycle,
     .key = "n_cycle",
     .label = "n cycles",
     .plain = "the fold count has no single answer; the smallest is shown",
     .has_folds = true,
     .equations_hold = true},
};
const RegimeInfo& regime_info(Regime r);

// The paper's lower boundary a_0 = 1.01 h, which both methods keep.
inline constexpr double kLowerBoundaryFactor = 1.01;

// Above this n the solve stops growing n and reports the count as capped (docs/model.md). Real
// cloths show a few to a few dozen folds, and the widest the input table allows (L up to 1e5 mm)
// with folds a few thicknesses apart is still in the thousands; 10,000 folds are 10,001 a_i, about
// 250 KB of `solve --json`, fold lines the explorer redraws within a frame, and a count a person
// can still read. The former 1e7 made valid inputs write 233 MB of JSON and stall the explorer.
inline constexpr int kMaxWrinkles = 10'000;

struct Solution {
  Method method = Method::paper;
  Regime regime = Regime::no_slack;
  int n = 0;                 // number of wrinkles
  double Q = 1.0;            // (a_0/a_n)^(1/n), the ratio the fold amplitudes actually have
  std::optional<double> Q7;  // Conci's law: root of eq. 7; none in the stiff regime or other laws
  // The law's count of eq. 10 (FoldCountRule::step is ln Q7, or the fold spacing lambda in mm);
  // none when the law allows one fold at most.
  std::optional<FoldCountRule> count_rule;
  double stress_ratio = 0.0;  // s = K E t³ / (w h l²) of eq. 7
  double z_max_mm = 0.0;
  std::vector<double> a_mm;        // a_0 (lower boundary) .. a_n (upper edge); empty when n = 0
  double span_mm = 0.0;            // l
  double sag_amplitude_mm = 0.0;   // A(L, l) = sqrt(a_n² + z_max²) that eq. 8 needs
  int iterations = 0;              // paper: iterations of the loop; exact: values of n tried
  bool hit_iteration_cap = false;  // paper: stopped at max_iterations without meeting tolerance
  // Paper: the initial guess already met the tolerance, so eq. 8 never moved a_n and z_max off
  // their starting values. Like hitting the cap, its z_max is then no prediction.
  bool stopped_at_first_iterate = false;
  bool n_capped = false;         // eq. 10 asked for more than kMaxWrinkles folds
  std::vector<int> n_cycle;      // exact: the values of n that eq. 10 cycles through
  double residual_length = 0.0;  // L(eq. 8, closed form)/L - 1 for the reported a_n, z_max
  double residual_height = 0.0;  // fibre length(eq. 9)/h - 1 for the reported a_i, z_max
};

// Precondition: validate(p) is empty. Never throws for valid input.
Solution solve(const Parameters& p);

// What a sweep's point, a regime map's cell and a calibration's prediction keep of a solution:
// the count and the folds' measures, without the amplitudes.
struct FoldSummary {
  int n = 0;
  double Q = 1.0;
  double z_max_mm = 0.0;
  Regime regime = Regime::no_slack;
  bool n_capped = false;  // eq. 10 asked for more than kMaxWrinkles folds: n is that cap
};
FoldSummary fold_summary(const Solution& s);

// One iterate of a method, so that a teacher (or the CLI) can follow the iteration step by step.
struct Iterate {
  int n = 0;                  // paper: eq. 10 at the a_n this iterate starts from; exact: n visited
  double Q = 1.0;             // (a_0/a_n)^(1/n)
  double a_n_mm = 0.0;        // paper: the a_n this iterate starts from; exact: eq. 9's root for n
  double z_max_mm = 0.0;      // eq. 9's root for this n and Q
  double length_ratio = 0.0;  // L'/L; paper: eq. 8 by the model's quadrature, exact: closed form
  double count_argument = 0.0;  // the argument of eq. 10's Int[] under the law; 0 without a count
  int next_n = 0;               // the n of the next iterate; for the last one, its own n
};

// Every iterate solve() goes through, in order, and what solve() returns. No iterates for the
// regimes decided before any iteration (no slack, short cloth, negligible slack).
struct IterationTrace {
  std::vector<Iterate> iterates;
  Solution solution;
};
IterationTrace trace_iterations(const Parameters& p);

// The exact method's fixed-point map at each n in [n_from, n_to]: `argument` is eq. 10's argument
// under the law (log(a_0/a_n(n)) / log Q7 for Conci's) with a_n(n) the root of eqs. 8 and 9 for n,
// `count` its Int[] (the next n). Empty when the exact method does not iterate (a law that allows
// one fold at most, or a regime decided before).
struct CountMapPoint {
  int n = 0;
  double argument = 0.0;
  int count = 0;
};
std::vector<CountMapPoint> count_map(const Parameters& p, int n_from, int n_to);

// One line for the user; empty for the plain wrinkled regime.
std::string describe(const Solution& s, const Parameters& p);

std::string_view to_string(Regime r);

}  // namespace foldlab
