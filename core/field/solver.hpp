// The tension field of a hung cloth: a geometrically nonlinear membrane in its own vertical plane
// under its weight, constant-strain triangles on the flat cut, supports pinned, and Pipkin's
// relaxed energy of a plane-stress St Venant-Kirchhoff membrane, so that the cloth takes no
// compression (it wrinkles out of plane instead). Minimised by Newton's method with a line search
// on analytic derivatives. docs/field.md explains the energy, the method and its checks.
#pragma once

#include <chrono>
#include <memory>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/field/mesh.hpp"

namespace foldlab::field {

struct Material {
  double stiffness_N_per_mm = 41.25;  // Y = E t, the membrane's stiffness
  double poisson_ratio = 0.3;
  double weight_N_per_mm2 = 1.5e-6;  // w, acting along +y (down)

  bool operator==(const Material&) const = default;
};
Material material_of(const Fabric& fabric);

// taut: tension both ways; wrinkled: tension along the ray only; slack: none.
enum class State { taut, wrinkled, slack };
std::string_view to_string(State s);

// The relaxed energy at one Green strain: which state, the principal strains e1 >= e2 and their
// directions in the flat cut, the energy per flat area and the second Piola-Kirchhoff stress.
struct RelaxedStrain {
  State state = State::slack;
  double e1 = 0.0;
  double e2 = 0.0;
  Eigen::Vector2d v1{1.0, 0.0};
  Eigen::Vector2d v2{0.0, 1.0};
  double energy_N_per_mm = 0.0;                               // energy per flat area: N mm / mm²
  Eigen::Matrix2d stress_N_per_mm = Eigen::Matrix2d::Zero();  // S, per flat width
};
RelaxedStrain relax(const Eigen::Matrix2d& green_strain, const Material& material);

// A field whose supports' reactions miss its weight by more than this share of it is not
// converged, whatever its residual.
inline constexpr double kStaticsTolerance = 1e-6;

struct SolveOptions {
  double relative_tolerance = 1e-8;  // converged: |force residual| <= this x |weight's forces|
  int max_iterations = 1000;
  // The Newton matrix's damping, as a share of the flat cloth's linear-elastic stiffness: it
  // starts here, falls tenfold after each full step and rises tenfold when a step fails, never
  // below the floor. It enters the Newton matrix only, never the energy or the residual: it
  // changes the path, not the converged field.
  double damping_start = 1e-3;
  // The floor is the smaller of damping_floor and damping_floor_per_stretch times the cloth's
  // stretch under its weight, w h / Y (h the cut's height). A hung cloth's shape is set by the
  // stiffness its tension gives it across the rays, about Y times that stretch: a floor fixed
  // against Y alone outweighs it on a stiff cloth (stretch 1e-6 and below), and Newton's steps
  // become a slow damped descent that ends at the iteration cap.
  double damping_floor = 1e-6;
  double damping_floor_per_stretch = 1e-5;
  // From a previous field (a warm start) the states have mostly settled: start at the floor
  // (this, or the floor above when it is lower).
  double warm_damping_start = 1e-6;
  // After a whole step that cut the residual fourfold, take the next with the same factors.
  bool reuse_factorisation = true;
  // Stop after this long (0: no limit) and say so: the last iterate is returned unconverged.
  double time_budget_ms = 0.0;
};

struct TriangleResult {
  State state = State::slack;  // of the triangle's own strain
  // What the regions are drawn and counted by: the triangle's own state, except that a slack
  // triangle with a tensed edge neighbour takes the neighbour's state (wrinkled before taut).
  // Linear triangles let one of a pair carry a uniaxial field while the other goes slack, at no
  // cost in the relaxed energy: stripes one element wide, in every split, that do not shrink with
  // the mesh. A slack region is counted where a triangle and all its neighbours are slack.
  State region = State::slack;
  double tension_N_per_mm = 0.0;             // the larger principal tension, per flat width
  double minor_tension_N_per_mm = 0.0;       // the smaller, 0 unless taut
  Eigen::Vector2d direction{1.0, 0.0};       // the larger tension's direction in the hung cloth
  Eigen::Vector2d flat_direction{1.0, 0.0};  // the same material line on the flat cut
  // The strain across the ray beyond the Poisson contraction, -(e2 + nu e1) for a wrinkled
  // triangle and -e2 for a slack one (0 when taut): the width the folds take up.
  double slack_strain = 0.0;
  bool folded_over = false;  // det F < 0: the triangle turned over, which costs no energy
};

struct Solution {
  std::vector<Eigen::Vector2d> positions_mm;  // hung position of each mesh node
  bool converged = false;
  double relative_residual = 0.0;
  int iterations = 0;      // Newton steps
  int factorisations = 0;  // of the Newton matrix: fewer than the steps when factors are reused
  // The Newton matrix's damping at the end: a solve resumed from this one (a time budget ran
  // out) goes on with it rather than from the warm start's floor.
  double damping = 0.0;
  double solve_ms = 0.0;
  double energy_Nmm = 0.0;     // strain energy
  double potential_Nmm = 0.0;  // strain energy minus the work of the weight
  double weight_N = 0.0;
  std::vector<Eigen::Vector2d> reactions_N;  // the force each support exerts on the cloth
  std::vector<TriangleResult> triangles;
  double taut_share = 0.0;  // shares of the flat area, by region
  double wrinkled_share = 0.0;
  double slack_share = 0.0;
  double folded_share = 0.0;
  double element_slack_share = 0.0;  // by the triangles' own states, for comparison
  // A cold solve of a stiff cloth, stopped by its budget while it was still solved softened
  // (solve_cold): the stiffness to go on at (resume_cold); 0 when it reached the cloth's own.
  double resume_stiffness_N_per_mm = 0.0;
};

// One mesh's solver: the mesh's sparsity and the Cholesky ordering are worked out once and
// reused by every solve on it (a drag re-solves on the same mesh, warm).
class Solver {
 public:
  explicit Solver(Mesh mesh);
  ~Solver();
  Solver(Solver&&) noexcept;
  Solver& operator=(Solver&&) noexcept;

  const Mesh& mesh() const;
  // Each support pinned at targets_mm[i]. From `start` (a solution on this mesh, e.g. of a
  // neighbouring input) when given, else from the flat cut mapped onto the supports.
  Solution solve(const Material& material, const std::vector<Eigen::Vector2d>& targets_mm,
                 const SolveOptions& options = {}, const Solution* start = nullptr);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The start of a cold solve: the flat cut mapped by the affine map that best puts the supports
// where they are pinned (x scaled by l / L for Conci's set-up), stretched down by w h / Y so that
// every fibre starts in tension.
std::vector<Eigen::Vector2d> flat_start(const Mesh& mesh, const Material& material,
                                        const std::vector<Eigen::Vector2d>& targets_mm);

}  // namespace foldlab::field
