#include "core/field/outline.hpp"

#include "core/model/named_enum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

#include "core/model/text_format.hpp"

namespace foldlab::field {
namespace {

using detail::printf_string;
using Eigen::Vector2d;

double edge_y(const std::vector<Vector2d>& edge, double x) {
  const auto after = std::upper_bound(
      edge.begin(), edge.end(), x, [](double value, const Vector2d& v) { return value < v.x(); });
  if (after == edge.begin()) {
    return edge.front().y();
  }
  if (after == edge.end()) {
    return edge.back().y();
  }
  const Vector2d& a = *(after - 1);
  const Vector2d& b = *after;
  const double s = (x - a.x()) / (b.x() - a.x());
  return a.y() + s * (b.y() - a.y());
}

std::string point_text(const Vector2d& p) {
  return printf_string("(%.6g, %.6g) mm", p.x(), p.y());
}

Support pinned_at(double X, double Y, double x, double y) {
  return {Vector2d(X, Y), Vector2d(x, y)};
}

// A cosine of amplitude `depth` over [-L/2, L/2] as a polyline fine enough that its chords stay
// within 1e-4 of the depth of the curve.
std::vector<Vector2d> cosine_edge(double L, double depth) {
  const int segments = 256;
  std::vector<Vector2d> edge;
  for (int i = 0; i <= segments; ++i) {
    const double X = -0.5 * L + L * i / segments;
    edge.emplace_back(X, depth * std::cos(std::numbers::pi * X / L));
  }
  edge.front().y() = 0.0;  // cos(+-pi/2) is not exactly 0 in doubles: the supports sit on it
  edge.back().y() = 0.0;
  return edge;
}

void check_edge(const std::vector<Vector2d>& edge, const char* name) {
  if (edge.size() < 2) {
    throw OutlineError(std::string("the ") + name + " edge needs at least two vertices");
  }
  if (edge.size() > static_cast<std::size_t>(kMaxOutlineVertices)) {
    throw OutlineError(printf_string("the %s edge has %zu vertices; at most %d are accepted", name,
                                     edge.size(), kMaxOutlineVertices));
  }
  for (std::size_t i = 0; i < edge.size(); ++i) {
    if (!std::isfinite(edge[i].x()) || !std::isfinite(edge[i].y())) {
      throw OutlineError(printf_string("the %s edge's vertex %zu is not a finite number", name, i));
    }
    if (std::abs(edge[i].x()) > kMaxOutlineCoordinate_mm ||
        std::abs(edge[i].y()) > kMaxOutlineCoordinate_mm) {
      throw OutlineError(printf_string(
          "the %s edge's vertex %zu %s is out of range: a cut's coordinates are within %.0e mm "
          "(10 km) of the origin",
          name, i, point_text(edge[i]).c_str(), kMaxOutlineCoordinate_mm));
    }
    if (i > 0 && !(edge[i].x() > edge[i - 1].x())) {
      throw OutlineError(printf_string(
          "the %s edge turns back or steps straight down at vertex %zu %s: each edge must run "
          "left to right with x increasing (x = %.6g after %.6g)",
          name, i, point_text(edge[i]).c_str(), edge[i].x(), edge[i - 1].x()));
    }
  }
}

// A key not in `known` is refused by name: a misspelt "suports" would otherwise leave a cut
// without the supports its author meant.
void refuse_unknown_keys(const nlohmann::json& object, std::initializer_list<const char*> known,
                         const std::string& where) {
  for (const auto& item : object.items()) {
    if (std::none_of(known.begin(), known.end(), [&](const char* k) { return item.key() == k; })) {
      std::string names;
      for (const char* k : known) {
        names += std::string(names.empty() ? "" : ", ") + "\"" + k + "\"";
      }
      throw OutlineError(where + "unknown key \"" + detail::cut(item.key()) + "\" (the keys are " +
                         names + ")");
    }
  }
}

Vector2d read_point(const nlohmann::json& value, const std::string& where) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number()) {
    throw OutlineError(where + " must be a pair of numbers [x, y] in mm");
  }
  return {value[0].get<double>(), value[1].get<double>()};
}

