#include "app/gui/panels/field_panel.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <imgui.h>
#include <imgui_internal.h>  // whether the layout placed the window this frame
#include <nlohmann/json.hpp>

#include "app/gui/panels/widgets.hpp"
#include "app/gui/presentation_bar.hpp"
#include "core/field/rays.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {
namespace {

using Eigen::Vector2d;
using nlohmann::json;

constexpr std::string_view kColouringNames[] = {"state", "tension"};
constexpr std::string_view kCutNames[] = {"shape", "triangle", "pennant", "wedge"};

field::OutlineKind outline_kind(const Parameters& parameters, FieldCut cut) {
  switch (cut) {
    case FieldCut::triangle:
      return field::OutlineKind::triangle;
    case FieldCut::pennant:
      return field::OutlineKind::pennant;
    case FieldCut::wedge:
      return field::OutlineKind::wedge;
    case FieldCut::shape:
      break;
  }
  return field::outline_kind_of(parameters.shape);
}
constexpr ViewRange<double> kCells{8.0, 80.0, " cells"};
constexpr const char* kCosinesLabel = "closed form's cosines";
constexpr const char* kCellsLabel = "mesh cells across";

// Okabe and Ito's colour-blind-safe blue and orange; slack a grey that reads on either theme.
constexpr ImU32 kTaut = IM_COL32(0, 114, 178, 255);
constexpr ImU32 kWrinkled = IM_COL32(230, 159, 0, 255);
constexpr ImU32 kSlack = IM_COL32(150, 150, 150, 255);
// Dark over every fill, whatever the background.
constexpr ImU32 kRayInk = IM_COL32(20, 20, 20, 230);
constexpr ImU32 kCosineInk = IM_COL32(200, 30, 120, 255);
// Okabe and Ito's reddish purple, the drawing's (field_svg) outline of a triangle turned over.
constexpr ImU32 kTurnedOver = IM_COL32(204, 121, 167, 255);

ImU32 state_colour(field::State state) {
  switch (state) {
    case field::State::taut:
      return kTaut;
    case field::State::wrinkled:
      return kWrinkled;
    case field::State::slack:
      break;
  }
  return kSlack;
}

// A sequential map from pale (no tension) to dark blue-violet (the most), monotone in lightness
// so that it reads in grey and to a colour-blind eye.
ImU32 tension_colour(double t) {
  static constexpr std::array<std::array<float, 3>, 5> kStops{{{0.99f, 0.98f, 0.80f},
                                                               {0.63f, 0.85f, 0.71f},
                                                               {0.25f, 0.71f, 0.77f},
                                                               {0.13f, 0.37f, 0.66f},
                                                               {0.15f, 0.10f, 0.40f}}};
  const float x = std::clamp(static_cast<float>(t), 0.0f, 1.0f) * (kStops.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(x), kStops.size() - 2);
  const float f = x - static_cast<float>(i);
  const auto mix = [&](int c) { return kStops[i][c] + f * (kStops[i + 1][c] - kStops[i][c]); };
  return ImGui::ColorConvertFloat4ToU32(ImVec4(mix(0), mix(1), mix(2), 1.0f));
}

ImU32 faded(ImU32 colour, bool stale) {
  return stale ? (colour & 0x00FFFFFFu) | (static_cast<ImU32>(110) << IM_COL32_A_SHIFT) : colour;
}

std::string printf_text(const char* format, double a, double b = 0.0) {
  char text[96];
  std::snprintf(text, sizeof text, format, a, b);
  return text;
}

// Millimetres to the canvas' pixels: one scale both ways, the field centred.
struct ToScreen {
  ImVec2 origin;
  double scale = 1.0;
  Vector2d low;
  ImVec2 operator()(const Vector2d& p) const {
    return ImVec2(origin.x + static_cast<float>((p.x() - low.x()) * scale),
                  origin.y + static_cast<float>((p.y() - low.y()) * scale));
  }
};

// Margins around the cloth, pixels: room for the supports' arrows and values.
struct Margins {
  float left = 0.0f, right = 0.0f, top = 0.0f, bottom = 0.0f;
};

ToScreen fit(const field::SolvedField& field, ImVec2 origin, ImVec2 size, Margins m,
             const Vector2d& least_extent_mm, Vector2d& extent_out) {
  Vector2d low = Vector2d::Constant(std::numeric_limits<double>::max());
  Vector2d high = -low;
  for (const Vector2d& p : field.report.solution.positions_mm) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const Vector2d extent = (high - low).cwiseMax(least_extent_mm).cwiseMax(Vector2d::Constant(1e-9));
  extent_out = extent;
  const double width = std::max(1.0, static_cast<double>(size.x - m.left - m.right));
  const double height = std::max(1.0, static_cast<double>(size.y - m.top - m.bottom));
  ToScreen to;
  to.scale = std::min(width / extent.x(), height / extent.y());
  to.low = low;
  to.origin =
      ImVec2(origin.x + m.left +
                 0.5f * (static_cast<float>(width) - static_cast<float>(extent.x() * to.scale)),
             origin.y + m.top);
  return to;
}

// The top of the tension scale: the tension below which 95 % of the nodes lie. A point support
// makes the tension beside it grow without bound as the mesh is refined; scaled to the largest,
// the rest of the cloth would be one pale colour.
double tension_scale_top(std::vector<double> tensions) {
  if (tensions.empty()) {
    return 0.0;
  }
  const auto at = tensions.begin() +
                  static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(tensions.size() - 1));
  std::nth_element(tensions.begin(), at, tensions.end());
  return *at;
}

void arrow(ImDrawList& draw, ImVec2 from, ImVec2 to, ImU32 colour, float line_px) {
  draw.AddLine(from, to, colour, 2.0f * line_px);
  const float dx = to.x - from.x;
  const float dy = to.y - from.y;
  const float length = std::sqrt(dx * dx + dy * dy);
  if (length < 1.0f) {
    return;
  }
  const float head = std::min(0.35f * length, 9.0f * line_px);
  const ImVec2 u(dx / length, dy / length);
  const ImVec2 n(-u.y, u.x);
  draw.AddTriangleFilled(
      to, ImVec2(to.x - head * u.x + 0.5f * head * n.x, to.y - head * u.y + 0.5f * head * n.y),
      ImVec2(to.x - head * u.x - 0.5f * head * n.x, to.y - head * u.y - 0.5f * head * n.y), colour);
}

