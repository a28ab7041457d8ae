#include "core/field/solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace foldlab::field {
namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

// The flat triangle's constants: Dm⁻¹ (so that F = Ds Dm⁻¹), its area and the gradients of its
// three shape functions, through which every derivative is written.
struct Element {
  std::array<int, 3> nodes{};
  Matrix2d rest_inverse;
  double area_mm2 = 0.0;
  std::array<Vector2d, 3> shape_gradients;
  Matrix6d linear_stiffness;  // of the flat, unstressed triangle: the Newton matrix's damping
};

// dF for a unit move of local dof k = 2 j + c: row c of dF is node j's shape gradient.
struct Kinematics {
  Matrix2d F;
  RelaxedStrain relaxed;
};

Kinematics kinematics(const Element& e, const std::vector<Vector2d>& x, const Material& m) {
  Matrix2d Ds;
  Ds.col(0) = x[e.nodes[1]] - x[e.nodes[0]];
  Ds.col(1) = x[e.nodes[2]] - x[e.nodes[0]];
  const Matrix2d F = Ds * e.rest_inverse;
  const Matrix2d green = 0.5 * (F.transpose() * F - Matrix2d::Identity());
  return {F, relax(green, m)};
}

// The 6 x 6 second derivative of the triangle's energy with its state held fixed (taut: the St
// Venant-Kirchhoff membrane; wrinkled: the bar along the ray, with the ray's rotation; slack:
// none). Positive semidefinite in every state, so the damped Newton matrix is positive definite.
Matrix6d element_hessian(const Element& e, const Matrix2d& F, const RelaxedStrain& r,
                         const Material& m) {
  Matrix6d H = Matrix6d::Zero();
  if (r.state == State::slack) {
    return H;
  }
  const double Y = m.stiffness_N_per_mm;
  const double nu = m.poisson_ratio;
  if (r.state == State::taut) {
    std::array<Matrix2d, 6> dE;
    for (int k = 0; k < 6; ++k) {
      const Vector2d f = F.row(k % 2).transpose();
      const Vector2d& g = e.shape_gradients[k / 2];
      dE[k] = 0.5 * (f * g.transpose() + g * f.transpose());
    }
    const double c = Y / (1.0 - nu * nu);
    for (int k = 0; k < 6; ++k) {
      for (int l = 0; l <= k; ++l) {
        double v =
            c * ((1.0 - nu) * dE[k].cwiseProduct(dE[l]).sum() + nu * dE[k].trace() * dE[l].trace());
        if (k % 2 == l % 2) {
          v += e.shape_gradients[k / 2].dot(r.stress_N_per_mm * e.shape_gradients[l / 2]);
        }
        H(k, l) = H(l, k) = e.area_mm2 * v;
      }
    }
    return H;
  }
  std::array<double, 6> de1;
  std::array<double, 6> cross;
  std::array<double, 3> g1;
  for (int j = 0; j < 3; ++j) {
    g1[j] = e.shape_gradients[j].dot(r.v1);
  }
  for (int k = 0; k < 6; ++k) {
    const Vector2d f = F.row(k % 2).transpose();
    const Vector2d& g = e.shape_gradients[k / 2];
    de1[k] = f.dot(r.v1) * g.dot(r.v1);
    cross[k] = 0.5 * (f.dot(r.v1) * g.dot(r.v2) + g.dot(r.v1) * f.dot(r.v2));
  }
  const double rotation = 2.0 / (r.e1 - r.e2);  // e1 - e2 >= (1 + nu) e1 > 0 when wrinkled
  for (int k = 0; k < 6; ++k) {
    for (int l = 0; l <= k; ++l) {
      double curvature = rotation * cross[k] * cross[l];
      if (k % 2 == l % 2) {
        curvature += g1[k / 2] * g1[l / 2];
      }
      H(k, l) = H(l, k) = e.area_mm2 * Y * (de1[k] * de1[l] + r.e1 * curvature);
    }
  }
  return H;
}

