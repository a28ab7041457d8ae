#include "foldlab/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace foldlab {
namespace {

constexpr double kPi = std::numbers::pi;

// The fibre at x = 0 as a zig-zag in the (y, z) plane, from the upper edge down to a_0.
std::vector<Eigen::Vector2d> central_zigzag(const Solution& s) {
  std::vector<Eigen::Vector2d> points;
  if (s.a_mm.empty()) {
    // No folds: the cloth hangs straight from the sag of its upper edge (0 without slack).
    return points;
  }
  for (int i = s.n; i >= 0; --i) {
    points.emplace_back(s.a_mm[static_cast<std::size_t>(i)], fold_sign(i) * s.z_max_mm);
  }
  return points;
}

// Points at arc-length fractions f_j = j/(count-1) along a polyline.
std::vector<Eigen::Vector2d> sample_by_arc_length(const std::vector<Eigen::Vector2d>& polyline,
                                                  int count) {
  std::vector<double> cumulative(polyline.size(), 0.0);
  for (std::size_t k = 1; k < polyline.size(); ++k) {
    cumulative[k] = cumulative[k - 1] + (polyline[k] - polyline[k - 1]).norm();
  }
  const double total = cumulative.back();
  std::vector<Eigen::Vector2d> samples;
  samples.reserve(static_cast<std::size_t>(count));
  std::size_t segment = 1;
  for (int j = 0; j < count; ++j) {
    const double target = total * j / (count - 1);
    while (segment + 1 < polyline.size() && cumulative[segment] < target) {
      ++segment;
    }
    const double length = cumulative[segment] - cumulative[segment - 1];
    const double t =
        length > 0.0 ? std::clamp((target - cumulative[segment - 1]) / length, 0.0, 1.0) : 0.0;
    samples.push_back(polyline[segment - 1] + t * (polyline[segment] - polyline[segment - 1]));
  }
  return samples;
}

}  // namespace

FoldLines fold_lines(const Solution& s, int samples, int max_lines) {
  FoldLines out;
  if (s.a_mm.empty()) {
    return out;
  }
  samples = std::max(2, samples);
  const int line_count = s.n + 1;
  out.stride = std::max(1, (line_count + max_lines - 1) / std::max(1, max_lines));
  const double l = s.span_mm;
  for (int i = 0; i <= s.n; i += out.stride) {
    FoldLine line;
    line.index = i;
    line.sign = fold_sign(i);
    line.points_mm.reserve(static_cast<std::size_t>(samples));
    const double a = s.a_mm[static_cast<std::size_t>(i)];
    for (int k = 0; k < samples; ++k) {
      const double x = l * (static_cast<double>(k) / (samples - 1) - 0.5);
      const double c = std::cos(kPi * x / l);
      line.points_mm.emplace_back(x, a * c, line.sign * s.z_max_mm * c);
    }
    out.lines.push_back(std::move(line));
  }
  return out;
}

DeformedGrid deformed_grid(const Solution& s, const Parameters& p, int nx, int ny) {
  DeformedGrid grid = deformed_grid_positions(s, p, nx, ny);
  grid.normals = vertex_normals(grid.positions_mm, grid.triangle_indices);
  return grid;
}

DeformedGrid deformed_grid_positions(const Solution& s, const Parameters& p, int nx, int ny) {
  DeformedGrid grid;
  grid.nx = std::max(2, nx);
  grid.ny = std::max(2, ny);
  const double h = p.hanging.height_mm;
  const double L = p.hanging.length_mm;
  const double l = s.span_mm > 0.0 ? s.span_mm : span_mm(p);

  std::vector<Eigen::Vector2d> zigzag = central_zigzag(s);
  if (zigzag.empty()) {
    zigzag = {Eigen::Vector2d(s.sag_amplitude_mm, 0.0),
              Eigen::Vector2d(s.sag_amplitude_mm + h, 0.0)};
  }
  // Every column is the central fibre scaled by cos(pi x/l), so the rows are sampled once.
  const std::vector<Eigen::Vector2d> rows = sample_by_arc_length(zigzag, grid.ny);
  double sampled_length = 0.0;
  for (std::size_t j = 1; j < rows.size(); ++j) {
    sampled_length += (rows[j] - rows[j - 1]).norm();
  }

  // Per column: x and the cosine that scales the central fibre there.
  std::vector<float> column_x(static_cast<std::size_t>(grid.nx));
  std::vector<double> column_scale(static_cast<std::size_t>(grid.nx));
  for (int i = 0; i < grid.nx; ++i) {
    const double X = L * (static_cast<double>(i) / (grid.nx - 1) - 0.5);
    const double c = std::max(0.0, std::cos(kPi * X / L));  // = cos(pi x / l) at x = X l / L
    column_x[static_cast<std::size_t>(i)] = static_cast<float>(X * l / L);
    column_scale[static_cast<std::size_t>(i)] = c;
    // The membrane's fibre at X is h cos(pi X / L) long; the grid's is c times the sampled one.
    grid.worst_fibre_error =
        std::max(grid.worst_fibre_error, std::abs(c * sampled_length - c * h) / h);
  }
  grid.positions_mm.resize(static_cast<std::size_t>(grid.nx) * grid.ny);
  Eigen::Vector3f* out = grid.positions_mm.data();
  for (int j = 0; j < grid.ny; ++j) {
    const Eigen::Vector2d& r = rows[static_cast<std::size_t>(j)];
    for (int i = 0; i < grid.nx; ++i) {
      const double c = column_scale[static_cast<std::size_t>(i)];
      *out++ = Eigen::Vector3f(column_x[static_cast<std::size_t>(i)], static_cast<float>(c * r.x()),
                               static_cast<float>(c * r.y()));
    }
  }

  grid.triangle_indices.resize(static_cast<std::size_t>(grid.nx - 1) * (grid.ny - 1) * 6);
  std::uint32_t* index = grid.triangle_indices.data();
  for (int j = 0; j + 1 < grid.ny; ++j) {
    for (int i = 0; i + 1 < grid.nx; ++i) {
      const auto v00 = static_cast<std::uint32_t>(j * grid.nx + i);
      const auto v10 = v00 + 1;
      const auto v01 = v00 + static_cast<std::uint32_t>(grid.nx);
      const auto v11 = v01 + 1;
      for (std::uint32_t v : {v00, v01, v10, v10, v01, v11}) {
        *index++ = v;
      }
    }
  }
  return grid;
}

std::vector<Eigen::Vector3f> vertex_normals(const std::vector<Eigen::Vector3f>& positions,
                                            const std::vector<std::uint32_t>& triangle_indices) {
  std::vector<Eigen::Vector3f> normals(positions.size(), Eigen::Vector3f::Zero());
  for (std::size_t t = 0; t + 2 < triangle_indices.size(); t += 3) {
    const std::uint32_t a = triangle_indices[t];
    const std::uint32_t b = triangle_indices[t + 1];
    const std::uint32_t c = triangle_indices[t + 2];
    // The cross product's length is twice the area: summing it weights by area.
    const Eigen::Vector3f face = (positions[b] - positions[a]).cross(positions[c] - positions[a]);
    normals[a] += face;
    normals[b] += face;
    normals[c] += face;
  }
  for (Eigen::Vector3f& n : normals) {
    const float length = n.norm();
    n = length > 0.0f ? Eigen::Vector3f(n / length) : Eigen::Vector3f::UnitZ();
  }
  return normals;
}

}  // namespace foldlab