// The legend in one row across the top (wrapping when the width runs out); its height.
float legend(ImDrawList& draw, ImVec2 origin, float width, const FieldDrawing& style,
             double top_N_per_mm, bool cosines_drawn, double turned_over_share, ImU32 ink) {
  ImFont* font = ImGui::GetFont();
  const float text = style.text_px;
  const float box = std::round(0.8f * text);
  const float gap = text;
  float x = origin.x;
  float y = origin.y;
  // Places an item `item_width` wide: on this row when it fits, else on the next.
  const auto place = [&](float item_width) {
    if (x > origin.x && x + item_width > origin.x + width) {
      x = origin.x;
      y += 1.4f * text;
    }
    const ImVec2 at(x, y);
    x += item_width + gap;
    return at;
  };
  const auto text_width = [&](const char* words) {
    return font->CalcTextSizeA(text, 1e9f, 0.0f, words).x;
  };
  // A swatch, then its words; the swatch drawn by `swatch` into the box at its corner.
  const auto item = [&](const char* words, const auto& swatch) {
    const ImVec2 at = place(box + 0.4f * text + text_width(words));
    swatch(ImVec2(at.x, at.y + 0.15f * text));
    draw.AddText(font, text, ImVec2(at.x + box + 0.4f * text, at.y), ink, words);
  };
  if (style.colouring == FieldColouring::state) {
    const std::array<std::pair<ImU32, const char*>, 3> rows{
        {{kTaut, "taut: tension both ways"},
         {kWrinkled, "wrinkled: tension along the rays only"},
         {kSlack, "slack: no tension"}}};
    for (const auto& row : rows) {
      const ImU32 colour = row.first;  // a structured binding cannot be captured in C++20
      item(row.second, [&](ImVec2 corner) {
        draw.AddRectFilled(corner, ImVec2(corner.x + box, corner.y + box), colour);
      });
    }
  } else {
    const float bar = 6.0f * text;
    std::string top = printf_text("%#.3g N/mm or more: tension along the rays", top_N_per_mm);
    const float zero_width = text_width("0") + 0.3f * text;
    // On a narrow canvas the words go to a row of their own rather than past its edge.
    const char* words = nullptr;
    if (zero_width + bar + 0.3f * text + text_width(top.c_str()) > width) {
      top = printf_text("%#.3g N/mm or more", top_N_per_mm);
      words = "(tension along the rays)";
    }
    const ImVec2 at = place(zero_width + bar + 0.3f * text + text_width(top.c_str()));
    draw.AddText(font, text, at, ink, "0");
    const float x0 = at.x + zero_width;
    const float top_y = at.y + 0.15f * text;
    for (int i = 0; i < 32; ++i) {
      const float a = x0 + bar * static_cast<float>(i) / 32.0f;
      draw.AddRectFilled(ImVec2(a, top_y), ImVec2(a + bar / 32.0f + 1.0f, top_y + box),
                         tension_colour((i + 0.5) / 32.0));
    }
    draw.AddRect(ImVec2(x0, top_y), ImVec2(x0 + bar, top_y + box), ink);
    draw.AddText(font, text, ImVec2(x0 + bar + 0.3f * text, at.y), ink, top.c_str());
    if (words != nullptr) {
      draw.AddText(font, text, place(text_width(words)), ink, words);
    }
  }
  // The lines as they are drawn over the cloth: on a patch of it, so that the rays' dark ink
  // shows on a dark background too.
  const ImU32 cloth = style.colouring == FieldColouring::state ? kWrinkled : tension_colour(0.25);
  const auto line_over_cloth = [&](ImU32 colour, float thickness) {
    return [&, colour, thickness](ImVec2 corner) {
      draw.AddRectFilled(corner, ImVec2(corner.x + box, corner.y + box), cloth);
      draw.AddLine(ImVec2(corner.x, corner.y + 0.5f * box),
                   ImVec2(corner.x + box, corner.y + 0.5f * box), colour, thickness);
    };
  };
  if (style.rays) {
    item("rays: the tension's paths", line_over_cloth(kRayInk, 1.5f * style.line_px));
  }
  if (cosines_drawn) {
    item("closed form's fold lines", line_over_cloth(kCosineInk, style.line_px));
  }
  if (turned_over_share > 0.0) {
    const std::string words =
        printf_text("turned over %.1f %%: the cut folded onto itself", 100.0 * turned_over_share);
    item(words.c_str(), [&](ImVec2 corner) {
      draw.AddRect(corner, ImVec2(corner.x + box, corner.y + box), kTurnedOver, 0.0f, 0,
                   2.0f * style.line_px);
    });
  }
  return y + 1.4f * text - origin.y;
}

// The tension at each node: the area-weighted mean over the tensed triangles around it. Linear
// triangles let one of a pair go slack beside a tensed one at no cost in the energy (field.md);
// coloured per triangle the cloth would read as a checkerboard, per node it reads as the field.
std::vector<double> node_tensions(const field::SolvedField& field) {
  const field::Mesh& mesh = field.mesh;
  std::vector<double> sum(mesh.nodes_mm.size(), 0.0);
  std::vector<double> area(mesh.nodes_mm.size(), 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const field::TriangleResult& r = field.report.solution.triangles[t];
    if (r.state == field::State::slack) {
      continue;
    }
    const auto& tri = mesh.triangles[t];
    const Vector2d a = mesh.nodes_mm[tri[1]] - mesh.nodes_mm[tri[0]];
    const Vector2d b = mesh.nodes_mm[tri[2]] - mesh.nodes_mm[tri[0]];
    const double flat_area = 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
    for (const int n : tri) {
      sum[n] += flat_area * r.tension_N_per_mm;
      area[n] += flat_area;
    }
  }
  for (std::size_t n = 0; n < sum.size(); ++n) {
    sum[n] = area[n] > 0.0 ? sum[n] / area[n] : 0.0;
  }
  return sum;
}