std::vector<Vector2d> read_edge(const nlohmann::json& doc, const char* key) {
  if (!doc.contains(key) || !doc[key].is_array()) {
    throw OutlineError(std::string("the outline needs \"") + key +
                       "\": a list of [x, y] points in mm");
  }
  const nlohmann::json& list = doc[key];
  if (list.size() > static_cast<std::size_t>(kMaxOutlineVertices)) {
    throw OutlineError(printf_string("the %s edge has %zu vertices; at most %d are accepted", key,
                                     list.size(), kMaxOutlineVertices));
  }
  std::vector<Vector2d> edge;
  for (std::size_t i = 0; i < list.size(); ++i) {
    edge.push_back(read_point(list[i], printf_string("%s[%zu]", key, i)));
  }
  return edge;
}

}  // namespace

double Outline::top_y_mm(double x_mm) const {
  return edge_y(top_mm, x_mm);
}

double Outline::bottom_y_mm(double x_mm) const {
  return edge_y(bottom_mm, x_mm);
}

double Outline::area_mm2() const {
  // Both edges are graphs over x: the area is the integral of their difference, exact for the
  // piecewise-linear difference on the union of their vertices' x.
  std::vector<double> xs;
  for (const Vector2d& v : top_mm)
    xs.push_back(v.x());
  for (const Vector2d& v : bottom_mm)
    xs.push_back(v.x());
  std::sort(xs.begin(), xs.end());
  double area = 0.0;
  for (std::size_t i = 1; i < xs.size(); ++i) {
    const double a = bottom_y_mm(xs[i - 1]) - top_y_mm(xs[i - 1]);
    const double b = bottom_y_mm(xs[i]) - top_y_mm(xs[i]);
    area += 0.5 * (a + b) * (xs[i] - xs[i - 1]);
  }
  return area;
}

std::string_view to_string(OutlineKind k) {
  switch (k) {
    case OutlineKind::rectangular:
      return "rectangular";
    case OutlineKind::cosine:
      return "cosine";
    case OutlineKind::strip:
      return "strip";
    case OutlineKind::inclined:
      return "inclined";
    case OutlineKind::triangle:
      return "triangle";
    case OutlineKind::pennant:
      return "pennant";
    case OutlineKind::wedge:
      return "wedge";
  }
  return "rectangular";
}

namespace {
constexpr OutlineKind kAllKinds[] = {
    OutlineKind::rectangular, OutlineKind::cosine,  OutlineKind::strip, OutlineKind::inclined,
    OutlineKind::triangle,    OutlineKind::pennant, OutlineKind::wedge};
}

bool parse_outline_kind(std::string_view s, OutlineKind& out) {
  // The paper's (Mansfield's) name for the cut on inclined supports.
  if (s == "parallelogram") {
    out = OutlineKind::inclined;
    return true;
  }
  return parse_named(s, out, kAllKinds);
}

std::string outline_kind_names() {
  std::string out;
  for (OutlineKind k : kAllKinds) {
    out += (out.empty() ? "" : ", ") + std::string(to_string(k));
  }
  return out;
}

OutlineKind outline_kind_of(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::cosine_membrane:
      return OutlineKind::cosine;
    case ShapeKind::rectangular:
      return OutlineKind::rectangular;
    case ShapeKind::strip:
      return OutlineKind::strip;
    case ShapeKind::inclined:
      return OutlineKind::inclined;
  }
  return OutlineKind::rectangular;
}

double cosine_top_depth_mm(const Parameters& p) {
  return 0.01 * p.hanging.height_mm;
}

double cosine_bottom_depth_mm(const Parameters& p) {
  return p.hanging.height_mm + cosine_top_depth_mm(p);
}

double Outline::height_mm() const {
  double top = top_mm.front().y();
  double bottom = bottom_mm.front().y();
  for (const Eigen::Vector2d& p : top_mm) {
    top = std::min(top, p.y());
  }
  for (const Eigen::Vector2d& p : bottom_mm) {
    bottom = std::max(bottom, p.y());
  }
  return bottom - top;
}

std::optional<Hanging> closed_form_hanging(const Outline& outline, SpanRule rule) {
  if (outline.supports.size() != 2) {
    return std::nullopt;
  }
  const Support& a = outline.supports[0];
  const Support& b = outline.supports[1];
  const double tolerance_mm = 1e-9 * std::max(1.0, outline.height_mm());
  for (const Support& s : {a, b}) {
    if (std::abs(s.at_mm.y() - outline.top_y_mm(s.at_mm.x())) > tolerance_mm) {
      return std::nullopt;
    }
  }
  Hanging hanging;
  const double middle_mm = 0.5 * (a.at_mm.x() + b.at_mm.x());
  hanging.height_mm = outline.bottom_y_mm(middle_mm) - outline.top_y_mm(middle_mm);
  hanging.length_mm = (b.at_mm - a.at_mm).norm();
  const double moved_in_mm = hanging.length_mm - (b.to_mm - a.to_mm).norm();
  if (!(moved_in_mm >= 0.0)) {
    return std::nullopt;
  }
  hanging.support_displacement_mm = rule == SpanRule::L_minus_2d ? 0.5 * moved_in_mm : moved_in_mm;
  return hanging;
}

