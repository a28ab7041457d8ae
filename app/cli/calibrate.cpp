#include "app/cli/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>

#include <unistd.h>

#include "app/cli/commands.hpp"
#include "app/cli/output.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/io/io.hpp"
#include "core/io/measurements.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {
namespace calibrate_command {
namespace {

using detail::printf_string;
using nlohmann::json;

// " [the best score reaches K at its lower bound ...; ...]" when the best-scoring constants reach
// an end of a range.
std::string bound_note(const FittedConstants& f, double poisson_ratio) {
  std::string out;
  for (const std::string& note : range_end_notes(f, poisson_ratio)) {
    out += (out.empty() ? " [" : "; ") + note;
  }
  return out.empty() ? out : out + "]";
}

// Ctrl+C during the fits: the work polls this flag through its progress callback and stops, and
// the command exits kExitInterrupted having written nothing (no half-made preset).
volatile std::sig_atomic_t interrupted = 0;
extern "C" void on_interrupt(int) {
  interrupted = 1;
}
// 128 + SIGINT, as a shell reports a command Ctrl+C ended.
constexpr int kExitInterrupted = 130;

int interrupted_exit() {
  std::cerr << "foldlab: calibrate: interrupted (Ctrl+C); nothing was written\n";
  return kExitInterrupted;
}

// Catches SIGINT while it lives, then restores what was there.
class InterruptGuard {
 public:
  InterruptGuard() : previous_(std::signal(SIGINT, on_interrupt)) { interrupted = 0; }
  ~InterruptGuard() { std::signal(SIGINT, previous_); }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  void (*previous_)(int);
};

// Progress on stderr, only when a person watches it (stderr a terminal): stdout stays the report
// (or JSON) alone, and scripts capturing stderr get no carriage-return noise. Returns false once
// Ctrl+C was pressed.
class ProgressLine {
 public:
  explicit ProgressLine(std::string what) : what_(std::move(what)), shown_(::isatty(2) == 1) {}
  ~ProgressLine() {
    if (shown_ && last_ >= 0) {
      std::cerr << "\r\033[K" << std::flush;
    }
  }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool operator()(double fraction) {
    const int percent = static_cast<int>(std::floor(100.0 * fraction));
    if (shown_ && percent != last_) {
      last_ = percent;
      std::cerr << "\r" << what_ << ": " << percent << " % (Ctrl+C stops)" << std::flush;
    }
    return interrupted == 0;
  }

