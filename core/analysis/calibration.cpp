#include "core/analysis/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <numeric>
#include <set>
#include <span>
#include <utility>

#include "core/analysis/parallel_tasks.hpp"
#include "core/io/export_budget.hpp"
#include "core/model/equations.hpp"
#include "core/model/named_enum.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A change of a row's prediction is located to this width in ln s (1e-10 relative in s).
constexpr double kEdgeTolerance = 1e-10;
// Below s = 1e-12 (about 2e6 folds) nothing is followed: the prediction there is held constant.
constexpr double kLowestLogS = -27.631021115928547;  // ln 1e-12

bool close(double x, double y) {
  return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y));
}

// Two predictions are the same when n agrees and z_max, Q agree to 1e-9: the exact method's last
// digits depend on the bracket its search for n went through, not on the constants.
bool same_prediction(const RowPrediction& a, const RowPrediction& b) {
  if (a.beyond_cap || b.beyond_cap) {
    return a.beyond_cap == b.beyond_cap;
  }
  return a.n == b.n && close(a.z_max_mm, b.z_max_mm) && close(a.Q, b.Q);
}

// One row's share of the loss in one state. The errors are summed in fixed point, in units of
// 2^-50 (about 1e-15, far below the 1e-9 at which scores tie): such a sum is exact and the same in
// any order, so a sweep that adds and removes rows as it crosses their edges gives what summing
// afresh gives, and fits on any number of threads agree to the bit. Each term is at most 1, so
// 2^13 terms fit in 63 bits: the row limit keeps well below.
constexpr double kErrorUnit = 0x1p-50;
static_assert(2 * kMaxCalibrationRows < (std::int64_t{1} << 13));
struct Contribution {
  int n_missed = 0;
  int n_missed_by_more_than_one = 0;
  std::int64_t error_units = 0;
  int terms = 0;
};

Contribution contribution(const PublishedResult& observed, const RowPrediction& p) {
  Contribution c;
  if (observed.n) {
    const int difference = p.beyond_cap ? kCalibrationFoldCap : std::abs(p.n - *observed.n);
    c.n_missed = difference != 0;
    c.n_missed_by_more_than_one = difference > 1;
  }
  auto units = [&p](double model, double seen) {
    const double error = p.beyond_cap ? 1.0 : std::min(std::abs(model / seen - 1.0), 1.0);
    return std::llround(error / kErrorUnit);
  };
  if (observed.z_max_mm) {
    c.error_units += units(p.z_max_mm, *observed.z_max_mm);
    ++c.terms;
  }
  if (observed.Q) {
    c.error_units += units(p.Q, *observed.Q);
    ++c.terms;
  }
  return c;
}

// The loss of score_predictions, summed one row at a time (sign -1 takes a row out again).
struct ScoreSum {
  int n_missed = 0;
  int n_missed_by_more_than_one = 0;
  std::int64_t error_units = 0;
  int terms = 0;

  void add(const Contribution& c, int sign = 1) {
    n_missed += sign * c.n_missed;
    n_missed_by_more_than_one += sign * c.n_missed_by_more_than_one;
    error_units += sign * c.error_units;
    terms += sign * c.terms;
  }

  CalibrationScore score() const {
    return {n_missed, n_missed_by_more_than_one,
            terms ? static_cast<double>(error_units) * kErrorUnit / terms : 0.0, terms};
  }
};

// One row's whole prediction as a function of x = ln s^p. K and p enter the solver only through
// the stress ratio eq. 7 is solved with (s = K E t³/(w h l²), raised to p), so a row tabulated once
// against x is scored at any (K, p) by a lookup at x = p (ln K + log_g), and its plateaus are known
// exactly instead of being sampled.
struct RowTable {
  double log_g = 0.0;                 // ln s at K = 1
  std::vector<double> edges;          // ascending x where the prediction changes
  std::vector<RowPrediction> states;  // states[j] on [edges[j-1], edges[j]); one more than edges
  std::vector<Contribution> shares;   // each state's share of the loss, against the observed row

  std::size_t index_at(double x) const {
    return static_cast<std::size_t>(std::upper_bound(edges.begin(), edges.end(), x) -
                                    edges.begin());
  }
  const RowPrediction& at(double x) const { return states[index_at(x)]; }
};

