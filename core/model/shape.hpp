// Which cloth the wrinkle pattern is drawn on (paper §3.1, Figs. 1-2). The solver is the same for
// every shape: a shape changes only how the one-span solution is laid out in space.
#pragma once

#include <string_view>

namespace foldlab {

enum class ShapeKind {
  cosine_membrane,  // the paper's membrane: the fibre at X is h cos(pi X / L) long
  rectangular,      // a rectangular cloth: cloth below the lowest fold hangs straight down
  strip,            // a strip on k equally spaced supports: the span's pattern repeats (Fig. 2)
  inclined,         // supports at different heights: the pattern sheared (Mansfield)
};

struct Shape {
  ShapeKind kind = ShapeKind::cosine_membrane;
  int supports = 3;           // strip: k >= 2 supports, k - 1 spans each of the given L and d
  double incline_deg = 15.0;  // inclined: the right support is higher by l tan(incline)

  bool operator==(const Shape&) const = default;

  int span_count() const { return kind == ShapeKind::strip ? supports - 1 : 1; }
  // tan of the shear angle: 0 unless inclined.
  double shear() const;
};

std::string_view to_string(ShapeKind k);
bool parse_shape_kind(std::string_view s, ShapeKind& out);

}  // namespace foldlab
