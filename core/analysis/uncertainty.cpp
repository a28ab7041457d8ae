#include "core/analysis/uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>
#include <utility>

#include "core/analysis/parallel_tasks.hpp"
#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

using detail::printf_string;

bool close(double a, double b) {
  return std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b));
}

// K = 29.56 at p = 1: the constant FoldLab reads eq. 7 as printed with (c = 26.9 at nu = 0.3), to
// the four digits a user types.
bool is_printed_constant(const Parameters& p) {
  const double printed_K =
      kCalibratedLoadConstantC / (1.0 - kDefaultPoissonRatio * kDefaultPoissonRatio);
  return p.model.stress_exponent_p == 1.0 &&
         std::abs(stiffness_constant_K(p) / printed_K - 1.0) < 2e-4;
}

}  // namespace

double interval_level(int residuals) {
  return residuals >= 2 ? (residuals - 1.0) / (residuals + 1.0) : 0.0;
}

HeldOutResidual held_out_residual(const PublishedResult& observed, const Solution& predicted) {
  // Clamped to what a preset stores (kMaxResidualFolds, kMaxLogResidual): only an absurd row gets
  // there, and its interval is clamped to the physical range anyway.
  HeldOutResidual r;
  if (observed.n) {
    r.n = std::clamp(static_cast<double>(*observed.n) - predicted.n, -kMaxResidualFolds,
                     kMaxResidualFolds);
  }
  if (observed.z_max_mm && predicted.z_max_mm > 0.0) {
    r.log_z_max = std::clamp(std::log(*observed.z_max_mm) - std::log(predicted.z_max_mm),
                             -kMaxLogResidual, kMaxLogResidual);
  }
  if (observed.Q && predicted.n >= 1) {
    r.log_Q = std::clamp(std::log(*observed.Q) - std::log(predicted.Q), -kMaxLogResidual,
                         kMaxLogResidual);
  }
  return r;
}

namespace {

// The smallest and largest of the shifted predictions of one quantity.
struct Extremes {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  int count = 0;
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    ++count;
  }
};

}  // namespace

std::optional<PredictionRange> prediction_interval(const Parameters& p,
                                                   const std::vector<Eq7Constants>& fits,
                                                   const std::vector<HeldOutResidual>& residuals) {
  Extremes n;
  Extremes log_z;
  Extremes log_Q;
  double sag_mm = 0.0;  // A(L, l), the same under every fit's constants
  for (std::size_t i = 0; i < fits.size() && i < residuals.size(); ++i) {
    const Solution s = solve(with_constants(p, fits[i].K, fits[i].p));
    sag_mm = s.sag_amplitude_mm;
    const HeldOutResidual& r = residuals[i];
    // Symmetric about each fit's prediction, as the jackknife+ has it: an error seen one way on
    // one row can go the other way on the next (signed shifts missed the table split's Q rows).
    auto add = [](Extremes& e, double prediction, double residual) {
      e.add(prediction - std::abs(residual));
      e.add(prediction + std::abs(residual));
      --e.count;  // one residual, two ends
    };
    if (r.n) {
      add(n, s.n, *r.n);
    }
    if (r.log_z_max && s.z_max_mm > 0.0) {
      add(log_z, std::log(s.z_max_mm), *r.log_z_max);
    }
    if (r.log_Q && s.n >= 1) {
      add(log_Q, std::log(s.Q), *r.log_Q);
    }
  }
  if (n.count < 2) {
    return std::nullopt;
  }
  PredictionRange out;
  out.level = interval_level(n.count);
  // Every end within what the geometry allows, whatever the residuals say: n from 0 to the
  // solver's cap; z_max from 0 to the sag A of the upper edge (A² = a_n² + z_max², and A is the
  // same for every fit: it depends on L and l alone) and to h; Q from 1 to a_0 / a_n at the least
  // a_n the solver gives, 0.01 h or, where the edge sags less (flat folds), A: 101 for most cloths.
  // A quantity the data never observed often enough gets that whole range. Clamped before
  // rounding: a residual of any size stays a finite int.
  const double h = p.hanging.height_mm;
  const bool sags = sag_mm > 0.0;
  const double z_ceiling = sags ? std::min(h, sag_mm) : h;
  const double least_a_n = sags ? std::min(0.01 * h, sag_mm) : 0.01 * h;
  const double Q_ceiling = kLowerBoundaryFactor * h / least_a_n;
  auto folds = [](double v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0, static_cast<double>(kMaxWrinkles))));
  };
  out.n_min = folds(n.lo);
  out.n_max = std::max(out.n_min, folds(n.hi));
  const bool z_known = log_z.count >= 2;
  out.z_max_min_mm = z_known ? std::min(std::exp(log_z.lo), z_ceiling) : 0.0;
  out.z_max_max_mm =
      z_known ? std::clamp(std::exp(log_z.hi), out.z_max_min_mm, z_ceiling) : z_ceiling;
  const bool Q_known = log_Q.count >= 2;
  out.Q_min = Q_known ? std::clamp(std::exp(log_Q.lo), 1.0, Q_ceiling) : 1.0;
  out.Q_max = Q_known ? std::clamp(std::exp(log_Q.hi), out.Q_min, Q_ceiling) : Q_ceiling;
  return out;
}

