// File formats for the deformed cloth and its fold lines. Pure text builders: the caller writes
// them (with write_file_atomically).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/geometry.hpp"

namespace foldlab {

// Texture coordinates of every grid vertex from its place on the flat cloth, so that a print on the
// fabric follows the folds: u = (X - X_min) / (X_max - X_min), v = Y / Y_max over the grid (v = 0
// at the upper edge). A coordinate whose range over the grid has zero length is 0.
std::vector<Eigen::Vector2f> texture_coordinates(const DeformedGrid& grid);

// Wavefront OBJ: v (mm), vt (texture_coordinates), vn, f with v/vt/vn; y points down as in the
// model (see the header comment).
std::string mesh_to_obj(const DeformedGrid& grid, const std::string& title);

// CSV with a header: line,sign,x_mm,y_mm,z_mm; one row per sampled point.
std::string fold_lines_to_csv(const FoldLines& lines);

// A drawing of the fold lines y_i(x) as in the paper's figures: y down, supports marked, negative
// folds red, axes in mm, a caption with n, Q and z_max.
std::string fold_lines_to_svg(const FoldLines& lines, const Solution& s, const std::string& title);

}  // namespace foldlab