 private:
  std::string what_;
  bool shown_;
  int last_ = -1;
};

std::string score_line(const CalibrationScore& s, int rows_with_n) {
  return "n missed in " + std::to_string(s.n_missed) + " of " + std::to_string(rows_with_n) +
         " rows (by more than one in " + std::to_string(s.n_missed_by_more_than_one) +
         "), mean capped error " + printf_string("%.2f", 100 * s.mean_relative_error) + " % over " +
         std::to_string(s.error_terms) + " z_max and Q values";
}

std::string range(double lo, double hi, const char* pattern) {
  return "[" + printf_string(pattern, lo) + ", " +
         (std::isinf(hi) ? "inf" : printf_string(pattern, hi)) + ")";
}

// "7 | 43.4 (-9.6%) | 1.251 (-3.0%)"
std::string model_cells(const PublishedComparison& c) {
  return std::to_string(c.solution.n) + " | " +
         value_with_error(c.solution.z_max_mm, c.z_error, "%.1f") + " | " +
         value_with_error(c.solution.Q, c.Q_error, "%.3f");
}

json summary_json(const ComparisonSummary& s) {
  return {{"rows_with_n", s.rows_with_n},         {"n_exact", s.n_exact},
          {"n_within_one", s.n_within_one},       {"median_abs_z_error", s.median_abs_z_error},
          {"max_abs_z_error", s.max_abs_z_error}, {"median_abs_Q_error", s.median_abs_Q_error},
          {"max_abs_Q_error", s.max_abs_Q_error}};
}

json number_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

// null, "lower", "upper" or "both".
json range_end_name(RangeEnd end) {
  switch (end) {
    case RangeEnd::none:
      return nullptr;
    case RangeEnd::lower:
      return "lower";
    case RangeEnd::upper:
      return "upper";
    case RangeEnd::both:
      return "both";
  }
  return nullptr;
}

json fit_json(const FittedConstants& f) {
  return {
      {"K", f.K},
      {"p", f.p},
      {"score",
       {{"n_missed", f.score.n_missed},
        {"n_missed_by_more_than_one", f.score.n_missed_by_more_than_one},
        {"mean_relative_error", f.score.mean_relative_error},
        {"error_terms", f.score.error_terms}}},
      {"K_range_at_p", {f.K_low, number_or_null(f.K_high)}},
      {"p_range_at_K", {f.p_low, f.p_high}},
      {"equally_good_elsewhere", f.equally_good_elsewhere},
      {"search_range", {{"K", {f.K_min, f.K_max}}, {"p", {f.p_min, f.p_max}}}},
      {"at_range_end", {{"K", range_end_name(f.K_end)}, {"p", range_end_name(f.p_end)}}},
      {"best_score_envelope",
       {{"K", {f.best_K_min, number_or_null(f.best_K_max)}}, {"p", {f.best_p_min, f.best_p_max}}}}};
}

json comparison_json(const PublishedComparison& c) {
  return {{"n", c.solution.n},
          {"z_max_mm", c.solution.z_max_mm},
          {"Q", c.solution.Q},
          {"regime", to_string(c.solution.regime)},
          {"z_error", optional_json(c.z_error)},
          {"Q_error", optional_json(c.Q_error)}};
}

json row_json(const CalibrationRow& row) {
  const Measurement& m = row.measurement;
  json j = {{"name", m.name},
            {"group", m.group},
            {"role", to_string(m.role)},
            {"observed",
             {{"n", optional_json(m.observed.n)},
              {"z_max_mm", optional_json(m.observed.z_max_mm)},
              {"Q", optional_json(m.observed.Q)}}},
            {"baseline", comparison_json(row.baseline)},
            {"fitted", comparison_json(row.fitted)}};
  if (row.held_out) {
    j["held_out"] = comparison_json(*row.held_out);
    j["held_out"]["K"] = row.held_out_K;
    j["held_out"]["p"] = row.held_out_p;
  }
  return j;
}

json report_json(const CalibrationReport& r, const std::string& data_path) {
  json rows = json::array();
  for (const CalibrationRow& row : r.rows) {
    rows.push_back(row_json(row));
  }
  json splits = json::array();
  for (const GroupSplit& s : r.group_splits) {
    splits.push_back({{"test_group", s.test_group},
                      {"fit", fit_json(s.fit)},
                      {"train", summary_json(s.train)},
                      {"test", summary_json(s.test)}});
  }
  return {{"data", data_path},
          {"fit", to_string(r.fit)},
          {"method", to_string(r.base.model.method)},
          {"base",
           {{"K", stiffness_constant_K(r.base)},
            {"p", r.base.model.stress_exponent_p},
            {"load_constant_c", r.base.model.load_constant_c},
            {"poisson_ratio", r.base.fabric.poisson_ratio},
            {"form", describe_model_form(r.base)}}},
          {"fitted", fit_json(r.fitted)},
          {"fitted_notes", range_end_notes(r.fitted, r.base.fabric.poisson_ratio)},
          {"fitted_load_constant_c",
           with_constants(r.base, r.fitted.K, r.fitted.p).model.load_constant_c},
          {"fit_rows", r.fit_row_count},
          {"check_rows", r.check_row_count},
          {"rows", rows},
          {"totals",
           {{"baseline_fit_rows", summary_json(r.baseline_fit_rows)},
            {"baseline_check_rows", summary_json(r.baseline_check_rows)},
            {"in_sample", summary_json(r.in_sample)},
            {"leave_one_out", summary_json(r.leave_one_out)},
            {"group_split_test", summary_json(r.group_split_test)},
            {"check_rows", summary_json(r.check_rows)}}},
          {"group_splits", splits}};
}

void print_header(const Result& result, std::ostream& out) {
  const CalibrationReport& r = result.report;
  out << "FoldLab calibrate: " << detail::escaped(result.data_path) << " (" << r.fit_row_count
      << " fit row" << (r.fit_row_count == 1 ? "" : "s") << ", " << r.check_row_count
      << " check row" << (r.check_row_count == 1 ? "" : "s") << "), "
      << to_string(r.base.model.method) << " method, fitting " << to_string(r.fit) << "\n";
  out << "Base: \"" << detail::escaped(result.base.name) << "\", " << describe_model_form(r.base)
      << "\n";
  out << "Loss (lexicographic): rows whose n is missed, then rows missed by more than one, "
         "then the mean of min(|model/observed - 1|, 1) over every observed z_max and Q.\n\n";
}

// The fitted constants, their score, and how far the same score reaches.
void print_fit(const CalibrationReport& r, std::ostream& out) {
  const FittedConstants& f = r.fitted;
  const Parameters fitted = with_constants(r.base, f.K, f.p);
  out << "Fitted: K = " << printf_string("%.4g", f.K) << ", p = " << printf_string("%.4g", f.p)
      << "  (c = " << printf_string("%.4g", fitted.model.load_constant_c)
      << " at nu = " << printf_string("%.3g", r.base.fabric.poisson_ratio) << ")\n";
  out << "  score: " << score_line(f.score, r.in_sample.rows_with_n) << "\n";
  out << "  the score stays the same for K in " << range(f.K_low, f.K_high, "%.4g")
      << " at p = " << printf_string("%.4g", f.p);
  if (r.fit == FitConstants::K_and_p) {
    out << ", and for p in [" << printf_string("%.4g", f.p_low) << ", "
        << printf_string("%.4g", f.p_high) << "] at K = " << printf_string("%.4g", f.K) << "\n";
    out << "  every point with this score lies in K " << range(f.best_K_min, f.best_K_max, "%.4g")
        << ", p [" << printf_string("%.3g", f.best_p_min) << ", "
        << printf_string("%.3g", f.best_p_max) << "] (K and p trade off along a valley)\n";
  } else {
    out << "\n";
    if (f.equally_good_elsewhere > 0) {
      out << "  " << f.equally_good_elsewhere
          << " other band(s) of K reach the same score, within K "
          << range(f.best_K_min, f.best_K_max, "%.4g") << "; the widest is taken\n";
    }
  }
  for (const std::string& note : range_end_notes(f, r.base.fabric.poisson_ratio)) {
    out << "  " << note << "\n";
  }
}

void print_rows(const CalibrationReport& r, std::ostream& out) {
  out << "\n| row | observed n | z_max (mm) | Q | fitted n | z_max (mm) | Q | held-out n "
         "| z_max (mm) | Q | held-out K | p |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const CalibrationRow& row : r.rows) {
    const Measurement& m = row.measurement;
    out << "| " << (m.name.empty() ? "row " + std::to_string(m.row) : detail::markdown_cell(m.name))
        << (m.role == MeasurementRole::check ? " (check)" : "") << " | "
        << optional_cell(m.observed.n, "%.0f") << " | " << optional_cell(m.observed.z_max_mm, "%g")
        << " | " << optional_cell(m.observed.Q, "%.2f") << " | " << model_cells(row.fitted)
        << " | ";
    if (row.held_out) {
      out << model_cells(*row.held_out) << " | " << printf_string("%.4g", row.held_out_K) << " | "
          << printf_string("%.3g", row.held_out_p) << " |\n";
    } else {
      out << "– | – | – | – | – |\n";
    }
  }
  out << "\nHeld out: fit rows by leave-one-out (each predicted by a fit on the others); "
         "check rows by the in-sample fit, which never sees them.\n\n";
}

void print_totals(const CalibrationReport& r, std::ostream& out) {
  out << "Totals\n";
  out << "  base constants, fit rows:           " << summary_text(r.baseline_fit_rows) << "\n";
  out << "  in-sample fit, fit rows:            " << summary_text(r.in_sample) << "\n";
  if (r.fit_row_count >= 2) {
    out << "  leave-one-out, fit rows:            " << summary_text(r.leave_one_out) << "\n";
  }
  if (!r.group_splits.empty()) {
    out << "  fit on other groups, test rows:     " << summary_text(r.group_split_test) << "\n";
    for (const GroupSplit& s : r.group_splits) {
      out << "    test " << (s.test_group.empty() ? "(no group)" : s.test_group)
          << " (fit on the rest: K = " << printf_string("%.4g", s.fit.K)
          << ", p = " << printf_string("%.3g", s.fit.p)
          << bound_note(s.fit, r.base.fabric.poisson_ratio) << "): " << summary_text(s.test)
          << "\n";
    }
  }
  if (r.check_row_count > 0) {
    out << "  base constants, check rows:         " << summary_text(r.baseline_check_rows) << "\n";
    out << "  fitted constants, check rows:       " << summary_text(r.check_rows) << "\n";
  }
}

void check_output_and_label(const Options& options) {
  // Over an input is the graver mistake: said first.
  check_outputs(
      {{"--save-preset", options.save_preset_path}},
      {{"--data", options.data_path}, app::preset_input("--preset", options.inputs.preset_path)});
  app::check_output_extension("--save-preset", options.save_preset_path, ".json", "a preset, JSON");
  // The label goes into the saved preset, whose JSON holds UTF-8 only.
  if (!detail::is_valid_utf8(options.calibrated_on)) {
    throw InputError("--calibrated-on '" + detail::cut(options.calibrated_on) +
                     "' is not UTF-8 text");
  }
}

CalibrationOptions calibration_options(const Options& options) {
  CalibrationOptions calibration;
  parse_fit_constants(options.fit, calibration.fit);
  calibration.held_out = !options.no_held_out;
  return calibration;
}

// The data, and the checks that need it before any fit: a preset stores one leave-one-out fit
// per fit row (at most kMaxCalibrationEntries), and a coverage check takes a limited number of
// rows; say so before the fit rather than after it.
MeasurementSet load_data(const Options& options) {
  try {
    return load_measurements(options.data_path);
  } catch (const MeasurementError& e) {
    throw InputError(e.what());
  }
}

int fit_rows(const MeasurementSet& data) {
  return static_cast<int>(
      std::count_if(data.rows.begin(), data.rows.end(),
                    [](const Measurement& m) { return m.role == MeasurementRole::fit; }));
}

void check_row_limits(const Options& options, const CalibrationOptions& calibration,
                      int fit_row_count) {
  if (!options.save_preset_path.empty() && !options.no_held_out &&
      static_cast<std::size_t>(fit_row_count) > kMaxCalibrationEntries) {
    throw InputError("--save-preset: " + std::to_string(fit_row_count) +
                     " fit rows would store as many leave-one-out fits, and a preset holds "
                     "at most " +
                     std::to_string(kMaxCalibrationEntries) +
                     " (add --no-held-out, or fit fewer rows)");
  }
  // Held-out fits of K and p take about m² fits' time: what would run past about a minute is
  // refused before any work, with the ways that finish.
  if (calibration.held_out && calibration.fit == FitConstants::K_and_p &&
      fit_row_count > kMaxHeldOutRowsKandP) {
    throw InputError(printf_string(
        "--fit K,p with held-out fits: %d fit rows would refit K and p once per row, each fit on "
        "the other %d rows, so the time grows as the rows squared: about %.0f minutes on a 2-core "
        "machine, "
        "where at most %d fit rows finish in about a minute. Fit K alone (--fit K), leave out "
        "the held-out fits (--no-held-out), or fit fewer rows",
        fit_row_count, fit_row_count - 1,
        std::ceil(kHeldOutSecondsPerRowSquared * fit_row_count * fit_row_count / 60.0),
        kMaxHeldOutRowsKandP));
  }
  // A coverage check refits about m² times: beyond its row limit --coverage is refused before
  // any work, and --save-preset saves without it (the preset then says it was not measured).
  if (options.coverage && calibration.held_out &&
      fit_row_count > max_coverage_rows(calibration.fit)) {
    throw InputError(printf_string(
        "--coverage: %d fit rows, and a coverage check fitting %s takes at most %d (it refits "
        "about m² times); fit K alone or use fewer rows",
        fit_row_count, options.fit.c_str(), max_coverage_rows(calibration.fit)));
  }
}

CalibrationReport fit(const MeasurementSet& data, const Parameters& base,
                      const CalibrationOptions& calibration) {
  try {
    ProgressLine progress("calibrate");
    return calibrate(data, base, calibration, std::ref(progress));
  } catch (const CalibrationError& e) {
    throw InputError(e.what());
  }
}

// describe_coverage() of the cross-validated intervals; nullopt when Ctrl+C stopped it.
std::optional<std::string> measured_coverage(const MeasurementSet& data, const Parameters& base,
                                             const CalibrationOptions& calibration,
                                             int fit_row_count) {
  std::optional<std::vector<CoverageCheck>> checks;
  try {
    ProgressLine progress(printf_string("coverage of %d rows", fit_row_count));
    checks = cross_validated_coverage(data, base, calibration, std::ref(progress));
  } catch (const CalibrationError& e) {
    throw InputError(e.what());
  }
  if (!checks) {
    return std::nullopt;
  }
  return describe_coverage(*checks);
}

// The coverage of the intervals where it was asked for or is to be saved (result.coverage), or
// a note that the rows are too many for it; result.interrupted when Ctrl+C stopped it.
void add_coverage(const Options& options, const CalibrationOptions& calibration,
                  const MeasurementSet& data, Result& result) {
  const int fit_row_count = result.report.fit_row_count;
  const bool saving = !options.save_preset_path.empty();
  const bool in_reach = fit_row_count <= max_coverage_rows(calibration.fit);
  if (calibration.held_out && saving && !options.coverage && !in_reach) {
    result.notes.push_back(printf_string(
        "coverage not measured: %d fit rows are more than the %d a coverage check fitting %s "
        "takes; the preset says so",
        fit_row_count, max_coverage_rows(calibration.fit), options.fit.c_str()));
  }
  if (calibration.held_out && (options.coverage || (saving && in_reach))) {
    const std::optional<std::string> coverage =
        measured_coverage(data, result.base.parameters, calibration, fit_row_count);
    result.coverage = coverage.value_or("");
    result.interrupted = !coverage;
  }
}

// The interval level of the fitted constants' prediction intervals, as the saved preset states it.
std::optional<double> fitted_interval_level(const Result& result) {
  const CalibrationRecord record = calibration_record(result.report, "");
  const std::optional<PredictionRange> range = prediction_interval(
      with_constants(result.base.parameters, result.report.fitted.K, result.report.fitted.p),
      record.leave_one_out, record.residuals);
  return range ? std::optional<double>(range->level) : std::nullopt;
}

}  // namespace

