// A solved tension field as an SVG drawing: the hung cloth's triangles coloured by region (taut,
// wrinkled, slack; a colour-blind-safe palette with a legend), the tension rays as polylines, and
// each support with the arrow of the force it exerts on the cloth and its value in N.
#pragma once

#include <string>

#include "core/field/field_case.hpp"
#include "core/field/mesh.hpp"
#include "core/field/outline.hpp"

namespace foldlab::field {

// `report` solved on `mesh` for `outline`. A field that did not converge is drawn under a banner
// that says so, with its residual. Throws std::logic_error on a non-finite coordinate.
std::string field_to_svg(const Mesh& mesh, const FieldReport& report, const Outline& outline,
                         const std::string& title);

}  // namespace foldlab::field