// Scans x from the law's ceiling (Conci: 0, s = 1, the stiff regime above) down on a log grid
// until n passes
// the row's fold cap, bisecting between every two grid points that differ. A change that starts
// and ends inside one grid step (0.23 % in s by default) is the only thing it can miss.
std::optional<RowTable> tabulate(const Measurement& m, const Parameters& base, double step_decades,
                                 const std::function<bool()>& keep_going) {
  Parameters p = parameters_for(m, base);
  p.model.stress_exponent_p = 1.0;
  const double g = stress_ratio(p, 1.0);
  const int cap = calibration_fold_cap(m.observed.n);
  auto predict = [&](double x) {
    set_stiffness_constant_K(p, std::exp(x) / g);
    return prediction_of(solve(p), cap);
  };
  std::vector<std::pair<double, RowPrediction>> samples;
  // Every change between two differing samples, found by recursive bisection.
  auto refine = [&](auto& self, double x_lo, const RowPrediction& lo, double x_hi,
                    const RowPrediction& hi) -> void {
    if (x_hi - x_lo <= kEdgeTolerance) {
      return;
    }
    const double x_mid = 0.5 * (x_lo + x_hi);
    const RowPrediction mid = predict(x_mid);
    samples.emplace_back(x_mid, mid);
    if (!same_prediction(lo, mid)) {
      self(self, x_lo, lo, x_mid, mid);
    }
    if (!same_prediction(mid, hi)) {
      self(self, x_mid, mid, x_hi, hi);
    }
  };
  const double step = step_decades * std::numbers::ln10;
  double x = wrinkle_law(p.model.law)
                 .log_strength_ceiling(kLowerBoundaryFactor * p.hanging.height_mm, span_mm(p));
  RowPrediction above = predict(x);
  samples.emplace_back(x, above);
  for (int count = 1; !above.beyond_cap && x > kLowestLogS; ++count) {
    const double next = x - step;
    const RowPrediction here = predict(next);
    samples.emplace_back(next, here);
    if (!same_prediction(here, above)) {
      refine(refine, next, here, x, above);
    }
    x = next;
    above = here;
    if (count % 256 == 0 && !keep_going()) {
      return std::nullopt;
    }
  }
  std::sort(samples.begin(), samples.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  RowTable table;
  table.log_g = std::log(g);
  table.states.push_back(samples.front().second);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    if (!same_prediction(samples[i].second, table.states.back())) {
      table.edges.push_back(0.5 * (samples[i - 1].first + samples[i].first));
      table.states.push_back(samples[i].second);
    }
  }
  for (const RowPrediction& state : table.states) {
    table.shares.push_back(contribution(m.observed, state));
  }
  return table;
}

// A stretch of one coordinate (ln K, or p) over which the score stays the same.
struct Segment {
  double lo = -kInfinity;
  double hi = kInfinity;
  CalibrationScore score;

  double width() const { return hi - lo; }
  // The middle; a decade inside the finite end of an unbounded stretch.
  double middle() const {
    if (std::isinf(lo) && std::isinf(hi)) {
      return 0.0;
    }
    if (std::isinf(lo)) {
      return hi - std::numbers::ln10;
    }
    if (std::isinf(hi)) {
      return lo + std::numbers::ln10;
    }
    return 0.5 * (lo + hi);
  }
  bool contains(double v) const { return lo <= v && (v < hi || (v == hi && std::isinf(hi))); }
};

// Scores the tabulated rows of one fit at any (ln K, p), ln K within [log_K_lo, log_K_hi].
class Fitter {
 public:
  Fitter(std::vector<const RowTable*> tables, double log_K_lo, double log_K_hi)
      : tables_(std::move(tables)), log_K_lo_(log_K_lo), log_K_hi_(log_K_hi) {}

  CalibrationScore score_at(double log_K, double p) const {
    ScoreSum sum;
    for (const RowTable* t : tables_) {
      sum.add(t->shares[t->index_at(p * (log_K + t->log_g))]);
    }
    return sum.score();
  }

  // Every plateau along ln K at fixed p: a row's prediction changes where p (ln K + log_g) crosses
  // one of its edges, so the breakpoints are known and nothing between them is missed.
  std::vector<Segment> sweep_K(double p) const {
    return sweep(log_K_lo_, log_K_hi_, [p](const RowTable& t, std::size_t j) {
      return Break{t.edges[j] / p - t.log_g, 1};
    });
  }

  // Every plateau along p in [p_min, p_max] at fixed ln K. Where ln s at p = 1 is negative, a
  // larger p lowers x = p ln s, so the row's prediction steps back through its states.
  std::vector<Segment> sweep_p(double log_K, double p_min, double p_max) const {
    return sweep(p_min, p_max, [log_K](const RowTable& t, std::size_t j) {
      const double c = log_K + t.log_g;  // ln s at p = 1
      return c == 0.0 ? Break{0.0, 0} : Break{t.edges[j] / c, c > 0.0 ? 1 : -1};
    });
  }

  // The mean over the rows of |ln s| at p = 1: how far a unit change of p moves ln s^p.
  double mean_abs_log_s(double log_K) const {
    double sum = 0.0;
    for (const RowTable* t : tables_) {
      sum += std::abs(log_K + t->log_g);
    }
    return tables_.empty() ? 0.0 : sum / static_cast<double>(tables_.size());
  }

  double log_K_lo() const { return log_K_lo_; }
  double log_K_hi() const { return log_K_hi_; }

 private:
  // Where along the swept coordinate a row's edge lies, and which way its state index steps when
  // the sweep passes it (+1 up, -1 down, 0: the row does not move along this coordinate).
  struct Break {
    double at;
    int step;
  };
  struct Event {
    double at;
    std::uint32_t row;
    int step;
  };