void declare(CLI::App& app, Options& options) {
  CLI::App* command = app.add_subcommand(
      "calibrate",
      "fit eq. 7's constants (K, or K and the exponent p) to measured n, z_max and Q, with "
      "leave-one-out and group-split figures beside the in-sample ones");
  command
      ->add_option("--data", options.data_path,
                   "measurements, CSV or JSON (e.g. data/paper-measurements.csv)")
      ->required()
      ->check(app::non_empty_path());
  command
      ->add_option("--fit", options.fit,
                   "K: fit K = c/(1-nu²) alone (p as the base has it); K,p: K and the exponent p "
                   "of s -> s^p in eq. 7")
      ->check(app::one_of("fit", {"K", "K,p"}));
  command->add_option("--method", options.inputs.method, "solution method (default: the base's)")
      ->check(app::input_choice("method"));
  app::add_law_option(*command, options.inputs.law);
  command
      ->add_option("--preset", options.inputs.preset_path,
                   "base preset: its model settings are used for every row, and --save-preset "
                   "starts from it (default: the built-in preset)")
      ->check(app::non_empty_path());
  command
      ->add_option("--set", options.inputs.assignments,
                   "override a base setting, KEY=VALUE (e.g. span_rule=L-2d)")
      ->type_name("KEY=VALUE");
  command
      ->add_option("--save-preset", options.save_preset_path,
                   "write the base preset with the fitted constants (model.load_constant_c, "
                   "model.stress_exponent_p)")
      ->check(app::non_empty_path());
  command->add_option("--calibrated-on", options.calibrated_on,
                      "how --save-preset names the data in its calibration record and labels "
                      "(default: the --data file's name)");
  command->add_flag("--json", options.json, "print JSON instead of tables");
  command->add_flag("--no-held-out", options.no_held_out,
                    "skip leave-one-out and group splits (the in-sample fit only)");
  command->add_flag("--coverage", options.coverage,
                    printf_string("measure how often the prediction intervals cover rows they "
                                  "were not fitted to (nested leave-one-out and group splits: "
                                  "about m² fits; at most %d fit rows for K, %d for K,p); done "
                                  "with --save-preset too, which stores it with the intervals "
                                  "(above those rows it saves without)",
                                  kMaxCoverageRowsK, kMaxCoverageRowsKandP));
}