Outline make_outline(const Parameters& p, OutlineKind kind) {
  const double h = p.hanging.height_mm;
  const double L = p.hanging.length_mm;
  const double l = span_mm(p);
  Outline o;
  switch (kind) {
    case OutlineKind::rectangular:
      o.top_mm = {{-0.5 * L, 0.0}, {0.5 * L, 0.0}};
      o.bottom_mm = {{-0.5 * L, h}, {0.5 * L, h}};
      o.supports = {pinned_at(-0.5 * L, 0, -0.5 * l, 0), pinned_at(0.5 * L, 0, 0.5 * l, 0)};
      break;
    case OutlineKind::cosine:
      o.top_mm = cosine_edge(L, cosine_top_depth_mm(p));
      o.bottom_mm = cosine_edge(L, cosine_bottom_depth_mm(p));
      o.supports = {pinned_at(-0.5 * L, 0, -0.5 * l, 0), pinned_at(0.5 * L, 0, 0.5 * l, 0)};
      break;
    case OutlineKind::strip: {
      const int k = std::max(2, p.shape.supports);
      const double width = (k - 1) * L;
      o.top_mm = {{-0.5 * width, 0.0}, {0.5 * width, 0.0}};
      o.bottom_mm = {{-0.5 * width, h}, {0.5 * width, h}};
      for (int i = 0; i < k; ++i) {
        const double X = -0.5 * width + i * L;
        o.supports.push_back(pinned_at(X, 0, X * l / L, 0));
      }
      break;
    }
    case OutlineKind::inclined: {
      // y is down, so the right support higher by l tan(theta) has the smaller y.
      const double slope = std::tan(p.shape.incline_deg * std::numbers::pi / 180.0);
      o.top_mm = {{-0.5 * L, 0.5 * L * slope}, {0.5 * L, -0.5 * L * slope}};
      o.bottom_mm = {{-0.5 * L, h + 0.5 * L * slope}, {0.5 * L, h - 0.5 * L * slope}};
      o.supports = {pinned_at(-0.5 * L, 0.5 * L * slope, -0.5 * l, 0.5 * l * slope),
                    pinned_at(0.5 * L, -0.5 * L * slope, 0.5 * l, -0.5 * l * slope)};
      break;
    }
    case OutlineKind::triangle:
      o.top_mm = {{-0.5 * L, 0.0}, {0.5 * L, 0.0}};
      o.bottom_mm = {{-0.5 * L, 0.0}, {0.0, h}, {0.5 * L, 0.0}};
      o.supports = {pinned_at(-0.5 * L, 0, -0.5 * l, 0), pinned_at(0.5 * L, 0, 0.5 * l, 0)};
      break;
    case OutlineKind::pennant:
      o.top_mm = {{-0.5 * L, 0.0}, {0.5 * L, 0.0}};
      o.bottom_mm = {{-0.5 * L, h}, {0.5 * L, 0.0}};
      o.supports = {pinned_at(-0.5 * L, 0, -0.5 * l, 0), pinned_at(0.5 * L, 0, 0.5 * l, 0)};
      break;
    case OutlineKind::wedge:
      o.top_mm = {{-0.5 * L, 0.0}, {0.5 * L, 0.0}};
      o.bottom_mm = {{-0.5 * L, h}, {0.5 * L, kWedgeThinEndShare * h}};
      o.supports = {pinned_at(-0.5 * L, 0, -0.5 * l, 0), pinned_at(0.5 * L, 0, 0.5 * l, 0)};
      break;
  }
  check_outline(o);
  return o;
}

