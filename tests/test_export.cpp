// The mesh exports: OBJ with texture coordinates, and binary glTF read back with
// tinygltf's own loader. Expected values come from the grid and the parameters, never from the
// exporters.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <tiny_gltf.h>

#include "core/geometry/geometry.hpp"
#include "core/io/export.hpp"
#include "core/io/gltf_export.hpp"
#include "core/model/solver.hpp"
#include "core/model/text_format.hpp"

namespace foldlab {
namespace {

// Odd nx puts a column at X = 0, whose fibre is the full height h: there v reaches 1.
constexpr int kNx = 9;
constexpr int kNy = 7;

struct Fixture {
  Parameters p;
  DeformedGrid grid;
};

Fixture make_fixture() {
  Fixture f;
  f.p.model.method = Method::exact;
  f.grid = deformed_grid(solve(f.p), f.p, kNx, kNy);
  return f;
}

// The texture coordinate vertex (i, j) should have: u runs evenly across the flat cloth's columns
// and v is the material depth over the full height h (the central fibre's length).
Eigen::Vector2f expected_uv(const Fixture& f, int i, int j) {
  const std::size_t v = static_cast<std::size_t>(j) * kNx + i;
  return Eigen::Vector2f(static_cast<float>(i) / (kNx - 1),
                         static_cast<float>(f.grid.material_mm[v].y() / f.p.hanging.height_mm));
}

// The model as TinyGLTF's own loader reads it, with neither error nor warning.
tinygltf::Model load_glb(const std::string& glb) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err;
  std::string warn;
  EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn,
                                          reinterpret_cast<const unsigned char*>(glb.data()),
                                          static_cast<unsigned int>(glb.size())))
      << err;
  EXPECT_TRUE(err.empty()) << err;
  EXPECT_TRUE(warn.empty()) << warn;
  return model;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    lines.push_back(line);
  }
  return lines;
}

TEST(ExportObj, WritesTextureCoordinatesAndFullFaces) {
  const Fixture f = make_fixture();
  ASSERT_EQ(f.grid.material_mm.size(), static_cast<std::size_t>(kNx * kNy));
  const std::string obj = mesh_to_obj(f.grid, "test");
  int v = 0;
  int vn = 0;
  int faces = 0;
  std::vector<Eigen::Vector2f> uv;
  const std::regex face(R"(f (\d+)/(\d+)/(\d+) (\d+)/(\d+)/(\d+) (\d+)/(\d+)/(\d+))");
  for (const std::string& line : lines_of(obj)) {
    v += line.rfind("v ", 0) == 0;
    vn += line.rfind("vn ", 0) == 0;
    if (line.rfind("vt ", 0) == 0) {
      float u = -1;
      float w = -1;
      ASSERT_EQ(std::sscanf(line.c_str(), "vt %f %f", &u, &w), 2) << line;
      uv.emplace_back(u, 1.0f - w);  // OBJ's v runs up the image: back to the grid's v
    }
    if (line.rfind("f ", 0) == 0) {
      ++faces;
      std::smatch m;
      ASSERT_TRUE(std::regex_match(line, m, face)) << line;
      // One index per grid vertex for all three attributes.
      for (int corner = 0; corner < 3; ++corner) {
        EXPECT_EQ(m[1 + 3 * corner], m[2 + 3 * corner]) << line;
        EXPECT_EQ(m[1 + 3 * corner], m[3 + 3 * corner]) << line;
        const int index = std::stoi(m[1 + 3 * corner]);
        EXPECT_GE(index, 1);
        EXPECT_LE(index, kNx * kNy);
      }
    }
  }
  EXPECT_EQ(v, kNx * kNy);
  EXPECT_EQ(vn, kNx * kNy);
  EXPECT_EQ(faces, 2 * (kNx - 1) * (kNy - 1));
  ASSERT_EQ(uv.size(), static_cast<std::size_t>(kNx * kNy));
  for (int j = 0; j < kNy; ++j) {
    for (int i = 0; i < kNx; ++i) {
      const Eigen::Vector2f& t = uv[static_cast<std::size_t>(j * kNx + i)];
      EXPECT_GE(t.x(), 0.0f);
      EXPECT_LE(t.x(), 1.0f);
      EXPECT_GE(t.y(), 0.0f);
      EXPECT_LE(t.y(), 1.0f);
      EXPECT_NEAR(t.x(), expected_uv(f, i, j).x(), 1e-5f) << i << "," << j;
      EXPECT_NEAR(t.y(), expected_uv(f, i, j).y(), 1e-5f) << i << "," << j;
    }
  }
  // Corners of the flat cloth: the upper edge is v = 0, the sides u = 0 and 1, the bottom of the
  // central (full-height) fibre v = 1.
  EXPECT_EQ(uv.front().x(), 0.0f);
  EXPECT_EQ(uv.front().y(), 0.0f);
  EXPECT_EQ(uv[kNx - 1].x(), 1.0f);
  EXPECT_FLOAT_EQ(uv[static_cast<std::size_t>((kNy - 1) * kNx + kNx / 2)].y(), 1.0f);
  // The header still states the frame.
  EXPECT_NE(obj.find("# units mm; x across, y down"), std::string::npos);
}

