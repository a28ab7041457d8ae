// How far the model lands from published (or measured) results: per row and in total.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/io/preset.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

struct PublishedComparison {
  PublishedResult published;
  Solution solution;
  std::optional<int> n_difference;  // model n - published n
  std::optional<double> z_error;    // z_max / published - 1
  std::optional<double> Q_error;    // Q / published - 1
};

PublishedComparison compare_with_published(const PublishedResult& published, const Parameters& p);

struct ComparisonSummary {
  int rows_with_n = 0;
  int n_exact = 0;
  int n_within_one = 0;
  double median_abs_z_error = 0.0;
  double max_abs_z_error = 0.0;
  double median_abs_Q_error = 0.0;
  double max_abs_Q_error = 0.0;
  int rows_with_z = 0;  // the errors of z_max and Q stand on this many rows
  int rows_with_Q = 0;
};

ComparisonSummary summarize(const std::vector<PublishedComparison>& rows);

// "n exact 3/6, within ±1 5/6; |z_max error| median 8.0 %, max 74.2 %; |Q error| median ...",
// with "none observed" for an error that no row stands on.
std::string summary_text(const ComparisonSummary& s);

}  // namespace foldlab
