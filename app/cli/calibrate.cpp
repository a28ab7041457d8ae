// `foldlab calibrate`: fits eq. 7's constants to measured n, z_max and Q (core/calibration.hpp)
// and prints the fit beside its held-out figures, so that a user sees how much of it is real.
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <utility>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/cli/commands.hpp"
#include "app/common/inputs.hpp"
#include "core/analysis/calibration.hpp"
#include "core/analysis/uncertainty.hpp"
#include "core/io/io.hpp"
#include "core/io/measurements.hpp"
#include "core/io/preset.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::cli {
namespace {

using nlohmann::json;

using detail::printf_string;

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

template <class T>
std::string optional_cell(const std::optional<T>& v, const char* pattern) {
  return v ? printf_string(pattern, static_cast<double>(*v)) : "–";
}

// "7 | 43.4 (-9.6%) | 1.251 (-3.0%)"
std::string model_cells(const PublishedComparison& c) {
  auto with_error = [](double value, const std::optional<double>& error, const char* pattern) {
    std::string out = printf_string(pattern, value);
    if (error) {
      out += " (" + printf_string("%+.1f", 100.0 * *error) + "%)";
    }
    return out;
  };
  return std::to_string(c.solution.n) + " | " + with_error(c.solution.z_max_mm, c.z_error, "%.1f") +
         " | " + with_error(c.solution.Q, c.Q_error, "%.3f");
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
  auto optional = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
  return {{"n", c.solution.n},
          {"z_max_mm", c.solution.z_max_mm},
          {"Q", c.solution.Q},
          {"regime", to_string(c.solution.regime)},
          {"z_error", optional(c.z_error)},
          {"Q_error", optional(c.Q_error)}};
}

json report_json(const CalibrationReport& r, const std::string& data_path) {
  json rows = json::array();
  for (const CalibrationRow& row : r.rows) {
    const Measurement& m = row.measurement;
    json j = {{"name", m.name},
              {"group", m.group},
              {"role", to_string(m.role)},
              {"observed",
               {{"n", m.observed.n ? json(*m.observed.n) : json(nullptr)},
                {"z_max_mm", m.observed.z_max_mm ? json(*m.observed.z_max_mm) : json(nullptr)},
                {"Q", m.observed.Q ? json(*m.observed.Q) : json(nullptr)}}},
              {"baseline", comparison_json(row.baseline)},
              {"fitted", comparison_json(row.fitted)}};
    if (row.held_out) {
      j["held_out"] = comparison_json(*row.held_out);
      j["held_out"]["K"] = row.held_out_K;
      j["held_out"]["p"] = row.held_out_p;
    }
    rows.push_back(std::move(j));
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

void print_report(const CalibrationReport& r, const std::string& data_path,
                  const std::string& base_name) {
  const FittedConstants& f = r.fitted;
  std::cout << "FoldLab calibrate: " << data_path << " (" << r.fit_row_count << " fit row"
            << (r.fit_row_count == 1 ? "" : "s") << ", " << r.check_row_count << " check row"
            << (r.check_row_count == 1 ? "" : "s") << "), " << to_string(r.base.model.method)
            << " method, fitting " << to_string(r.fit) << "\n";
  std::cout << "Base: \"" << detail::escaped(base_name) << "\", " << describe_model_form(r.base)
            << "\n";
  std::cout << "Loss (lexicographic): rows whose n is missed, then rows missed by more than one, "
               "then the mean of min(|model/observed - 1|, 1) over every observed z_max and Q.\n\n";
  const Parameters fitted = with_constants(r.base, f.K, f.p);
  std::cout << "Fitted: K = " << printf_string("%.4g", f.K)
            << ", p = " << printf_string("%.4g", f.p)
            << "  (c = " << printf_string("%.4g", fitted.model.load_constant_c)
            << " at nu = " << printf_string("%.3g", r.base.fabric.poisson_ratio) << ")\n";
  std::cout << "  score: " << score_line(f.score, r.in_sample.rows_with_n) << "\n";
  std::cout << "  the score stays the same for K in " << range(f.K_low, f.K_high, "%.4g")
            << " at p = " << printf_string("%.4g", f.p);
  if (r.fit == FitConstants::K_and_p) {
    std::cout << ", and for p in [" << printf_string("%.4g", f.p_low) << ", "
              << printf_string("%.4g", f.p_high) << "] at K = " << printf_string("%.4g", f.K)
              << "\n";
    std::cout << "  every point with this score lies in K "
              << range(f.best_K_min, f.best_K_max, "%.4g") << ", p ["
              << printf_string("%.3g", f.best_p_min) << ", " << printf_string("%.3g", f.best_p_max)
              << "] (K and p trade off along a valley)\n";
  } else {
    std::cout << "\n";
    if (f.equally_good_elsewhere > 0) {
      std::cout << "  " << f.equally_good_elsewhere
                << " other band(s) of K reach the same score, within K "
                << range(f.best_K_min, f.best_K_max, "%.4g") << "; the widest is taken\n";
    }
  }
  for (const std::string& note : range_end_notes(f, r.base.fabric.poisson_ratio)) {
    std::cout << "  " << note << "\n";
  }
  std::cout << "\n| row | observed n | z_max (mm) | Q | fitted n | z_max (mm) | Q | held-out n "
               "| z_max (mm) | Q | held-out K | p |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const CalibrationRow& row : r.rows) {
    const Measurement& m = row.measurement;
    std::cout << "| "
              << (m.name.empty() ? "row " + std::to_string(m.row) : detail::markdown_cell(m.name))
              << (m.role == MeasurementRole::check ? " (check)" : "") << " | "
              << optional_cell(m.observed.n, "%.0f") << " | "
              << optional_cell(m.observed.z_max_mm, "%g") << " | "
              << optional_cell(m.observed.Q, "%.2f") << " | " << model_cells(row.fitted) << " | ";
    if (row.held_out) {
      std::cout << model_cells(*row.held_out) << " | " << printf_string("%.4g", row.held_out_K)
                << " | " << printf_string("%.3g", row.held_out_p) << " |\n";
    } else {
      std::cout << "– | – | – | – | – |\n";
    }
  }
  std::cout << "\nHeld out: fit rows by leave-one-out (each predicted by a fit on the others); "
               "check rows by the in-sample fit, which never sees them.\n\n";
  std::cout << "Totals\n";
  std::cout << "  base constants, fit rows:           " << summary_text(r.baseline_fit_rows)
            << "\n";
  std::cout << "  in-sample fit, fit rows:            " << summary_text(r.in_sample) << "\n";
  if (r.fit_row_count >= 2) {
    std::cout << "  leave-one-out, fit rows:            " << summary_text(r.leave_one_out) << "\n";
  }
  if (!r.group_splits.empty()) {
    std::cout << "  fit on other groups, test rows:     " << summary_text(r.group_split_test)
              << "\n";
    for (const GroupSplit& s : r.group_splits) {
      std::cout << "    test " << (s.test_group.empty() ? "(no group)" : s.test_group)
                << " (fit on the rest: K = " << printf_string("%.4g", s.fit.K)
                << ", p = " << printf_string("%.3g", s.fit.p)
                << bound_note(s.fit, r.base.fabric.poisson_ratio) << "): " << summary_text(s.test)
                << "\n";
    }
  }
  if (r.check_row_count > 0) {
    std::cout << "  base constants, check rows:         " << summary_text(r.baseline_check_rows)
              << "\n";
    std::cout << "  fitted constants, check rows:       " << summary_text(r.check_rows) << "\n";
  }
}

}  // namespace

Command add_calibrate_command(CLI::App& app) {
  struct Options {
    std::string data_path;
    std::string fit = "K";
    InputOptions inputs;
    std::string save_preset_path;
    std::string calibrated_on;
    bool json = false;
    bool no_held_out = false;
    bool coverage = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "calibrate",
      "fit eq. 7's constants (K, or K and the exponent p) to measured n, z_max and Q, with "
      "leave-one-out and group-split figures beside the in-sample ones");
  command
      ->add_option("--data", options->data_path,
                   "measurements, CSV or JSON (e.g. data/paper-measurements.csv)")
      ->required()
      ->check(app::non_empty_path());
  command
      ->add_option("--fit", options->fit,
                   "K: fit K = c/(1-nu²) alone (p as the base has it); K,p: K and the exponent p "
                   "of s -> s^p in eq. 7")
      ->check(CLI::IsMember({"K", "K,p"}));
  command->add_option("--method", options->inputs.method, "solution method (default: the base's)")
      ->check(CLI::IsMember({"paper", "exact"}));
  app::add_law_option(*command, options->inputs.law);
  command
      ->add_option("--preset", options->inputs.preset_path,
                   "base preset: its model settings are used for every row, and --save-preset "
                   "starts from it (default: the built-in preset)")
      ->check(app::non_empty_path());
  command
      ->add_option("--set", options->inputs.assignments,
                   "override a base setting, KEY=VALUE (e.g. span_rule=L-2d)")
      ->type_name("KEY=VALUE");
  command
      ->add_option("--save-preset", options->save_preset_path,
                   "write the base preset with the fitted constants (model.load_constant_c, "
                   "model.stress_exponent_p)")
      ->check(app::non_empty_path());
  command->add_option("--calibrated-on", options->calibrated_on,
                      "how --save-preset names the data in its calibration record and labels "
                      "(default: the --data file's name)");
  command->add_flag("--json", options->json, "print JSON instead of tables");
  command->add_flag("--no-held-out", options->no_held_out,
                    "skip leave-one-out and group splits (the in-sample fit only)");
  command->add_flag("--coverage", options->coverage,
                    printf_string("measure how often the prediction intervals cover rows they "
                                  "were not fitted to (nested leave-one-out and group splits: "
                                  "about m² fits; at most %d fit rows for K, %d for K,p); done "
                                  "with --save-preset too, which stores it with the intervals "
                                  "(above those rows it saves without)",
                                  kMaxCoverageRowsK, kMaxCoverageRowsKandP));
  return [options] {
    return guarded([&] {
      check_distinct_files(
          {{"--save-preset", options->save_preset_path}},
          {{"--data", options->data_path}, {"--preset", options->inputs.preset_path}});
      // The label goes into the saved preset, whose JSON holds UTF-8 only.
      if (!detail::is_valid_utf8(options->calibrated_on)) {
        throw InputError("--calibrated-on '" + detail::cut(options->calibrated_on) +
                         "' is not UTF-8 text");
      }
      const Preset base = resolve_inputs(options->inputs);
      MeasurementSet data;
      try {
        data = load_measurements(options->data_path);
      } catch (const MeasurementError& e) {
        throw InputError(e.what());
      }
      // A preset stores one leave-one-out fit per fit row and holds at most
      // kMaxCalibrationEntries: say so before the fit rather than after it.
      const auto fit_row_count =
          std::count_if(data.rows.begin(), data.rows.end(),
                        [](const Measurement& m) { return m.role == MeasurementRole::fit; });
      if (!options->save_preset_path.empty() && !options->no_held_out &&
          static_cast<std::size_t>(fit_row_count) > kMaxCalibrationEntries) {
        throw InputError("--save-preset: " + std::to_string(fit_row_count) +
                         " fit rows would store as many leave-one-out fits, and a preset holds "
                         "at most " +
                         std::to_string(kMaxCalibrationEntries) +
                         " (add --no-held-out, or fit fewer rows)");
      }
      CalibrationOptions calibration;
      parse_fit_constants(options->fit, calibration.fit);
      calibration.held_out = !options->no_held_out;
      // A coverage check refits about m² times: beyond its row limit --coverage is refused before
      // any work, and --save-preset saves without it (the preset then says it was not measured).
      const bool coverage_in_reach = fit_row_count <= max_coverage_rows(calibration.fit);
      if (options->coverage && calibration.held_out && !coverage_in_reach) {
        throw InputError(printf_string(
            "--coverage: %d fit rows, and a coverage check fitting %s takes at most %d (it refits "
            "about m² times); fit K alone or use fewer rows",
            static_cast<int>(fit_row_count), options->fit.c_str(),
            max_coverage_rows(calibration.fit)));
      }
      const InterruptGuard interrupt_guard;
      CalibrationReport report;
      try {
        ProgressLine progress("calibrate");
        report = calibrate(data, base.parameters, calibration, std::ref(progress));
      } catch (const CalibrationError& e) {
        throw InputError(e.what());
      }
      if (report.cancelled) {
        return interrupted_exit();
      }
      std::string coverage;
      const bool saving = !options->save_preset_path.empty();
      if (calibration.held_out && saving && !options->coverage && !coverage_in_reach) {
        std::cerr << printf_string(
            "foldlab: coverage not measured: %d fit rows are more than the %d a coverage check "
            "fitting %s takes; the preset says so\n",
            static_cast<int>(fit_row_count), max_coverage_rows(calibration.fit),
            options->fit.c_str());
      }
      if (calibration.held_out && (options->coverage || (saving && coverage_in_reach))) {
        std::optional<std::vector<CoverageCheck>> checks;
        try {
          ProgressLine progress(printf_string("coverage of %d rows", report.fit_row_count));
          checks = cross_validated_coverage(data, base.parameters, calibration, std::ref(progress));
        } catch (const CalibrationError& e) {
          throw InputError(e.what());
        }
        if (!checks) {
          return interrupted_exit();
        }
        coverage = describe_coverage(*checks);
      }
      // Ctrl+C after the last progress call still means: print and write nothing.
      if (interrupted != 0) {
        return interrupted_exit();
      }
      if (options->json) {
        nlohmann::json j = report_json(report, options->data_path);
        const CalibrationRecord record = calibration_record(report, "");
        const std::optional<PredictionRange> level =
            prediction_interval(with_constants(base.parameters, report.fitted.K, report.fitted.p),
                                record.leave_one_out, record.residuals);
        j["interval_level"] = level ? nlohmann::json(level->level) : nlohmann::json(nullptr);
        j["interval_coverage"] =
            coverage.empty() ? nlohmann::json(nullptr) : nlohmann::json(coverage);
        std::cout << j.dump(2) << "\n";
      } else {
        print_report(report, options->data_path, base.name);
        if (!coverage.empty()) {
          std::cout << "\nPrediction intervals (jackknife+ over the leave-one-out fits), how often "
                       "they covered rows they were not fitted to:\n  "
                    << coverage << "\n";
        }
      }
      if (!options->save_preset_path.empty()) {
        Preset out = base;
        const FittedConstants& f = report.fitted;
        out.parameters = with_constants(base.parameters, f.K, f.p);
        out.name = base.name + " (calibrated: K = " + printf_string("%.4g", f.K) +
                   ", p = " + printf_string("%.4g", f.p) + ")";
        out.description = "Eq. 7's constants fitted by foldlab calibrate --fit " +
                          std::string(to_string(report.fit)) + " on " + options->data_path + " (" +
                          std::string(to_string(base.parameters.model.method)) +
                          " method): in-sample " + summary_text(report.in_sample) +
                          "; leave-one-out " + summary_text(report.leave_one_out) + ".";
        const std::string data_label =
            options->calibrated_on.empty()
                ? std::filesystem::path(options->data_path).filename().string()
                : options->calibrated_on;
        out.calibration = calibration_record(report, data_label, coverage);
        out.written_by = app::version_line();
        save_preset(out, options->save_preset_path);
        std::cerr << "foldlab: wrote " << options->save_preset_path << "\n";
      }
      return kExitOk;
    });
  };
}

}  // namespace foldlab::cli