void hold_prediction(PredictionRange& range, const Solution& predicted) {
  range.n_min = std::min(range.n_min, predicted.n);
  range.n_max = std::max(range.n_max, predicted.n);
  range.z_max_min_mm = std::min(range.z_max_min_mm, predicted.z_max_mm);
  range.z_max_max_mm = std::max(range.z_max_max_mm, predicted.z_max_mm);
  if (predicted.n >= 1) {
    range.Q_min = std::min(range.Q_min, predicted.Q);
    range.Q_max = std::max(range.Q_max, predicted.Q);
  }
}

bool record_applies(const Parameters& p, const CalibrationRecord& record) {
  return p.model.method == record.method && p.model.law == record.law &&
         close(stiffness_constant_K(p), record.fitted.K) &&
         close(p.model.stress_exponent_p, record.fitted.p);
}

ModelStanding model_standing(const Parameters& p, const std::optional<CalibrationRecord>& record) {
  return model_standing(p, record, solve(p));
}

ModelStanding model_standing(const Parameters& p, const std::optional<CalibrationRecord>& record,
                             const Solution& predicted) {
  ModelStanding out;
  const double K = stiffness_constant_K(p);
  const double exponent = p.model.stress_exponent_p;
  const std::string constants = printf_string("K = %.4g, p = %.4g", K, exponent);
  out.form = exponent == 1.0 ? "printed" : "calibrated";
  const bool applies = record && record_applies(p, *record);
  if (applies) {
    out.label = "calibrated on " + record->calibrated_on + " (" + constants + ", " +
                std::to_string(record->fit_rows) + (record->fit_rows == 1 ? " row, " : " rows, ") +
                std::string(to_string(record->method)) + " method)";
  } else if (p.model.law != WrinkleLawKind::conci) {
    const WrinkleLaw& law = wrinkle_law(p.model.law);
    out.label = std::string(law.title()) +
                (model_form(p.model) == ModelForm::paper ? ", as published (" : ", tuned (") +
                constants + ")";
  } else if (is_printed_constant(p)) {
    out.label = "Conci's eq. 7 as printed (" + constants + ")";
  } else if (exponent == 1.0) {
    out.label = "eq. 7 as printed with another constant (" + constants + ")";
  } else {
    out.label = "eq. 7 with s -> s^p (" + constants + "), not a stored calibration";
  }
  if (!applies) {
    out.range_basis =
        record ? "none: these constants, this method or this law differ from the preset's "
                 "calibration"
               : "none: the preset carries no calibration";
    return out;
  }
  out.range = prediction_interval(p, record->leave_one_out, record->residuals);
  if (!out.range) {
    out.range_basis = "none: the calibration stored fewer than two leave-one-out residuals";
    return out;
  }
  hold_prediction(*out.range, predicted);
  out.range_basis = printf_string("jackknife+ over the %zu leave-one-out fits on ",
                                  record->leave_one_out.size()) +
                    record->calibrated_on + " and each one's error on the row it left out" +
                    (record->coverage.empty() ? std::string("; coverage not measured")
                                              : "; cross-validated coverage: " + record->coverage);
  return out;
}

CalibrationRecord calibration_record(const CalibrationReport& report, std::string calibrated_on,
                                     std::string coverage) {
  CalibrationRecord record;
  record.calibrated_on = std::move(calibrated_on);
  record.method = report.base.model.method;
  record.law = report.base.model.law;
  record.fitted = {report.fitted.K, report.fitted.p};
  record.fit_rows = report.fit_row_count;
  record.equally_good = report.fitted.equally_good_ends;
  for (const CalibrationRow& row : report.rows) {
    if (row.measurement.role == MeasurementRole::fit && row.held_out) {
      record.leave_one_out.push_back({row.held_out_K, row.held_out_p});
      record.residuals.push_back(
          held_out_residual(row.measurement.observed, row.held_out->solution));
    }
  }
  record.coverage = std::move(coverage);
  return record;
}