// The elements of a float accessor as N-vectors, honouring the view's stride.
template <int N>
std::vector<Eigen::Matrix<float, N, 1>> read_floats(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(index));
  EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(a.type, N == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3);
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const std::vector<unsigned char>& data =
      model.buffers.at(static_cast<std::size_t>(view.buffer)).data;
  const std::size_t stride = view.byteStride > 0 ? view.byteStride : N * sizeof(float);
  std::vector<Eigen::Matrix<float, N, 1>> out(a.count);
  for (std::size_t k = 0; k < a.count; ++k) {
    const std::size_t at = view.byteOffset + a.byteOffset + k * stride;
    EXPECT_LE(at + N * sizeof(float), data.size());
    if (at + N * sizeof(float) <= data.size()) {
      std::memcpy(out[k].data(), data.data() + at, N * sizeof(float));
    }
  }
  return out;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(index));
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const std::vector<unsigned char>& data =
      model.buffers.at(static_cast<std::size_t>(view.buffer)).data;
  std::vector<std::uint32_t> out(a.count);
  for (std::size_t k = 0; k < a.count; ++k) {
    const unsigned char* at = data.data() + view.byteOffset + a.byteOffset;
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      std::memcpy(&out[k], at + 4 * k, 4);
    } else {
      EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
      std::uint16_t i16 = 0;
      std::memcpy(&i16, at + 2 * k, 2);
      out[k] = i16;
    }
  }
  return out;
}

// glTF's frame: metres, +Y up; the model's y points down.
Eigen::Vector3f mirrored(const Eigen::Vector3f& v) {
  return Eigen::Vector3f(v.x(), -v.y(), v.z());
}

TEST(ExportGlb, ReadsBackAsOneMeshInMetresWithYUp) {
  const Fixture f = make_fixture();
  const std::string glb = mesh_to_glb(f.grid, "test cloth");
  ASSERT_GE(glb.size(), 12u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  std::uint32_t version = 0;
  std::uint32_t length = 0;
  std::memcpy(&version, glb.data() + 4, 4);
  std::memcpy(&length, glb.data() + 8, 4);
  EXPECT_EQ(version, 2u);
  EXPECT_EQ(length, glb.size());

  const tinygltf::Model model = load_glb(glb);
  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
  EXPECT_EQ(model.meshes[0].name, "test cloth");
  const tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
  EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
  ASSERT_EQ(primitive.attributes.count("POSITION"), 1u);
  ASSERT_EQ(primitive.attributes.count("NORMAL"), 1u);
  ASSERT_EQ(primitive.attributes.count("TEXCOORD_0"), 1u);
  // The scene shows the mesh.
  ASSERT_EQ(model.scenes.size(), 1u);
  ASSERT_EQ(model.scenes[0].nodes.size(), 1u);
  EXPECT_EQ(model.nodes.at(static_cast<std::size_t>(model.scenes[0].nodes[0])).mesh, 0);

  const std::size_t count = static_cast<std::size_t>(kNx * kNy);
  const auto positions = read_floats<3>(model, primitive.attributes.at("POSITION"));
  const auto normals = read_floats<3>(model, primitive.attributes.at("NORMAL"));
  const auto uv = read_floats<2>(model, primitive.attributes.at("TEXCOORD_0"));
  ASSERT_EQ(positions.size(), count);
  ASSERT_EQ(normals.size(), count);
  ASSERT_EQ(uv.size(), count);
  float lowest = 0.0f;
  for (std::size_t v = 0; v < count; ++v) {
    const Eigen::Vector3f& mm = f.grid.positions_mm[v];
    EXPECT_NEAR(positions[v].x(), mm.x() / 1000.0f, 1e-6f) << v;
    EXPECT_NEAR(positions[v].y(), -mm.y() / 1000.0f, 1e-6f) << v;
    EXPECT_NEAR(positions[v].z(), mm.z() / 1000.0f, 1e-6f) << v;
    lowest = std::min(lowest, positions[v].y());
    EXPECT_NEAR(normals[v].norm(), 1.0f, 1e-5f) << v;
    EXPECT_NEAR((normals[v] - mirrored(f.grid.normals[v])).norm(), 0.0f, 1e-6f) << v;
    const int i = static_cast<int>(v) % kNx;
    const int j = static_cast<int>(v) / kNx;
    EXPECT_NEAR(uv[v].x(), expected_uv(f, i, j).x(), 1e-5f) << v;
    EXPECT_NEAR(uv[v].y(), expected_uv(f, i, j).y(), 1e-5f) << v;
  }
  // The cloth hangs down from the supports at y = 0.
  EXPECT_LT(lowest, -0.1f * static_cast<float>(f.p.hanging.height_mm) / 1000.0f);

  const auto indices = read_indices(model, primitive.indices);
  ASSERT_EQ(indices.size(), static_cast<std::size_t>(6 * (kNx - 1) * (kNy - 1)));
  // Winding: each front face must point where the model's face points, mirrored. The model's face
  // normal comes from the grid's own triangles, so a mirror without a winding swap fails here.
  int checked = 0;
  for (std::size_t t = 0; t < indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      ASSERT_LT(indices[t + k], count);
    }
    const Eigen::Vector3f& a = positions[indices[t]];
    const Eigen::Vector3f face =
        (positions[indices[t + 1]] - a).cross(positions[indices[t + 2]] - a);
    const Eigen::Vector3f& A = f.grid.positions_mm[f.grid.triangle_indices[t]];
    const Eigen::Vector3f model_face =
        (f.grid.positions_mm[f.grid.triangle_indices[t + 1]] - A)
            .cross(f.grid.positions_mm[f.grid.triangle_indices[t + 2]] - A);
    if (model_face.norm() < 1e-3f) {
      continue;  // triangles collapsed onto a support have no direction
    }
    ++checked;
    EXPECT_GT(face.normalized().dot(mirrored(model_face).normalized()), 0.99f) << t / 3;
  }
  EXPECT_GT(checked, static_cast<int>(indices.size() / 3) / 2);

  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(primitive.material, 0);
  EXPECT_TRUE(model.materials[0].doubleSided);
  EXPECT_EQ(model.materials[0].pbrMetallicRoughness.baseColorFactor.size(), 4u);
}

