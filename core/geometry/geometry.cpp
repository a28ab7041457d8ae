#include "core/geometry/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/geometry/level_of_detail.hpp"

namespace foldlab {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

Eigen::Vector3d place_on_shape(const Eigen::Vector3d& span_point, int span, double span_mm,
                               const Shape& shape) {
  const int spans = shape.span_count();
  const double x = span_point.x() + (span - 0.5 * (spans - 1)) * span_mm;
  // Shear about the left support: y' = y - tan(incline) (x + W/2), W the whole width.
  const double y = span_point.y() - shape.shear() * (x + 0.5 * spans * span_mm);
  return {x, y, span_point.z()};
}

double lowest_point_mm(const Solution& s, double height_mm) {
  return s.a_mm.empty() ? s.sag_amplitude_mm + height_mm : s.a_mm.front();
}

std::vector<Eigen::Vector3d> support_points(double span_mm, const Shape& shape) {
  std::vector<Eigen::Vector3d> points;
  for (int span = 0; span < shape.span_count(); ++span) {
    if (span == 0) {
      points.push_back(place_on_shape({-0.5 * span_mm, 0.0, 0.0}, span, span_mm, shape));
    }
    points.push_back(place_on_shape({0.5 * span_mm, 0.0, 0.0}, span, span_mm, shape));
  }
  return points;
}

namespace {

// Every stride-th line is drawn so that at most about max_lines lines are.
int fold_line_stride(const Solution& s, int spans, int max_lines) {
  const std::int64_t line_count = (static_cast<std::int64_t>(s.n) + 1) * spans;
  const std::int64_t per = std::max(1, max_lines);
  return static_cast<int>(std::max<std::int64_t>(1, (line_count + per - 1) / per));
}

}  // namespace

std::int64_t fold_line_point_count(const Solution& s, const Shape& shape, int samples,
                                   int max_lines) {
  if (s.a_mm.empty()) {
    return 0;
  }
  const int spans = shape.span_count();
  const std::int64_t stride = fold_line_stride(s, spans, max_lines);
  const std::int64_t lines_per_span = s.n / stride + 1;
  return lines_per_span * spans * std::max(2, samples);
}

FoldLines fold_lines(const Solution& s, const FoldRounding& rounding, const Shape& shape,
                     int samples, int max_lines) {
  FoldLines out;
  if (s.a_mm.empty()) {
    return out;
  }
  samples = std::max(2, samples);
  const int spans = shape.span_count();
  out.stride = fold_line_stride(s, spans, max_lines);
  const double l = s.span_mm;
  for (int span = 0; span < spans; ++span) {
    for (int i = 0; i <= s.n; i += out.stride) {
      FoldLine line;
      line.index = i;
      line.sign = fold_sign(i);
      line.span = span;
      line.points_mm.reserve(static_cast<std::size_t>(samples));
      const double a = s.a_mm[static_cast<std::size_t>(i)];
      const double z = line.sign * rounding.fold_depth_mm(s, i);
      for (int k = 0; k < samples; ++k) {
        const double x = l * (static_cast<double>(k) / (samples - 1) - 0.5);
        const double c = std::cos(kPi * x / l);
        line.points_mm.push_back(place_on_shape({x, a * c, z * c}, span, l, shape));
      }
      out.lines.push_back(std::move(line));
    }
  }
  return out;
}

FoldLines fold_lines(const Solution& s, const Parameters& p, int samples, int max_lines) {
  return fold_lines(s, fold_rounding(s, p), p.shape, samples, max_lines);
}

DeformedGrid deformed_grid(const Solution& s, const Parameters& p, int nx, int ny) {
  DeformedGrid grid = deformed_grid_positions(s, p, nx, ny);
  grid.normals = vertex_normals(grid.positions_mm, grid.triangle_indices);
  return grid;
}

DeformedGrid deformed_grid_positions(const Solution& s, const Parameters& p, int nx, int ny) {
  return deformed_grid_positions(s, p, CentreFibre(s, p.hanging.height_mm, fold_rounding(s, p)), nx,
                                 ny);
}

namespace {

// Where a column of the grid falls: its span and its across-the-cloth coordinate in the flat
// cloth (all spans side by side, centred) and in its own span.
struct ColumnPlace {
  int span = 0;
  double X_total = 0.0;
  double X = 0.0;
};

// The columns across the spans. Each span gets a whole number of the grid's intervals, so that a
// column falls on every support of a strip: a cell across a support would hang cloth below it.
class ColumnLayout {
 public:
  ColumnLayout(int nx, int spans, double L)
      : spans_(spans),
        L_(L),
        total_width_(spans * L),
        intervals_(nx - 1),
        per_span_(spans > 1 && intervals_ >= spans) {}

  // Asked for in order of i: each column's span is searched for from the last one's.
  ColumnPlace place(int i) {
    double X_total = total_width_ * (static_cast<double>(i) / intervals_ - 0.5);
    if (per_span_) {
      while (span_ + 1 < spans_ && i > first_column(span_ + 1)) {
        ++span_;
      }
      const int from = first_column(span_);
      X_total = L_ * (span_ + static_cast<double>(i - from) / (first_column(span_ + 1) - from)) -
                0.5 * total_width_;
    } else {
      span_ = std::clamp(static_cast<int>(std::floor((X_total + 0.5 * total_width_) / L_)), 0,
                         spans_ - 1);
    }
    return {span_, X_total, X_total + 0.5 * total_width_ - (span_ + 0.5) * L_};
  }

