#include "core/geometry/rounded_folds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/geometry/geometry.hpp"
#include "core/model/root_finding.hpp"

namespace foldlab {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A flank runs from one crest down to the next: it drops by D = drop_mm (along y) while it crosses
// H = across_mm (along z) from one side of the cloth to the other. Both crests leave it along +y;
// rho = radii_mm is the sum of their radii.
//
// The largest sum of its two crest radii: when H < D the crests meet with no straight part between
// them (D² + H² = 2 H rho); when H >= D the flank would turn past horizontal and run upward first,
// which a fibre pulled down by the weight below it does not do, so the turn stops at 90° (rho = D).
double radius_sum_limit(double drop_mm, double across_mm) {
  if (across_mm <= 0.0) {
    return kInfinity;
  }
  return across_mm >= drop_mm ? drop_mm
                              : (drop_mm * drop_mm + across_mm * across_mm) / (2.0 * across_mm);
}

// How far each crest of the flank turns (rad): its straight part leaves the first crest at this
// angle to +y. Arcs of radii summing to rho and a straight part of length s close the flank when
// D = rho sin(theta) + s cos(theta) and H = rho (1 - cos(theta)) + s sin(theta); eliminating s
// gives D sin(theta) - (H - rho) cos(theta) = rho.
double flank_turn(double drop_mm, double across_mm, double radii_mm) {
  if (radii_mm <= 0.0) {
    return std::atan2(across_mm, drop_mm);
  }
  const double r = std::hypot(drop_mm, across_mm - radii_mm);
  return std::max(
      0.0, std::atan2(across_mm - radii_mm, drop_mm) + std::asin(std::min(1.0, radii_mm / r)));
}

// The straight part's length: the tangent from one crest circle to the other.
double flank_straight_mm(double drop_mm, double across_mm, double radii_mm) {
  return std::sqrt(
      std::max(0.0, drop_mm * drop_mm + across_mm * across_mm - 2.0 * across_mm * radii_mm));
}

double flank_length_mm(double drop_mm, double across_mm, double radii_mm) {
  if (radii_mm <= 0.0) {
    return std::hypot(drop_mm, across_mm);
  }
  return radii_mm * flank_turn(drop_mm, across_mm, radii_mm) +
         flank_straight_mm(drop_mm, across_mm, radii_mm);
}

struct Rounder {
  const Solution& s;
  double target_radius_mm;

  double depth_mm(int i, double depth_scale) const {
    return i == s.n ? s.z_max_mm : depth_scale * s.z_max_mm;
  }
  double flank_drop_mm(int k) const {  // flank k joins fold k to fold k - 1 below it
    return s.a_mm[static_cast<std::size_t>(k - 1)] - s.a_mm[static_cast<std::size_t>(k)];
  }
  double flank_across_mm(int k, double depth_scale) const {
    return depth_mm(k, depth_scale) + depth_mm(k - 1, depth_scale);
  }

  // Each crest takes the target radius, or half of what its narrower flank allows.
  void radii(double depth_scale, std::vector<double>& out) const {
    out.assign(static_cast<std::size_t>(s.n) + 1, target_radius_mm);
    for (int k = 1; k <= s.n; ++k) {
      const double half = 0.5 * radius_sum_limit(flank_drop_mm(k), flank_across_mm(k, depth_scale));
      for (int i : {k, k - 1}) {
        double& r = out[static_cast<std::size_t>(i)];
        r = std::min(r, half);
      }
    }
  }

  double length_mm(double depth_scale, std::vector<double>& scratch) const {
    radii(depth_scale, scratch);
    double total = 0.0;
    for (int k = 1; k <= s.n; ++k) {
      const double radii_mm =
          scratch[static_cast<std::size_t>(k)] + scratch[static_cast<std::size_t>(k - 1)];
      total += flank_length_mm(flank_drop_mm(k), flank_across_mm(k, depth_scale), radii_mm);
    }
    return total;
  }
};

}  // namespace

FoldRounding fold_rounding(const Solution& s, double height_mm, double target_radius_mm) {
  FoldRounding out;
  out.target_radius_mm = std::max(0.0, target_radius_mm);
  if (s.n < 1 || s.a_mm.size() != static_cast<std::size_t>(s.n) + 1 || s.n > kMaxRoundedFolds ||
      !(target_radius_mm > 0.0)) {
    return out;
  }
  out.rounded = true;
  const Rounder rounder{s, out.target_radius_mm};
  std::vector<double> scratch;
  auto excess = [&](double depth_scale) {
    return rounder.length_mm(depth_scale, scratch) - height_mm;
  };
  // The zig-zag is h long (eq. 9) and rounding only lengthens it, so at full depth the fibre is
  // too long (or exactly right, when every crest is flat).
  const double at_full = excess(1.0);
  if (at_full > 0.0) {
    const double at_flat = excess(0.0);
    if (at_flat >= 0.0) {
      out.depth_scale = 0.0;
      out.length_kept = at_flat == 0.0;
    } else {
      out.depth_scale = detail::brent_root(excess, 0.0, 1.0, at_flat, at_full, 1e-14);
    }
  }
  rounder.radii(out.depth_scale, out.radius_mm);
  return out;
}

