#include "core/io/gltf_export.hpp"

#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <tiny_gltf.h>

#include "core/io/export.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

// The model's frame (mm, y down) in glTF's (m, +Y up): mirroring y makes the cloth hang down.
Eigen::Vector3f to_gltf_position(const Eigen::Vector3f& p_mm) {
  return Eigen::Vector3f(p_mm.x(), -p_mm.y(), p_mm.z()) * 1e-3f;
}

Eigen::Vector3f to_gltf_direction(const Eigen::Vector3f& n) {
  return Eigen::Vector3f(n.x(), -n.y(), n.z());
}

// Appends `count` plain values to the buffer as one tightly packed buffer view; returns its index.
template <class T>
int append_view(tinygltf::Model& model, const T* values, std::size_t count, int target) {
  std::vector<unsigned char>& data = model.buffers[0].data;
  // Every component here is 4 bytes wide, so views stay 4-byte aligned as glTF requires.
  const std::size_t offset = data.size();
  const std::size_t bytes = count * sizeof(T);
  data.resize(offset + bytes);
  if (bytes > 0) {
    std::memcpy(data.data() + offset, values, bytes);
  }
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = bytes;
  view.target = target;
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, int component_type, int type,
                 std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.byteOffset = 0;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size()) - 1;
}

// The grid in glTF's frame and units, checked finite.
struct GltfArrays {
  std::vector<Eigen::Vector3f> positions;  // m
  std::vector<Eigen::Vector3f> normals;
  std::vector<Eigen::Vector2f> uv;
  std::vector<std::uint32_t> indices;
  // glTF requires POSITION's bounds (viewers frame the scene with them).
  Eigen::Vector3f min_m = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f max_m = Eigen::Vector3f::Constant(std::numeric_limits<float>::lowest());
};

GltfArrays gltf_arrays(const DeformedGrid& grid) {
  GltfArrays a;
  a.positions.resize(grid.positions_mm.size());
  a.normals.resize(grid.normals.size());
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    a.positions[v] = to_gltf_position(grid.positions_mm[v]);
    for (int i = 0; i < 3; ++i) {
      detail::finite_or_throw(a.positions[v][i], "glTF POSITION (m)");
    }
    a.min_m = a.min_m.cwiseMin(a.positions[v]);
    a.max_m = a.max_m.cwiseMax(a.positions[v]);
  }
  for (std::size_t v = 0; v < a.normals.size(); ++v) {
    a.normals[v] = to_gltf_direction(grid.normals[v]);
    for (int i = 0; i < 3; ++i) {
      detail::finite_or_throw(a.normals[v][i], "glTF NORMAL");
    }
  }
  a.uv = texture_coordinates(grid);
  // Mirroring y turns every triangle's geometric normal against the mirrored vertex normals:
  // swapping two corners keeps front faces on the side the normals point to.
  a.indices.resize(grid.triangle_indices.size());
  for (std::size_t t = 0; t + 2 < a.indices.size(); t += 3) {
    a.indices[t] = grid.triangle_indices[t];
    a.indices[t + 1] = grid.triangle_indices[t + 2];
    a.indices[t + 2] = grid.triangle_indices[t + 1];
  }
  return a;
}

// The arrays as the buffer's views and accessors, and the triangles that use them.
tinygltf::Primitive add_triangles(tinygltf::Model& model, const GltfArrays& a) {
  static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "tightly packed vec3");
  static_assert(sizeof(Eigen::Vector2f) == 2 * sizeof(float), "tightly packed vec2");
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  const int position_accessor = add_accessor(
      model,
      append_view(model, a.positions.data(), a.positions.size(), TINYGLTF_TARGET_ARRAY_BUFFER),
      TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, a.positions.size());
  if (!a.positions.empty()) {
    tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(position_accessor)];
    accessor.minValues = {a.min_m.x(), a.min_m.y(), a.min_m.z()};
    accessor.maxValues = {a.max_m.x(), a.max_m.y(), a.max_m.z()};
  }
  primitive.attributes["POSITION"] = position_accessor;
  if (!a.normals.empty()) {
    primitive.attributes["NORMAL"] = add_accessor(
        model, append_view(model, a.normals.data(), a.normals.size(), TINYGLTF_TARGET_ARRAY_BUFFER),
        TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, a.normals.size());
  }
  primitive.attributes["TEXCOORD_0"] = add_accessor(
      model, append_view(model, a.uv.data(), a.uv.size(), TINYGLTF_TARGET_ARRAY_BUFFER),
      TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, a.uv.size());
  primitive.indices = add_accessor(
      model,
      append_view(model, a.indices.data(), a.indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
      TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, a.indices.size());
  return primitive;
}

// Both sides of a hanging cloth are seen; a rough, non-metallic linen colour reads as fabric.
tinygltf::Material fabric_material() {
  tinygltf::Material material;
  material.name = "fabric";
  material.doubleSided = true;
  material.pbrMetallicRoughness.baseColorFactor = {0.78, 0.70, 0.58, 1.0};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.9;
  return material;
}

// One mesh of `primitive` in one node of the one scene, all named by the title.
void add_scene(tinygltf::Model& model, const tinygltf::Primitive& primitive,
               const DeformedGrid& grid, const std::string& title) {
  tinygltf::Mesh mesh;
  mesh.name = detail::escaped(title);
  // Diagnostics a viewer ignores and a script can read.
  mesh.extras = tinygltf::Value(
      tinygltf::Value::Object{{"worst_fibre_error", tinygltf::Value(grid.worst_fibre_error)},
                              {"sharpest_turn_deg", tinygltf::Value(grid.sharpest_turn_deg)}});
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.name = mesh.name;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.name = mesh.name;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
}

std::string glb_bytes(tinygltf::Model& model) {
  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true) || !out) {
    throw std::runtime_error("could not serialise the mesh as glTF");
  }
  return std::move(out).str();
}

}  // namespace

std::string mesh_to_glb(const DeformedGrid& grid, const std::string& title) {
  const GltfArrays arrays = gltf_arrays(grid);
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "FoldLab";
  model.buffers.emplace_back();  // no uri: WriteGltfSceneToStream puts it in the GLB's BIN chunk
  tinygltf::Primitive primitive = add_triangles(model, arrays);
  model.materials.push_back(fabric_material());
  primitive.material = 0;
  add_scene(model, primitive, grid, title);
  return glb_bytes(model);
}

}  // namespace foldlab