// H beside the cosine pencil's: each span's when a few hang side by side, else the widest's
// (the figures of a cut on more spans than fit one line), named as such.
std::string thrust_text(const field::FieldReport& report) {
  constexpr std::size_t kSpansListed = 4;
  const std::size_t spans = report.spans.size();
  if (spans < 2) {
    return detail::printf_string("thrust H %#.3g N (the cosine pencil's %#.3g N)", report.thrust_N,
                                 report.pencil_thrust_N);
  }
  if (spans > kSpansListed) {
    return detail::printf_string(
        "thrust H across the widest of %zu spans %#.3g N (its cosine pencil's %#.3g N)", spans,
        report.thrust_N, report.pencil_thrust_N);
  }
  std::string out = "thrust H across each span (its cosine pencil's):";
  for (std::size_t k = 0; k < spans; ++k) {
    out += detail::printf_string("%s %#.3g N (%#.3g N)", k == 0 ? "" : ",",
                                 report.spans[k].thrust_N, report.spans[k].pencil_thrust_N);
  }
  return out;
}

bool closed_form_knows(field::OutlineKind kind) {
  return kind != field::OutlineKind::triangle && kind != field::OutlineKind::pennant &&
         kind != field::OutlineKind::wedge;
}

// Why the closed form's cosines, asked for over a field on a cut called `cut_name` and hung from
// `supports` points, are not drawn; nullopt when they are. `closed_form_cut`: the closed form
// solves a cloth of that cut (the model's shapes, a designer's or a preset's own cut hung from
// its supports); `cosines` the closed form's fold lines for `parameters`.
std::optional<std::string> cosines_not_drawn(bool closed_form_cut, std::string_view cut_name,
                                             std::size_t supports, const Parameters& parameters,
                                             const FoldLines& cosines) {
  const std::string head = "The closed form's cosines are not drawn: ";
  if (!closed_form_cut) {
    return head + "the closed form solves the rectangular, cosine, strip and inclined cloths, " +
           "not the " + std::string(cut_name) + " cut.";
  }
  if (supports < 2) {
    return head + "the cut hangs from one support, and the closed form's cloth from two.";
  }
  if (cosines.lines.empty()) {
    if (parameters.hanging.support_displacement_mm <= 0.0) {
      return head + "at d = 0 the supports are not moved in, and the closed form has no folds.";
    }
    return head + "the closed form has no folds for these inputs.";
  }
  return std::nullopt;
}

}  // namespace

field::FieldInputs field_inputs(const Parameters& parameters, int cells_x, FieldCut cut,
                                const field::Outline* own_cut) {
  field::FieldInputs in;
  in.outline = cut == FieldCut::shape && own_cut != nullptr
                   ? *own_cut
                   : field::make_outline(parameters, outline_kind(parameters, cut));
  in.material = field::material_of(parameters.fabric);
  double top = std::numeric_limits<double>::max();
  double bottom = -top;
  for (const Vector2d& p : in.outline.top_mm) {
    top = std::min(top, p.y());
  }
  for (const Vector2d& p : in.outline.bottom_mm) {
    bottom = std::max(bottom, p.y());
  }
  const double width = std::max(1e-9, in.outline.right_mm() - in.outline.left_mm());
  in.resolution.cells_x = cells_x;
  in.resolution.cells_y =
      std::clamp(static_cast<int>(std::lround(cells_x * (bottom - top) / width)), 4, 2 * cells_x);
  return in;
}

std::vector<std::vector<Vector2d>> cosines_on_field(const FoldLines& cosines,
                                                    const std::vector<Vector2d>& targets) {
  std::vector<std::vector<Vector2d>> out;
  if (targets.size() < 2) {
    return out;
  }
  // The closed form's frame: x from the middle between the outermost supports, y down from the
  // line through them. Each fold line is hung from the field's supports by its depth below its
  // own chord: the closed form's lines of inclined supports are already sheared, and sheared
  // again by the field's line they would rise twice as far.
  const field::SupportFrame frame = field::support_frame(targets);
  const double mid = 0.5 * (frame.left_mm.x() + frame.right_mm.x());
  const double span = std::max(1e-9, frame.span_mm());
  for (const FoldLine& line : cosines.lines) {
    if (line.points_mm.size() < 2) {
      continue;
    }
    const Eigen::Vector3d& first = line.points_mm.front();
    const Eigen::Vector3d& last = line.points_mm.back();
    const double chord_slope =
        last.x() > first.x() ? (last.y() - first.y()) / (last.x() - first.x()) : 0.0;
    std::vector<Vector2d>& points = out.emplace_back();
    for (const Eigen::Vector3d& p : line.points_mm) {
      const double depth = p.y() - (first.y() + chord_slope * (p.x() - first.x()));
      const double along = (p.x() + 0.5 * span) / span;
      const double line_y = frame.left_mm.y() + along * (frame.right_mm.y() - frame.left_mm.y());
      points.emplace_back(mid + p.x(), line_y + depth);
    }
  }
  return out;
}