namespace {

// One held-out part of the fit rows and the rows it is predicted from.
struct Split {
  std::vector<std::size_t> train;
  std::vector<std::size_t> test;
};

void count(QuantityCoverage& into, std::optional<double> observed, double lo, double hi,
           double level) {
  if (!observed) {
    return;
  }
  // Weighted by rows, so that the stated level reads as the share the rows should have met.
  into.level = (into.level * into.total + level) / (into.total + 1);
  ++into.total;
  into.covered += *observed >= lo && *observed <= hi;
}

}  // namespace

int max_coverage_rows(FitConstants fit) {
  return fit == FitConstants::K ? kMaxCoverageRowsK : kMaxCoverageRowsKandP;
}

namespace {

// A named way of holding out parts of the fit rows (rows by index into data.rows).
using NamedSplits = std::pair<std::string, std::vector<Split>>;

void check_coverage_rows(std::size_t fit_rows, FitConstants fit) {
  check_fit_row_count(static_cast<int>(fit_rows), fit);
  if (static_cast<int>(fit_rows) > max_coverage_rows(fit)) {
    throw CalibrationError(printf_string(
        "%zu fit rows: a coverage check fitting %s takes at most %d (it refits about m² times, "
        "each on m rows; docs/performance.md); fit K alone or use fewer rows",
        fit_rows, std::string(to_string(fit)).c_str(), max_coverage_rows(fit)));
  }
}

// Leave-one-out, and with more than one group, each group held out in turn.
std::vector<NamedSplits> coverage_splits(const MeasurementSet& data,
                                         const std::vector<std::size_t>& fit_rows) {
  std::vector<NamedSplits> checks(1);
  checks[0].first = "leave-one-out";
  std::set<std::string> groups;
  for (std::size_t i : fit_rows) {
    Split split;
    split.test = {i};
    std::copy_if(fit_rows.begin(), fit_rows.end(), std::back_inserter(split.train),
                 [i](std::size_t k) { return k != i; });
    checks[0].second.push_back(std::move(split));
    groups.insert(data.rows[i].group);
  }
  if (groups.size() > 1) {
    checks.push_back({"fit on the other groups, test on one", {}});
    for (const std::string& group : groups) {
      Split split;
      for (std::size_t i : fit_rows) {
        (data.rows[i].group == group ? split.test : split.train).push_back(i);
      }
      checks.back().second.push_back(std::move(split));
    }
  }
  return checks;
}

// The fit without one training row of a split, for that row's residual under it.
struct Job {
  std::size_t check;
  std::size_t split;
  std::size_t left_out;
  std::vector<std::size_t> rows;  // positions in the tables
};

// One job per training row of every split large enough; `position`: a row's place in the tables
// by its index in data.rows.
std::vector<Job> held_out_jobs(const std::vector<NamedSplits>& checks, int needed,
                               const std::vector<std::size_t>& position) {
  std::vector<Job> jobs;
  for (std::size_t c = 0; c < checks.size(); ++c) {
    for (std::size_t s = 0; s < checks[c].second.size(); ++s) {
      const Split& split = checks[c].second[s];
      // Each training row's residual under the fit without it: that fit needs `needed` rows.
      if (static_cast<int>(split.train.size()) < needed + 1) {
        continue;
      }
      for (std::size_t left_out : split.train) {
        Job job{c, s, left_out, {}};
        for (std::size_t k : split.train) {
          if (k != left_out) {
            job.rows.push_back(position[k]);
          }
        }
        jobs.push_back(std::move(job));
      }
    }
  }
  return jobs;
}

struct JobResults {
  std::vector<Eq7Constants> fits;
  std::vector<HeldOutResidual> residuals;
};

// Every job at once, each into its own slot, so that the counts do not depend on the number of
// threads; nullopt when cancelled.
std::optional<JobResults> run_jobs(const std::vector<Job>& jobs, const CalibrationTables& tables,
                                   const MeasurementSet& data, const Parameters& base, int threads,
                                   const std::function<bool(double)>& progress) {
  std::vector<std::optional<Eq7Constants>> fits(jobs.size());
  std::vector<HeldOutResidual> residuals(jobs.size());
  const bool finished = run_tasks(
      jobs.size(), threads,
      [&](std::size_t i, const std::atomic<bool>& stop) {
        const std::optional<FittedConstants> fit =
            tables.fit(jobs[i].rows, [&stop](double) { return !stop.load(); });
        if (!fit) {
          return;
        }
        const Measurement& m = data.rows[jobs[i].left_out];
        fits[i] = Eq7Constants{fit->K, fit->p};
        residuals[i] = held_out_residual(
            m.observed, solve(with_constants(parameters_for(m, base), fit->K, fit->p)));
      },
      progress);
  if (!finished || std::any_of(fits.begin(), fits.end(), [](const auto& f) { return !f; })) {
    return std::nullopt;
  }
  JobResults out;
  for (const std::optional<Eq7Constants>& fit : fits) {
    out.fits.push_back(*fit);
  }
  out.residuals = std::move(residuals);
  return out;
}

// Whether the split's test rows fall inside the prediction intervals of the fits without each of
// its training rows.
void count_split(CoverageCheck& check, const MeasurementSet& data, const Parameters& base,
                 const Split& split, const std::vector<Eq7Constants>& split_fits,
                 const std::vector<HeldOutResidual>& split_residuals) {
  for (std::size_t j : split.test) {
    const Measurement& m = data.rows[j];
    const std::optional<PredictionRange> r =
        prediction_interval(parameters_for(m, base), split_fits, split_residuals);
    if (!r) {
      continue;
    }
    const std::optional<double> n =
        m.observed.n ? std::optional<double>(*m.observed.n) : std::nullopt;
    count(check.n, n, r->n_min, r->n_max, r->level);
    count(check.z_max, m.observed.z_max_mm, r->z_max_min_mm, r->z_max_max_mm, r->level);
    count(check.Q, m.observed.Q, r->Q_min, r->Q_max, r->level);
  }
}

// The jobs' results gathered per split (the jobs run in the order of the checks and their
// splits), and each split's test rows counted.
std::vector<CoverageCheck> tally(const std::vector<NamedSplits>& checks,
                                 const std::vector<Job>& jobs, const JobResults& results,
                                 const MeasurementSet& data, const Parameters& base) {
  std::vector<CoverageCheck> out;
  std::size_t next_job = 0;
  for (std::size_t c = 0; c < checks.size(); ++c) {
    CoverageCheck check;
    check.name = checks[c].first;
    for (std::size_t s = 0; s < checks[c].second.size(); ++s) {
      std::vector<Eq7Constants> split_fits;
      std::vector<HeldOutResidual> split_residuals;
      for (; next_job < jobs.size() && jobs[next_job].check == c && jobs[next_job].split == s;
           ++next_job) {
        split_fits.push_back(results.fits[next_job]);
        split_residuals.push_back(results.residuals[next_job]);
      }
      if (!split_fits.empty()) {
        count_split(check, data, base, checks[c].second[s], split_fits, split_residuals);
      }
    }
    out.push_back(std::move(check));
  }
  return out;
}

}  // namespace