// The triangle's forces dW/dx on its nodes: A P Dm⁻ᵀ with P = F S.
std::array<Vector2d, 3> element_forces(const Element& e, const Matrix2d& F,
                                       const RelaxedStrain& r) {
  const Matrix2d dDs = e.area_mm2 * F * r.stress_N_per_mm * e.rest_inverse.transpose();
  return {-dDs.col(0) - dDs.col(1), dDs.col(0), dDs.col(1)};
}

}  // namespace

Material material_of(const Fabric& fabric) {
  return {fabric.youngs_modulus_MPa * fabric.thickness_mm, fabric.poisson_ratio,
          fabric.weight_N_per_mm2};
}

std::string_view to_string(State s) {
  switch (s) {
    case State::taut:
      return "taut";
    case State::wrinkled:
      return "wrinkled";
    case State::slack:
      return "slack";
  }
  return "slack";
}

RelaxedStrain relax(const Matrix2d& E, const Material& m) {
  RelaxedStrain r;
  const double mean = 0.5 * (E(0, 0) + E(1, 1));
  const double half_difference = 0.5 * (E(0, 0) - E(1, 1));
  const double off = 0.5 * (E(0, 1) + E(1, 0));
  const double radius = std::sqrt(half_difference * half_difference + off * off);
  r.e1 = mean + radius;
  r.e2 = mean - radius;
  // The eigenvector of e1 without trigonometry (it runs for every triangle on every pass): from
  // the larger column of E - e2 I, which is never zero unless E is isotropic.
  const Vector2d along = half_difference >= 0.0 ? Vector2d(half_difference + radius, off)
                                                : Vector2d(off, radius - half_difference);
  const double length = along.norm();
  r.v1 = length > 0.0 ? Vector2d(along / length) : Vector2d(1.0, 0.0);
  r.v2 = Vector2d(-r.v1.y(), r.v1.x());
  const double Y = m.stiffness_N_per_mm;
  const double nu = m.poisson_ratio;
  if (r.e1 <= 0.0) {
    r.state = State::slack;
    return r;
  }
  if (r.e2 <= -nu * r.e1) {
    r.state = State::wrinkled;
    r.energy_N_per_mm = 0.5 * Y * r.e1 * r.e1;
    r.stress_N_per_mm = Y * r.e1 * r.v1 * r.v1.transpose();
    return r;
  }
  r.state = State::taut;
  const double c = Y / (1.0 - nu * nu);
  r.energy_N_per_mm = 0.5 * c * (r.e1 * r.e1 + r.e2 * r.e2 + 2.0 * nu * r.e1 * r.e2);
  r.stress_N_per_mm = c * ((1.0 - nu) * E + nu * E.trace() * Matrix2d::Identity());
  return r;
}

struct Solver::Impl {
  Mesh mesh;
  std::vector<Element> elements;
  std::vector<int> dof;  // node -> first of its two unknowns, -1 for a support
  int unknowns = 0;
  Eigen::SparseMatrix<double> matrix;      // lower triangle of the Newton matrix
  std::vector<std::array<int, 36>> slots;  // each element's entries in matrix's values
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> cholesky;
  std::vector<double> damping_values;        // the flat linear stiffness, assembled
  std::vector<double> node_area_mm2;         // a third of each touching triangle
  std::vector<std::vector<int>> neighbours;  // the elements sharing an edge with each
  double height_mm = 0.0;                    // of the flat cut, top to bottom