// A preset's name is the user's text: a line break, a terminal escape, markup or a byte that is
// not UTF-8 in it stays a name in every format. Each file is read back as its own readers would:
// the OBJ's vertex count, the SVG as XML (every control character is invalid there), the glTF by
// TinyGLTF's loader, a measurements CSV's columns.
TEST(ExportNames, AHostileNameStaysANameInEveryFormat) {
  const std::string name = "Evil\nv 1e9 1e9 1e9\r\x1b[2J\x07<b>&\"\xff ν";
  const Fixture f = make_fixture();
  const auto is_control = [](char c) {
    const auto b = static_cast<unsigned char>(c);
    return (b < 0x20 && c != '\n') || b == 0x7F;
  };

  const std::string obj = mesh_to_obj(f.grid, name);
  int vertices = 0;
  for (const std::string& line : lines_of(obj)) {
    vertices += line.starts_with("v ") ? 1 : 0;
    EXPECT_TRUE(line.empty() || line[0] == '#' || line.find("Evil") == std::string::npos) << line;
  }
  EXPECT_EQ(vertices, kNx * kNy);
  EXPECT_TRUE(std::none_of(obj.begin(), obj.end(), is_control));
  EXPECT_EQ(lines_of(obj)[0], "# FoldLab deformed cloth: " + detail::escaped(name));

  const Solution s = solve(f.p);
  const std::string svg = fold_lines_to_svg(fold_lines(s, f.p, 11), s, name);
  EXPECT_TRUE(std::none_of(svg.begin(), svg.end(), is_control));
  EXPECT_TRUE(detail::is_valid_utf8(svg));
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
  EXPECT_NE(svg.find(">Evil\\x0av 1e9 1e9 1e9\\x0d\\x1b[2J\\x07&lt;b&gt;&amp;&quot;\\xff ν</text>"),
            std::string::npos)
      << svg.substr(0, 600);
  // Well formed: every '<' opens a tag that a '>' closes, every '&' starts an entity.
  for (std::size_t at = svg.find('&'); at != std::string::npos; at = svg.find('&', at + 1)) {
    const std::string entity = svg.substr(at, svg.find(';', at) - at + 1);
    EXPECT_TRUE(entity == "&amp;" || entity == "&lt;" || entity == "&gt;" || entity == "&quot;")
        << entity;
  }
  int depth = 0;
  for (const char c : svg) {
    depth += c == '<' ? 1 : c == '>' ? -1 : 0;
    ASSERT_GE(depth, 0);
    ASSERT_LE(depth, 1);
  }

  const tinygltf::Model model = load_glb(mesh_to_glb(f.grid, name));
  ASSERT_EQ(model.meshes.size(), 1u);
  EXPECT_EQ(model.meshes[0].name, detail::escaped(name));
  EXPECT_EQ(model.nodes.at(0).name, detail::escaped(name));
}

TEST(ExportUv, TextureCoordinatesSpanTheUnitSquare) {
  const Fixture f = make_fixture();
  const std::vector<Eigen::Vector2f> uv = texture_coordinates(f.grid);
  ASSERT_EQ(uv.size(), static_cast<std::size_t>(kNx * kNy));
  float u_min = 1;
  float u_max = 0;
  float v_min = 1;
  float v_max = 0;
  for (const Eigen::Vector2f& t : uv) {
    u_min = std::min(u_min, t.x());
    u_max = std::max(u_max, t.x());
    v_min = std::min(v_min, t.y());
    v_max = std::max(v_max, t.y());
  }
  EXPECT_EQ(u_min, 0.0f);
  EXPECT_EQ(u_max, 1.0f);
  EXPECT_EQ(v_min, 0.0f);
  EXPECT_FLOAT_EQ(v_max, 1.0f);
}

}  // namespace
}  // namespace foldlab
