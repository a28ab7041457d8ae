// Fitting eq. 7's constants to measured n, z_max and Q, and showing honestly how much of the fit
// is real: the loss, the search, leave-one-out and group-split validation (docs/calibration.md).
// Pure functions; a caller that wants progress or cancellation passes a callback.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/comparison.hpp"
#include "core/io/measurements.hpp"
#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

// Which constants of eq. 7 are fitted: K = c/(1 - nu²) alone (p stays as the base has it, 1 for
// the paper's form), or K together with the exponent p of the calibrated variant s -> s^p.
enum class FitConstants { K, K_and_p };
std::string_view to_string(FitConstants f);  // "K", "K,p"
bool parse_fit_constants(std::string_view s, FitConstants& out);

// What the model predicts for one measured row. Eq. 10 may ask for very many folds at small s;
// the calibration follows n up to a cap (kCalibrationFoldCap, or 4 times the observed n if more)
// and scores anything beyond it as a miss without solving it.
inline constexpr int kCalibrationFoldCap = 100;
// The cap for a row that observed `observed_n` folds: kCalibrationFoldCap, or 4 times the
// observed n if more, never above the solver's kMaxWrinkles.
int calibration_fold_cap(std::optional<int> observed_n);
struct RowPrediction : FoldSummary {
  bool beyond_cap = false;  // more folds than the cap: n, z_max and Q are not computed
};
RowPrediction prediction_of(const Solution& s, int fold_cap);

// The loss, compared lexicographically, smaller first:
//   1. rows whose observed n the model misses,
//   2. rows whose observed n it misses by more than one,
//   3. the mean over every observed z_max and Q of min(|model/observed - 1|, 1).
// n comes first because it is what a viewer counts and what eq. 7 decides; the 100 % cap keeps
// one wild row from outweighing all the others in the tie-break. A row beyond the fold cap misses
// its n by more than one and counts 100 % for each observed z_max and Q.
struct CalibrationScore {
  int n_missed = 0;
  int n_missed_by_more_than_one = 0;
  double mean_relative_error = 0.0;
  int error_terms = 0;  // observed z_max and Q values behind the mean
};
// Errors closer than 1e-9 count as equal: plateaus with the same predictions must tie exactly.
bool better(const CalibrationScore& a, const CalibrationScore& b);
bool same_score(const CalibrationScore& a, const CalibrationScore& b);
CalibrationScore score_predictions(const std::vector<Measurement>& rows,
                                   const std::vector<RowPrediction>& predictions);

// The most fit rows a fit of K and p with held-out fits takes. Each held-out fit refits both
// constants on m - 1 rows, so the time grows as m²: measured on a shared 2-core VM
// (docs/cli.md, calibrate), 50 rows take 21 s, 80 rows 54 s, and 500 rows would take about 35
// minutes, where K alone on 500 rows takes 20 s and K and p without held-out fits 18 s.
inline constexpr int kMaxHeldOutRowsKandP = 80;
// The time of those fits per fit row squared, as measured there: for a message's estimate.
inline constexpr double kHeldOutSecondsPerRowSquared = 0.0085;

struct CalibrationOptions {
  FitConstants fit = FitConstants::K;
  // Coarse grid in p (K_and_p only), then a grid ten times finer around the best p values.
  double p_min = 0.1;
  double p_max = 5.0;
  double p_step = 0.02;
  int refined_p_values = 8;
  // Each row's prediction is tabulated against ln s^p on a log grid of this step (in decades),
  // every change located by bisection to 1e-10.
  double tabulation_step_decades = 0.001;
  bool held_out = true;  // leave-one-out and group splits (off: the in-sample fit only)
  // Rows are tabulated and independent fits run on this many threads (<= 0: every core). The
  // results do not depend on it.
  int threads = 0;
};

// Which end of its search range a fitted constant's plateau reaches, if any.
enum class RangeEnd { none, lower, upper, both };

// Fitted constants and the plateau around them: every K in [K_low, K_high) at this p, and every p
// in [p_low, p_high] at this K, gives the same score (the loss is piecewise constant: it changes
// only where some row's n changes).
struct FittedConstants {
  double K = 0.0;
  double p = 1.0;
  CalibrationScore score;
  double K_low = 0.0;
  double K_high = 0.0;  // may be infinite
  double p_low = 1.0;
  double p_high = 1.0;
  // Other disjoint K bands with the same score (K alone); 0 for K_and_p.
  int equally_good_elsewhere = 0;
  // The envelope of every grid point that reaches the best score (K and p trade off along a
  // valley where s^p stays about the same).
  double best_K_min = 0.0;
  double best_K_max = 0.0;
  double best_p_min = 1.0;
  double best_p_max = 1.0;
  // Points at the ends of the set with the best score, inside it: the smallest and the largest p
  // reached (K and p), or each equally good band of K (K alone). Predictions there are what the
  // data cannot tell apart from the fit's.
  std::vector<Eq7Constants> equally_good_ends;
  // The search stays inside the input table's ranges: K within c's range at the base's Poisson
  // ratio, p within p's range (and the options' p_min, p_max). Where the constants with the best
  // score reach one of these ends (K_end, p_end), the data would take that constant further.
  double K_min = 0.0;
  double K_max = 0.0;
  double p_min = 0.0;
  double p_max = 0.0;
  RangeEnd K_end = RangeEnd::none;
  RangeEnd p_end = RangeEnd::none;  // always none when p is not fitted
};

// "the best score reaches K at its lower bound 0.001099 (c from 0.001 to 1e+04 at nu = 0.3, ...)",
// one note per constant whose best-scoring values reach an end of its range; empty when none do.
std::vector<std::string> range_end_notes(const FittedConstants& f, double poisson_ratio);

