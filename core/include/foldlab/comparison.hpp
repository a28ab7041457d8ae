// How far the model lands from published (or measured) results: per row and in total.
#pragma once

#include <optional>
#include <vector>

#include "foldlab/preset.hpp"
#include "foldlab/solver.hpp"

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
};

ComparisonSummary summarize(const std::vector<PublishedComparison>& rows);

}  // namespace foldlab
