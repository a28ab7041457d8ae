#include "core/field/field_folds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/field/rays.hpp"
#include "core/model/equations.hpp"
#include "core/model/root_finding.hpp"
#include "core/model/solver.hpp"
#include "core/model/wrinkle_law.hpp"

namespace foldlab::field {
namespace {

using Eigen::Vector2d;

// The ray tension at each centre-line sample averaged over about one cell either side: linear
// triangles let one of a pair carry the rays while the other goes slack (docs/field.md, "Slack
// stripes"), and the force a band of cloth carries is the pair's mean, not either triangle's.
std::vector<double> smoothed_tension(const Mesh& mesh, const Solution& solution,
                                     const std::vector<Vector2d>& flat) {
  const std::size_t count = flat.size();
  std::vector<double> raw(count, 0.0);
  for (std::size_t i = 0; i < count; ++i) {
    const int t = mesh.locate(flat[i]);
    if (t >= 0 && solution.triangles[t].state != State::slack) {
      raw[i] = solution.triangles[t].tension_N_per_mm;
    }
  }
  double area = 0.0;
  for (const auto& tri : mesh.triangles) {
    const Vector2d u = mesh.nodes_mm[tri[1]] - mesh.nodes_mm[tri[0]];
    const Vector2d v = mesh.nodes_mm[tri[2]] - mesh.nodes_mm[tri[0]];
    area += 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
  }
  const double cell_mm = std::sqrt(2.0 * area / static_cast<double>(mesh.triangles.size()));
  const double step_mm = (flat.back() - flat.front()).norm() / static_cast<double>(count - 1);
  const auto half = static_cast<std::ptrdiff_t>(std::max(1.0, std::round(cell_mm / step_mm)));
  std::vector<double> prefix(count + 1, 0.0);
  for (std::size_t i = 0; i < count; ++i) {
    prefix[i + 1] = prefix[i] + raw[i];
  }
  std::vector<double> out(count);
  const auto last = static_cast<std::ptrdiff_t>(count) - 1;
  for (std::ptrdiff_t i = 0; i <= last; ++i) {
    const std::ptrdiff_t lo = std::max<std::ptrdiff_t>(0, i - half);
    const std::ptrdiff_t hi = std::min(last, i + half);
    out[static_cast<std::size_t>(i)] =
        (prefix[static_cast<std::size_t>(hi) + 1] - prefix[static_cast<std::size_t>(lo)]) /
        static_cast<double>(hi - lo + 1);
  }
  return out;
}

// Folds per mm of depth at depth `depth_mm` where the rays carry `tension`: the law's count rule
// with the closed form's w h replaced by the ray tension, so that its strength is
// s = K E t³ / (T l²) (eq. 7's, and Cerda and Mahadevan's as FoldLab reads them).
double fold_density_per_mm(const Parameters& p, double tension_N_per_mm, double span_mm,
                           double depth_mm, double depth_floor_mm) {
  if (!(tension_N_per_mm > 0.0)) {
    return 0.0;
  }
  const Fabric& f = p.fabric;
  const double s = stiffness_constant_K(p) * f.youngs_modulus_MPa * std::pow(f.thickness_mm, 3) /
                   (tension_N_per_mm * span_mm * span_mm);
  const double exponent = p.model.stress_exponent_p;
  const double strength = exponent == 1.0 ? s : std::pow(s, exponent);
  const std::optional<FoldCountRule> rule = wrinkle_law(p.model.law).count_rule(strength, span_mm);
  if (!rule) {
    return 0.0;  // the stiff regime of Conci's law: no more than one fold here
  }
  return rule->spacing == FoldSpacing::geometric
             ? 1.0 / (std::max(depth_mm, depth_floor_mm) * rule->step)
             : 1.0 / rule->step;
}

// The z >= 0 at which a fibre through the fold points, offset +-z alternately out of the plane,
// is `length_mm` long: sum sqrt(da_i² + (2 z)²) = length (eq. 9's form); 0 when the in-plane
// steps alone reach it.
double depth_for_length(const std::vector<double>& a_mm, double length_mm) {
  auto excess = [&](double z) {
    double sum = 0.0;
    for (std::size_t i = 1; i < a_mm.size(); ++i) {
      sum += std::hypot(a_mm[i - 1] - a_mm[i], 2.0 * z);
    }
    return sum - length_mm;
  };
  const double at_zero = excess(0.0);
  if (at_zero >= 0.0) {
    return 0.0;
  }
  // At z = length / 2 every one of the n >= 1 steps is at least the whole length.
  const double hi = 0.5 * length_mm;
  return detail::brent_root(excess, 0.0, hi, at_zero, excess(hi), 1e-13);
}

// The span whose folds are counted: between the two neighbouring supports (by where they are
// pinned) farthest apart, so that a strip's folds are those of one of its spans, not of the
// column through a middle support; its fibre is the flat column midway between the two.
struct Span {
  SupportFrame frame;
  double flat_x_mm = 0.0;
};
std::optional<Span> widest_span(const Mesh& mesh, const std::vector<Vector2d>& targets_mm) {
  std::vector<std::size_t> order(targets_mm.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    order[i] = i;
  }
  // Left to right, and of supports pinned at one x the topmost first: it is the one the cloth
  // hangs from there.
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Vector2d& p = targets_mm[a];
    const Vector2d& q = targets_mm[b];
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  });
  std::erase_if(order,
                [&, previous = -std::numeric_limits<double>::infinity()](std::size_t i) mutable {
                  const bool same_x = targets_mm[i].x() == previous;
                  previous = targets_mm[i].x();
                  return same_x;
                });
  std::optional<Span> best;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Vector2d& left = targets_mm[order[k - 1]];
    const Vector2d& right = targets_mm[order[k]];
    if (right.x() - left.x() > (best ? best->frame.span_mm() : 0.0)) {
      const double flat_left = mesh.nodes_mm[mesh.support_nodes[order[k - 1]]].x();
      const double flat_right = mesh.nodes_mm[mesh.support_nodes[order[k]]].x();
      best = Span{SupportFrame{left, right}, 0.5 * (flat_left + flat_right)};
    }
  }
  return best;
}

}  // namespace

