// The flat cut of a hung cloth for the tension-field solver: its top and bottom edges (each a
// polyline monotone in x, y down, mm) and its supports (material points of the cut and where each
// is pinned). Every outline of the paper's Figs. 1-2 is built here from the model's inputs; a
// designer's own cut is read from JSON. Anything that cannot be meshed is refused with an
// OutlineError whose message names what is wrong.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "core/model/parameters.hpp"

namespace foldlab::field {

class OutlineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Support {
  Eigen::Vector2d at_mm;  // the material point on the flat cut
  Eigen::Vector2d to_mm;  // where it is pinned in the hung state

  bool operator==(const Support&) const = default;
};

struct Outline {
  std::vector<Eigen::Vector2d> top_mm;     // left to right, x never decreasing
  std::vector<Eigen::Vector2d> bottom_mm;  // left to right, from the same first x to the same last
  std::vector<Support> supports;

  // y of an edge at x (x within the outline's range), the last of equal-x vertices for a step.
  double top_y_mm(double x_mm) const;
  double bottom_y_mm(double x_mm) const;
  double left_mm() const { return top_mm.front().x(); }
  double right_mm() const { return top_mm.back().x(); }
  // The cut's height, from its highest top point to its lowest bottom point (y down).
  double height_mm() const;
  double area_mm2() const;

  bool operator==(const Outline&) const = default;
};

// The outlines the field command offers: the project's shapes and the paper's further cuts.
enum class OutlineKind {
  rectangular,  // Conci's set-up: an L x h rectangle hung from its top corners moved in by d
  cosine,       // Mansfield's: between a_n cos(pi X / L) and a_0 cos(pi X / L), hung from its ends
  strip,        // k - 1 rectangles side by side, hung from k points of the top edge
  inclined,     // the rectangle sheared so that its right support is higher by l tan(incline)
  triangle,     // a triangle, point down, hung from its two top corners
  pennant,      // a right triangle, its long side vertical at the left, hung from its top corners
  wedge,        // Mansfield's wedge cut short of its apex: h deep at the left, h / 4 at the right
};

// The wedge's depth at its thin (right) end as a share of h: its edges would meet a third of
// L beyond the right support.
inline constexpr double kWedgeThinEndShare = 0.25;

std::string_view to_string(OutlineKind k);
bool parse_outline_kind(std::string_view s, OutlineKind& out);
// "rectangular, cosine, ..." for help texts and refusals.
std::string outline_kind_names();
// The field's outline for one of the project's shapes.
OutlineKind outline_kind_of(const Shape& shape);

// The cosine outline's edges at the centre: a_0 = h + a_n below the supports' line and
// a_n = h / 100 (the paper's starting a_n): the cut is h tall at its centre like the others.
double cosine_top_depth_mm(const Parameters& p);
double cosine_bottom_depth_mm(const Parameters& p);

// The cut with its supports for the model's inputs: h, L, d with the span rule of the model
// (l from span_mm), the strip's k and the incline from the shape.
Outline make_outline(const Parameters& p, OutlineKind kind);

// The cloth the closed form sees in a cut hung from two supports on its top edge: h its height
// down the middle between them, L the distance between them as cut, d how far they were moved
// together (by `rule`: the span is L - d or L - 2d). Empty for any other cut (one support or
// three and more, a support below the top edge, supports moved apart), which has no such cloth.
std::optional<Hanging> closed_form_hanging(const Outline& outline, SpanRule rule);

inline constexpr int kMaxOutlineVertices = 10000;
// Every coordinate of a cut, its supports' pins included, within this of the origin: 10 km, far
// beyond any cloth, and small enough that a cut's millimetres keep 9 digits in a double.
inline constexpr double kMaxOutlineCoordinate_mm = 1e7;
// A support pinned farther than this many times the cut's size (the larger of its width and
// height) from where it is on the cut: no hung cloth stretches so, and the solver's forces would
// lose the weight in their round-off.
inline constexpr double kMaxSupportPullPerSize = 10.0;
// Tolerance of the cut's checks and of its mesh, as a share of its width: two vertices of one
// edge closer in x than this, or a cut no taller than this, cannot be meshed.
inline constexpr double kOutlineTolerancePerWidth = 1e-6;

// Reads {"top": [[x, y], ...], "bottom": [[x, y], ...], "supports": [{"at": [X, Y], "to": [x,
// y]}, ...]} in mm, y down. Throws OutlineError naming what is wrong: a key given twice or one
// not in that list included.
Outline parse_outline_json(std::string_view text);
// The same from a parsed value (a preset's "outline"): the one reader of a cut and its rules.
Outline outline_from_json(const nlohmann::json& doc);

// Throws OutlineError unless the outline can be meshed: at least two vertices per edge, each edge
// monotone in x with its vertices at least kOutlineTolerancePerWidth of the width apart, both
// edges over the same x range, the bottom never above the top, taller than that tolerance, at
// most kMaxOutlineVertices vertices, every coordinate within kMaxOutlineCoordinate_mm, at least
// one support, each support on the top or bottom edge (or an end) and pinned within
// kMaxSupportPullPerSize times the cut's size of it, no two supports at one point, every number
// finite.
void check_outline(const Outline& outline);

// The cut moved by `offset_mm`, its supports' pins with it.
Outline translated(const Outline& outline, const Eigen::Vector2d& offset_mm);
// Where a cut is solved from: its centre rounded to a multiple of a power of two no smaller than
// its size, so that subtracting it is exact and a cut about the origin is solved where it is
// (zero). Solving relative to it keeps a cut's field the same wherever the cut sits.
Eigen::Vector2d solve_origin_mm(const Outline& outline);

}  // namespace foldlab::field