FieldFit draw_field(ImDrawList& draw, ImVec2 origin, ImVec2 size, const field::SolvedField& field,
                    const FoldLines* cosines, const FieldDrawing& style) {
  const field::Solution& s = field.report.solution;
  const ImU32 ink = style.dark ? IM_COL32(235, 235, 235, 255) : IM_COL32(25, 25, 25, 255);
  const std::vector<double> tensions = node_tensions(field);
  const double top_N_per_mm = tension_scale_top(tensions);
  const std::vector<Vector2d> targets = field::support_targets(field.inputs.outline);
  const bool cosines_drawn =
      style.cosines && cosines != nullptr && !cosines->lines.empty() && targets.size() >= 2;
  const float legend_px = style.legend ? legend(draw, origin, size.x, style, top_N_per_mm,
                                                cosines_drawn, s.folded_share, ink)
                                       : 0.0f;
  // Room above the cloth for the supports' arrows and values, and beside it for a value that
  // reaches past the cloth's side: never more than a share of the canvas, so that a small
  // canvas still shows the cloth.
  const float text = style.text_px;
  Margins margins;
  margins.top = std::min(3.2f * text, 0.3f * size.y);
  margins.bottom = std::min(0.5f * text, 0.05f * size.y);
  margins.left = margins.right = std::min(3.0f * text, 0.15f * size.x);
  const ImVec2 body_origin(origin.x, origin.y + legend_px);
  const ImVec2 body_size(size.x, std::max(1.0f, size.y - legend_px));
  FieldFit fitted;
  const ToScreen to =
      fit(field, body_origin, body_size, margins, style.least_extent_mm, fitted.extent_mm);
  fitted.px_per_mm = to.scale;
  // Without the fill's anti-aliased fringe: neighbouring triangles meet with no hairline between.
  const ImDrawListFlags flags = draw.Flags;
  draw.Flags &= ~ImDrawListFlags_AntiAliasedFill;
  const ImVec2 white = ImGui::GetFontTexUvWhitePixel();
  for (std::size_t t = 0; t < field.mesh.triangles.size(); ++t) {
    const auto& tri = field.mesh.triangles[t];
    draw.PrimReserve(3, 3);
    for (const int n : tri) {
      const ImU32 colour =
          style.colouring == FieldColouring::state
              ? state_colour(s.triangles[t].region)
              : tension_colour(top_N_per_mm > 0.0
                                   ? tensions[static_cast<std::size_t>(n)] / top_N_per_mm
                                   : 0.0);
      draw.PrimVtx(to(s.positions_mm[static_cast<std::size_t>(n)]), white,
                   faded(colour, style.stale));
    }
  }
  draw.Flags = flags;
  // A triangle turned over costs no energy and is drawn with the rest; outlined, so that a cut
  // folded onto itself is seen, as the legend says.
  for (std::size_t t = 0; t < field.mesh.triangles.size(); ++t) {
    if (s.triangles[t].folded_over) {
      const auto& tri = field.mesh.triangles[t];
      draw.AddTriangle(to(s.positions_mm[static_cast<std::size_t>(tri[0])]),
                       to(s.positions_mm[static_cast<std::size_t>(tri[1])]),
                       to(s.positions_mm[static_cast<std::size_t>(tri[2])]),
                       faded(kTurnedOver, style.stale), 1.5f * style.line_px);
    }
  }
  if (style.rays) {
    const ImU32 ray_colour = faded(kRayInk, style.stale);
    std::vector<ImVec2> points;
    for (const field::Ray& ray : field.report.rays) {
      points.clear();
      for (const Vector2d& p : ray.points_mm) {
        points.push_back(to(p));
      }
      draw.AddPolyline(points.data(), static_cast<int>(points.size()), ray_colour, 0,
                       1.5f * style.line_px);
    }
  }
  if (cosines_drawn) {
    const ImU32 dash = faded(kCosineInk, style.stale);
    std::vector<ImVec2> points;
    for (const std::vector<Vector2d>& line : cosines_on_field(*cosines, targets)) {
      points.clear();
      for (const Vector2d& p : line) {
        points.push_back(to(p));
      }
      draw.AddPolyline(points.data(), static_cast<int>(points.size()), dash, 0, style.line_px);
    }
  }
  // The supports, and the force each exerts on the cloth, its arrow's length in proportion. A
  // value is written outward of its arrow (left of a support left of the middle, right of one
  // right of it), a line higher when it would overlap the one before.
  double largest_N = 0.0;
  for (const Vector2d& r : s.reactions_N) {
    largest_N = std::max(largest_N, r.norm());
  }
  ImFont* font = ImGui::GetFont();
  const double middle_mm = targets.empty() ? 0.0 : 0.5 * (targets.front().x() + targets.back().x());
  std::vector<ImVec4> labels;  // min x, min y, max x, max y of those written
  const float arrow_px = std::min(2.2f * text, 0.8f * margins.top);
  for (std::size_t i = 0; i < targets.size() && i < s.reactions_N.size(); ++i) {
    const ImVec2 at = to(targets[i]);
    const Vector2d r = s.reactions_N[i];
    if (largest_N > 0.0) {
      const Vector2d d = r.normalized() * (arrow_px * r.norm() / largest_N);
      const ImVec2 tip(at.x + static_cast<float>(d.x()), at.y + static_cast<float>(d.y()));
      arrow(draw, at, tip, ink, style.line_px);
      // A force that statics makes zero is written 0, not as the solve's round-off.
      const auto shown_N = [&](double f) { return std::abs(f) < 1e-6 * largest_N ? 0.0 : f; };
      const std::string words =
          printf_text("%#.3g N up, %#.3g N across", shown_N(-r.y()), std::abs(shown_N(r.x())));
      const float width = font->CalcTextSizeA(text, 1e9f, 0.0f, words.c_str()).x;
      const bool left = targets[i].x() < middle_mm;
      float x = left ? tip.x - width : tip.x;
      x = std::clamp(x, origin.x, std::max(origin.x, origin.x + size.x - width));
      float y = std::max(body_origin.y, tip.y - 1.3f * text);
      for (const ImVec4& other : labels) {
        if (x < other.z && other.x < x + width && y < other.w && other.y < y + text) {
          y = other.y - 1.1f * text;
        }
      }
      // Never up into the legend: below the one it would meet instead.
      if (y < body_origin.y) {
        y = body_origin.y;
        for (const ImVec4& other : labels) {
          if (x < other.z && other.x < x + width && y < other.w && other.y < y + text) {
            y = other.w + 0.1f * text;
          }
        }
      }
      labels.emplace_back(x, y, x + width, y + text);
      draw.AddText(font, text, ImVec2(x, y), ink, words.c_str());
    }
    draw.AddCircleFilled(at, 4.0f * style.line_px, ink);
  }
  return fitted;
}

