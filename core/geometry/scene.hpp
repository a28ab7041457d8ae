// The pipeline parameters -> solution -> fold lines / grid -> normals, lazy in both directions:
// a stage recomputes only when an input it depends on has changed AND somebody asks for its
// output. A view that is hidden does not ask, so it costs nothing; the headless `solve` never asks
// for the grid, so it never builds one.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/geometry/geometry.hpp"
#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

enum class Stage { solution, fold_lines, grid, normals };

// Folds found elsewhere than by the closed form (the tension field's, core/field/field_folds.hpp)
// that a scene draws in place of the closed form's: n, Q, z_max and a_0 (bottom) .. a_n (top),
// hung depths below the supports' line; a_mm has n + 1 entries, none when n = 0.
struct FoldOverride {
  int n = 0;
  double Q = 1.0;
  double z_max_mm = 0.0;
  std::vector<double> a_mm;

  bool operator==(const FoldOverride&) const = default;
};
inline constexpr int kStageCount = 4;
std::string_view to_string(Stage s);

struct StageStats {
  std::uint64_t evaluations = 0;
  double total_ms = 0.0;
  double last_ms = 0.0;
};

class Scene {
 public:
  explicit Scene(const Parameters& parameters = Parameters{});

  // Inputs. Each is a no-op when the value does not change.
  void set_parameters(const Parameters& parameters);
  void set_grid_resolution(int nx, int ny);
  void set_fold_line_samples(int samples);
  // Folds to draw in place of the closed form's (nothing: the closed form's). The rest of the
  // solution (span, regime, the law's constants) stays the closed form's.
  void set_folds(std::optional<FoldOverride> folds);
  const std::optional<FoldOverride>& folds() const { return folds_; }

  const Parameters& parameters() const { return parameters_; }
  int grid_nx() const { return grid_nx_; }
  int grid_ny() const { return grid_ny_; }

  // Outputs, computed on demand.
  const Solution& solution();
  const FoldLines& fold_lines();
  const DeformedGrid& grid();  // positions, triangles and fibre error; normals via normals()
  const std::vector<Eigen::Vector3f>& normals();
  // How the solution's folds are rounded, and the centre fibre through them: computed with the
  // first of fold lines or grid that needs them (and timed with it), kept until the next solve.
  const FoldRounding& fold_rounding();
  const CentreFibre& centre_fibre();

  const StageStats& stats(Stage stage) const { return stats_[index(stage)]; }
  // Changes each time the stage's output is recomputed, to a number no other scene's stage has
  // had: a consumer (a GPU buffer, say) that remembers the number it last saw knows whether to
  // upload again, even when it was another scene's.
  std::uint64_t version(Stage stage) const { return versions_[index(stage)]; }
  // Zeroes the counters (not the versions).
  void reset_stats();

 private:
  static std::size_t index(Stage stage) { return static_cast<std::size_t>(stage); }
  void invalidate_from(Stage stage);
  template <class Compute>
  void run(Stage stage, Compute&& compute);

  Parameters parameters_;
  int grid_nx_ = 128;
  int grid_ny_ = 128;
  int fold_line_samples_ = 201;

  std::optional<FoldOverride> folds_;
  Solution solution_;
  FoldRounding rounding_;
  std::optional<CentreFibre> fibre_;  // empty while stale, like the rounding
  bool rounding_stale_ = true;
  FoldLines fold_lines_;
  DeformedGrid grid_;
  std::array<bool, kStageCount> stale_{true, true, true, true};
  std::array<StageStats, kStageCount> stats_{};
  std::array<std::uint64_t, kStageCount> versions_{};
};

}  // namespace foldlab
