// The tension field's stress test: cold solves of every outline the field offers, on the
// explorer's live and refined meshes, over the same inputs as the closed form's stress test,
// each under a budget, counting what the solver promises never happens (NaN, inf, a hang, a
// "converged" that is not, a converged field out of balance) and reporting what it says instead
// (not converged, with its residual).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/field/mesh.hpp"
#include "core/field/outline.hpp"
#include "core/model/parameters.hpp"

namespace foldlab {

// The explorer's Tension field view solves on half its cells while an input moves and on all
// of them at rest, 32 across by default: the two meshes every outline is stressed on.
inline constexpr int kFieldStressLiveCells = 16;
inline constexpr int kFieldStressRefinedCells = 32;
// Field samples of one run: a sample takes 0.01 to 2 s on a 2-core machine.
inline constexpr std::int64_t kMaxFieldStressSamples = 10'000;

struct FieldStressOptions {
  int samples = 280;  // 20 of each outline on each mesh
  std::uint64_t seed = 1;
  int first_index = 0;  // samples first_index .. first_index + samples - 1
  int threads = 0;      // <= 0: std::thread::hardware_concurrency()
  // A cold solve's budget: Newton steps on each rung of the coarse-to-fine ladder, and the wall
  // time of all of them together (0: none).
  int max_iterations = 1000;
  double time_budget_s = 10.0;
  // A solve that overruns its time budget by more than this is a hang (the budget is checked
  // between Newton steps, each of which takes milliseconds on these meshes).
  double hang_margin_s = 1.0;
};

// Sample `index`: the closed form's stress_sample(seed, index) inputs, the outline by turns
// (rectangular, cosine, strip, inclined, triangle, pennant, wedge), the live mesh for the first
// seven of every fourteen and the refined one for the next, a strip's supports and the incline
// drawn over their rows' typical ranges. Rows by the explorer's rule: cells across times the
// cut's height over its width, at least 4 and at most twice the cells across.
struct FieldStressSample {
  int index = 0;
  Parameters parameters;
  field::OutlineKind kind = field::OutlineKind::rectangular;
  field::MeshResolution resolution;
};
FieldStressSample field_stress_sample(std::uint64_t seed, int index);
// The explorer's rows for `cells_x` across this cut.
int field_view_rows(const field::Outline& outline, int cells_x);

struct FieldStressCase {
  FieldStressSample sample;
  int nodes = 0;
  bool converged = false;
  double relative_residual = 0.0;
  double recomputed_residual = 0.0;  // from the returned positions, by a fresh solver
  int iterations = 0;                // Newton steps over all rungs
  double solve_ms = 0.0;             // as the solution reports it
  double wall_ms = 0.0;              // the solve, its report and its folds
  double balance = 0.0;              // |sum of reactions + weight| / weight, both components
  int rays = 0;
  int rays_turning_back = 0;  // rays with two consecutive hung segments more than 90 deg apart
  bool non_finite = false;
  bool hung = false;
  bool false_converged = false;
  bool unmarked = false;
  bool unbalanced = false;
  bool region_sum = false;
  bool folds_non_finite = false;
  bool refused = false;
  std::string problem;  // what failed, empty when nothing did
};

// One outline on one mesh.
struct FieldStressGroup {
  field::OutlineKind kind = field::OutlineKind::rectangular;
  int cells_x = 0;
  int samples = 0;
  int converged = 0;
  std::vector<int> iterations;  // per sample, converged or not
  std::vector<double> solve_ms;
};

struct FieldStressReport {
  int samples = 0;
  std::uint64_t seed = 0;
  int first_index = 0;
  int threads = 1;
  double wall_seconds = 0.0;
  int max_iterations = 0;
  double time_budget_s = 0.0;
  double hang_seconds = 0.0;
  int converged = 0;
  int non_finite = 0;        // a NaN or inf anywhere in the solution, its report or its folds
  int hangs = 0;             // over the time budget plus the margin
  int false_converged = 0;   // said converged with a residual (reported or recomputed) above 1e-8
  int unmarked = 0;          // not converged, yet its residual does not say so
  int unbalanced = 0;        // converged, and the reactions miss the weight by more than 1e-6 of it
  int region_sums = 0;       // taut + wrinkled + slack shares not 1
  int folds_non_finite = 0;  // the folds read from the field
  int refused = 0;           // outline or mesh refused (never, within the sampled ranges)
  double worst_balance = 0.0;  // over converged samples: |sum of reactions + weight| / weight
  int rays = 0;                // traced on converged samples
  int rays_turning_back = 0;   // of them, turning back on themselves somewhere (not a failure)
  std::vector<int> rays_turning_back_by_kind;  // per outline, in the groups' order
  double worst_converged_recomputed_residual = 0.0;
  std::vector<FieldStressGroup> groups;        // by outline, then mesh
  std::vector<FieldStressCase> not_converged;  // by index
  std::vector<FieldStressCase> failures;       // by index, the first few
  bool passed() const {
    return non_finite + hangs + false_converged + unmarked + unbalanced + region_sums +
               folds_non_finite + refused ==
           0;
  }
};

// One sample solved and checked (the report's counts for it alone).
FieldStressCase run_field_stress_sample(const FieldStressSample& sample,
                                        const FieldStressOptions& options);
FieldStressReport run_field_stress(const FieldStressOptions& options);

nlohmann::json field_stress_to_json(const FieldStressReport& report);
std::string field_stress_table(const FieldStressReport& report);

}  // namespace foldlab
