#include "core/field/mesh.hpp"

#include "core/model/named_enum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/model/text_format.hpp"

namespace foldlab::field {
namespace {

using Eigen::Vector2d;

// Edges turn at a corner of the cut (the triangle's point) by more than this: a column goes
// there so that the mesh's edge is the cut's. Gentler bends (a cosine drawn as a polyline) are
// followed by the columns' chords.
constexpr double kCornerTurn_rad = 5.0 * std::numbers::pi / 180.0;

void add_corners(const std::vector<Vector2d>& edge, std::vector<double>& xs) {
  for (std::size_t i = 1; i + 1 < edge.size(); ++i) {
    const Vector2d a = edge[i] - edge[i - 1];
    const Vector2d b = edge[i + 1] - edge[i];
    const double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    if (std::abs(turn) > kCornerTurn_rad) {
      xs.push_back(edge[i].x());
    }
  }
}

// Uniform positions from `lo` to `hi` in `cells` steps with each required position put in place
// of the uniform ones closer to it than 0.3 of a step.
std::vector<double> positions(double lo, double hi, int cells, std::vector<double> required,
                              double tolerance) {
  std::sort(required.begin(), required.end());
  const double step = (hi - lo) / cells;
  std::vector<double> out = required;
  for (int i = 0; i <= cells; ++i) {
    const double v = i == cells ? hi : lo + i * step;
    const bool near_required = std::any_of(required.begin(), required.end(),
                                           [&](double r) { return std::abs(r - v) < 0.3 * step; });
    if (!near_required) {
      out.push_back(v);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(),
                        [&](double a, double b) { return std::abs(a - b) <= tolerance; }),
            out.end());
  return out;
}

// The solve's peak memory per node, measured (the ladder's meshes, the Newton matrix and its
// factors): 408 MB for 102 261 nodes, 652 MB for 174 000. A mesh whose estimate is above the cap
// is refused before it takes the machine's memory.
constexpr double kSolveBytesPerNode = 4096.0;
constexpr double kMaxSolveBytes = 512.0 * 1024.0 * 1024.0;

double signed_area(const Vector2d& a, const Vector2d& b, const Vector2d& c) {
  const Vector2d u = b - a;
  const Vector2d v = c - a;
  return 0.5 * (u.x() * v.y() - u.y() * v.x());
}

}  // namespace

std::string_view to_string(MeshSplit s) {
  switch (s) {
    case MeshSplit::uniform:
      return "uniform";
    case MeshSplit::union_jack:
      return "union-jack";
    case MeshSplit::crossed:
      return "crossed";
  }
  return "union-jack";
}

bool parse_mesh_split(std::string_view s, MeshSplit& out) {
  return parse_named(s, out, {MeshSplit::uniform, MeshSplit::union_jack, MeshSplit::crossed});
}

Mesh make_mesh(const Outline& outline, const MeshResolution& resolution) {
  check_outline(outline);
  if (resolution.cells_x < 1 || resolution.cells_y < 1) {
    throw OutlineError("the mesh needs at least one cell across and one down");
  }
  const double left = outline.left_mm();
  const double right = outline.right_mm();
  const double size = right - left;
  const double tolerance = 1e-6 * size;

  std::vector<double> required_x{left, right};
  add_corners(outline.top_mm, required_x);
  add_corners(outline.bottom_mm, required_x);
  for (const Support& s : outline.supports) {
    required_x.push_back(s.at_mm.x());
  }
  const std::vector<double> xs = positions(left, right, resolution.cells_x, required_x, tolerance);

  double tallest = 0.0;
  for (double x : xs) {
    tallest = std::max(tallest, outline.bottom_y_mm(x) - outline.top_y_mm(x));
  }
  const double estimated_nodes = static_cast<double>(xs.size()) * (resolution.cells_y + 1.0) *
                                 (resolution.split == MeshSplit::crossed ? 2.0 : 1.0);
  if (estimated_nodes > kMaxMeshNodes) {
    throw OutlineError(detail::printf_string(
        "a mesh of %d x %d cells on this cut would have about %.0f nodes; at most %d are solved",
        resolution.cells_x, resolution.cells_y, estimated_nodes, kMaxMeshNodes));
  }
  if (estimated_nodes * kSolveBytesPerNode > kMaxSolveBytes) {
    throw OutlineError(detail::printf_string(
        "a mesh of %d x %d cells on this cut would have about %.0f nodes and take about %.0f MB "
        "to solve; at most %.0f MB (%.0f nodes) are taken",
        resolution.cells_x, resolution.cells_y, estimated_nodes,
        estimated_nodes * kSolveBytesPerNode / (1024.0 * 1024.0),
        kMaxSolveBytes / (1024.0 * 1024.0), kMaxSolveBytes / kSolveBytesPerNode));
  }

  Mesh mesh;
  mesh.column_x_mm = xs;
  std::vector<std::vector<int>> columns;      // node indices, top to bottom
  std::vector<std::vector<double>> fraction;  // each node's depth as a share of its column
  for (double x : xs) {
    const double top = outline.top_y_mm(x);
    const double bottom = outline.bottom_y_mm(x);
    const double height = bottom - top;
    std::vector<int> column;
    std::vector<double> shares;
    if (height <= tolerance) {
      column.push_back(static_cast<int>(mesh.nodes_mm.size()));
      mesh.nodes_mm.emplace_back(x, top);
      shares.push_back(0.0);
    } else {
      const int rows =
          std::max(1, static_cast<int>(std::lround(resolution.cells_y * height / tallest)));
      std::vector<double> required_y{top, bottom};
      for (const Support& s : outline.supports) {
        if (std::abs(s.at_mm.x() - x) <= tolerance) {
          required_y.push_back(std::clamp(s.at_mm.y(), top, bottom));
        }
      }
      for (double y : positions(top, bottom, rows, required_y, tolerance)) {
        column.push_back(static_cast<int>(mesh.nodes_mm.size()));
        mesh.nodes_mm.emplace_back(x, y);
        shares.push_back((y - top) / height);
      }
    }
    columns.push_back(std::move(column));
    fraction.push_back(std::move(shares));
  }

  const double tiny_area = 1e-12 * size * size;
  auto add_triangle = [&](int column, int a, int b, int c) {
    const double area = signed_area(mesh.nodes_mm[a], mesh.nodes_mm[b], mesh.nodes_mm[c]);
    if (std::abs(area) <= tiny_area) {
      return;
    }
    mesh.column_triangles[column].push_back(static_cast<int>(mesh.triangles.size()));
    mesh.triangles.push_back(area > 0 ? std::array<int, 3>{a, b, c} : std::array<int, 3>{a, c, b});
  };
  mesh.column_triangles.resize(xs.size() - 1);
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const std::vector<int>& a = columns[i];
    const std::vector<int>& b = columns[i + 1];
    const int col = static_cast<int>(i);
    if (a.size() == b.size() && a.size() > 1) {
      for (std::size_t k = 0; k + 1 < a.size(); ++k) {
        switch (resolution.split) {
          case MeshSplit::uniform:
            add_triangle(col, a[k], b[k], b[k + 1]);
            add_triangle(col, a[k], b[k + 1], a[k + 1]);
            break;
          case MeshSplit::union_jack:
            if ((i + k) % 2 == 0) {
              add_triangle(col, a[k], b[k], b[k + 1]);
              add_triangle(col, a[k], b[k + 1], a[k + 1]);
            } else {
              add_triangle(col, a[k], b[k], a[k + 1]);
              add_triangle(col, b[k], b[k + 1], a[k + 1]);
            }
            break;
          case MeshSplit::crossed: {
            const int c = static_cast<int>(mesh.nodes_mm.size());
            mesh.nodes_mm.push_back(0.25 * (mesh.nodes_mm[a[k]] + mesh.nodes_mm[a[k + 1]] +
                                            mesh.nodes_mm[b[k]] + mesh.nodes_mm[b[k + 1]]));
            add_triangle(col, a[k], b[k], c);
            add_triangle(col, b[k], b[k + 1], c);
            add_triangle(col, b[k + 1], a[k + 1], c);
            add_triangle(col, a[k + 1], a[k], c);
            break;
          }
        }
      }
      continue;
    }
    // Unequal columns: zip down both, always advancing the side whose next node is shallower.
    const std::vector<double>& fa = fraction[i];
    const std::vector<double>& fb = fraction[i + 1];
    std::size_t p = 0;
    std::size_t q = 0;
    while (p + 1 < a.size() || q + 1 < b.size()) {
      const bool advance_a = q + 1 >= b.size() || (p + 1 < a.size() && fa[p + 1] <= fb[q + 1]);
      if (advance_a) {
        add_triangle(col, a[p], a[p + 1], b[q]);
        ++p;
      } else {
        add_triangle(col, a[p], b[q], b[q + 1]);
        ++q;
      }
    }
  }