void FieldPanel::view_settings(ViewSettings& settings, Document& /*document*/) {
  settings.add_switch("field", &open_, kEveryUse);
  settings.add_choice<FieldColouring>("field_colour", &colouring_, kColouringNames, kEveryUse);
  settings.add_choice<FieldCut>("field_cut", &cut_, kCutNames, kEveryUse);
  settings.add_switch("field_rays", &rays_, kEveryUse);
  settings.add_switch("field_cosines", &cosines_, kEveryUse);
  settings.add_number_by(
      "field_cells", kCells, kEveryUse, [this] { return static_cast<double>(cells_); },
      [this](double cells) { cells_ = static_cast<int>(cells); }, true);
}

FieldDrawing FieldPanel::drawing_style(const PanelContext& context) const {
  FieldDrawing style;
  style.colouring = colouring_;
  style.rays = rays_;
  style.cosines = cosines_;
  style.stale = !live_.current() || !cut_refusal_.empty();
  style.text_px = ImGui::GetFontSize();
  style.line_px = std::max(1.0f, ImGui::GetFontSize() / 13.0f);
  style.dark = !context.appearance.light_theme();
  return style;
}

void FieldPanel::controls() {
  constexpr const char* kColourings = "state\0tension\0";
  ImGui::SetNextItemWidth(combo_width(kColourings));
  int colouring = static_cast<int>(colouring_);
  if (combo("colour by", &colouring, kColourings)) {
    colouring_ = static_cast<FieldColouring>(colouring);
  }
  // A preset with a cut of its own puts it in the shape's place.
  const char* cuts = preset_cut_ ? "the preset's cut\0triangle\0pennant\0wedge\0"
                                 : "as the shape\0triangle\0pennant\0wedge\0";
  const float cut_width = combo_width(cuts);
  same_line_if_fits(labelled_width(cut_width, "cut"));
  ImGui::SetNextItemWidth(cut_width);
  int cut = static_cast<int>(cut_);
  if (combo("cut", &cut, cuts)) {
    cut_ = static_cast<FieldCut>(cut);
  }
  same_line_if_fits(checkbox_width("rays"));
  ImGui::Checkbox("rays", &rays_);
  same_line_if_fits(checkbox_width(kCosinesLabel));
  ImGui::Checkbox(kCosinesLabel, &cosines_);
  same_line_if_fits(labelled_width(ems(6.0f), kCellsLabel));
  ImGui::SetNextItemWidth(ems(6.0f));
  notched_slider_int(kCellsLabel, cells_, static_cast<int>(kCells.lo), static_cast<int>(kCells.hi),
                     "%d");
}

void FieldPanel::status_line(Document& document, bool side_by_side) {
  const field::SolvedField* shown = live_.shown();
  const std::string& refusal = cut_refusal_.empty() ? live_.refusal() : cut_refusal_;
  if (!refusal.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, message_colour(MessageKind::error));
    ImGui::TextWrapped("%s", refusal.c_str());
    ImGui::PopStyleColor();
  }
  if (shown == nullptr) {
    if (refusal.empty()) {
      ImGui::TextUnformatted("Solving the tension field...");
    }
    return;
  }
  const field::Solution& s = shown->report.solution;
  if (!live_.current() && refusal.empty()) {
    ImGui::TextColored(message_colour(MessageKind::warning),
                       "Solving (residual %.0e): the field shown is of the inputs before.",
                       live_.residual());
  }
  const std::string regions =
      detail::printf_string("taut %.0f %%, wrinkled %.0f %%, slack %.0f %%; weight %#.3g N; %s",
                            100.0 * s.taut_share, 100.0 * s.wrinkled_share, 100.0 * s.slack_share,
                            s.weight_N, thrust_text(shown->report).c_str());
  if (!folds_) {
    wrapped_text("%s", regions.c_str());
    return;
  }
  const Solution& closed = document.scene().solution();
  // No fold says why, or a wrinkled cloth with n = 0 reads as a contradiction.
  const std::string field_folds =
      folds_->n > 0 ? detail::printf_string("n = %d, Q = %.3f, z_max = %.0f mm", folds_->n,
                                            folds_->Q, folds_->z_max_mm)
      : folds_->slack_width_mm > 0.0
          ? std::string(
                "none: under the wrinkle law in force the cloth is too thick or stiff to fold at "
                "the rays' tension")
          : std::string("none: no width across the rays to take up");
  const std::string folds = detail::printf_string(
      "folds from the field: %s (the closed form's: n = %d, Q = %.3f, z_max = %.0f mm)",
      field_folds.c_str(), closed.n, closed.Q, closed.z_max_mm);
  if (!side_by_side) {
    wrapped_text("%s", regions.c_str());
    wrapped_text("%s", folds.c_str());
    return;
  }
  // Presented, side by side, each in half of the width: each a line a little longer than the
  // window would otherwise take two rows, and the rows are the canvas's.
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float column = std::floor(0.5f * (ImGui::GetContentRegionAvail().x - spacing));
  ImGui::BeginGroup();
  ImGui::TextUnformatted(wrap_at_spaces(regions, column).c_str());
  ImGui::EndGroup();
  ImGui::SameLine(0.0f, spacing);
  ImGui::BeginGroup();
  ImGui::TextUnformatted(wrap_at_spaces(folds, column).c_str());
  ImGui::EndGroup();
}

void FieldPanel::cosines_line(Document& document) const {
  const field::SolvedField* shown = live_.shown();
  if (!cosines_ || shown == nullptr) {
    return;
  }
  if (const std::optional<std::string> why =
          cosines_not_drawn(cut_ == FieldCut::shape, kCutNames[static_cast<int>(cut_)],
                            shown->inputs.outline.supports.size(), document.scene().parameters(),
                            document.scene().fold_lines())) {
    wrapped_text("%s", why->c_str());
  }
}

void FieldPanel::solve_line() const {
  if (const field::SolvedField* shown = live_.shown()) {
    const field::Solution& s = shown->report.solution;
    // Wrapped at its spaces: a phone's window is narrower than the line.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    wrapped_text("converged: force residual %.0e, %d Newton steps, mesh %d x %d, %zu triangles",
                 s.relative_residual, s.iterations, shown->inputs.resolution.cells_x,
                 shown->inputs.resolution.cells_y, shown->mesh.triangles.size());
    ImGui::PopStyleColor();
  }
}