FoldRounding fold_rounding(const Solution& s, const Parameters& p) {
  return fold_rounding(s, p.hanging.height_mm, bending_length_mm(p.fabric));
}

void CentreFibre::add(const Eigen::Vector2d& start, double length_mm, double heading,
                      double curvature) {
  if (!(length_mm > 0.0)) {
    return;
  }
  pieces_.push_back({start, total_mm_, heading, curvature});
  total_mm_ += length_mm;
}

CentreFibre::CentreFibre(const Solution& s, double height_mm, const FoldRounding& rounding) {
  if (s.a_mm.empty()) {
    // No folds: the cloth hangs straight from the sag of its upper edge (0 without slack).
    const Eigen::Vector2d top(s.sag_amplitude_mm, 0.0);
    end_ = top + Eigen::Vector2d(height_mm, 0.0);
    add(top, height_mm, 0.0, 0.0);
    return;
  }
  auto fold_point = [&](int i) {
    return Eigen::Vector2d(s.a_mm[static_cast<std::size_t>(i)],
                           fold_sign(i) * rounding.fold_depth_mm(s, i));
  };
  end_ = fold_point(0);
  pieces_.reserve(static_cast<std::size_t>(s.n) * (rounding.rounded ? 3 : 1));
  for (int k = s.n; k >= 1; --k) {
    const Eigen::Vector2d upper = fold_point(k);
    const Eigen::Vector2d lower = fold_point(k - 1);
    if (!rounding.rounded) {
      add(upper, (lower - upper).norm(), 0.0, 0.0);
      continue;
    }
    const double sigma = fold_sign(k);  // the upper crest's side; the flank heads for -sigma
    const double upper_radius_mm = rounding.radius_mm[static_cast<std::size_t>(k)];
    const double lower_radius_mm = rounding.radius_mm[static_cast<std::size_t>(k - 1)];
    const double drop_mm = lower.x() - upper.x();
    const double across_mm = sigma * (upper.y() - lower.y());
    const double theta = flank_turn(drop_mm, across_mm, upper_radius_mm + lower_radius_mm);
    const double sin_t = std::sin(theta);
    const double versine = 1.0 - std::cos(theta);
    // Each crest arc turns by theta: it advances R sin(theta) down and R (1 - cos theta) across.
    const Eigen::Vector2d leave =
        upper + upper_radius_mm * Eigen::Vector2d(sin_t, -sigma * versine);
    const Eigen::Vector2d arrive =
        lower - lower_radius_mm * Eigen::Vector2d(sin_t, -sigma * versine);
    if (upper_radius_mm > 0.0) {
      add(upper, upper_radius_mm * theta, 0.0, -sigma / upper_radius_mm);
    }
    add(leave, (arrive - leave).norm(), -sigma * theta, 0.0);
    if (lower_radius_mm > 0.0) {
      add(arrive, lower_radius_mm * theta, -sigma * theta, sigma / lower_radius_mm);
    }
  }
}

Eigen::Vector2d CentreFibre::at_length(double at_mm, std::size_t& piece) const {
  if (pieces_.empty()) {
    return end_;
  }
  at_mm = std::clamp(at_mm, 0.0, total_mm_);
  piece = std::min(piece, pieces_.size() - 1);
  while (piece + 1 < pieces_.size() && pieces_[piece + 1].start_mm <= at_mm) {
    ++piece;
  }
  const Piece& p = pieces_[piece];
  const double u = at_mm - p.start_mm;
  if (p.curvature == 0.0) {
    const Eigen::Vector2d next = piece + 1 < pieces_.size() ? pieces_[piece + 1].start : end_;
    const double length =
        (piece + 1 < pieces_.size() ? pieces_[piece + 1].start_mm : total_mm_) - p.start_mm;
    const double t = length > 0.0 ? std::clamp(u / length, 0.0, 1.0) : 0.0;
    return p.start + t * (next - p.start);
  }
  // The chord of an arc turning by k u is 2 sin(k u / 2) / k long, along the mean heading: exact,
  // and free of the cancellation of sin(h + k u) - sin(h) on flat arcs.
  const double half_turn = 0.5 * p.curvature * u;
  const double chord = 2.0 * std::sin(half_turn) / p.curvature;
  const double mean_heading = p.heading + half_turn;
  return p.start + chord * Eigen::Vector2d(std::cos(mean_heading), std::sin(mean_heading));
}

double sharpest_turn_deg(const std::vector<Eigen::Vector2d>& polyline) {
  double sharpest = 0.0;
  Eigen::Vector2d previous = Eigen::Vector2d::Zero();
  for (std::size_t k = 1; k < polyline.size(); ++k) {
    const Eigen::Vector2d segment = polyline[k] - polyline[k - 1];
    if (segment.squaredNorm() == 0.0) {
      continue;
    }
    if (previous.squaredNorm() > 0.0) {
      const double cross = previous.x() * segment.y() - previous.y() * segment.x();
      sharpest = std::max(sharpest, std::atan2(std::abs(cross), previous.dot(segment)));
    }
    previous = segment;
  }
  return sharpest * 180.0 / std::numbers::pi;
}

}  // namespace foldlab
