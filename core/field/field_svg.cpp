#include "core/field/field_svg.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/model/svg_text.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::field {
namespace {

using detail::finite_or_throw;
using detail::printf_string;
using detail::xml_escape;
using Eigen::Vector2d;

// Okabe and Ito's palette, which readers with any common colour-vision deficiency tell apart:
// blue and orange differ in lightness too; slack is a light grey, "no tension".
constexpr const char* kTautColour = "#0072B2";
constexpr const char* kWrinkledColour = "#E69F00";
constexpr const char* kSlackColour = "#D9D9D9";
constexpr const char* kTurnedOverColour = "#CC79A7";
constexpr const char* kRayColour = "#222222";
constexpr const char* kReactionColour = "#009E73";

const char* region_colour(State s) {
  switch (s) {
    case State::taut:
      return kTautColour;
    case State::wrinkled:
      return kWrinkledColour;
    case State::slack:
      return kSlackColour;
  }
  return kSlackColour;
}

// The page: the hung cloth drawn to scale (mm to px, y down in both) left of a legend column.
struct Page {
  static constexpr double width_px = 1000.0;
  static constexpr double max_height_px = 760.0;
  static constexpr double min_height_px = 420.0;  // the legend's height
  static constexpr double left = 40.0;
  static constexpr double top = 90.0;
  static constexpr double legend_w = 220.0;
  static constexpr double bottom = 20.0;
  static constexpr double plot_w = width_px - left - legend_w - 20.0;
  static constexpr double max_plot_h = max_height_px - top - bottom;
  static constexpr double arrow_px = 70.0;  // the largest reaction's arrow
  Vector2d min_mm{0.0, 0.0};
  double px_per_mm = 1.0;
  double offset_x = 0.0;  // centres the drawing in the plot area
  double offset_y = 0.0;
  double height_px = max_height_px;  // the page ends below the drawing

  Vector2d px(const Vector2d& p) const {
    return {left + offset_x + (p.x() - min_mm.x()) * px_per_mm,
            top + offset_y + (p.y() - min_mm.y()) * px_per_mm};
  }
};

// The arrows reach out of the cloth by up to arrow_px: the cloth is fitted inside a margin of it.
Page fit_page(const Solution& solution, const std::vector<Vector2d>& targets) {
  Vector2d lo = Vector2d::Constant(std::numeric_limits<double>::infinity());
  Vector2d hi = -lo;
  auto grow = [&](const Vector2d& p) {
    finite_or_throw(p.x(), "hung x (mm)");
    finite_or_throw(p.y(), "hung y (mm)");
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const Vector2d& p : solution.positions_mm) {
    grow(p);
  }
  for (const Vector2d& p : targets) {
    grow(p);
  }
  Page page;
  const double margin = Page::arrow_px + 10.0;
  const double w_mm = std::max(hi.x() - lo.x(), 1e-9);
  const double h_mm = std::max(hi.y() - lo.y(), 1e-9);
  page.px_per_mm =
      std::min((Page::plot_w - 2 * margin) / w_mm, (Page::max_plot_h - 2 * margin) / h_mm);
  page.min_mm = lo;
  page.offset_x = 0.5 * (Page::plot_w - w_mm * page.px_per_mm);
  page.offset_y = margin;
  page.height_px =
      std::max(Page::min_height_px, Page::top + h_mm * page.px_per_mm + 2 * margin + Page::bottom);
  return page;
}

std::string triangles_svg(const Mesh& mesh, const Solution& s, const Page& page) {
  std::string out = "<g id=\"triangles\" stroke-width=\"0.4\" stroke-linejoin=\"round\">\n";
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const TriangleResult& r = s.triangles[t];
    // The fill's own colour as its stroke closes the hairline gaps a renderer leaves between
    // neighbours; a turned-over triangle is outlined in its own colour.
    const char* fill = region_colour(r.region);
    out += printf_string("<polygon class=\"triangle %s\" fill=\"%s\" stroke=\"%s\" points=\"",
                         std::string(to_string(r.region)).c_str(), fill,
                         r.folded_over ? kTurnedOverColour : fill);
    for (int n : mesh.triangles[t]) {
      const Vector2d p = page.px(s.positions_mm[n]);
      out += printf_string("%.2f,%.2f ", p.x(), p.y());
    }
    out += "\"/>\n";
  }
  return out + "</g>\n";
}