void FieldPanel::canvas(PanelContext& context) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  canvas_rect_.reset();
  if (size.x < 8.0f || size.y < 8.0f) {
    return;
  }
  ImGui::InvisibleButton("##field", size);
  canvas_rect_ = PanelRect{origin, size};
  drawn_.mark(*canvas_rect_);
  const field::SolvedField* shown = live_.shown();
  if (shown == nullptr) {
    return;
  }
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  draw.PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  FieldDrawing style = drawing_style(context);
  // The extent, not the scale: the canvas changes height as the status line over it comes and goes.
  if (coarse_) {
    style.least_extent_mm = canvas_fit_.extent_mm;
  }
  canvas_fit_ = draw_field(
      draw, origin, size, *shown,
      cosines_ && cut_ == FieldCut::shape ? &context.document.scene().fold_lines() : nullptr,
      style);
  draw.PopClipRect();
}

void FieldPanel::update_folds(FieldSolve& solve, const Parameters& parameters) {
  const field::SolvedField* shown = solve.live.shown();
  if (shown == nullptr) {
    solve.folds.reset();
    return;
  }
  // A field of other inputs than those shown is read by its own inputs' law: its folds are those
  // it had when it converged, drawn as the previous inputs' folds.
  const Parameters& law =
      solve.live.current() || !solve.shown_parameters ? parameters : *solve.shown_parameters;
  if (!solve.folds || solve.folds_of != solve.live.shown_count() || !solve.folds_parameters ||
      !(*solve.folds_parameters == law)) {
    solve.folds_of = solve.live.shown_count();
    solve.folds_parameters = law;
    solve.folds = field::field_folds(shown->mesh, shown->report.solution,
                                     field::support_targets(shown->inputs.outline), law);
  }
}

void FieldPanel::solve_slice(FieldSolve& solve, FieldCut cut, PanelContext& context, bool moving,
                             double budget_ms) {
  const Parameters& parameters = context.document.scene().parameters();
  const int cells = moving ? std::max(static_cast<int>(kCells.lo), cells_ / 2) : cells_;
  const std::optional<field::Outline>& own = context.document.loaded().outline;
  solve.own_cut = cut == FieldCut::shape && own.has_value();
  solve.requested_parameters = parameters;
  try {
    solve.live.request(field_inputs(parameters, cells, cut, own ? &*own : nullptr));
    solve.cut_refusal.clear();
  } catch (const field::OutlineError& e) {
    // The last field stays on show, marked as of other inputs.
    solve.cut_refusal = std::string("This cut cannot be solved: ") + e.what();
  }
  const auto began = std::chrono::steady_clock::now();
  if (budget_ms > 0.0 && solve.live.step(budget_ms)) {
    solve.shown_parameters = parameters;
  }
  solve.slice_ms +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count();
  update_folds(solve, parameters);
}

void FieldPanel::prepare(PanelContext& context) {
  const Parameters& parameters = context.document.scene().parameters();
  const int frame = ImGui::GetFrameCount();
  const bool again = prepared_frame_ == frame;
  if (again && prepared_parameters_ && *prepared_parameters_ == parameters) {
    return;
  }
  prepared_frame_ = frame;
  prepared_parameters_ = parameters;
  consumers_.clear();
  if (open_) {
    consumers_.emplace_back("view");
  }
  if (folds_asked_) {
    consumers_.emplace_back("fold_source");
  }
  view_solving_ = false;
  cloth_solving_ = false;
  if (consumers_.empty()) {
    return;  // nobody asks: nothing is solved
  }
  // While a value moves (dragged, nudged, played, animated) and a moment after, a coarser mesh
  // keeps up with the hand; the finer one follows when it rests.
  const double now_s = ImGui::GetTime();
  if (!last_parameters_ || !(*last_parameters_ == parameters)) {
    if (last_parameters_) {
      last_change_s_ = now_s;  // the first inputs seen are no move
    }
    last_parameters_ = parameters;
  }
  const bool moving = context.holding_frame || now_s - last_change_s_ < kRestS;
  coarse_ = moving;
  preset_cut_ = context.document.loaded().outline.has_value();
  // A share of the frame while a value moves, so that the drag stays smooth; more at rest, when
  // nothing else moves and the finer mesh is wanted soon. Each solve asked for has its own: two
  // cost twice the time only while the view shows another cut than the cloth's.
  const double budget_ms = moving ? 6.0 : 25.0;
  const auto slice = [&](FieldSolve& solve, FieldCut cut) {
    if (!again) {
      solve.slice_ms = 0.0;
    }
    solve_slice(solve, cut, context, moving, std::max(0.0, budget_ms - solve.slice_ms));
  };
  view_solving_ = open_ || cut_ == FieldCut::shape;
  cloth_solving_ = folds_asked_ && cut_ != FieldCut::shape;
  if (view_solving_) {
    slice(view_solve_, cut_);
  }
  if (cloth_solving_) {
    slice(cloth_solve_, FieldCut::shape);
  }
  slice_ms_ =
      (view_solving_ ? view_solve_.slice_ms : 0.0) + (cloth_solving_ ? cloth_solve_.slice_ms : 0.0);
}

void FieldPanel::end_frame(PanelContext& /*context*/) {
  folds_asked_ = false;
}