  explicit Impl(Mesh m) : mesh(std::move(m)) {
    dof.assign(mesh.nodes_mm.size(), 0);
    for (int s : mesh.support_nodes) {
      dof[s] = -1;
    }
    for (int& d : dof) {
      if (d == 0) {
        d = unknowns;
        unknowns += 2;
      }
    }
    node_area_mm2.assign(mesh.nodes_mm.size(), 0.0);
    if (!mesh.nodes_mm.empty()) {
      double top = mesh.nodes_mm.front().y();
      double bottom = top;
      for (const Vector2d& p : mesh.nodes_mm) {
        top = std::min(top, p.y());
        bottom = std::max(bottom, p.y());
      }
      height_mm = bottom - top;
    }
    const Material unit{1.0, 0.3, 0.0};
    for (const auto& tri : mesh.triangles) {
      Element e;
      e.nodes = tri;
      Matrix2d Dm;
      Dm.col(0) = mesh.nodes_mm[tri[1]] - mesh.nodes_mm[tri[0]];
      Dm.col(1) = mesh.nodes_mm[tri[2]] - mesh.nodes_mm[tri[0]];
      e.rest_inverse = Dm.inverse();
      e.area_mm2 = 0.5 * Dm.determinant();
      e.shape_gradients[1] = e.rest_inverse.row(0).transpose();
      e.shape_gradients[2] = e.rest_inverse.row(1).transpose();
      e.shape_gradients[0] = -e.shape_gradients[1] - e.shape_gradients[2];
      RelaxedStrain rest;
      rest.state = State::taut;
      e.linear_stiffness = element_hessian(e, Matrix2d::Identity(), rest, unit);
      for (int n : tri) {
        node_area_mm2[n] += e.area_mm2 / 3.0;
      }
      elements.push_back(e);
    }
    std::map<std::pair<int, int>, std::vector<int>> edges;
    for (std::size_t t = 0; t < elements.size(); ++t) {
      for (int j = 0; j < 3; ++j) {
        const int a = elements[t].nodes[j];
        const int b = elements[t].nodes[(j + 1) % 3];
        edges[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(t));
      }
    }
    neighbours.resize(elements.size());
    for (const auto& [edge, sharing] : edges) {
      if (sharing.size() == 2) {
        neighbours[sharing[0]].push_back(sharing[1]);
        neighbours[sharing[1]].push_back(sharing[0]);
      }
    }
    std::vector<Eigen::Triplet<double>> pattern;
    for (int i = 0; i < unknowns; ++i) {
      pattern.emplace_back(i, i, 0.0);
    }
    for (const Element& e : elements) {
      for (int k = 0; k < 6; ++k) {
        for (int l = 0; l < 6; ++l) {
          const int row = global(e, k);
          const int col = global(e, l);
          if (row >= 0 && col >= 0 && row >= col) {
            pattern.emplace_back(row, col, 0.0);
          }
        }
      }
    }
    matrix.resize(unknowns, unknowns);
    matrix.setFromTriplets(pattern.begin(), pattern.end());
    matrix.makeCompressed();
    slots.resize(elements.size());
    for (std::size_t t = 0; t < elements.size(); ++t) {
      for (int k = 0; k < 6; ++k) {
        for (int l = 0; l < 6; ++l) {
          const int row = global(elements[t], k);
          const int col = global(elements[t], l);
          slots[t][6 * k + l] = row >= 0 && col >= 0 && row >= col ? slot(row, col) : -1;
        }
      }
    }
    damping_values.assign(matrix.nonZeros(), 0.0);
    for (std::size_t t = 0; t < elements.size(); ++t) {
      for (int kl = 0; kl < 36; ++kl) {
        if (slots[t][kl] >= 0) {
          damping_values[slots[t][kl]] += elements[t].linear_stiffness(kl / 6, kl % 6);
        }
      }
    }
    if (unknowns > 0) {
      cholesky.analyzePattern(matrix);
    }
  }

  int global(const Element& e, int k) const {
    const int d = dof[e.nodes[k / 2]];
    return d < 0 ? -1 : d + k % 2;
  }