  // One pass along [lo, hi]: each row's state is followed through its breaks in order, and the
  // score is kept as a running sum, so a sweep costs a sort of its breaks rather than a lookup of
  // every row in every segment (the fits of a coverage check run this hundreds of thousands of
  // times). A row's state in a segment is set by how many of its breaks, as computed here, lie
  // at or below the segment's start: the segments and their scores are those of evaluating each
  // segment's middle.
  template <class BreakOf>
  std::vector<Segment> sweep(double lo, double hi, const BreakOf& break_of) const {
    std::vector<Event> events;
    std::vector<std::size_t> index(tables_.size());
    ScoreSum sum;
    for (std::size_t r = 0; r < tables_.size(); ++r) {
      const RowTable& t = *tables_[r];
      const std::size_t edges = t.edges.size();
      const int step = edges == 0 ? 0 : break_of(t, 0).step;
      if (step == 0) {
        index[r] = t.index_at(0.0);  // x = p ln s with ln s = 0: the same state for every p
      } else {
        // The breaks run up with the edges (step +1) or down (step -1); the state at lo counts
        // the edges already passed.
        std::size_t passed = 0;
        for (std::size_t j = 0; j < edges; ++j) {
          const Break b = break_of(t, j);
          if (b.at > lo && b.at < hi) {
            events.push_back({b.at, static_cast<std::uint32_t>(r), b.step});
          }
          passed += step > 0 ? b.at <= lo : b.at > lo;
        }
        index[r] = passed;
      }
      sum.add(t.shares[index[r]]);
    }
    std::sort(events.begin(), events.end(),
              [](const Event& a, const Event& b) { return a.at < b.at; });
    std::vector<Segment> segments;
    auto close_segment = [&](double end) {
      Segment s{segments.empty() ? lo : segments.back().hi, end, sum.score()};
      if (!segments.empty() && same_score(segments.back().score, s.score)) {
        segments.back().hi = end;  // the score stays the same across this break
      } else {
        segments.push_back(s);
      }
    };
    std::size_t e = 0;
    while (e < events.size()) {
      const double at = events[e].at;
      close_segment(at);
      for (; e < events.size() && events[e].at == at; ++e) {
        const RowTable& t = *tables_[events[e].row];
        std::size_t& i = index[events[e].row];
        sum.add(t.shares[i], -1);
        i = events[e].step > 0 ? i + 1 : i - 1;
        sum.add(t.shares[i]);
      }
    }
    if (hi > lo) {
      close_segment(hi);
    }
    return segments;
  }

  std::vector<const RowTable*> tables_;
  double log_K_lo_;
  double log_K_hi_;
};

// The best segment: lowest score, then the widest (the fit least sensitive to its constants).
const Segment* best_segment(const std::vector<Segment>& segments) {
  const Segment* best = nullptr;
  for (const Segment& s : segments) {
    if (!best || better(s.score, best->score) ||
        (same_score(s.score, best->score) && s.width() > best->width())) {
      best = &s;
    }
  }
  return best;
}

const Segment* segment_containing(const std::vector<Segment>& segments, double v) {
  for (const Segment& s : segments) {
    if (s.contains(v)) {
      return &s;
    }
  }
  return segments.empty() ? nullptr : &segments.back();
}

// Both return a pointer into their argument, which a temporary (a sweep's result passed straight
// in) would free before the pointer is read: name the sweep's result first.
const Segment* best_segment(std::vector<Segment>&& segments) = delete;
const Segment* segment_containing(std::vector<Segment>&& segments, double v) = delete;

// Which ends of [lo, hi] the values [low, high] reach, to a relative 1e-12 (the envelope's ends
// come from the same bounds through exp and back).
RangeEnd range_end(double low, double high, double lo, double hi) {
  const bool at_lo = low <= lo * (1.0 + 1e-12);
  const bool at_hi = high >= hi * (1.0 - 1e-12);
  return at_lo && at_hi ? RangeEnd::both
         : at_lo        ? RangeEnd::lower
         : at_hi        ? RangeEnd::upper
                        : RangeEnd::none;
}

// K alone: every plateau along ln K is visited; the widest of the best is taken, at its
// geometric middle (as docs/calibration.md fixed the default c).
FittedConstants fit_K(const Fitter& fitter, double p) {
  const std::vector<Segment> segments = fitter.sweep_K(p);
  const Segment& best = *best_segment(segments);
  FittedConstants fit;
  fit.p = fit.p_low = fit.p_high = fit.best_p_min = fit.best_p_max = p;
  fit.K = std::exp(best.middle());
  fit.K_low = std::exp(best.lo);
  fit.K_high = std::exp(best.hi);
  fit.score = best.score;
  fit.best_K_min = kInfinity;
  fit.best_K_max = 0.0;
  for (const Segment& s : segments) {
    if (same_score(s.score, best.score)) {
      fit.equally_good_elsewhere += &s != &best;
      fit.best_K_min = std::min(fit.best_K_min, std::exp(s.lo));
      fit.best_K_max = std::max(fit.best_K_max, std::exp(s.hi));
      fit.equally_good_ends.push_back({std::exp(s.middle()), p});
    }
  }
  return fit;
}

struct Candidate {
  double p;
  Segment along_K;
};

// The best plateaus along ln K at each p visited, and each p's best score.
struct PlateausAlongP {
  std::vector<Candidate> candidates;
  std::vector<std::pair<CalibrationScore, double>> best_at_p;

  void visit(const Fitter& fitter, double p) {
    const std::vector<Segment> segments = fitter.sweep_K(p);
    const Segment* best = best_segment(segments);
    best_at_p.emplace_back(best->score, p);
    for (const Segment& s : segments) {
      if (same_score(s.score, best->score)) {
        candidates.push_back({p, s});
      }
    }
  }
};

// The p values of the coarse grid to search again on a finer one: the best first, one per
// neighbourhood (the finer grid around p covers its neighbours' gaps).
std::vector<double> refinement_centres(std::vector<std::pair<CalibrationScore, double>> ranked,
                                       const CalibrationOptions& o) {
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return better(a.first, b.first); });
  std::vector<double> refined;
  for (const auto& [score, p] : ranked) {
    if (static_cast<int>(refined.size()) >= o.refined_p_values) {
      break;
    }
    if (std::none_of(refined.begin(), refined.end(),
                     [&, centre = p](double q) { return std::abs(q - centre) < 1.5 * o.p_step; })) {
      refined.push_back(p);
    }
  }
  return refined;
}