 private:
  int first_column(int span) const {
    return static_cast<int>(static_cast<long long>(span) * intervals_ / spans_);
  }

  int spans_;
  double L_;
  double total_width_;
  int intervals_;
  bool per_span_;
  int span_ = 0;
};

// What every column of the membrane shares: the cloth, its shape and the central fibre.
struct Membrane {
  const CentreFibre& fibre;
  const std::vector<Eigen::Vector2d>& rows;  // the central fibre at each row's fraction
  const Shape& shape;
  double h = 0.0;         // the cloth's height, mm
  double L = 0.0;         // its upper edge, mm
  double l = 0.0;         // the span between supports, mm
  double fibre_mm = 0.0;  // the central fibre's length
  bool rectangular = false;
};

// The membrane's rows sit at the same fraction of every fibre: the central one sampled once.
std::vector<Eigen::Vector2d> sampled_rows(const CentreFibre& fibre, int ny) {
  std::vector<Eigen::Vector2d> rows(static_cast<std::size_t>(ny));
  std::size_t row_piece = 0;
  for (int j = 0; j < ny; ++j) {
    rows[static_cast<std::size_t>(j)] =
        fibre.at_length(fibre.length_mm() * j / (ny - 1), row_piece);
  }
  return rows;
}

// One column's vertices into the grid; returns how far the column's length along them departs
// from the flat cloth's, relative to the cloth's height.
double place_column(DeformedGrid& grid, int i, const ColumnPlace& at, const Membrane& m) {
  const double c = std::max(0.0, std::cos(kPi * at.X / m.L));  // = cos(pi x / l) at x = X l / L
  const double x = at.X * m.l / m.L;
  double column_length = 0.0;
  Eigen::Vector3d previous;
  std::size_t piece = 0;
  for (int j = 0; j < grid.ny; ++j) {
    const double fraction = static_cast<double>(j) / (grid.ny - 1);
    Eigen::Vector2d yz;
    double material_Y;
    if (!m.rectangular) {
      yz = c * m.rows[static_cast<std::size_t>(j)];
      material_Y = fraction * m.h * c;
    } else {
      // Arc length Y along the fibre (c times the central one), then straight down.
      material_Y = fraction * m.h;
      const double fibre_here = c * m.fibre_mm;
      if (material_Y <= fibre_here && c > 0.0) {
        yz = c * m.fibre.at_length(material_Y / c, piece);
      } else {
        yz = c * m.rows.back() + Eigen::Vector2d(material_Y - fibre_here, 0.0);
      }
    }
    const Eigen::Vector3d point = place_on_shape({x, yz.x(), yz.y()}, at.span, m.l, m.shape);
    if (j > 0) {
      column_length += (point - previous).norm();
    }
    previous = point;
    const std::size_t v = static_cast<std::size_t>(j) * grid.nx + i;
    grid.positions_mm[v] = point.cast<float>();
    grid.material_mm[v] =
        Eigen::Vector2f(static_cast<float>(at.X_total), static_cast<float>(material_Y));
  }
  const double flat_length = m.rectangular ? m.h : m.h * c;
  return std::abs(column_length - flat_length) / m.h;
}

}  // namespace

DeformedGrid deformed_grid_positions(const Solution& s, const Parameters& p,
                                     const CentreFibre& fibre, int nx, int ny) {
  DeformedGrid grid;
  grid.nx = std::max(2, nx);
  grid.ny = std::max(2, ny);
  const std::vector<Eigen::Vector2d> rows = sampled_rows(fibre, grid.ny);
  grid.sharpest_turn_deg = sharpest_turn_deg(rows);
  const Membrane m{fibre,
                   rows,
                   p.shape,
                   p.hanging.height_mm,
                   p.hanging.length_mm,
                   s.span_mm > 0.0 ? s.span_mm : span_mm(p),
                   fibre.length_mm(),
                   p.shape.kind == ShapeKind::rectangular};
  const std::size_t count = static_cast<std::size_t>(grid.nx) * grid.ny;
  grid.positions_mm.resize(count);
  grid.material_mm.resize(count);
  ColumnLayout layout(grid.nx, p.shape.span_count(), m.L);
  for (int i = 0; i < grid.nx; ++i) {
    grid.worst_fibre_error =
        std::max(grid.worst_fibre_error, place_column(grid, i, layout.place(i), m));
  }
  grid.triangle_indices = lattice_triangles(grid.nx, grid.ny);
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

namespace foldlab {

Eigen::Vector3f breeze_offset(const Eigen::Vector3f& position_mm, float depth_mm,
                              float amplitude_mm, float time_s) {
  constexpr float kOmega = 2.0f * static_cast<float>(kPi) * 0.4f;  // 0.4 Hz
  const float down = std::max(0.0f, position_mm.y()) / std::max(depth_mm, 1.0f);
  const float weight = amplitude_mm * down * down;
  return {0.25f * weight * std::sin(0.7f * kOmega * time_s + 1.3f), 0.0f,
          weight * std::sin(kOmega * time_s - 2.5f * static_cast<float>(kPi) * down)};
}

}  // namespace foldlab