Result run(const Options& options) {
  check_output_and_label(options);
  Result result;
  result.base = resolve_inputs(options.inputs);
  result.data_path = options.data_path;
  const MeasurementSet data = load_data(options);
  const int fit_row_count = fit_rows(data);
  const CalibrationOptions calibration = calibration_options(options);
  check_row_limits(options, calibration, fit_row_count);
  result.report = fit(data, result.base.parameters, calibration);
  if (result.report.cancelled) {
    result.interrupted = true;
    return result;
  }
  add_coverage(options, calibration, data, result);
  // Ctrl+C after the last progress call still means: print and write nothing.
  result.interrupted = result.interrupted || interrupted != 0;
  if (options.json && !result.interrupted) {
    result.interval_level = fitted_interval_level(result);
  }
  return result;
}

void print_text(const Result& result, std::ostream& out) {
  print_header(result, out);
  print_fit(result.report, out);
  print_rows(result.report, out);
  print_totals(result.report, out);
  if (!result.coverage.empty()) {
    out << "\nPrediction intervals (jackknife+ over the leave-one-out fits), how often they "
           "covered rows they were not fitted to:\n  "
        << result.coverage << "\n";
  }
}

json print_json(const Result& result) {
  json out = report_json(result.report, result.data_path);
  out["interval_level"] = optional_json(result.interval_level);
  out["interval_coverage"] = result.coverage.empty() ? json(nullptr) : json(result.coverage);
  return out;
}