// Returns false to cancel. `fraction_done` is in [0, 1].
using CalibrationProgress = std::function<bool(double fraction_done)>;

// Raised for a calibration that cannot run (no row to fit, invalid base parameters).
class CalibrationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The indices in data.rows of the rows whose role is fit, in order.
std::vector<std::size_t> fit_row_indices(const MeasurementSet& data);

// Throws CalibrationError when `fit_rows` rows are fewer than the constants `fit` asks for (one
// row cannot pin down both K and p).
void check_fit_row_count(int fit_rows, FitConstants fit);

// The search on every row given (roles ignored): the rows' inputs with `base`'s model settings.
// nullopt when cancelled.
std::optional<FittedConstants> fit_constants(const std::vector<Measurement>& rows,
                                             const Parameters& base,
                                             const CalibrationOptions& options,
                                             const CalibrationProgress& progress = {});

// Each row's prediction tabulated against ln s^p (docs/calibration.md, "The search"): the costly
// part of a fit, thousands of solves per row, while a fit on tabulated rows is lookups alone. A
// leave-one-out or coverage check fits many subsets of the same rows; tabulating each row once
// and fitting every subset from these tables gives each fit exactly what fit_constants() on that
// subset gives.
class CalibrationTables {
 public:
  // Tabulates `rows` with `base`'s model settings on options.threads threads. nullopt when
  // `progress` cancels; throws CalibrationError as fit_constants() does.
  static std::optional<CalibrationTables> tabulate(const std::vector<Measurement>& rows,
                                                   const Parameters& base,
                                                   const CalibrationOptions& options,
                                                   const CalibrationProgress& progress = {});
  // The fit on the rows at `subset` (indices into the rows tabulated, at least one). nullopt when
  // `keep_going` (polled now and then) returns false.
  std::optional<FittedConstants> fit(const std::vector<std::size_t>& subset,
                                     const std::function<bool(double)>& keep_going = {}) const;
  std::size_t size() const;

 private:
  friend class CalibrationSteps;
  struct Data;
  explicit CalibrationTables(std::shared_ptr<const Data> data) : data_(std::move(data)) {}
  std::shared_ptr<const Data> data_;
};

// `base` with K (c set at base's Poisson ratio) and p.
Parameters with_constants(const Parameters& base, double K, double p);

struct CalibrationRow {
  Measurement measurement;
  PublishedComparison baseline;  // base constants, no fit
  PublishedComparison fitted;    // the in-sample fit
  // Fit rows: predicted by a fit on every other fit row (leave-one-out). Check rows: the
  // in-sample fit, which never saw them.
  std::optional<PublishedComparison> held_out;
  double held_out_K = 0.0;
  double held_out_p = 1.0;
};

// Fit on every fit row outside one group, tested on that group.
struct GroupSplit {
  std::string test_group;
  FittedConstants fit;
  ComparisonSummary train;
  ComparisonSummary test;
};

struct CalibrationReport {
  FitConstants fit = FitConstants::K;
  Parameters base;
  FittedConstants fitted;
  std::vector<CalibrationRow> rows;
  ComparisonSummary baseline_fit_rows;
  ComparisonSummary baseline_check_rows;
  ComparisonSummary in_sample;      // fit rows at the in-sample fit
  ComparisonSummary leave_one_out;  // fit rows, each from the fit without it
  ComparisonSummary check_rows;     // check rows at the in-sample fit
  std::vector<GroupSplit> group_splits;
  ComparisonSummary group_split_test;  // every split's test rows pooled
  int fit_row_count = 0;
  int check_row_count = 0;
  bool cancelled = false;
};

// The whole calibration: in-sample fit, leave-one-out, group splits, check rows and the baseline.
// Throws CalibrationError when there is nothing to fit or `base` is invalid.
CalibrationReport calibrate(const MeasurementSet& data, const Parameters& base,
                            const CalibrationOptions& options,
                            const CalibrationProgress& progress = {});

// calibrate() in steps, for a caller that runs it a piece at a time (the explorer in the browser,
// which has no threads, between frames): each step tabulates as many fit rows as
// options.threads has threads (one where there are none), or runs as many of the fits (the
// in-sample one, one per left-out row, one per left-out group), in parallel; report() assembles
// what calibrate() returns, which runs these same steps.
class CalibrationSteps {
 public:
  // Checks what calibrate() checks; throws CalibrationError.
  CalibrationSteps(const MeasurementSet& data, const Parameters& base,
                   const CalibrationOptions& options);
  ~CalibrationSteps();
  CalibrationSteps(const CalibrationSteps&) = delete;
  CalibrationSteps& operator=(const CalibrationSteps&) = delete;
  // Runs the next step; true once every step has run (then report()).
  bool step();
  // The tabulations as the first 40 % (about as much work as the fits together for K and p, far
  // more for K alone), the fits as the rest.
  double fraction_done() const;
  // The report once every step has run; before that, a report marked cancelled.
  CalibrationReport report() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Whether eq. 7 is the paper's form (p = 1 with FoldLab's c = 26.9, docs/calibration.md), the
// paper's form with some other c, or the calibrated variant (p != 1).
enum class ModelForm { paper, paper_other_c, calibrated };
ModelForm model_form(const ModelSettings& m);
// One line naming the form and its constants, e.g. "paper's form: p = 1, c = 26.9 (K = 29.56 at
// nu = 0.3)".
std::string describe_model_form(const Parameters& p);

}  // namespace foldlab
