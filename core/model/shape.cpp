#include "core/model/shape.hpp"

#include <cmath>
#include <numbers>

#include "core/model/named_enum.hpp"

namespace foldlab {

double Shape::shear() const {
  return kind == ShapeKind::inclined ? std::tan(incline_deg * std::numbers::pi / 180.0) : 0.0;
}

std::string_view to_string(ShapeKind k) {
  switch (k) {
    case ShapeKind::cosine_membrane:
      return "cosine";
    case ShapeKind::rectangular:
      return "rectangular";
    case ShapeKind::strip:
      return "strip";
    case ShapeKind::inclined:
      return "inclined";
  }
  return "cosine";
}

bool parse_shape_kind(std::string_view s, ShapeKind& out) {
  return parse_named(
      s, out,
      {ShapeKind::cosine_membrane, ShapeKind::rectangular, ShapeKind::strip, ShapeKind::inclined});
}

}  // namespace foldlab