FieldFolds field_folds(const Mesh& mesh, const Solution& solution,
                       const std::vector<Vector2d>& targets_mm, const Parameters& p) {
  FieldFolds out;
  const std::optional<Span> widest = widest_span(mesh, targets_mm);
  if (!widest) {
    return out;
  }
  const CentreLine centre = column_line(mesh, solution, widest->flat_x_mm, widest->frame);
  const std::size_t count = centre.flat_mm.size();
  if (count < 2) {
    return out;
  }
  const double span = widest->frame.span_mm();
  const Material material = material_of(p.fabric);
  const std::vector<double> tension = smoothed_tension(mesh, solution, centre.flat_mm);
  std::vector<Vector2d> hung(count);
  for (std::size_t i = 0; i < count; ++i) {
    hung[i] = hung_position(mesh, solution, centre.flat_mm[i]);
  }

  // The length the centre fibre keeps: where taut, what it is in the plane (nothing to take up);
  // where wrinkled or slack, its flat length less the Poisson contraction of the ray tension
  // across it. What it keeps beyond its hung in-plane length the folds take up.
  std::vector<bool> wrinkled(count - 1, false);
  double tension_length = 0.0;
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const double flat_mm = (centre.flat_mm[i + 1] - centre.flat_mm[i]).norm();
    const double in_plane_mm = (hung[i + 1] - hung[i]).norm();
    const int t = mesh.locate(0.5 * (centre.flat_mm[i] + centre.flat_mm[i + 1]));
    wrinkled[i] = t >= 0 && solution.triangles[t].region != State::taut;
    const double mean_tension = 0.5 * (tension[i] + tension[i + 1]);
    const double kept_mm =
        wrinkled[i]
            ? flat_mm * (1.0 - material.poisson_ratio * mean_tension / material.stiffness_N_per_mm)
            : in_plane_mm;
    out.kept_length_mm += kept_mm;
    out.slack_width_mm += kept_mm - in_plane_mm;
    if (wrinkled[i]) {
      out.mean_ray_tension_N_per_mm += mean_tension * flat_mm;
      tension_length += flat_mm;
    }
  }
  if (tension_length > 0.0) {
    out.mean_ray_tension_N_per_mm /= tension_length;
  }
  const double floor_mm = kFieldFoldsDepthFloorShare * out.kept_length_mm;

  // Folds counted from the bottom (a_0) up: the running sum of the local densities over depth.
  std::vector<double> below(count, 0.0);  // folds between sample i and the bottom
  for (std::size_t i = count - 1; i-- > 0;) {
    double folds = 0.0;
    if (wrinkled[i]) {
      const double depth = 0.5 * (centre.depth_mm[i] + centre.depth_mm[i + 1]);
      folds = std::abs(centre.depth_mm[i + 1] - centre.depth_mm[i]) *
              fold_density_per_mm(p, 0.5 * (tension[i] + tension[i + 1]), span, depth, floor_mm);
    }
    below[i] = below[i + 1] + folds;
  }
  out.count_argument = below.front();
  if (!(out.slack_width_mm > 0.0) || !(out.count_argument > 0.0)) {
    return out;
  }
  const int asked = wrinkle_count_from_logs(out.count_argument, 1.0,
                                            p.model.int_rounding == IntRounding::nearest);
  out.n_capped = asked > kMaxWrinkles;
  out.n = std::min(asked, kMaxWrinkles);

  // a_i where the running count reaches i / n of the whole: the field's own spacing, whole folds.
  out.a_mm.push_back(centre.depth_mm.back());
  std::size_t at = count - 1;
  for (int i = 1; i < out.n; ++i) {
    const double target = out.count_argument * i / out.n;
    while (at > 0 && below[at - 1] < target) {
      --at;
    }
    if (at == 0) {
      out.a_mm.push_back(centre.depth_mm.front());
      continue;
    }
    const double share = (target - below[at]) / (below[at - 1] - below[at]);
    out.a_mm.push_back(centre.depth_mm[at] +
                       share * (centre.depth_mm[at - 1] - centre.depth_mm[at]));
  }
  out.a_mm.push_back(centre.depth_mm.front());
  out.Q = std::pow(out.a_mm.front() / std::max(out.a_mm.back(), floor_mm), 1.0 / out.n);
  out.z_max_mm = depth_for_length(out.a_mm, out.kept_length_mm);
  return out;
}

}  // namespace foldlab::field