// The coarse grid in p (80 % of the progress), then the finer one around its best p values;
// nullopt when cancelled.
std::optional<PlateausAlongP> search_along_p(const Fitter& fitter, const CalibrationOptions& o,
                                             const std::function<bool(double)>& keep_going) {
  PlateausAlongP found;
  const int coarse = static_cast<int>(std::floor((o.p_max - o.p_min) / o.p_step + 1e-9)) + 1;
  for (int i = 0; i < coarse; ++i) {
    found.visit(fitter, o.p_min + i * o.p_step);
    if (!keep_going(0.8 * (i + 1) / coarse)) {
      return std::nullopt;
    }
  }
  const std::vector<double> refined = refinement_centres(found.best_at_p, o);
  for (std::size_t r = 0; r < refined.size(); ++r) {
    for (int k = -9; k <= 9; ++k) {
      const double p = refined[r] + k * 0.1 * o.p_step;
      if (k != 0 && p >= o.p_min && p <= o.p_max) {
        found.visit(fitter, p);
      }
    }
    if (!keep_going(0.8 + 0.1 * static_cast<double>(r + 1) / static_cast<double>(refined.size()))) {
      return std::nullopt;
    }
  }
  return found;
}

CalibrationScore best_score(const std::vector<Candidate>& candidates) {
  CalibrationScore best = candidates.front().along_K.score;
  for (const Candidate& c : candidates) {
    best = better(c.along_K.score, best) ? c.along_K.score : best;
  }
  return best;
}

// The extent of the constants that reach the best score, and the candidates at its lowest and
// highest p, into `fit`.
void bound_best(const std::vector<Candidate>& candidates, const CalibrationScore& best,
                FittedConstants& fit) {
  fit.best_K_min = fit.best_p_min = kInfinity;
  fit.best_K_max = fit.best_p_max = 0.0;
  const Candidate* lowest_p = nullptr;
  const Candidate* highest_p = nullptr;
  for (const Candidate& c : candidates) {
    if (!same_score(c.along_K.score, best)) {
      continue;
    }
    lowest_p = lowest_p == nullptr || c.p < lowest_p->p ? &c : lowest_p;
    highest_p = highest_p == nullptr || c.p > highest_p->p ? &c : highest_p;
    fit.best_K_min = std::min(fit.best_K_min, std::exp(c.along_K.lo));
    fit.best_K_max = std::max(fit.best_K_max, std::exp(c.along_K.hi));
    fit.best_p_min = std::min(fit.best_p_min, c.p);
    fit.best_p_max = std::max(fit.best_p_max, c.p);
  }
  for (const Candidate* end : {lowest_p, highest_p}) {
    fit.equally_good_ends.push_back({std::exp(end->along_K.middle()), end->p});
  }
}

// How far a candidate's middle lies from the nearest edge of its plateau, along ln K and along p
// (p's distance scaled to the change of ln s^p it makes).
double robustness(const Fitter& fitter, const CalibrationOptions& o, const Candidate& c) {
  const double u = c.along_K.middle();
  const std::vector<Segment> along_p_all = fitter.sweep_p(u, o.p_min, o.p_max);
  const Segment* along_p = segment_containing(along_p_all, c.p);
  const double per_p = fitter.mean_abs_log_s(u);
  return std::min({c.p * (u - c.along_K.lo), c.p * (c.along_K.hi - u), per_p * (c.p - along_p->lo),
                   per_p * (along_p->hi - c.p)});
}

// (ln K, p) of the best-scoring candidate furthest inside its plateau.
std::pair<double, double> most_robust(const Fitter& fitter, const CalibrationOptions& o,
                                      const std::vector<Candidate>& candidates,
                                      const CalibrationScore& best) {
  double most = -kInfinity;
  double log_K = 0.0;
  double p = 1.0;
  for (const Candidate& c : candidates) {
    if (!same_score(c.along_K.score, best)) {
      continue;
    }
    const double r = robustness(fitter, o, c);
    if (r > most) {
      most = r;
      log_K = c.along_K.middle();
      p = c.p;
    }
  }
  return {log_K, p};
}

// Centre along p, then along ln K, a few times: each move stays on the same plateau.
void centre_on_plateau(const Fitter& fitter, const CalibrationOptions& o,
                       const CalibrationScore& best, double& log_K, double& p) {
  for (int round = 0; round < 3; ++round) {
    const std::vector<Segment> along_p_all = fitter.sweep_p(log_K, o.p_min, o.p_max);
    const Segment* along_p = segment_containing(along_p_all, p);
    const double p_next = std::sqrt(along_p->lo * along_p->hi);
    const std::vector<Segment> along_K_all = fitter.sweep_K(p_next);
    const Segment* along_K = segment_containing(along_K_all, log_K);
    if (!same_score(along_K->score, best)) {
      break;
    }
    p = p_next;
    log_K = along_K->middle();
  }
}

// K and p: a coarse grid in p with every plateau along ln K at each p, then a grid ten times finer
// in p around the best p values (a narrow plateau between two coarse p values is found there),
// then, of the constants that reach the best score, those nearest the paper's form (p closest to
// 1), centred in their plateau along both coordinates. Where the data cannot tell p apart (the
// best score holds along a valley of (K, p)), that departs from the paper no further than they
// demand, instead of drifting to whichever end of the valley is widest.
std::optional<FittedConstants> fit_K_and_p(const Fitter& fitter, const CalibrationOptions& o,
                                           const std::function<bool(double)>& keep_going) {
  const std::optional<PlateausAlongP> found = search_along_p(fitter, o, keep_going);
  if (!found) {
    return std::nullopt;
  }
  const CalibrationScore best = best_score(found->candidates);
  FittedConstants fit;
  bound_best(found->candidates, best, fit);
  auto [log_K, p] = most_robust(fitter, o, found->candidates, best);
  centre_on_plateau(fitter, o, best, log_K, p);
  const std::vector<Segment> along_K_all = fitter.sweep_K(p);
  const std::vector<Segment> along_p_all = fitter.sweep_p(log_K, o.p_min, o.p_max);
  const Segment along_K = *segment_containing(along_K_all, log_K);
  const Segment along_p = *segment_containing(along_p_all, p);
  fit.K = std::exp(log_K);
  fit.p = p;
  fit.K_low = std::exp(along_K.lo);
  fit.K_high = std::exp(along_K.hi);
  fit.p_low = along_p.lo;
  fit.p_high = along_p.hi;
  fit.score = fitter.score_at(log_K, p);
  return fit;
}