Outline parse_outline_json(std::string_view text) {
  nlohmann::json doc;
  // One set of keys per open object: a key given twice is refused (the last would silently win).
  std::vector<std::vector<std::string>> open_keys;
  std::string duplicate;
  const nlohmann::json::parser_callback_t note_keys =
      [&](int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        if (event == nlohmann::json::parse_event_t::object_start) {
          open_keys.emplace_back();
        } else if (event == nlohmann::json::parse_event_t::object_end && !open_keys.empty()) {
          open_keys.pop_back();
        } else if (event == nlohmann::json::parse_event_t::key && !open_keys.empty() &&
                   parsed.is_string()) {
          std::vector<std::string>& keys = open_keys.back();
          const std::string& key = parsed.get_ref<const std::string&>();
          if (duplicate.empty() && std::find(keys.begin(), keys.end(), key) != keys.end()) {
            duplicate = key;
          }
          keys.push_back(key);
        }
        return true;
      };
  try {
    doc = nlohmann::json::parse(text, note_keys);
  } catch (const nlohmann::json::exception& e) {
    throw OutlineError(std::string("the outline is not valid JSON: ") + e.what());
  }
  if (!duplicate.empty()) {
    throw OutlineError("the key \"" + detail::cut(duplicate) +
                       "\" is given twice in one object (each key may appear once; which one "
                       "is meant?)");
  }
  return outline_from_json(doc);
}

Outline outline_from_json(const nlohmann::json& doc) {
  if (!doc.is_object()) {
    throw OutlineError(
        "the outline must be a JSON object with \"top\", \"bottom\" and \"supports\"");
  }
  refuse_unknown_keys(doc, {"top", "bottom", "supports"}, "");
  Outline o;
  o.top_mm = read_edge(doc, "top");
  o.bottom_mm = read_edge(doc, "bottom");
  if (!doc.contains("supports") || !doc["supports"].is_array()) {
    throw OutlineError(
        "the outline needs \"supports\": a list of {\"at\": [X, Y], \"to\": [x, y]} in mm");
  }
  for (std::size_t i = 0; i < doc["supports"].size(); ++i) {
    const nlohmann::json& s = doc["supports"][i];
    const std::string where = printf_string("supports[%zu]", i);
    if (!s.is_object() || !s.contains("at") || !s.contains("to")) {
      throw OutlineError(where + " must be {\"at\": [X, Y], \"to\": [x, y]} in mm");
    }
    refuse_unknown_keys(s, {"at", "to"}, where + ": ");
    o.supports.push_back({read_point(s["at"], where + ".at"), read_point(s["to"], where + ".to")});
  }
  check_outline(o);
  return o;
}