FieldFoldsNow FieldPanel::folds_now(PanelContext& context) {
  prepare(context);
  const Parameters& parameters = context.document.scene().parameters();
  FieldFoldsNow now;
  if (consumers_.empty()) {
    now.words = "not solved";
    return now;
  }
  if (cut_ != FieldCut::shape && !folds_asked_) {
    now.state = FieldFoldsNow::State::other_cut;
    now.words =
        "the tension field view shows another cut than the cloth's (set its cut to "
        "\"as the shape\")";
    return now;
  }
  const FieldSolve& solve = fold_solve();
  now.residual = solve.live.residual();
  const std::string& refusal = solve.cut_refusal.empty() ? solve.live.refusal() : solve.cut_refusal;
  if (!refusal.empty()) {
    // LiveField says a solve that gave up in these words; any other refusal is the cut's.
    const bool gave_up =
        solve.cut_refusal.empty() && refusal.starts_with("the field did not converge");
    now.state = gave_up ? FieldFoldsNow::State::not_converged : FieldFoldsNow::State::refused;
    now.words =
        gave_up ? detail::printf_string("not converged (residual %.1e)", now.residual) : refusal;
    return now;
  }
  if (!solve.live.current() || !solve.requested_parameters ||
      !(*solve.requested_parameters == parameters) || !solve.folds || !solve.folds_parameters ||
      !(*solve.folds_parameters == parameters)) {
    now.state = FieldFoldsNow::State::solving;
    now.words = solve.live.shown() == nullptr || solve.live.iterations() == 0
                    ? std::string("solving...")
                    : detail::printf_string("solving... (residual %.0e)", now.residual);
    if (solve.folds && solve.folds_of == solve.live.shown_count()) {
      now.previous = &*solve.folds;
    }
    return now;
  }
  now.state = FieldFoldsNow::State::converged;
  now.folds = &*solve.folds;
  return now;
}

void FieldPanel::draw(PanelContext& context) {
  prepare(context);
  if (consumers_.empty()) {
    was_open_ = false;
    return;
  }
  if (!open_) {
    was_open_ = false;
    return;
  }
  // A first place of its own, unless the layout placed it (presented, or put back).
  if ((ImGui::GetCurrentContext()->NextWindowData.Flags & ImGuiNextWindowDataFlags_HasPos) == 0) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImGuiWindow* menu = ImGui::FindWindowByName("##MainMenuBar");
    const float top = menu != nullptr ? menu->Size.y : 0.0f;
    const PanelRect first = first_window_place(display, top);
    ImGui::SetNextWindowPos(first.pos, ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(first.size, ImGuiCond_FirstUseEver);
    // A window made smaller (1920 x 1080 to 1024 x 640) keeps the view, its close button and
    // its title on the display, under the menu bar (which would hide them and take their clicks).
    if (const ImGuiWindow* window = ImGui::FindWindowByName(window_label().c_str())) {
      const ImVec2 size(std::min(window->SizeFull.x, display.x),
                        std::min(window->SizeFull.y, display.y - top));
      const ImVec2 pos(std::clamp(window->Pos.x, 0.0f, display.x - size.x),
                       std::clamp(window->Pos.y, top, display.y - size.y));
      if (size.x != window->SizeFull.x || size.y != window->SizeFull.y || pos.x != window->Pos.x ||
          pos.y != window->Pos.y) {
        ImGui::SetNextWindowPos(pos);
        ImGui::SetNextWindowSize(size);
      }
    }
  }

  if (!was_open_) {
    ImGui::SetNextWindowFocus();  // opened from the menu or a script: in front
  }
  was_open_ = true;
  // NoCollapse: a double-click on the title presents the window (Layout), as it does a tile.
  if (begin_panel(window_label().c_str(), context.renderer, &open_)) {
    // At a large text size in a small window the settings and the solve's figures fold behind
    // one button, so that the field keeps the room; presented, always, the button in the title
    // bar.
    const bool presented = context.presented == this;
    if (toolbar_.begin("field settings...", kLeastCanvasEms * ImGui::GetFontSize(), presented)) {
      controls();
      solve_line();
      toolbar_.end();
    }
    status_line(context.document, presented && !shows_one_view());
    cosines_line(context.document);
    canvas(context);
  }
  ImGui::End();
}

namespace {

// What the report says of one solve: its state and the field on show.
void describe_solve(json& out, const FieldSolve& solve) {
  out["current"] = solve.live.current();
  out["working"] = solve.live.working();
  const std::string& refusal = solve.cut_refusal.empty() ? solve.live.refusal() : solve.cut_refusal;
  out["refusal"] = refusal.empty() ? json(nullptr) : json(refusal);
  const field::SolvedField* shown = solve.live.shown();
  if (shown == nullptr) {
    return;
  }
  const field::Solution& s = shown->report.solution;
  out["converged"] = s.converged;
  out["relative_residual"] = s.relative_residual;
  out["iterations"] = s.iterations;
  out["mesh"] = {{"cells_x", shown->inputs.resolution.cells_x},
                 {"cells_y", shown->inputs.resolution.cells_y},
                 {"triangles", shown->mesh.triangles.size()}};
  out["regions"] = {
      {"taut", s.taut_share}, {"wrinkled", s.wrinkled_share}, {"slack", s.slack_share}};
  out["weight_N"] = s.weight_N;
  out["thrust_N"] = shown->report.thrust_N;
  out["pencil_thrust_N"] = shown->report.pencil_thrust_N;
  out["supports"] = json::array();
  for (std::size_t i = 0; i < s.reactions_N.size(); ++i) {
    const field::Support& support = shown->inputs.outline.supports[i];
    out["supports"].push_back({{"at_mm", {support.at_mm.x(), support.at_mm.y()}},
                               {"to_mm", {support.to_mm.x(), support.to_mm.y()}},
                               {"reaction_N", {s.reactions_N[i].x(), s.reactions_N[i].y()}}});
  }
  out["rays"] = shown->report.rays.size();
  out["spans"] = json::array();
  for (const field::SpanReport& span : shown->report.spans) {
    out["spans"].push_back({{"l_mm", span.span_mm},
                            {"thrust_N", span.thrust_N},
                            {"pencil_thrust_N", span.pencil_thrust_N}});
  }
  out["thrust_text"] = thrust_text(shown->report);
  out["outline_area_mm2"] = shown->inputs.outline.area_mm2();
  if (solve.folds && solve.folds_of == solve.live.shown_count()) {
    // The a_i too: a test compares them with the 3D view's.
    out["folds"] = {{"n", solve.folds->n},
                    {"Q", solve.folds->Q},
                    {"z_max_mm", solve.folds->z_max_mm},
                    {"a_mm", solve.folds->a_mm}};
  }
}

}  // namespace