std::optional<FittedConstants> fit_with(const Fitter& fitter, double base_p,
                                        const CalibrationOptions& o,
                                        const std::function<bool(double)>& keep_going) {
  std::optional<FittedConstants> fit = o.fit == FitConstants::K
                                           ? std::optional(fit_K(fitter, base_p))
                                           : fit_K_and_p(fitter, o, keep_going);
  if (fit) {
    fit->K_min = std::exp(fitter.log_K_lo());
    fit->K_max = std::exp(fitter.log_K_hi());
    fit->p_min = o.fit == FitConstants::K ? base_p : o.p_min;
    fit->p_max = o.fit == FitConstants::K ? base_p : o.p_max;
    fit->K_end = range_end(fit->best_K_min, fit->best_K_max, fit->K_min, fit->K_max);
    if (o.fit == FitConstants::K_and_p) {
      fit->p_end = range_end(fit->best_p_min, fit->best_p_max, fit->p_min, fit->p_max);
    }
  }
  return fit;
}

const InputSpec& input_row(std::string_view key) {
  return *find_input(key);
}

void check_options(const CalibrationOptions& o) {
  const InputInterval& p_range = input_row("p").valid;
  if (!(p_range.contains(o.p_min) && p_range.contains(o.p_max) && o.p_min < o.p_max &&
        o.p_step > 0.0 && o.tabulation_step_decades > 0.0 && o.tabulation_step_decades <= 0.1)) {
    throw CalibrationError("calibration options: need p_min < p_max, both in p's range " +
                           p_range.text() +
                           ", p_step > 0 and a tabulation step in (0, 0.1] decades");
  }
}

void check_base(const Parameters& base) {
  if (const auto issues = validate(base); !issues.empty()) {
    throw CalibrationError("the base parameters are not valid:\n" + format_issues(issues));
  }
}

// ln K over c's range in the input table at the base's Poisson ratio, a hair inside its ends so
// that any K the search returns reads back as a c the table (and a preset) accepts.
std::pair<double, double> log_K_range(const Parameters& base) {
  const InputInterval& c = input_row("c").valid;
  Parameters at = base;
  at.model.load_constant_c = c.lo;
  const double lo = std::log(stiffness_constant_K(at));
  at.model.load_constant_c = c.hi;
  const double hi = std::log(stiffness_constant_K(at));
  constexpr double kInside = 1e-9;
  return {lo + kInside, hi - kInside};
}

}  // namespace

struct CalibrationTables::Data {
  std::vector<RowTable> tables;
  CalibrationOptions options;
  double base_p = 1.0;
  std::pair<double, double> log_K;
};

std::optional<CalibrationTables> CalibrationTables::tabulate(const std::vector<Measurement>& rows,
                                                             const Parameters& base,
                                                             const CalibrationOptions& options,
                                                             const CalibrationProgress& progress) {
  check_options(options);
  check_base(base);
  if (static_cast<std::int64_t>(rows.size()) > kMaxCalibrationRows) {
    throw CalibrationError(std::to_string(rows.size()) + " rows, above the limit of " +
                           std::to_string(kMaxCalibrationRows) + " rows a calibration fits");
  }
  auto data = std::make_shared<Data>();
  data->tables.resize(rows.size());
  data->options = options;
  data->base_p = base.model.stress_exponent_p;
  data->log_K = log_K_range(base);
  std::vector<char> complete(rows.size(), 0);
  const bool finished = run_tasks(
      rows.size(), options.threads,
      [&](std::size_t i, const std::atomic<bool>& stop) {
        std::optional<RowTable> t = foldlab::tabulate(
            rows[i], base, options.tabulation_step_decades, [&stop] { return !stop.load(); });
        if (t) {
          data->tables[i] = std::move(*t);
          complete[i] = 1;
        }
      },
      progress);
  if (!finished || std::count(complete.begin(), complete.end(), 0) > 0) {
    return std::nullopt;
  }
  return CalibrationTables(std::move(data));
}

std::optional<FittedConstants> CalibrationTables::fit(
    const std::vector<std::size_t>& subset, const std::function<bool(double)>& keep_going) const {
  std::vector<const RowTable*> tables;
  for (std::size_t i : subset) {
    tables.push_back(&data_->tables.at(i));
  }
  return fit_with(Fitter(std::move(tables), data_->log_K.first, data_->log_K.second), data_->base_p,
                  data_->options, [&](double f) { return !keep_going || keep_going(f); });
}

std::size_t CalibrationTables::size() const {
  return data_->tables.size();
}

