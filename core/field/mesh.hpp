// The triangle mesh of a flat cut: columns of nodes at x positions across the cut, each column
// from the top edge to the bottom edge, with a column at every vertex of either edge and at every
// support, and a node at every support, so that the supports are nodes and the edges are exact.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/field/outline.hpp"

namespace foldlab::field {

// How each cell between two columns of equal node count is cut into triangles. One diagonal
// direction everywhere ("uniform") gives the mesh a grain; the alternating "union-jack" split
// cancels it pairwise; "crossed" cuts each cell into four about a node at its centre, the most
// isotropic and the costliest (docs/field.md compares them).
enum class MeshSplit { uniform, union_jack, crossed };

std::string_view to_string(MeshSplit s);
bool parse_mesh_split(std::string_view s, MeshSplit& out);

struct MeshResolution {
  int cells_x = 40;  // cells across the cut's width (columns at edge vertices and supports added)
  int cells_y = 28;  // cells down the tallest column; shorter columns get proportionally fewer
  MeshSplit split = MeshSplit::union_jack;

  bool operator==(const MeshResolution&) const = default;
};

// Refused above this many nodes: a mesh past it would not solve in a reasonable time.
inline constexpr int kMaxMeshNodes = 200000;

struct Mesh {
  std::vector<Eigen::Vector2d> nodes_mm;  // flat positions
  // Each with a positive signed area in (x, y), so that det F > 0 unless it turned over.
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::vector<int>> column_triangles;  // the triangles between columns i and i + 1
  std::vector<double> column_x_mm;                 // the columns' x, increasing
  std::vector<int> support_nodes;                  // one per outline support, in its order

  // The triangle that holds the flat point p, -1 when p is outside the cut.
  int locate(const Eigen::Vector2d& p_mm) const;
  // Barycentric coordinates of p in triangle t.
  Eigen::Vector3d barycentric(int t, const Eigen::Vector2d& p_mm) const;
};

// Throws OutlineError when the mesh would exceed kMaxMeshNodes.
Mesh make_mesh(const Outline& outline, const MeshResolution& resolution);

}  // namespace foldlab::field
