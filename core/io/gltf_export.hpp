// The deformed cloth as binary glTF 2.0 (.glb), for viewers and renderers that expect glTF's
// conventions rather than the model's: the caller writes the bytes (with write_file_atomically).
#pragma once

#include <string>

#include "core/geometry/geometry.hpp"

namespace foldlab {

// One mesh with one indexed triangle primitive: POSITION, NORMAL and TEXCOORD_0
// (texture_coordinates of export.hpp) per grid vertex, and a double-sided fabric-coloured PBR
// material. glTF is +Y up in metres, so positions are (x, -y, z) / 1000 and normals (x, -y, z) of
// the model's (mm, y down), and each triangle's winding is reversed because the flip mirrors it.
// The title names the mesh, node and scene. Throws std::runtime_error if tinygltf cannot serialise.
std::string mesh_to_glb(const DeformedGrid& grid, const std::string& title);

}  // namespace foldlab