std::vector<std::string> range_end_notes(const FittedConstants& f, double poisson_ratio) {
  std::vector<std::string> notes;
  auto note = [&](const char* name, RangeEnd end, double lo, double hi, const std::string& why) {
    if (end == RangeEnd::none) {
      return;
    }
    const std::string ends =
        end == RangeEnd::both
            ? detail::printf_string("both its bounds, %.4g and %.4g", lo, hi)
            : detail::printf_string("its %s bound %.4g", end == RangeEnd::lower ? "lower" : "upper",
                                    end == RangeEnd::lower ? lo : hi);
    notes.push_back("the best score reaches " + std::string(name) + " at " + ends + " (" + why +
                    "): the data would take " + name + " further than the search allows");
  };
  const double c_per_K = 1.0 - poisson_ratio * poisson_ratio;
  note("K", f.K_end, f.K_min, f.K_max,
       detail::printf_string("c from %.4g to %.4g at nu = %.3g, the input table's range of c",
                             f.K_min * c_per_K, f.K_max * c_per_K, poisson_ratio));
  note("p", f.p_end, f.p_min, f.p_max, "the search range of p");
  return notes;
}

std::string_view to_string(FitConstants f) {
  return f == FitConstants::K ? "K" : "K,p";
}

bool parse_fit_constants(std::string_view s, FitConstants& out) {
  return parse_named(s, out, {FitConstants::K, FitConstants::K_and_p});
}

int calibration_fold_cap(std::optional<int> observed_n) {
  // In 64 bits and clamped to the solver's own cap, so that no observed n can overflow it.
  const std::int64_t wanted = observed_n ? 4 * static_cast<std::int64_t>(*observed_n) : 0;
  return static_cast<int>(std::clamp<std::int64_t>(wanted, kCalibrationFoldCap, kMaxWrinkles));
}

RowPrediction prediction_of(const Solution& s, int fold_cap) {
  if (s.n > fold_cap || s.n_capped) {
    return {FoldSummary{}, true};
  }
  return {fold_summary(s), false};
}

bool better(const CalibrationScore& a, const CalibrationScore& b) {
  if (a.n_missed != b.n_missed) {
    return a.n_missed < b.n_missed;
  }
  if (a.n_missed_by_more_than_one != b.n_missed_by_more_than_one) {
    return a.n_missed_by_more_than_one < b.n_missed_by_more_than_one;
  }
  return a.mean_relative_error < b.mean_relative_error - 1e-9;
}

bool same_score(const CalibrationScore& a, const CalibrationScore& b) {
  return !better(a, b) && !better(b, a);
}

CalibrationScore score_predictions(const std::vector<Measurement>& rows,
                                   const std::vector<RowPrediction>& predictions) {
  ScoreSum sum;
  for (std::size_t i = 0; i < rows.size() && i < predictions.size(); ++i) {
    sum.add(contribution(rows[i].observed, predictions[i]));
  }
  return sum.score();
}

Parameters with_constants(const Parameters& base, double K, double p) {
  Parameters out = base;
  out.model.stress_exponent_p = p;
  set_stiffness_constant_K(out, K);
  return out;
}

void check_fit_row_count(int fit_rows, FitConstants fit) {
  const int constants = fit == FitConstants::K ? 1 : 2;
  if (fit_rows < constants) {
    throw CalibrationError(detail::printf_string(
        "%d fit row%s cannot determine %d constants (%s): the fit would be anything that "
        "passes through %s; add rows, or fit K alone",
        fit_rows, fit_rows == 1 ? "" : "s", constants, std::string(to_string(fit)).c_str(),
        fit_rows == 1 ? "that row" : "those rows"));
  }
}