void check_outline(const Outline& o) {
  check_edge(o.top_mm, "top");
  check_edge(o.bottom_mm, "bottom");
  const double size = std::max({o.right_mm() - o.left_mm(), 1.0});
  const double tolerance = kOutlineTolerancePerWidth * size;
  if (std::abs(o.top_mm.front().x() - o.bottom_mm.front().x()) > tolerance ||
      std::abs(o.top_mm.back().x() - o.bottom_mm.back().x()) > tolerance) {
    throw OutlineError(printf_string(
        "the top edge runs from x = %.6g to %.6g mm and the bottom edge from %.6g to %.6g mm: "
        "both must start and end at the same x",
        o.top_mm.front().x(), o.top_mm.back().x(), o.bottom_mm.front().x(),
        o.bottom_mm.back().x()));
  }
  std::vector<double> xs;
  for (const Vector2d& v : o.top_mm)
    xs.push_back(v.x());
  for (const Vector2d& v : o.bottom_mm)
    xs.push_back(v.x());
  double tallest = 0.0;
  for (double x : xs) {
    const double gap = o.bottom_y_mm(x) - o.top_y_mm(x);
    if (gap < -tolerance) {
      throw OutlineError(printf_string(
          "the edges cross: at x = %.6g mm the bottom edge (y = %.6g mm) is above the top edge "
          "(y = %.6g mm)",
          x, o.bottom_y_mm(x), o.top_y_mm(x)));
    }
    tallest = std::max(tallest, gap);
  }
  if (!(tallest > 0.0)) {
    throw OutlineError("the outline has no area: its top and bottom edges coincide");
  }
  if (!(tallest > tolerance)) {
    throw OutlineError(printf_string(
        "the cut is %.6g mm tall at most across its %.6g mm width: too thin to mesh (a cut must "
        "be taller than %.0e of its width, here %.6g mm)",
        tallest, o.right_mm() - o.left_mm(), kOutlineTolerancePerWidth, tolerance));
  }
  for (const auto& [edge, name] :
       {std::pair{&o.top_mm, "top"}, std::pair{&o.bottom_mm, "bottom"}}) {
    for (std::size_t i = 1; i < edge->size(); ++i) {
      const double step = (*edge)[i].x() - (*edge)[i - 1].x();
      if (step <= tolerance) {
        throw OutlineError(printf_string(
            "the %s edge's vertices %zu and %zu are %.6g mm apart in x: narrower than the mesh "
            "can follow (%.0e of the cut's width, %.6g mm); make the step that wide or drop a "
            "vertex",
            name, i - 1, i, step, kOutlineTolerancePerWidth, tolerance));
      }
    }
  }
  const double pull_limit_mm = kMaxSupportPullPerSize * std::max(size, o.height_mm());
  if (o.supports.empty()) {
    throw OutlineError("the outline needs at least one support to hang from");
  }
  for (std::size_t i = 0; i < o.supports.size(); ++i) {
    const Support& s = o.supports[i];
    if (!s.at_mm.allFinite() || !s.to_mm.allFinite()) {
      throw OutlineError(printf_string("support %zu is not a pair of finite numbers", i + 1));
    }
    if (s.to_mm.cwiseAbs().maxCoeff() > kMaxOutlineCoordinate_mm) {
      throw OutlineError(printf_string(
          "support %zu is pinned at %s, out of range: a cut's coordinates are within %.0e mm "
          "(10 km) of the origin",
          i + 1, point_text(s.to_mm).c_str(), kMaxOutlineCoordinate_mm));
    }
    if ((s.to_mm - s.at_mm).norm() > pull_limit_mm) {
      throw OutlineError(printf_string(
          "support %zu at %s is pinned at %s, %.6g mm away: a support is pinned within %.0f "
          "times the cut's size (%.6g mm) of where it is on the cut",
          i + 1, point_text(s.at_mm).c_str(), point_text(s.to_mm).c_str(),
          (s.to_mm - s.at_mm).norm(), kMaxSupportPullPerSize, pull_limit_mm));
    }
    const double X = s.at_mm.x();
    const double Y = s.at_mm.y();
    if (X < o.left_mm() - tolerance || X > o.right_mm() + tolerance) {
      throw OutlineError(printf_string(
          "support %zu at %s is off the outline: the cut runs from x = %.6g to %.6g mm", i + 1,
          point_text(s.at_mm).c_str(), o.left_mm(), o.right_mm()));
    }
    const double top = o.top_y_mm(X);
    const double bottom = o.bottom_y_mm(X);
    const bool on_edge = std::abs(Y - top) <= tolerance || std::abs(Y - bottom) <= tolerance;
    const bool on_end =
        (std::abs(X - o.left_mm()) <= tolerance || std::abs(X - o.right_mm()) <= tolerance) &&
        Y >= top - tolerance && Y <= bottom + tolerance;
    if (!on_edge && !on_end) {
      throw OutlineError(printf_string(
          "support %zu at %s is off the outline: at x = %.6g mm the top edge is at y = %.6g mm "
          "and the bottom edge at y = %.6g mm",
          i + 1, point_text(s.at_mm).c_str(), X, top, bottom));
    }
    for (std::size_t j = 0; j < i; ++j) {
      if ((o.supports[j].at_mm - s.at_mm).norm() <= tolerance) {
        throw OutlineError(printf_string("supports %zu and %zu are at the same point %s", j + 1,
                                         i + 1, point_text(s.at_mm).c_str()));
      }
    }
  }
}

Outline translated(const Outline& outline, const Vector2d& offset_mm) {
  Outline out = outline;
  for (Vector2d& v : out.top_mm)
    v += offset_mm;
  for (Vector2d& v : out.bottom_mm)
    v += offset_mm;
  for (Support& s : out.supports) {
    s.at_mm += offset_mm;
    s.to_mm += offset_mm;
  }
  return out;
}

Vector2d solve_origin_mm(const Outline& o) {
  double top = o.top_mm.front().y();
  for (const Vector2d& v : o.top_mm)
    top = std::min(top, v.y());
  const Vector2d centre(0.5 * (o.left_mm() + o.right_mm()), top + 0.5 * o.height_mm());
  const double size = std::max({o.right_mm() - o.left_mm(), o.height_mm(), 1.0});
  const double grid = std::exp2(std::ceil(std::log2(size)));
  return {grid * std::round(centre.x() / grid), grid * std::round(centre.y() / grid)};
}

}  // namespace foldlab::field