  if (mesh.triangles.empty()) {
    throw OutlineError(detail::printf_string(
        "a mesh of %d x %d cells on this cut has no triangle: its columns stand only where the "
        "cut has no height; give it more cells across",
        resolution.cells_x, resolution.cells_y));
  }
  for (std::size_t s = 0; s < outline.supports.size(); ++s) {
    const Vector2d& at = outline.supports[s].at_mm;
    int found = -1;
    for (std::size_t i = 0; i < xs.size() && found < 0; ++i) {
      if (std::abs(xs[i] - at.x()) > tolerance) {
        continue;
      }
      for (int n : columns[i]) {
        if (std::abs(mesh.nodes_mm[n].y() - at.y()) <= tolerance) {
          found = n;
        }
      }
    }
    if (found < 0) {
      throw OutlineError(detail::printf_string(
          "support %zu at (%.6g, %.6g) mm is not a node of the mesh", s + 1, at.x(), at.y()));
    }
    mesh.support_nodes.push_back(found);
  }
  return mesh;
}

Eigen::Vector3d Mesh::barycentric(int t, const Vector2d& p) const {
  const auto& tri = triangles[t];
  const Vector2d& a = nodes_mm[tri[0]];
  const Vector2d& b = nodes_mm[tri[1]];
  const Vector2d& c = nodes_mm[tri[2]];
  const double whole = signed_area(a, b, c);
  const double la = signed_area(p, b, c) / whole;
  const double lb = signed_area(a, p, c) / whole;
  return {la, lb, 1.0 - la - lb};
}

int Mesh::locate(const Vector2d& p) const {
  if (column_x_mm.size() < 2 || p.x() < column_x_mm.front() || p.x() > column_x_mm.back()) {
    return -1;
  }
  const auto after = std::upper_bound(column_x_mm.begin(), column_x_mm.end(), p.x());
  const int interval = std::clamp(static_cast<int>(after - column_x_mm.begin()) - 1, 0,
                                  static_cast<int>(column_x_mm.size()) - 2);
  // A point on a column lies in both intervals beside it: look in the one before as well.
  for (int c : {interval, interval - 1}) {
    if (c < 0) {
      continue;
    }
    for (int t : column_triangles[c]) {
      if (barycentric(t, p).minCoeff() >= -1e-10) {
        return t;
      }
    }
  }
  return -1;
}

}  // namespace foldlab::field
