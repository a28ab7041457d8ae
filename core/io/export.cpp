#include "core/io/export.hpp"

#include "core/model/svg_text.hpp"
#include "core/model/text_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace foldlab {
namespace {

using detail::finite_or_throw;
using detail::printf_string;
using detail::tick_step;
using detail::xml_escape;

// Every coordinate of a point, checked before it is written.
template <class Vector>
void check_finite(const Vector& v, const char* field) {
  for (int i = 0; i < v.size(); ++i) {
    finite_or_throw(static_cast<double>(v[i]), field);
  }
}

constexpr const char* kPositiveColour = "#1f3a93";
constexpr const char* kNegativeColour = "#d62728";

}  // namespace

std::vector<Eigen::Vector2f> texture_coordinates(const DeformedGrid& grid) {
  std::vector<Eigen::Vector2f> uv(grid.material_mm.size(), Eigen::Vector2f::Zero());
  if (grid.material_mm.empty()) {
    return uv;
  }
  float x_min = grid.material_mm.front().x();
  float x_max = x_min;
  float y_max = 0.0f;
  for (const Eigen::Vector2f& m : grid.material_mm) {
    x_min = std::min(x_min, m.x());
    x_max = std::max(x_max, m.x());
    y_max = std::max(y_max, m.y());
  }
  // A degenerate extent (no width, or a cloth without height) maps to 0 rather than NaN.
  const float width = x_max - x_min;
  for (std::size_t v = 0; v < uv.size(); ++v) {
    const Eigen::Vector2f& m = grid.material_mm[v];
    uv[v] = Eigen::Vector2f(width > 0.0f ? (m.x() - x_min) / width : 0.0f,
                            y_max > 0.0f ? m.y() / y_max : 0.0f);
  }
  return uv;
}

std::string mesh_to_obj(const DeformedGrid& grid, const std::string& title) {
  // One comment line, whatever the name holds: a line break in it would start an OBJ statement.
  std::string out = "# FoldLab deformed cloth: " + detail::escaped(title) + "\n";
  out += "# units mm; x across, y down (gravity), z out of the initial plane\n";
  out += printf_string("# grid %d x %d, worst fibre-length error %.3e of h\n", grid.nx, grid.ny,
                       grid.worst_fibre_error);
  out += printf_string("# sharpest turn of the centre fibre between neighbouring rows %.2f deg\n",
                       grid.sharpest_turn_deg);
  out += "# vt: u across the flat cloth, v = Y / Y_max down it (v = 0 at the upper edge)\n";
  out += "o cloth\n";
  out.reserve(out.size() + grid.positions_mm.size() * 110 + grid.triangle_indices.size() * 20);
  for (const Eigen::Vector3f& v : grid.positions_mm) {
    check_finite(v, "OBJ vertex position (mm)");
    out += printf_string("v %.6g %.6g %.6g\n", v.x(), v.y(), v.z());
  }
  for (const Eigen::Vector2f& t : texture_coordinates(grid)) {
    // OBJ puts v = 0 at the bottom of an image, glTF at the top: flip for OBJ.
    check_finite(t, "OBJ texture coordinate");
    out += printf_string("vt %.6g %.6g\n", t.x(), 1.0f - t.y());
  }
  for (const Eigen::Vector3f& n : grid.normals) {
    check_finite(n, "OBJ vertex normal");
    out += printf_string("vn %.6g %.6g %.6g\n", n.x(), n.y(), n.z());
  }
  for (std::size_t t = 0; t + 2 < grid.triangle_indices.size(); t += 3) {
    const unsigned a = grid.triangle_indices[t] + 1;
    const unsigned b = grid.triangle_indices[t + 1] + 1;
    const unsigned c = grid.triangle_indices[t + 2] + 1;
    // Position, texture coordinate and normal share the vertex's index.
    out += printf_string("f %u/%u/%u %u/%u/%u %u/%u/%u\n", a, a, a, b, b, b, c, c, c);
  }
  return out;
}

std::string fold_lines_to_csv(const FoldLines& lines) {
  std::string out = "line,sign,x_mm,y_mm,z_mm\n";
  for (const FoldLine& line : lines.lines) {
    for (const Eigen::Vector3d& p : line.points_mm) {
      check_finite(p, "fold-line point (mm)");
      out += printf_string("%d,%d,%.9g,%.9g,%.9g\n", line.index, line.sign, p.x(), p.y(), p.z());
    }
  }
  return out;
}

namespace {

void check_solution_finite(const Solution& s) {
  finite_or_throw(s.Q, "Q");
  finite_or_throw(s.z_max_mm, "z_max_mm");
  finite_or_throw(s.span_mm, "l_mm");
  for (double a : s.a_mm) {
    finite_or_throw(a, "a_mm");
  }
}

// The fold plot's page and its millimetres in pixels: x across the span, y downward from the
// line through the supports, as in the paper.
struct FoldPlotFrame {
  static constexpr double width_px = 800.0;
  static constexpr double height_px = 560.0;
  static constexpr double margin_left = 80.0;
  static constexpr double margin_right = 30.0;
  static constexpr double margin_top = 60.0;
  static constexpr double margin_bottom = 60.0;
  static constexpr double plot_w = width_px - margin_left - margin_right;
  static constexpr double plot_h = height_px - margin_top - margin_bottom;
  double l = 0.0;  // the span, mm
  double x_min = 0.0;
  double x_max = 0.0;
  double y_max = 0.0;