std::string rays_svg(const std::vector<Ray>& rays, bool several_spans, const Page& page) {
  std::string out = printf_string(
      "<g id=\"rays\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.3\">\n", kRayColour);
  for (const Ray& ray : rays) {
    out += "<polyline class=\"ray\" points=\"";
    for (const Vector2d& q : ray.points_mm) {
      finite_or_throw(q.x(), "ray x (mm)");
      finite_or_throw(q.y(), "ray y (mm)");
      const Vector2d p = page.px(q);
      out += printf_string("%.2f,%.2f ", p.x(), p.y());
    }
    out += printf_string(
        "\"><title>%sray at depth %.1f mm: nearest cosine a = %.1f mm, %.1f mm rms from it</title>"
        "</polyline>\n",
        several_spans ? printf_string("span %d: ", ray.span + 1).c_str() : "", ray.depth_mm,
        ray.fitted_amplitude_mm, ray.fit_rms_mm);
  }
  return out + "</g>\n";
}

// An arrow from `from` along `v` (px), its head a filled triangle.
std::string arrow_svg(const Vector2d& from, const Vector2d& v) {
  const double length = v.norm();
  if (!(length > 1.0)) {
    return "";
  }
  const Vector2d u = v / length;
  const Vector2d n(-u.y(), u.x());
  const Vector2d tip = from + v;
  const Vector2d base = tip - 10.0 * u;
  const Vector2d a = base + 4.5 * n;
  const Vector2d b = base - 4.5 * n;
  return printf_string(
      "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke-width=\"2.5\"/>"
      "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\" stroke=\"none\"/>\n",
      from.x(), from.y(), base.x(), base.y(), tip.x(), tip.y(), a.x(), a.y(), b.x(), b.y());
}

std::string supports_svg(const Solution& s, const std::vector<Vector2d>& targets,
                         const Page& page) {
  double largest = 0.0;
  for (const Vector2d& r : s.reactions_N) {
    largest = std::max(largest, r.norm());
  }
  std::string out = printf_string("<g id=\"supports\" fill=\"%s\" stroke=\"%s\">\n",
                                  kReactionColour, kReactionColour);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    finite_or_throw(s.reactions_N[i].x(), "reaction (N)");
    finite_or_throw(s.reactions_N[i].y(), "reaction (N)");
    // A component at round-off of the largest force is printed as the 0 it is.
    const Vector2d r = s.reactions_N[i].unaryExpr(
        [&](double c) { return std::abs(c) <= 1e-9 * largest ? 0.0 : c; });
    const Vector2d at = page.px(targets[i]);
    const Vector2d v = largest > 0.0 ? Vector2d(r / largest * Page::arrow_px) : Vector2d::Zero();
    out += printf_string(
        "<circle class=\"support\" cx=\"%.2f\" cy=\"%.2f\" r=\"4\" fill=\"black\" "
        "stroke=\"white\"><title>support %zu</title></circle>\n",
        at.x(), at.y(), i + 1);
    out += arrow_svg(at, v);
    // The value centred beyond the arrow's tip, away from the cloth and clear of the legend.
    const Vector2d label = at + v + Vector2d(0.0, v.y() < 0.0 ? -8.0 : 18.0);
    out += printf_string(
        "<text class=\"reaction\" x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" "
        "stroke=\"none\" fill=\"black\">(%+.4g, %+.4g) N</text>\n",
        label.x(), label.y(), r.x(), r.y());
  }
  return out + "</g>\n";
}

