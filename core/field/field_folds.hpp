// How many folds a solved tension field makes, how they are spaced and how deep they stand out of
// the plane: n, Q, z_max and the fold amplitudes a_i read from the field along its centre line,
// for comparison with the closed form's (docs/field.md, "Folds from the field").
//
// Tension field theory says where the cloth wrinkles and how much width the wrinkles must take up
// out of the plane, not how many there are: that needs the bending stiffness. Here the width comes
// from the field (the centre fibre's flat length beyond its hung in-plane length), the spacing from
// the model's wrinkle law in force with the field's local ray tension in place of the closed form's
// w h, and the depth from the centre fibre's inextensibility, as in the closed form's eq. 9.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/field/mesh.hpp"
#include "core/field/solver.hpp"
#include "core/model/parameters.hpp"

namespace foldlab::field {

struct FieldFolds {
  int n = 0;                    // folds down the centre line; 0 when there is no width to take up
  double Q = 1.0;               // (a_0 / a_n)^(1/n), a_n no less than the floor below
  double z_max_mm = 0.0;        // out of the plane, from the centre fibre's length
  std::vector<double> a_mm;     // a_0 (bottom) .. a_n (top): hung depths below the supports' line
  double slack_width_mm = 0.0;  // the centre fibre's length the folds take up out of the plane
  double kept_length_mm = 0.0;  // the centre fibre's length: flat, less the Poisson contraction
  double count_argument = 0.0;  // the sum of the local fold densities that n rounds
  double mean_ray_tension_N_per_mm = 0.0;  // the ray tension across the centre line, averaged
  bool n_capped = false;                   // more than kMaxWrinkles folds were asked for
};

// Depths below this share of the centre fibre's kept length count as this depth where a law
// spaces folds by ratio (ln a has no floor at a = 0): the closed form's starting a_n = 0.01 h.
inline constexpr double kFieldFoldsDepthFloorShare = 0.01;

// The folds of `solution` (solved on `mesh` with its supports pinned at `targets_mm`) under the
// wrinkle law, constants and rounding of `p.model` and the fabric of `p.fabric`, read along the
// flat column midway between the two neighbouring supports farthest apart (the centre line of a
// cloth on two supports; one span's of a strip), l their distance. Pure.
FieldFolds field_folds(const Mesh& mesh, const Solution& solution,
                       const std::vector<Eigen::Vector2d>& targets_mm, const Parameters& p);

}  // namespace foldlab::field