std::optional<FittedConstants> fit_constants(const std::vector<Measurement>& rows,
                                             const Parameters& base,
                                             const CalibrationOptions& options,
                                             const CalibrationProgress& progress) {
  check_options(options);
  check_base(base);
  if (rows.empty()) {
    throw CalibrationError("nothing to fit: no rows");
  }
  auto keep_going = [&](double fraction) { return !progress || progress(fraction); };
  const std::optional<CalibrationTables> tables = CalibrationTables::tabulate(
      rows, base, options, [&](double f) { return keep_going(0.5 * f); });
  if (!tables) {
    return std::nullopt;
  }
  std::vector<std::size_t> all(rows.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  return tables->fit(all, [&](double f) { return keep_going(0.5 + 0.5 * f); });
}

struct CalibrationSteps::State {
  MeasurementSet data;
  Parameters base;
  CalibrationOptions options;
  std::vector<std::size_t> fit_rows;  // indices into data.rows
  std::set<std::string> groups;       // of the fit rows
  bool leave_one_out = false;
  bool split_groups = false;
  std::vector<Measurement> fit_measurements;
  std::shared_ptr<CalibrationTables::Data> tables;
  std::vector<char> tabulated;  // per fit row
  // Subsets as positions in fit_rows; subsets[0] is the in-sample fit.
  std::vector<std::vector<std::size_t>> subsets;
  std::vector<std::optional<FittedConstants>> fits;
  std::size_t next_row = 0;
  std::size_t next_fit = 0;
  bool failed = false;  // a tabulation or fit came back empty (cancelled)

  // Where a step's batch from `first` ends: one piece per thread, within `count`.
  std::size_t batch_end(std::size_t first, std::size_t count) const {
    return std::min(count, first + static_cast<std::size_t>(resolve_thread_count(options.threads)));
  }
  CalibrationReport assemble() const;
};

CalibrationSteps::CalibrationSteps(const MeasurementSet& data, const Parameters& base,
                                   const CalibrationOptions& options)
    : state_(std::make_unique<State>()) {
  check_options(options);
  check_base(base);
  if (static_cast<std::int64_t>(data.rows.size()) > kMaxCalibrationRows) {
    throw CalibrationError(data.origin + ": " + std::to_string(data.rows.size()) +
                           " rows, above the limit of " + std::to_string(kMaxCalibrationRows) +
                           " rows a calibration fits; split the file");
  }
  State& s = *state_;
  s.data = data;
  s.base = base;
  s.options = options;
  s.fit_rows = fit_row_indices(data);
  // Rows built in code (the explorer's clicked folds) skip the file reader's bounds: the same
  // bound here keeps one implausible n from making the fit follow millions of folds.
  for (const Measurement& m : data.rows) {
    if (m.observed.n && (*m.observed.n < 0 || *m.observed.n > kMaxObservedFolds)) {
      throw CalibrationError(data.origin + ": row " + std::to_string(m.row) +
                             ", column n: " + std::to_string(*m.observed.n) + " folds: at most " +
                             std::to_string(kMaxObservedFolds) + " can be observed on one cloth");
    }
  }
  if (s.fit_rows.empty()) {
    throw CalibrationError(data.origin + ": nothing to fit: every row has role check");
  }
  check_fit_row_count(static_cast<int>(s.fit_rows.size()), options.fit);
  // The groups of the fit rows, for fitting on all but one and testing on that one.
  for (std::size_t i : s.fit_rows) {
    s.groups.insert(data.rows[i].group);
  }
  // A held-out fit, like every fit, stands on at least as many rows as it has constants.
  const std::size_t constants = options.fit == FitConstants::K ? 1 : 2;
  s.leave_one_out = options.held_out && s.fit_rows.size() >= constants + 1;
  s.split_groups = options.held_out && s.groups.size() >= 2 &&
                   std::all_of(s.groups.begin(), s.groups.end(), [&](const std::string& g) {
                     return static_cast<std::size_t>(std::count_if(
                                s.fit_rows.begin(), s.fit_rows.end(), [&](std::size_t i) {
                                  return data.rows[i].group != g;
                                })) >= constants;
                   });
  for (std::size_t i : s.fit_rows) {
    s.fit_measurements.push_back(data.rows[i]);
  }
  s.tables = std::make_shared<CalibrationTables::Data>();
  s.tables->tables.resize(s.fit_measurements.size());
  s.tables->options = options;
  s.tables->base_p = base.model.stress_exponent_p;
  s.tables->log_K = log_K_range(base);
  s.tabulated.assign(s.fit_measurements.size(), 0);
  s.subsets.resize(1);
  for (std::size_t k = 0; k < s.fit_rows.size(); ++k) {
    s.subsets[0].push_back(k);
  }
  if (s.leave_one_out) {
    for (std::size_t left_out = 0; left_out < s.fit_rows.size(); ++left_out) {
      std::vector<std::size_t>& subset = s.subsets.emplace_back();
      for (std::size_t k = 0; k < s.fit_rows.size(); ++k) {
        if (k != left_out) {
          subset.push_back(k);
        }
      }
    }
  }
  if (s.split_groups) {
    for (const std::string& group : s.groups) {
      std::vector<std::size_t>& subset = s.subsets.emplace_back();
      for (std::size_t k = 0; k < s.fit_rows.size(); ++k) {
        if (data.rows[s.fit_rows[k]].group != group) {
          subset.push_back(k);
        }
      }
    }
  }
  s.fits.resize(s.subsets.size());
}

CalibrationSteps::~CalibrationSteps() = default;

bool CalibrationSteps::step() {
  State& s = *state_;
  const std::size_t rows = s.fit_measurements.size();
  if (s.next_row < rows) {
    // Plain names, not a structured binding: the lambda captures them (emcc's clang cannot).
    const std::size_t first = s.next_row;
    const std::size_t last = s.batch_end(first, rows);
    run_tasks(last - first, s.options.threads, [&](std::size_t k, const std::atomic<bool>& stop) {
      const std::size_t i = first + k;
      std::optional<RowTable> t =
          foldlab::tabulate(s.fit_measurements[i], s.base, s.options.tabulation_step_decades,
                            [&stop] { return !stop.load(); });
      if (t) {
        s.tables->tables[i] = std::move(*t);
        s.tabulated[i] = 1;
      }
    });
    s.next_row = last;
    s.failed |= std::count(s.tabulated.begin(),
                           s.tabulated.begin() + static_cast<std::ptrdiff_t>(last), 0) > 0;
    return false;
  }
  if (s.next_fit < s.subsets.size()) {
    const CalibrationTables tables(s.tables);
    const std::size_t first = s.next_fit;
    const std::size_t last = s.batch_end(first, s.subsets.size());
    run_tasks(last - first, s.options.threads, [&](std::size_t k, const std::atomic<bool>& stop) {
      s.fits[first + k] =
          tables.fit(s.subsets[first + k], [&stop](double) { return !stop.load(); });
    });
    s.next_fit = last;
    s.failed |= std::any_of(s.fits.begin(), s.fits.begin() + static_cast<std::ptrdiff_t>(last),
                            [](const auto& f) { return !f; });
  }
  return s.next_fit >= s.subsets.size();
}

double CalibrationSteps::fraction_done() const {
  const State& s = *state_;
  const double rows = static_cast<double>(s.fit_measurements.size());
  const double fits = static_cast<double>(s.subsets.size());
  return 0.4 * static_cast<double>(s.next_row) / rows +
         0.6 * static_cast<double>(s.next_fit) / fits;
}

CalibrationReport CalibrationSteps::report() const {
  const State& s = *state_;
  if (s.failed || s.next_row < s.fit_measurements.size() || s.next_fit < s.subsets.size()) {
    CalibrationReport report;
    report.fit = s.options.fit;
    report.base = s.base;
    report.fit_row_count = static_cast<int>(s.fit_rows.size());
    report.check_row_count = static_cast<int>(s.data.rows.size() - s.fit_rows.size());
    report.cancelled = true;
    return report;
  }
  return s.assemble();
}

CalibrationReport CalibrationSteps::State::assemble() const {
  CalibrationReport report;
  report.fit = options.fit;
  report.base = base;
  report.fit_row_count = static_cast<int>(fit_rows.size());
  report.check_row_count = static_cast<int>(data.rows.size() - fit_rows.size());
  auto predict = [&](const Measurement& m, double K, double p) {
    return compare_with_published(m.observed, with_constants(parameters_for(m, base), K, p));
  };
  const FittedConstants& in_sample = *fits[0];
  report.fitted = in_sample;
  for (const Measurement& m : data.rows) {
    CalibrationRow row;
    row.measurement = m;
    row.baseline = compare_with_published(m.observed, parameters_for(m, base));
    row.fitted = predict(m, in_sample.K, in_sample.p);
    if (m.role == MeasurementRole::check) {
      row.held_out = row.fitted;
      row.held_out_K = in_sample.K;
      row.held_out_p = in_sample.p;
    }
    report.rows.push_back(std::move(row));
  }
  std::size_t fit_at = 1;
  if (leave_one_out) {
    for (std::size_t left_out : fit_rows) {
      const FittedConstants& fit = *fits[fit_at++];
      CalibrationRow& row = report.rows[left_out];
      row.held_out = predict(row.measurement, fit.K, fit.p);
      row.held_out_K = fit.K;
      row.held_out_p = fit.p;
    }
  }
  std::vector<PublishedComparison> pooled_test;
  if (split_groups) {
    for (const std::string& group : groups) {
      const FittedConstants& fit = *fits[fit_at++];
      GroupSplit split;
      split.test_group = group;
      split.fit = fit;
      std::vector<PublishedComparison> train;
      std::vector<PublishedComparison> test;
      for (std::size_t i : fit_rows) {
        (data.rows[i].group == group ? test : train).push_back(predict(data.rows[i], fit.K, fit.p));
      }
      split.train = summarize(train);
      split.test = summarize(test);
      pooled_test.insert(pooled_test.end(), test.begin(), test.end());
      report.group_splits.push_back(std::move(split));
    }
  }
  report.group_split_test = summarize(pooled_test);
  std::vector<PublishedComparison> baseline_fit, baseline_check, fitted, held_out, check;
  for (const CalibrationRow& row : report.rows) {
    const bool is_fit = row.measurement.role == MeasurementRole::fit;
    (is_fit ? baseline_fit : baseline_check).push_back(row.baseline);
    (is_fit ? fitted : check).push_back(row.fitted);
    if (is_fit && row.held_out) {
      held_out.push_back(*row.held_out);
    }
  }
  report.baseline_fit_rows = summarize(baseline_fit);
  report.baseline_check_rows = summarize(baseline_check);
  report.in_sample = summarize(fitted);
  report.leave_one_out = summarize(held_out);
  report.check_rows = summarize(check);
  return report;
}

std::vector<std::size_t> fit_row_indices(const MeasurementSet& data) {
  std::vector<std::size_t> fit_rows;
  for (std::size_t i = 0; i < data.rows.size(); ++i) {
    if (data.rows[i].role == MeasurementRole::fit) {
      fit_rows.push_back(i);
    }
  }
  return fit_rows;
}

CalibrationReport calibrate(const MeasurementSet& data, const Parameters& base,
                            const CalibrationOptions& options,
                            const CalibrationProgress& progress) {
  CalibrationSteps steps(data, base, options);
  while (!steps.step()) {
    if (progress && !progress(steps.fraction_done())) {
      return steps.report();  // marked cancelled
    }
  }
  if (progress && !progress(1.0)) {
    CalibrationReport cancelled = steps.report();
    cancelled.cancelled = true;
    return cancelled;
  }
  return steps.report();
}

ModelForm model_form(const ModelSettings& m) {
  if (m.stress_exponent_p != 1.0) {
    return ModelForm::calibrated;
  }
  return m.load_constant_c == wrinkle_law(m.law).published_load_constant_c()
             ? ModelForm::paper
             : ModelForm::paper_other_c;
}

std::string describe_model_form(const Parameters& p) {
  const WrinkleLaw& law = wrinkle_law(p.model.law);
  const std::string constants = detail::printf_string(
      "p = %.4g, c = %.4g (K = %.4g at nu = %.3g)", p.model.stress_exponent_p,
      p.model.load_constant_c, stiffness_constant_K(p), p.fabric.poisson_ratio);
  // Conci's law keeps the words FoldLab has always used for eq. 7; another law names itself.
  const bool conci = p.model.law == WrinkleLawKind::conci;
  const std::string printed =
      conci ? "paper's form of eq. 7" : std::string(law.title()) + ", as published";
  switch (model_form(p.model)) {
    case ModelForm::paper:
      return printed + ": " + constants;
    case ModelForm::paper_other_c:
      return printed + " with its own c: " + constants + "; " +
             (conci ? "FoldLab's default is c = 26.9"
                    : "the published c is " +
                          detail::printf_string("%.4g", law.published_load_constant_c()));
    case ModelForm::calibrated:
      return (conci ? std::string("calibrated eq. 7") : std::string(law.title()) + ", calibrated") +
             ", s -> s^p: " + constants;
  }
  return constants;
}

}  // namespace foldlab