std::optional<std::vector<CoverageCheck>> cross_validated_coverage(
    const MeasurementSet& data, const Parameters& base, const CalibrationOptions& options,
    const CalibrationProgress& progress) {
  const std::vector<std::size_t> fit_rows = fit_row_indices(data);
  check_coverage_rows(fit_rows.size(), options.fit);
  const std::vector<NamedSplits> checks = coverage_splits(data, fit_rows);
  CalibrationOptions inner = options;
  inner.held_out = false;
  const int needed = options.fit == FitConstants::K ? 1 : 2;
  // Each fit row tabulated once (the first 30 % of the progress); every nested fit then looks up
  // those tables.
  std::vector<Measurement> fit_measurements;
  std::vector<std::size_t> position(data.rows.size());
  for (std::size_t k = 0; k < fit_rows.size(); ++k) {
    fit_measurements.push_back(data.rows[fit_rows[k]]);
    position[fit_rows[k]] = k;
  }
  auto keep_going = [&](double fraction) { return !progress || progress(fraction); };
  const std::optional<CalibrationTables> tables = CalibrationTables::tabulate(
      fit_measurements, base, inner, [&](double f) { return keep_going(0.3 * f); });
  if (!tables) {
    return std::nullopt;
  }
  const std::vector<Job> jobs = held_out_jobs(checks, needed, position);
  const std::optional<JobResults> results =
      run_jobs(jobs, *tables, data, base, options.threads,
               [&](double f) { return keep_going(0.3 + 0.7 * f); });
  if (!results) {
    return std::nullopt;
  }
  return tally(checks, jobs, *results, data, base);
}

std::string describe_coverage(const std::vector<CoverageCheck>& checks) {
  std::string out;
  for (const CoverageCheck& c : checks) {
    if (c.n.total == 0) {
      continue;
    }
    auto part = [](const char* name, const QuantityCoverage& q) {
      return q.total > 0 ? printf_string(", %s %d/%d", name, q.covered, q.total) : std::string();
    };
    out += (out.empty() ? "" : "; ") + c.name + printf_string(" n %d/%d", c.n.covered, c.n.total) +
           part("z_max", c.z_max) + part("Q", c.Q) +
           printf_string(" at a stated %.0f %%", 100.0 * c.n.level);
  }
  return out;
}

}  // namespace foldlab
