// Rounded folds: the centre fibre (x = 0) passes through the fold points (a_i, +-z_i) as the
// zig-zag does, but each fold is a crest of radius R_i, about the fabric's bending length, joined
// to the next by a straight flank. docs/rounded-folds.md derives the rule and what it costs.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab {

// Above this many folds no grid can show a crest (an export has at most 4096 rows, and a crest
// needs several), so the zig-zag stays sharp and the depth needs no root finding.
inline constexpr int kMaxRoundedFolds = 4096;

struct FoldRounding {
  // False for the paper's sharp zig-zag: no folds, a radius of 0, or more than kMaxRoundedFolds.
  bool rounded = false;
  double target_radius_mm = 0.0;  // the rule's radius, the bending length c_b
  // The out-of-plane depth of every fold but the upper edge's, as a fraction of z_max: a rounded
  // path between the same points is longer than the straight one, so the folds come in until the
  // centre fibre is h long again. The upper edge keeps z_max, so its length stays the L of eq. 8.
  double depth_scale = 1.0;
  // False when even flat folds (depth_scale 0) leave the rounded fibre longer than h; the folds
  // are then flat and the fibre as short as it gets.
  bool length_kept = true;
  std::vector<double> radius_mm;  // crest radius of fold i = 0..n; empty when not rounded

  // |z| of fold i (mm): z_max at the upper edge (i = n), depth_scale z_max below it.
  double fold_depth_mm(const Solution& s, int i) const {
    return i == s.n ? s.z_max_mm : depth_scale * s.z_max_mm;
  }
};

// The rounding of the solution's folds with crests of target_radius_mm where they fit (a crest
// never overlaps its neighbour's and the fibre never runs upward). height_mm is h, the length the
// centre fibre keeps. A radius <= 0 gives the sharp zig-zag.
FoldRounding fold_rounding(const Solution& s, double height_mm, double target_radius_mm);
// The same with the fabric's bending length as the radius: the rule.
FoldRounding fold_rounding(const Solution& s, const Parameters& p);

// The centre fibre as a path in the (y, z) plane from the upper edge down to a_0: circular arcs
// at the crests and straight flanks, parametrised by arc length. Without folds it is the straight
// fibre from the sag A down to A + h.
class CentreFibre {
 public:
  CentreFibre(const Solution& s, double height_mm, const FoldRounding& rounding);

  double length_mm() const { return total_mm_; }
  // The point at arc length `at_mm` (clamped to the fibre). `piece` remembers where the last lookup
  // ended, so lookups at increasing lengths walk the path once; start it at 0.
  Eigen::Vector2d at_length(double at_mm, std::size_t& piece) const;

 private:
  // A circular arc (curvature != 0) or a straight piece from `start` with direction angle
  // `heading` (from +y towards +z) at its start.
  struct Piece {
    Eigen::Vector2d start;
    double start_mm = 0.0;   // arc length from the upper edge to `start`
    double heading = 0.0;    // rad
    double curvature = 0.0;  // 1/mm, positive turning towards +z
  };
  void add(const Eigen::Vector2d& start, double length_mm, double heading, double curvature);

  std::vector<Piece> pieces_;
  Eigen::Vector2d end_;
  double total_mm_ = 0.0;
};

// Largest angle between neighbouring segments of a polyline (degrees); 0 for fewer than 3 points.
// Coincident points are skipped.
double sharpest_turn_deg(const std::vector<Eigen::Vector2d>& polyline);

}  // namespace foldlab
