// File formats for the deformed cloth and its fold lines. Pure text builders: the caller writes
// them (with write_file_atomically).
#pragma once

#include <string>

#include "foldlab/geometry.hpp"

namespace foldlab {

// Wavefront OBJ: v (mm), vn, f with v//vn; y points down as in the model (see the header comment).
std::string mesh_to_obj(const DeformedGrid& grid, const std::string& title);

// CSV with a header: line,sign,x_mm,y_mm,z_mm; one row per sampled point.
std::string fold_lines_to_csv(const FoldLines& lines);

// A drawing of the fold lines y_i(x) as in the paper's figures: y down, supports marked, negative
// folds red, axes in mm, a caption with n, Q and z_max.
std::string fold_lines_to_svg(const FoldLines& lines, const Solution& s, const std::string& title);

}  // namespace foldlab