  int slot(int row, int col) const {
    const int* begin = matrix.innerIndexPtr() + matrix.outerIndexPtr()[col];
    const int* end = matrix.innerIndexPtr() + matrix.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - matrix.innerIndexPtr());
  }

  double potential(const std::vector<Vector2d>& x, const Material& m) const {
    double energy = 0.0;
    for (const Element& e : elements) {
      energy += e.area_mm2 * kinematics(e, x, m).relaxed.energy_N_per_mm;
    }
    return energy - work_of_weight(x, m);
  }

  double work_of_weight(const std::vector<Vector2d>& x, const Material& m) const {
    double work = 0.0;
    for (std::size_t n = 0; n < x.size(); ++n) {
      work += m.weight_N_per_mm2 * node_area_mm2[n] * x[n].y();
    }
    return work;
  }

  // dΠ/dx for every node (supports included: there it is the support's reaction).
  std::vector<Vector2d> gradient(const std::vector<Vector2d>& x, const Material& m) const {
    std::vector<Vector2d> g(x.size(), Vector2d::Zero());
    for (std::size_t n = 0; n < x.size(); ++n) {
      g[n].y() = -m.weight_N_per_mm2 * node_area_mm2[n];
    }
    for (const Element& e : elements) {
      const Kinematics k = kinematics(e, x, m);
      if (k.relaxed.state == State::slack) {
        continue;
      }
      const auto f = element_forces(e, k.F, k.relaxed);
      for (int j = 0; j < 3; ++j) {
        g[e.nodes[j]] += f[j];
      }
    }
    return g;
  }

  // The free nodes' force imbalance against every external force: the weight's nodal forces and
  // the supports' reactions (a patch pulled into shape by its edges has no weight).
  double relative_residual(const std::vector<Vector2d>& g, const Eigen::VectorXd& free_g,
                           const Material& m) const {
    double external = 0.0;
    for (double a : node_area_mm2) {
      external += std::pow(m.weight_N_per_mm2 * a, 2);
    }
    for (int n : mesh.support_nodes) {
      external += g[n].squaredNorm();
    }
    const double imbalance = free_g.norm();
    return external > 0.0 ? imbalance / std::sqrt(external) : imbalance;
  }

  Eigen::VectorXd free_part(const std::vector<Vector2d>& g) const {
    Eigen::VectorXd out(unknowns);
    for (std::size_t n = 0; n < g.size(); ++n) {
      if (dof[n] >= 0) {
        out.segment<2>(dof[n]) = g[n];
      }
    }
    return out;
  }

  void assemble(const std::vector<Vector2d>& x, const Material& m, double damping) {
    double* values = matrix.valuePtr();
    const double scale = m.stiffness_N_per_mm * damping;
    for (std::size_t i = 0; i < damping_values.size(); ++i) {
      values[i] = scale * damping_values[i];
    }
    for (std::size_t t = 0; t < elements.size(); ++t) {
      const Kinematics k = kinematics(elements[t], x, m);
      if (k.relaxed.state == State::slack) {
        continue;
      }
      const Matrix6d H = element_hessian(elements[t], k.F, k.relaxed, m);
      for (int kl = 0; kl < 36; ++kl) {
        if (slots[t][kl] >= 0) {
          values[slots[t][kl]] += H(kl / 6, kl % 6);
        }
      }
    }
  }
};

Solver::Solver(Mesh mesh) : impl_(std::make_unique<Impl>(std::move(mesh))) {}
Solver::~Solver() = default;
Solver::Solver(Solver&&) noexcept = default;
Solver& Solver::operator=(Solver&&) noexcept = default;

const Mesh& Solver::mesh() const {
  return impl_->mesh;
}

std::vector<Vector2d> flat_start(const Mesh& mesh, const Material& material,
                                 const std::vector<Vector2d>& targets) {
  // Least squares for x = a X + b and for the shift y - (1 + s) Y = c X + d over the supports.
  const std::size_t count = mesh.support_nodes.size();
  double top = std::numeric_limits<double>::infinity();
  double bottom = -top;
  for (const Vector2d& p : mesh.nodes_mm) {
    top = std::min(top, p.y());
    bottom = std::max(bottom, p.y());
  }
  const double stretch = material.weight_N_per_mm2 * (bottom - top) / material.stiffness_N_per_mm;
  double mean_X = 0.0;
  double mean_x = 0.0;
  double mean_shift = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const Vector2d& at = mesh.nodes_mm[mesh.support_nodes[i]];
    mean_X += at.x() / static_cast<double>(count);
    mean_x += targets[i].x() / static_cast<double>(count);
    mean_shift += (targets[i].y() - (1.0 + stretch) * at.y()) / static_cast<double>(count);
  }
  double sXX = 0.0;
  double sXx = 0.0;
  double sXs = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const Vector2d& at = mesh.nodes_mm[mesh.support_nodes[i]];
    const double dX = at.x() - mean_X;
    sXX += dX * dX;
    sXx += dX * (targets[i].x() - mean_x);
    sXs += dX * (targets[i].y() - (1.0 + stretch) * at.y() - mean_shift);
  }
  const bool spread = sXX > 0.0;
  const double a = spread ? sXx / sXX : 1.0;
  const double c = spread ? sXs / sXX : 0.0;
  std::vector<Vector2d> x;
  x.reserve(mesh.nodes_mm.size());
  for (const Vector2d& p : mesh.nodes_mm) {
    const double dX = p.x() - mean_X;
    x.emplace_back(mean_x + a * dX, (1.0 + stretch) * p.y() + mean_shift + c * dX);
  }
  for (std::size_t i = 0; i < count; ++i) {
    x[mesh.support_nodes[i]] = targets[i];
  }
  return x;
}