std::string legend_svg(const Solution& s, const Page& page) {
  const double x = Page::width_px - Page::legend_w;
  double y = Page::top;
  std::string out = "<g id=\"legend\">\n";
  out += printf_string("<text x=\"%.1f\" y=\"%.1f\" font-weight=\"bold\">regions (area)</text>\n",
                       x, y);
  const struct {
    const char* colour;
    const char* word;
    double share;
  } rows[] = {{kTautColour, "taut", s.taut_share},
              {kWrinkledColour, "wrinkled", s.wrinkled_share},
              {kSlackColour, "slack", s.slack_share}};
  for (const auto& row : rows) {
    y += 22.0;
    out += printf_string(
        "<rect x=\"%.1f\" y=\"%.1f\" width=\"18\" height=\"14\" fill=\"%s\" stroke=\"#555\"/>"
        "<text x=\"%.1f\" y=\"%.1f\">%s %.1f %%</text>\n",
        x, y - 11.0, row.colour, x + 26.0, y, row.word, 100.0 * row.share);
  }
  if (s.folded_share > 0.0) {
    y += 22.0;
    out += printf_string(
        "<rect x=\"%.1f\" y=\"%.1f\" width=\"18\" height=\"14\" fill=\"white\" stroke=\"%s\" "
        "stroke-width=\"2\"/><text x=\"%.1f\" y=\"%.1f\">turned over %.1f %%</text>\n",
        x, y - 11.0, kTurnedOverColour, x + 26.0, y, 100.0 * s.folded_share);
  }
  y += 30.0;
  out += printf_string(
      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"1.3\"/>"
      "<text x=\"%.1f\" y=\"%.1f\">tension ray</text>\n",
      x, y - 4.0, x + 18.0, y - 4.0, kRayColour, x + 26.0, y);
  y += 22.0;
  out += printf_string("<g fill=\"%s\" stroke=\"%s\">", kReactionColour, kReactionColour) +
         arrow_svg(Vector2d(x, y - 4.0), Vector2d(20.0, 0.0)) + "</g>" +
         printf_string("<text x=\"%.1f\" y=\"%.1f\">reaction on the cloth</text>\n", x + 26.0, y);
  y += 16.0;
  out += printf_string("<text x=\"%.1f\" y=\"%.1f\" fill=\"#555\">(x right, y down; N)</text>\n",
                       x + 26.0, y);
  // A scale bar of the longest round length (1, 2 or 5 times a power of ten) the legend holds.
  const double room_mm = 0.8 * Page::legend_w / page.px_per_mm;
  const double power = std::pow(10.0, std::floor(std::log10(room_mm)));
  const double bar_mm = room_mm >= 5 * power ? 5 * power : room_mm >= 2 * power ? 2 * power : power;
  y += 40.0;
  out += printf_string(
      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"black\" "
      "stroke-width=\"2\"/><text x=\"%.1f\" y=\"%.1f\">%g mm</text>\n",
      x, y, x + bar_mm * page.px_per_mm, y, x, y + 16.0, bar_mm);
  return out + "</g>\n";
}

}  // namespace

std::string field_to_svg(const Mesh& mesh, const FieldReport& report, const Outline& outline,
                         const std::string& title) {
  const Solution& s = report.solution;
  const std::vector<Vector2d> targets = support_targets(outline);
  const Page page = fit_page(s, targets);
  std::string out = detail::svg_open(Page::width_px, page.height_px, 13);
  // A long preset name (an edited one lists its edits) is set smaller to stay on the page, by a
  // bold sans-serif's width of about 0.6 em a character.
  const double room_px = Page::width_px - 2.0 * Page::left;
  const double title_px = std::clamp(
      room_px / (0.6 * static_cast<double>(std::max<std::size_t>(title.size(), 1))), 9.0, 17.0);
  out += printf_string("<text x=\"%.0f\" y=\"26\" font-size=\"%.1f\" font-weight=\"bold\">",
                       Page::left, title_px) +
         xml_escape(detail::escaped(title)) + "</text>\n";
  // With several spans the figures are the widest span's, and each span's are in a title.
  const bool several_spans = report.spans.size() > 1;
  out += printf_string(
      "<text x=\"%.0f\" y=\"48\">weight %.4g N; %s %.4g N (cosine pencil %.4g N); "
      "%zu triangles, hung, to scale",
      Page::left, s.weight_N,
      several_spans ? printf_string("widest of %zu spans: H", report.spans.size()).c_str()
                    : "thrust H",
      report.thrust_N, report.pencil_thrust_N, mesh.triangles.size());
  if (several_spans) {
    out += "<title>";
    for (std::size_t k = 0; k < report.spans.size(); ++k) {
      const SpanReport& sp = report.spans[k];
      out += printf_string("%sspan %zu: l %.1f mm, H %.4g N, cosine pencil %.4g N",
                           k == 0 ? "" : "; ", k + 1, sp.span_mm, sp.thrust_N, sp.pencil_thrust_N);
    }
    out += "</title>";
  }
  out += "</text>\n";
  if (!s.converged) {
    out += printf_string(
        "<text x=\"%.0f\" y=\"70\" fill=\"#B00000\" font-weight=\"bold\">NOT converged: the last "
        "iterate, relative force residual %.2e after %d Newton steps</text>\n",
        Page::left, s.relative_residual, s.iterations);
  } else {
    out += printf_string(
        "<text x=\"%.0f\" y=\"70\" fill=\"#555\">converged: relative force residual %.2e after "
        "%d Newton steps</text>\n",
        Page::left, s.relative_residual, s.iterations);
  }
  out += triangles_svg(mesh, s, page);
  out += rays_svg(report.rays, several_spans, page);
  out += supports_svg(s, targets, page);
  out += legend_svg(s, page);
  return out + "</svg>\n";
}

}  // namespace foldlab::field