void FieldPanel::report(json& state, PanelContext& /*context*/) const {
  json out;
  out["open"] = open_;
  out["slice_ms"] = slice_ms_;
  out["canvas_px_per_mm"] = canvas_fit_.px_per_mm;
  out["solving_for"] = consumers_;
  out["cut"] = view_solve_.own_cut ? "preset" : std::string(kCutNames[static_cast<int>(cut_)]);
  describe_solve(out, view_solve_);
  json cloth = nullptr;
  if (cut_ != FieldCut::shape &&
      (cloth_solve_.live.shown() != nullptr || cloth_solve_.live.working())) {
    cloth = json::object();
    cloth["cut"] = cloth_solve_.own_cut ? "preset" : "shape";
    describe_solve(cloth, cloth_solve_);
  }
  out["fold_source_solve"] = std::move(cloth);
  state["field"] = out;
}

void FieldPanel::use_picture_cut(field::Outline outline, std::string name,
                                 std::optional<field::OutlineKind> kind, bool closed_form_of_cut) {
  picture_cut_ = GivenCut{std::move(outline), std::move(name), kind, closed_form_of_cut};
}

std::string FieldPanel::closed_form_words() const {
  return picture_cut_ && picture_cut_->closed_form_of_cut
             ? "the closed form's folds, for the cut's h, L and d: "
             : "the closed form's folds: ";
}

bool FieldPanel::picture_cut_is_closed_forms() const {
  if (picture_cut_) {
    return !picture_cut_->kind || closed_form_knows(*picture_cut_->kind);
  }
  return cut_ == FieldCut::shape;
}

std::string FieldPanel::picture_cut_words(const Document& document) const {
  if (picture_cut_) {
    if (picture_cut_->kind) {
      return "the " + picture_cut_->name + " cut";
    }
    return "the cut in " + std::filesystem::path(picture_cut_->name).filename().string();
  }
  if (cut_ == FieldCut::shape && document.loaded().outline) {
    return "the preset's own cut";
  }
  return "the " + std::string(field::to_string(outline_kind(document.scene().parameters(), cut_))) +
         " cut";
}

const field::SolvedField* FieldPanel::picture_field(const Document& document,
                                                    std::string& refusal) const {
  field::FieldInputs inputs;
  try {
    const std::optional<field::Outline>& own = document.loaded().outline;
    inputs = picture_cut_
                 ? field_inputs(document.scene().parameters(), cells_, FieldCut::shape,
                                &picture_cut_->outline)
                 : field_inputs(document.scene().parameters(), cells_, cut_, own ? &*own : nullptr);
  } catch (const field::OutlineError& e) {
    refusal = std::string("the tension field's cut: ") + e.what();
    return nullptr;
  }
  if (!picture_inputs_ || !(*picture_inputs_ == inputs)) {
    picture_inputs_ = inputs;
    picture_field_ = field::solve_field(inputs, picture_refusal_);
  }
  refusal = picture_refusal_;
  return picture_field_ ? &*picture_field_ : nullptr;
}

std::optional<std::string> FieldPanel::picture_unavailable(PictureView /*view*/,
                                                           const Document& document,
                                                           bool as_drawn) const {
  if (as_drawn) {
    if (!open_) {
      return "Open View > Tension field to take it as drawn.";
    }
    return std::nullopt;
  }
  std::string refusal;
  if (picture_field(document, refusal) == nullptr) {
    return refusal;
  }
  return std::nullopt;
}

bool FieldPanel::draw_picture(PictureView /*view*/, ImVec2 size_px, Document& document,
                              const PictureStyle& style) {
  std::string refusal;
  const field::SolvedField* solved = picture_field(document, refusal);
  if (solved == nullptr) {
    return true;  // picture_problem said why before any drawing
  }
  FieldDrawing drawing;
  drawing.colouring = colouring_;
  drawing.rays = rays_;
  drawing.cosines = cosines_;
  drawing.legend = true;  // the colours mean nothing without it
  drawing.text_px = style.text_px;
  drawing.line_px = style.line_px;
  drawing.dark = style.dark;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  draw_field(*ImGui::GetWindowDrawList(), origin, size_px, *solved,
             cosines_ && picture_cut_is_closed_forms() ? &document.scene().fold_lines() : nullptr,
             drawing);
  return true;
}

std::vector<std::string> FieldPanel::picture_figures(PictureView /*view*/,
                                                     Document& document) const {
  std::string refusal;
  const field::SolvedField* solved = picture_field(document, refusal);
  if (solved == nullptr) {
    return {};
  }
  const field::Solution& s = solved->report.solution;
  const Parameters& parameters = document.scene().parameters();
  std::vector<std::string> lines;
  // As `foldlab field` finds them, on the mesh said, so that the command repeats them.
  lines.push_back(detail::printf_string(
      "Tension field on %s, mesh %d x %d cells: weight %.4g N, thrust H %.4g N (the cosine "
      "pencil's through the supports: %.4g N)",
      picture_cut_words(document).c_str(), solved->inputs.resolution.cells_x,
      solved->inputs.resolution.cells_y, s.weight_N, solved->report.thrust_N,
      solved->report.pencil_thrust_N));
  const field::FieldFolds folds = field::field_folds(
      solved->mesh, s, field::support_targets(solved->inputs.outline), parameters);
  lines.push_back(detail::printf_string(
      "the field's folds: n = %d, Q = %.4g, z_max = %.1f mm; %s (relative force residual %.1e)",
      folds.n, folds.Q, folds.z_max_mm, s.converged ? "converged" : "NOT converged",
      s.relative_residual));
  if (cosines_) {
    const std::string cut_name =
        picture_cut_ ? picture_cut_->name : std::string(kCutNames[static_cast<int>(cut_)]);
    if (const std::optional<std::string> why = cosines_not_drawn(
            picture_cut_is_closed_forms(), cut_name, solved->inputs.outline.supports.size(),
            parameters, document.scene().fold_lines())) {
      lines.push_back(*why);
    }
  }
  return lines;
}

}  // namespace foldlab::gui