void save_calibrated_preset(const Options& options, const Result& result) {
  const CalibrationReport& report = result.report;
  const FittedConstants& f = report.fitted;
  Preset out = result.base;
  out.parameters = with_constants(result.base.parameters, f.K, f.p);
  out.name = result.base.name + " (calibrated: K = " + printf_string("%.4g", f.K) +
             ", p = " + printf_string("%.4g", f.p) + ")";
  out.description = "Eq. 7's constants fitted by foldlab calibrate --fit " +
                    std::string(to_string(report.fit)) + " on " + options.data_path + " (" +
                    std::string(to_string(result.base.parameters.model.method)) +
                    " method): in-sample " + summary_text(report.in_sample) + "; leave-one-out " +
                    summary_text(report.leave_one_out) + ".";
  const std::string data_label = options.calibrated_on.empty()
                                     ? std::filesystem::path(options.data_path).filename().string()
                                     : options.calibrated_on;
  out.calibration = calibration_record(report, data_label, result.coverage);
  out.written_by = app::version_line();
  save_preset(out, options.save_preset_path);
}

int execute(const Options& options) {
  // Up until the preset is written: a Ctrl+C stops the fits, never a half-written file.
  const InterruptGuard interrupt_guard;
  const Result result = run(options);
  write_notes(result.notes, std::cerr);
  if (result.interrupted) {
    return interrupted_exit();
  }
  if (options.json) {
    write_json(print_json(result), std::cout);
  } else {
    print_text(result, std::cout);
  }
  if (!options.save_preset_path.empty()) {
    save_calibrated_preset(options, result);
    write_notes({"wrote " + options.save_preset_path}, std::cerr);
  }
  return kExitOk;
}

}  // namespace calibrate_command

Command add_calibrate_command(CLI::App& app) {
  return make_command(app, calibrate_command::declare, calibrate_command::execute);
}

}  // namespace foldlab::cli
