// docs/bench.svg: a small SVG writer for the run-time-against-error chart (no plotting library).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/model/svg_text.hpp"
#include "core/model/text_format.hpp"
#include "core/tools/benchmark_cases.hpp"

namespace foldlab {
namespace {

// Errors below this are drawn on the chart's floor: the exact method lands within a few ulps of
// the long-double reference, and log axes have no 0.
constexpr double kErrorFloor = 1e-16;

using detail::printf_string;

// 10^k as SVG text with a raised exponent.
std::string decade_label(int k) {
  return "10<tspan dy=\"-6\" font-size=\"10\">" + std::to_string(k) + "</tspan>";
}

struct Axis {
  double lo_log;  // decades
  double hi_log;
  double pixel_lo;
  double pixel_hi;
  double at(double value) const {
    const double t = (std::log10(value) - lo_log) / (hi_log - lo_log);
    return pixel_lo + t * (pixel_hi - pixel_lo);
  }
};

Axis decade_axis(double lo, double hi, double pixel_lo, double pixel_hi) {
  const double lo_log = std::floor(std::log10(lo));
  double hi_log = std::ceil(std::log10(hi));
  if (hi_log <= lo_log) {
    hi_log = lo_log + 1.0;
  }
  return {lo_log, hi_log, pixel_lo, pixel_hi};
}

// The chart's size and its plot area's margins, in pixels.
constexpr double kWidth = 960;
constexpr double kHeight = 640;
constexpr double kLeft = 90;
constexpr double kRight = 250;  // room for the legend and labels
constexpr double kTop = 70;
constexpr double kBottom = 70;

double shown_error(const BenchmarkRow& r) {
  return std::max(r.accuracy.median_z_error, kErrorFloor);
}

// Run time across, error up, each over the decades the rows reach.
std::pair<Axis, Axis> chart_axes(const std::vector<BenchmarkRow>& rows) {
  double t_lo = 1e300;
  double t_hi = 0;
  double e_lo = 1e300;
  double e_hi = 0;
  for (const BenchmarkRow& r : rows) {
    t_lo = std::min(t_lo, r.timing.median_ns);
    t_hi = std::max(t_hi, r.timing.median_ns);
    e_lo = std::min(e_lo, shown_error(r));
    e_hi = std::max(e_hi, shown_error(r));
  }
  if (rows.empty()) {
    t_lo = 1;
    t_hi = 10;
    e_lo = kErrorFloor;
    e_hi = 1;
  }
  return {decade_axis(std::max(t_lo, 1.0), std::max(t_hi, 1.0), kLeft, kWidth - kRight),
          decade_axis(e_lo, e_hi, kHeight - kBottom, kTop)};
}

std::string chart_heading(const std::string& subtitle) {
  std::string svg = detail::svg_open(kWidth, kHeight, 13);
  svg += printf_string("<text x=\"%.0f\" y=\"28\" font-size=\"17\" font-weight=\"bold\">", kLeft) +
         "FoldLab: run time against error of z_max</text>\n";
  svg += printf_string("<text x=\"%.0f\" y=\"50\" fill=\"#555\">", kLeft) +
         detail::xml_escape(subtitle) + "</text>\n";
  return svg;
}

// Decade grid and labels, the plot area's frame and the axes' titles.
std::string chart_axes_svg(const Axis& x, const Axis& y) {
  std::string svg;
  for (int k = static_cast<int>(x.lo_log); k <= static_cast<int>(x.hi_log); ++k) {
    const double px = x.at(std::pow(10.0, k));
    svg +=
        printf_string("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n",
                      px, kTop, px, kHeight - kBottom);
    svg += printf_string("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">", px,
                         kHeight - kBottom + 22) +
           decade_label(k) + "</text>\n";
  }
  for (int k = static_cast<int>(y.lo_log); k <= static_cast<int>(y.hi_log); ++k) {
    const double py = y.at(std::pow(10.0, k));
    svg +=
        printf_string("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n",
                      kLeft, py, kWidth - kRight, py);
    svg += printf_string("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">", kLeft - 8, py + 4) +
           decade_label(k) + "</text>\n";
  }
  svg += printf_string(
      "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
      "stroke=\"#333\"/>\n",
      kLeft, kTop, kWidth - kRight - kLeft, kHeight - kBottom - kTop);
  svg += printf_string("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">",
                       (kLeft + kWidth - kRight) / 2, kHeight - 22) +
         "median time per solve (ns, log scale)</text>\n";
  svg += printf_string("<text transform=\"translate(22 %.1f) rotate(-90)\" text-anchor=\"middle\">",
                       (kTop + kHeight - kBottom) / 2) +
         "median relative error of z_max (log scale)</text>\n";
  return svg;
}

// The rows on the Pareto front, in order of time.
std::vector<const BenchmarkRow*> pareto_front(const std::vector<BenchmarkRow>& rows) {
  std::vector<const BenchmarkRow*> front;
  for (const BenchmarkRow& r : rows) {
    if (r.pareto) {
      front.push_back(&r);
    }
  }
  std::sort(front.begin(), front.end(), [](const BenchmarkRow* a, const BenchmarkRow* b) {
    return a->timing.median_ns < b->timing.median_ns;
  });
  return front;
}

std::string front_line(const std::vector<const BenchmarkRow*>& front, const Axis& x,
                       const Axis& y) {
  if (front.size() <= 1) {
    return "";
  }
  std::string svg =
      "<polyline fill=\"none\" stroke=\"#222\" stroke-width=\"1.5\" stroke-dasharray=\"5 4\" "
      "points=\"";
  for (const BenchmarkRow* r : front) {
    svg += printf_string("%.1f,%.1f ", x.at(r->timing.median_ns), y.at(shown_error(*r)));
  }
  return svg + "\"/>\n";
}

// A circle for Simpson, a square for the trapezoid rule, a diamond for the exact method; more
// opaque for tighter tolerances; a thick outline on the Pareto front.
std::string point_marker(const BenchmarkRow& r, const Axis& x, const Axis& y) {
  const double px = x.at(r.timing.median_ns);
  const double py = y.at(shown_error(r));
  const double opacity = r.method.tolerance >= 0.05 ? 0.45 : r.method.tolerance >= 0.01 ? 0.7 : 1;
  const std::string style =
      printf_string(" fill-opacity=\"%.2f\" stroke=\"#000\" stroke-width=\"%.1f\"",
                    r.method.method == Method::exact ? 1.0 : opacity, r.pareto ? 2.0 : 0.5);
  const std::string title =
      "<title>" + detail::xml_escape(r.method.name) +
      printf_string(": %.0f ns, z_max error %.2g", r.timing.median_ns, r.accuracy.median_z_error) +
      "</title>";
  if (r.method.method == Method::exact) {
    return printf_string("<path d=\"M %.1f %.1f l 9 9 l -9 9 l -9 -9 z\" fill=\"#1a9850\"", px,
                         py - 9) +
           style + ">" + title + "</path>\n";
  }
  if (r.method.quadrature == LengthQuadrature::simpson) {
    return printf_string("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"6\" fill=\"#2166ac\"", px, py) +
           style + ">" + title + "</circle>\n";
  }
  return printf_string("<rect x=\"%.1f\" y=\"%.1f\" width=\"11\" height=\"11\" fill=\"#d6604d\"",
                       px - 5.5, py - 5.5) +
         style + ">" + title + "</rect>\n";
}

// The front's names, to the right of each point.
std::string front_labels(const std::vector<const BenchmarkRow*>& front, const Axis& x,
                         const Axis& y) {
  std::string svg;
  for (const BenchmarkRow* r : front) {
    const double px = x.at(r->timing.median_ns);
    const double py = y.at(shown_error(*r));
    svg += printf_string("<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">", px + 11, py + 4) +
           detail::xml_escape(r->method.name) + "</text>\n";
  }
  return svg;
}

std::string legend() {
  std::string svg;
  const double lx = kWidth - kRight + 20;
  double ly = kTop + 10;
  auto legend_line = [&](const std::string& marker, const std::string& text) {
    svg += marker + printf_string("<text x=\"%.1f\" y=\"%.1f\">", lx + 18, ly + 4) +
           detail::xml_escape(text) + "</text>\n";
    ly += 22;
  };
  legend_line(printf_string("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"6\" fill=\"#2166ac\"/>", lx, ly),
              "paper, Simpson");
  legend_line(
      printf_string("<rect x=\"%.1f\" y=\"%.1f\" width=\"11\" height=\"11\" fill=\"#d6604d\"/>",
                    lx - 5.5, ly - 5.5),
      "paper, trapezoid");
  legend_line(printf_string("<path d=\"M %.1f %.1f l 8 8 l -8 8 l -8 -8 z\" fill=\"#1a9850\"/>", lx,
                            ly - 8),
              "exact");
  legend_line(printf_string("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#222\" "
                            "stroke-dasharray=\"5 4\" stroke-width=\"1.5\"/>",
                            lx - 9, ly, lx + 9, ly),
              "Pareto front (ringed)");
  ly += 6;
  for (const char* text : {"pale: tolerance 5 %", "mid: tolerance 1 %", "dark: tolerance 0.1 %",
                           "N = 4, 8, 16, 20, 32, 64, 128"}) {
    svg += printf_string("<text x=\"%.1f\" y=\"%.1f\" fill=\"#555\">", lx - 8, ly + 4) + text +
           "</text>\n";
    ly += 18;
  }
  svg += printf_string("<text x=\"%.1f\" y=\"%.1f\" fill=\"#555\">", lx - 8, ly + 4) +
         printf_string("errors &lt; %.0e drawn at %.0e", kErrorFloor, kErrorFloor) + "</text>\n";
  return svg;
}

}  // namespace

std::string benchmark_svg(const std::vector<BenchmarkRow>& rows, const std::string& subtitle) {
  const auto [x, y] = chart_axes(rows);
  const std::vector<const BenchmarkRow*> front = pareto_front(rows);
  std::string svg = chart_heading(subtitle) + chart_axes_svg(x, y) + front_line(front, x, y);
  for (const BenchmarkRow& r : rows) {
    svg += point_marker(r, x, y);
  }
  svg += front_labels(front, x, y) + legend();
  svg += "</svg>\n";
  return svg;
}

}  // namespace foldlab
