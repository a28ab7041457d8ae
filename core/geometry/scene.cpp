#include "core/geometry/scene.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <utility>

namespace foldlab {

std::string_view to_string(Stage s) {
  switch (s) {
    case Stage::solution:
      return "solution";
    case Stage::fold_lines:
      return "fold_lines";
    case Stage::grid:
      return "grid";
    case Stage::normals:
      return "normals";
  }
  return "unknown";
}

namespace {

// One count for every scene: a view that draws one scene and then another (the 3D view's fold
// source) never takes the other's stage for the one it uploaded because their numbers agree.
std::uint64_t next_version() {
  static std::atomic<std::uint64_t> count{0};
  return ++count;
}

}  // namespace

Scene::Scene(const Parameters& parameters) : parameters_(parameters) {}

// What depends on what: the solution feeds fold lines and grid; the grid feeds the normals.
void Scene::invalidate_from(Stage stage) {
  switch (stage) {
    case Stage::solution:
      stale_.fill(true);
      rounding_stale_ = true;
      fibre_.reset();
      break;
    case Stage::fold_lines:
      stale_[index(Stage::fold_lines)] = true;
      break;
    case Stage::grid:
      stale_[index(Stage::grid)] = true;
      stale_[index(Stage::normals)] = true;
      break;
    case Stage::normals:
      stale_[index(Stage::normals)] = true;
      break;
  }
}

void Scene::set_parameters(const Parameters& parameters) {
  if (parameters == parameters_) {
    return;
  }
  // The shape only lays the solution out: a new shape redraws, it does not re-solve.
  Parameters same_shape = parameters;
  same_shape.shape = parameters_.shape;
  const bool solver_inputs_changed = !(same_shape == parameters_);
  parameters_ = parameters;
  if (solver_inputs_changed) {
    invalidate_from(Stage::solution);
  } else {
    invalidate_from(Stage::fold_lines);
    invalidate_from(Stage::grid);
  }
}

void Scene::set_grid_resolution(int nx, int ny) {
  nx = std::max(2, nx);
  ny = std::max(2, ny);
  if (nx == grid_nx_ && ny == grid_ny_) {
    return;
  }
  grid_nx_ = nx;
  grid_ny_ = ny;
  invalidate_from(Stage::grid);
}

void Scene::set_folds(std::optional<FoldOverride> folds) {
  if (folds == folds_) {
    return;
  }
  folds_ = std::move(folds);
  invalidate_from(Stage::solution);
}

void Scene::set_fold_line_samples(int samples) {
  samples = std::max(2, samples);
  if (samples == fold_line_samples_) {
    return;
  }
  fold_line_samples_ = samples;
  invalidate_from(Stage::fold_lines);
}

template <class Compute>
void Scene::run(Stage stage, Compute&& compute) {
  const auto start = std::chrono::steady_clock::now();
  compute();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  StageStats& s = stats_[index(stage)];
  ++s.evaluations;
  versions_[index(stage)] = next_version();
  s.total_ms += ms;
  s.last_ms = ms;
  stale_[index(stage)] = false;
}

const Solution& Scene::solution() {
  if (stale_[index(Stage::solution)]) {
    run(Stage::solution, [this] {
      solution_ = solve(parameters_);
      if (folds_) {
        solution_.n = folds_->n;
        solution_.Q = folds_->Q;
        solution_.z_max_mm = folds_->z_max_mm;
        solution_.a_mm = folds_->n > 0 ? folds_->a_mm : std::vector<double>{};
        // Eq. 8's sag of the upper edge, which the geometry draws the top fold line with.
        if (!solution_.a_mm.empty()) {
          solution_.sag_amplitude_mm = std::hypot(solution_.a_mm.back(), solution_.z_max_mm);
        }
      }
    });
  }
  return solution_;
}

const FoldLines& Scene::fold_lines() {
  if (stale_[index(Stage::fold_lines)]) {
    const Solution& s = solution();
    run(Stage::fold_lines, [&] {
      fold_lines_ = foldlab::fold_lines(s, fold_rounding(), parameters_.shape, fold_line_samples_);
    });
  }
  return fold_lines_;
}

const DeformedGrid& Scene::grid() {
  if (stale_[index(Stage::grid)]) {
    const Solution& s = solution();
    run(Stage::grid, [&] {
      grid_ = deformed_grid_positions(s, parameters_, centre_fibre(), grid_nx_, grid_ny_);
    });
    stale_[index(Stage::normals)] = true;
  }
  return grid_;
}

const std::vector<Eigen::Vector3f>& Scene::normals() {
  if (stale_[index(Stage::normals)]) {
    grid();
    run(Stage::normals,
        [this] { grid_.normals = vertex_normals(grid_.positions_mm, grid_.triangle_indices); });
  }
  return grid_.normals;
}

const FoldRounding& Scene::fold_rounding() {
  const Solution& s = solution();
  if (rounding_stale_) {
    rounding_ = foldlab::fold_rounding(s, parameters_);
    rounding_stale_ = false;
  }
  return rounding_;
}

const CentreFibre& Scene::centre_fibre() {
  if (!fibre_) {
    const FoldRounding& rounding = fold_rounding();
    fibre_.emplace(solution_, parameters_.hanging.height_mm, rounding);
  }
  return *fibre_;
}

void Scene::reset_stats() {
  stats_.fill(StageStats{});
}

}  // namespace foldlab
