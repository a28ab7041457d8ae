#include "core/model/shape.hpp"

#include <cmath>
#include <numbers>

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
  for (ShapeKind k : {ShapeKind::cosine_membrane, ShapeKind::rectangular, ShapeKind::strip,
                      ShapeKind::inclined}) {
    if (s == to_string(k)) {
      out = k;
      return true;
    }
  }
  return false;
}

}  // namespace foldlab
