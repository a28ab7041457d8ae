// Memory and time budgets of the exports and of the commands that repeat solves. A desktop tool
// refuses work it cannot finish in a minute or so within a few hundred MB, up front and naming the
// limit, rather than running out of memory half way. Measured on the Release build (peak RSS and
// wall time of `foldlab export`): at the limits below, an OBJ and a glTF of the grid take 0.34 GB
// and 15 s, a CSV and an SVG of the fold lines 0.44 GB and 30 s.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/model/text_format.hpp"

namespace foldlab {

// Vertices of an exported grid (OBJ, glTF): 1024 x 1024.
inline constexpr std::int64_t kMaxExportGridVertices = 1024 * 1024;
// Points of all exported fold lines together (CSV, SVG): lines x spans x samples.
inline constexpr std::int64_t kMaxExportFoldPoints = 4'000'000;
// Solves of one run. A typical solve takes tens of microseconds, the slowest one within the input
// table's ranges (simpson_intervals = 10000, max_iterations = 1000) about 0.3 s: a sweep's steps
// are few enough to finish in under an hour even then, the stress and bench counts in minutes at
// typical settings.
inline constexpr std::int64_t kMaxSweepSteps = 10'000;
inline constexpr std::int64_t kMaxStressSamples = 10'000'000;
// cases x repeats: 6,000 cases x 10 repeats took 17 s and 71 MB on a 2-core machine, so this is
// about 5 min; the case count alone bounds the memory (100,000 cases, about 1.2 GB).
inline constexpr std::int64_t kMaxBenchSolves = 1'000'000;
inline constexpr int kMaxBenchCases = 100'000;
// Measurement rows of one calibration: each costs about 0.5 s of fitting, so 500 rows are minutes.
inline constexpr std::int64_t kMaxCalibrationRows = 500;

// nullopt when `count` (what a run is asked to repeat, e.g. "--steps") is within [1, limit].
inline std::optional<std::string> check_count_budget(const std::string& what, std::int64_t count,
                                                     std::int64_t limit) {
  if (count >= 1 && count <= limit) {
    return std::nullopt;
  }
  return what + " = " + std::to_string(count) + " must be in [1, " + std::to_string(limit) +
         "]: the run would take too long";
}

// nullopt when an nx x ny grid fits the budget, else why not.
inline std::optional<std::string> check_grid_budget(std::int64_t nx, std::int64_t ny) {
  if (nx * ny <= kMaxExportGridVertices) {
    return std::nullopt;
  }
  return detail::printf_string(
      "a %lld x %lld grid has %lld vertices, above the export limit of %lld (1024 x 1024); ask for "
      "a coarser --grid",
      static_cast<long long>(nx), static_cast<long long>(ny), static_cast<long long>(nx * ny),
      static_cast<long long>(kMaxExportGridVertices));
}

// nullopt when this many fold points fit the budget, else why not.
inline std::optional<std::string> check_fold_point_budget(std::int64_t points, int samples) {
  if (points <= kMaxExportFoldPoints) {
    return std::nullopt;
  }
  return detail::printf_string(
      "the fold lines would have %lld points (%d samples a line), above the export limit of %lld "
      "points; ask for fewer --samples",
      static_cast<long long>(points), samples, static_cast<long long>(kMaxExportFoldPoints));
}

}  // namespace foldlab
