#include "core/analysis/comparison.hpp"

#include "core/model/text_format.hpp"

#include <algorithm>
#include <cmath>

namespace foldlab {
namespace {

// Median and maximum of |values|; both 0 for none.
std::pair<double, double> median_and_max_abs(std::vector<double> values) {
  if (values.empty()) {
    return {0.0, 0.0};
  }
  for (double& v : values) {
    v = std::abs(v);
  }
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  const double median =
      values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
  return {median, values.back()};
}

}  // namespace

PublishedComparison compare_with_published(const PublishedResult& published, const Parameters& p) {
  PublishedComparison row;
  row.published = published;
  row.solution = solve(p);
  if (published.n) {
    row.n_difference = row.solution.n - *published.n;
  }
  if (published.z_max_mm && *published.z_max_mm > 0.0) {
    row.z_error = row.solution.z_max_mm / *published.z_max_mm - 1.0;
  }
  if (published.Q && *published.Q > 0.0) {
    row.Q_error = row.solution.Q / *published.Q - 1.0;
  }
  return row;
}

ComparisonSummary summarize(const std::vector<PublishedComparison>& rows) {
  ComparisonSummary summary;
  std::vector<double> z_errors;
  std::vector<double> Q_errors;
  for (const PublishedComparison& row : rows) {
    if (row.n_difference) {
      ++summary.rows_with_n;
      summary.n_exact += *row.n_difference == 0;
      summary.n_within_one += std::abs(*row.n_difference) <= 1;
    }
    if (row.z_error) {
      z_errors.push_back(*row.z_error);
    }
    if (row.Q_error) {
      Q_errors.push_back(*row.Q_error);
    }
  }
  summary.rows_with_z = static_cast<int>(z_errors.size());
  summary.rows_with_Q = static_cast<int>(Q_errors.size());
  std::tie(summary.median_abs_z_error, summary.max_abs_z_error) = median_and_max_abs(z_errors);
  std::tie(summary.median_abs_Q_error, summary.max_abs_Q_error) = median_and_max_abs(Q_errors);
  return summary;
}

std::string summary_text(const ComparisonSummary& s) {
  std::string out = detail::printf_string("n exact %d/%d, within ±1 %d/%d", s.n_exact,
                                          s.rows_with_n, s.n_within_one, s.rows_with_n);
  auto errors = [&out](const char* label, int count, double median, double max) {
    out += std::string("; |") + label + " error| ";
    out += count == 0
               ? std::string("none observed")
               : detail::printf_string("median %.1f %%, max %.1f %%", 100 * median, 100 * max);
  };
  errors("z_max", s.rows_with_z, s.median_abs_z_error, s.max_abs_z_error);
  errors("Q", s.rows_with_Q, s.median_abs_Q_error, s.max_abs_Q_error);
  return out;
}

}  // namespace foldlab