  double px(double x) const { return margin_left + (x - x_min) / (x_max - x_min) * plot_w; }
  double py(double y) const { return margin_top + y / y_max * plot_h; }
};

FoldPlotFrame fold_plot_frame(const Solution& s) {
  FoldPlotFrame f;
  f.l = std::max(s.span_mm, 1e-9);
  double y_max = s.a_mm.empty() ? 1.0 : s.a_mm.front();
  f.y_max = std::max(y_max, 1e-9) * 1.05;
  f.x_min = -0.55 * f.l;
  f.x_max = 0.55 * f.l;
  return f;
}

std::string fold_plot_heading(const FoldPlotFrame& f, const Solution& s, const std::string& title) {
  std::string out = detail::svg_open(f.width_px, f.height_px, 12);
  out += "<text x=\"" + printf_string("%.0f", f.margin_left) + "\" y=\"22\" font-size=\"15\">" +
         xml_escape(detail::caption_text(title)) + "</text>\n";
  out += printf_string(
      "<text x=\"%.0f\" y=\"42\">n = %d, Q = %.3f, z_max = %.1f mm, l = %.0f mm "
      "(y downward from the line through the supports)</text>\n",
      f.margin_left, s.n, s.Q, s.z_max_mm, s.span_mm);
  return out;
}

// The plot area's frame, ticks in mm and the axes' titles.
std::string fold_plot_axes(const FoldPlotFrame& f) {
  std::string out = printf_string(
      "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
      "stroke=\"#888\"/>\n",
      f.margin_left, f.margin_top, f.plot_w, f.plot_h);
  const double x_step = tick_step(f.x_max - f.x_min, 8);
  for (double x = std::ceil(f.x_min / x_step) * x_step; x <= f.x_max; x += x_step) {
    out += printf_string(
        "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ccc\"/>"
        "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%g</text>\n",
        f.px(x), f.margin_top, f.px(x), f.margin_top + f.plot_h, f.px(x),
        f.margin_top + f.plot_h + 16, x);
  }
  const double y_step = tick_step(f.y_max, 6);
  for (double y = 0.0; y <= f.y_max; y += y_step) {
    out += printf_string(
        "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ccc\"/>"
        "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%g</text>\n",
        f.margin_left, f.py(y), f.margin_left + f.plot_w, f.py(y), f.margin_left - 6, f.py(y) + 4,
        y);
  }
  out += printf_string("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">x (mm)</text>\n",
                       f.margin_left + f.plot_w / 2, f.height_px - 14);
  out += printf_string(
      "<text x=\"18\" y=\"%.1f\" text-anchor=\"middle\" transform=\"rotate(-90 18 %.1f)\">"
      "y (mm, down)</text>\n",
      f.margin_top + f.plot_h / 2, f.margin_top + f.plot_h / 2);
  return out;
}

std::string fold_polylines(const FoldLines& lines, const FoldPlotFrame& f) {
  std::string out;
  for (const FoldLine& line : lines.lines) {
    out += printf_string("<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"",
                         line.sign < 0 ? kNegativeColour : kPositiveColour);
    for (const Eigen::Vector3d& p : line.points_mm) {
      check_finite(p, "fold-line point (mm)");
      out += printf_string("%.2f,%.2f ", f.px(p.x()), f.py(p.y()));
    }
    out += printf_string("\"><title>line %d (%s fold)</title></polyline>\n", line.index,
                         line.sign < 0 ? "negative" : "positive");
  }
  return out;
}

// Triangles at x = +-l/2 on the line y = 0.
std::string fold_plot_supports(const FoldPlotFrame& f) {
  std::string out;
  for (double x : {-0.5 * f.l, 0.5 * f.l}) {
    const double cx = f.px(x);
    const double cy = f.py(0.0);
    out += printf_string(
        "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"#333\"><title>support</title>"
        "</polygon>\n",
        cx, cy, cx - 7, cy - 12, cx + 7, cy - 12);
  }
  return out;
}

std::string fold_plot_legend(const FoldPlotFrame& f) {
  const double lx = f.margin_left + f.plot_w - 170;
  const double ly = f.margin_top + f.plot_h - 46;
  return printf_string(
      "<rect x=\"%.1f\" y=\"%.1f\" width=\"160\" height=\"40\" fill=\"white\" stroke=\"#888\"/>\n"
      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"2\"/>"
      "<text x=\"%.1f\" y=\"%.1f\">positive fold</text>\n"
      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"2\"/>"
      "<text x=\"%.1f\" y=\"%.1f\">negative fold</text>\n",
      lx, ly, lx + 8, ly + 13, lx + 38, ly + 13, kPositiveColour, lx + 46, ly + 17, lx + 8, ly + 29,
      lx + 38, ly + 29, kNegativeColour, lx + 46, ly + 33);
}

}  // namespace

std::string fold_lines_to_svg(const FoldLines& lines, const Solution& s, const std::string& title) {
  check_solution_finite(s);
  const FoldPlotFrame f = fold_plot_frame(s);
  std::string out = fold_plot_heading(f, s, title);
  out += fold_plot_axes(f);
  out += fold_polylines(lines, f);
  out += fold_plot_supports(f);
  out += fold_plot_legend(f);
  if (lines.stride > 1) {
    out += printf_string("<text x=\"%.1f\" y=\"%.1f\">every %d-th of %d lines drawn</text>\n",
                         f.margin_left + 8, f.margin_top + 16, lines.stride, s.n + 1);
  }
  out += "</svg>\n";
  return out;
}

}  // namespace foldlab