Solution Solver::solve(const Material& m, const std::vector<Vector2d>& targets,
                       const SolveOptions& options, const Solution* start) {
  const Clock::time_point began = Clock::now();
  Impl& s = *impl_;
  Solution out;
  std::vector<Vector2d> x = start != nullptr && start->positions_mm.size() == s.mesh.nodes_mm.size()
                                ? start->positions_mm
                                : flat_start(s.mesh, m, targets);
  for (std::size_t i = 0; i < s.mesh.support_nodes.size(); ++i) {
    x[s.mesh.support_nodes[i]] = targets[i];
  }
  double weight_N = 0.0;
  for (double a : s.node_area_mm2) {
    weight_N += m.weight_N_per_mm2 * a;
  }
  // A weightless patch (pulled into shape by its edges) has no stretch of its own to scale by.
  const double stretch = m.weight_N_per_mm2 * s.height_mm / m.stiffness_N_per_mm;
  const double floor =
      stretch > 0.0 ? std::min(options.damping_floor, options.damping_floor_per_stretch * stretch)
                    : options.damping_floor;
  double damping = start == nullptr       ? options.damping_start
                   : start->damping > 0.0 ? start->damping
                                          : std::min(options.warm_damping_start, floor);
  std::vector<Vector2d> g = s.gradient(x, m);
  Eigen::VectorXd gf = s.free_part(g);
  double residual = s.relative_residual(g, gf, m);
  double potential = s.potential(x, m);
  int iterations = 0;
  bool reusable = false;
  while (residual > options.relative_tolerance && iterations < options.max_iterations) {
    // At least one step a call: a slice shorter than the set-up must still make progress.
    if (options.time_budget_ms > 0.0 && iterations > 0 &&
        elapsed_ms(began) > options.time_budget_ms) {
      break;
    }
    ++iterations;
    // A step that was taken whole and cut the residual fourfold says the states have settled and
    // the matrix changes slowly: the next step reuses its factors (a chord step) and is checked
    // by the same line search. Half of an iteration's time is the factorisation.
    if (!(options.reuse_factorisation && reusable)) {
      s.assemble(x, m, damping);
      for (int i = 0; i < s.unknowns; ++i) {
        s.matrix.coeffRef(i, i) += 1e-12 * m.stiffness_N_per_mm;  // one support leaves a rotation
      }
      s.cholesky.factorize(s.matrix);
      ++out.factorisations;
      if (s.cholesky.info() != Eigen::Success) {
        damping *= 10.0;
        continue;
      }
    }
    reusable = false;
    const Eigen::VectorXd step = -s.cholesky.solve(gf);
    const double slope = gf.dot(step);
    if (!(slope < 0.0)) {
      damping *= 10.0;
      continue;
    }
    double alpha = 1.0;
    bool accepted = false;
    std::vector<Vector2d> trial = x;
    std::vector<Vector2d> trial_g;
    double trial_potential = potential;
    for (int halvings = 0; halvings < 40 && !accepted; ++halvings, alpha *= 0.5) {
      for (std::size_t n = 0; n < x.size(); ++n) {
        if (s.dof[n] >= 0) {
          trial[n] = x[n] + alpha * step.segment<2>(s.dof[n]);
        }
      }
      trial_potential = s.potential(trial, m);
      if (trial_potential <= potential + 1e-4 * alpha * slope) {
        accepted = true;
      } else if (std::abs(alpha * slope) <= 1e-11 * (std::abs(potential) + 1e-300)) {
        // The change is below the potential's round-off: judge the step by the forces instead.
        trial_g = s.gradient(trial, m);
        accepted = s.free_part(trial_g).norm() < gf.norm();
      }
      if (accepted) {
        break;
      }
    }
    if (!accepted) {
      damping *= 10.0;
      continue;
    }
    const double before = residual;
    x = std::move(trial);
    potential = trial_potential;
    g = trial_g.empty() ? s.gradient(x, m) : std::move(trial_g);
    gf = s.free_part(g);
    residual = s.relative_residual(g, gf, m);
    reusable = alpha == 1.0 && residual < 0.25 * before;
    if (alpha == 1.0) {
      damping = std::max(floor, 0.1 * damping);
    } else if (alpha < 0.1) {
      damping *= 10.0;
    }
  }

  out.damping = damping;
  // Small forces at every node can still add up, or round-off swamp the weight when supports are
  // pulled far: a field is converged only when its supports also carry its weight.
  Vector2d imbalance_N(0.0, weight_N);
  for (int n : s.mesh.support_nodes) {
    imbalance_N += g[n];
  }
  const bool carried = !(weight_N > 0.0) || imbalance_N.norm() <= kStaticsTolerance * weight_N;
  out.converged = residual <= options.relative_tolerance && carried;
  out.relative_residual = residual;
  out.iterations = iterations;
  out.weight_N = weight_N;
  out.potential_Nmm = potential;
  out.energy_Nmm = potential + s.work_of_weight(x, m);
  for (int n : s.mesh.support_nodes) {
    out.reactions_N.push_back(g[n]);
  }
  std::vector<State> states;
  for (const Element& e : s.elements) {
    states.push_back(kinematics(e, x, m).relaxed.state);
  }
  double area = 0.0;
  for (std::size_t i = 0; i < s.elements.size(); ++i) {
    const Element& e = s.elements[i];
    const Kinematics k = kinematics(e, x, m);
    const RelaxedStrain& r = k.relaxed;
    TriangleResult t;
    t.state = r.state;
    t.region = r.state;
    if (r.state == State::slack) {
      for (int n : s.neighbours[i]) {
        if (states[n] == State::wrinkled ||
            (states[n] == State::taut && t.region == State::slack)) {
          t.region = states[n];
        }
      }
    }
    t.flat_direction = r.v1;
    const Vector2d along = k.F * r.v1;
    t.direction = along.norm() > 0.0 ? Vector2d(along.normalized()) : r.v1;
    const double c = m.stiffness_N_per_mm / (1.0 - m.poisson_ratio * m.poisson_ratio);
    const double nu = m.poisson_ratio;
    // The force on a unit of flat width across the ray, S1 |F v1|, with |F v1|² = 1 + 2 e1.
    if (r.state == State::wrinkled) {
      t.tension_N_per_mm = m.stiffness_N_per_mm * r.e1 * std::sqrt(1.0 + 2.0 * r.e1);
      t.slack_strain = -(r.e2 + nu * r.e1);
    } else if (r.state == State::taut) {
      t.tension_N_per_mm = c * (r.e1 + nu * r.e2) * std::sqrt(1.0 + 2.0 * r.e1);
      t.minor_tension_N_per_mm = c * (r.e2 + nu * r.e1) * std::sqrt(1.0 + 2.0 * r.e2);
    } else {
      t.slack_strain = -r.e2;
    }
    t.folded_over = k.F.determinant() < 0.0;
    const double a = e.area_mm2;
    area += a;
    (t.region == State::taut       ? out.taut_share
     : t.region == State::wrinkled ? out.wrinkled_share
                                   : out.slack_share) += a;
    if (r.state == State::slack) {
      out.element_slack_share += a;
    }
    if (t.folded_over) {
      out.folded_share += a;
    }
    out.triangles.push_back(t);
  }
  for (double* share : {&out.taut_share, &out.wrinkled_share, &out.slack_share, &out.folded_share,
                        &out.element_slack_share}) {
    *share /= area;
  }
  out.positions_mm = std::move(x);
  out.solve_ms = elapsed_ms(began);
  return out;
}

}  // namespace foldlab::field
