#include "core/field/rays.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>

namespace foldlab::field {
namespace {

using Eigen::Vector2d;

const Vector2d kOutside(std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::quiet_NaN());

// One way along the ray from the flat point `from`, starting along `heading`: the flat points.
std::vector<Vector2d> trace_one_way(const Mesh& mesh, const Solution& solution, Vector2d from,
                                    Vector2d heading, double step_mm, int max_steps) {
  std::vector<Vector2d> points;
  Vector2d p = from;
  for (int i = 0; i < max_steps; ++i) {
    const int t = mesh.locate(p);
    if (t < 0) {
      break;
    }
    // A slack triangle has no ray: keep the heading through it.
    if (solution.triangles[t].state != State::slack) {
      Vector2d v = solution.triangles[t].flat_direction;
      heading = v.dot(heading) < 0.0 ? Vector2d(-v) : v;
    }
    for (int s : mesh.support_nodes) {
      if ((mesh.nodes_mm[s] - p).norm() < step_mm) {
        points.push_back(mesh.nodes_mm[s]);
        return points;
      }
    }
    // Midpoint rule: the heading at half a step ahead, where the field may have turned.
    const int half = mesh.locate(p + 0.5 * step_mm * heading);
    if (half >= 0 && solution.triangles[half].state != State::slack) {
      const Vector2d v = solution.triangles[half].flat_direction;
      heading = v.dot(heading) < 0.0 ? Vector2d(-v) : v;
    }
    p += step_mm * heading;
    points.push_back(p);
  }
  if (!points.empty() && mesh.locate(points.back()) < 0) {
    points.pop_back();
  }
  return points;
}

}  // namespace

double SupportFrame::depth_mm(const Vector2d& p) const {
  const double s = (p.x() - left_mm.x()) / span_mm();
  return p.y() - (left_mm.y() + s * (right_mm.y() - left_mm.y()));
}

SupportFrame support_frame(const std::vector<Vector2d>& targets) {
  SupportFrame f{targets.front(), targets.front()};
  for (const Vector2d& t : targets) {
    if (t.x() < f.left_mm.x())
      f.left_mm = t;
    if (t.x() > f.right_mm.x())
      f.right_mm = t;
  }
  return f;
}

Vector2d hung_position(const Mesh& mesh, const Solution& solution, const Vector2d& p) {
  const int t = mesh.locate(p);
  if (t < 0) {
    return kOutside;
  }
  const Eigen::Vector3d b = mesh.barycentric(t, p);
  const auto& tri = mesh.triangles[t];
  return b[0] * solution.positions_mm[tri[0]] + b[1] * solution.positions_mm[tri[1]] +
         b[2] * solution.positions_mm[tri[2]];
}

CentreLine centre_line(const Mesh& mesh, const Solution& solution,
                       const std::vector<Vector2d>& targets) {
  if (targets.size() < 2 || !(support_frame(targets).span_mm() > 0.0)) {
    return {};
  }
  // The flat centre column: the flat point midway between the outermost supports' columns.
  double left_X = std::numeric_limits<double>::infinity();
  double right_X = -left_X;
  for (int s : mesh.support_nodes) {
    left_X = std::min(left_X, mesh.nodes_mm[s].x());
    right_X = std::max(right_X, mesh.nodes_mm[s].x());
  }
  return column_line(mesh, solution, 0.5 * (left_X + right_X), support_frame(targets));
}

CentreLine column_line(const Mesh& mesh, const Solution& solution, double flat_x_mm,
                       const SupportFrame& frame) {
  CentreLine out;
  double top = std::numeric_limits<double>::infinity();
  double bottom = -top;
  for (const Vector2d& n : mesh.nodes_mm) {
    top = std::min(top, n.y());
    bottom = std::max(bottom, n.y());
  }
  // Samples down the flat column with their hung depths.
  const int samples = 2000;
  for (int i = 0; i <= samples; ++i) {
    const Vector2d p(flat_x_mm, top + (bottom - top) * i / samples);
    const Vector2d q = hung_position(mesh, solution, p);
    if (std::isfinite(q.x())) {
      out.flat_mm.push_back(p);
      out.depth_mm.push_back(frame.depth_mm(q));
    }
  }
  return out;
}

namespace {

// `count` rays through the column `centre` (flat points with their depths below `frame`'s
// supports), each fitted to the cosine of `frame` and marked with `span`.
std::vector<Ray> rays_through(const Mesh& mesh, const Solution& solution, const CentreLine& centre,
                              const SupportFrame& frame, int count, int span) {
  std::vector<Ray> rays;
  const std::vector<Vector2d>& flat = centre.flat_mm;
  const std::vector<double>& depth = centre.depth_mm;
  if (flat.size() < 2 || count < 1 || !(frame.span_mm() > 0.0)) {
    return rays;
  }
  double top = std::numeric_limits<double>::infinity();
  double bottom = -top;
  for (const Vector2d& n : mesh.nodes_mm) {
    top = std::min(top, n.y());
    bottom = std::max(bottom, n.y());
  }
  double area = 0.0;
  for (const auto& tri : mesh.triangles) {
    const Vector2d u = mesh.nodes_mm[tri[1]] - mesh.nodes_mm[tri[0]];
    const Vector2d v = mesh.nodes_mm[tri[2]] - mesh.nodes_mm[tri[0]];
    area += 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
  }
  const double step_mm = 0.3 * std::sqrt(2.0 * area / static_cast<double>(mesh.triangles.size()));
  const double width = mesh.column_x_mm.back() - mesh.column_x_mm.front();
  const int max_steps = static_cast<int>(4.0 * (width + bottom - top) / step_mm);
  const double a_top = depth.front();
  const double a_bottom = depth.back();
  for (int k = 1; k <= count; ++k) {
    const double a = a_top + (a_bottom - a_top) * k / (count + 1);
    std::size_t i = 1;
    while (i + 1 < depth.size() && (depth[i] - a) * (depth[i - 1] - a) > 0.0) {
      ++i;
    }
    const double rise = depth[i] - depth[i - 1];
    const double s = rise != 0.0 ? std::clamp((a - depth[i - 1]) / rise, 0.0, 1.0) : 0.0;
    const Vector2d start = flat[i - 1] + s * (flat[i] - flat[i - 1]);
    std::vector<Vector2d> left =
        trace_one_way(mesh, solution, start, Vector2d(-1.0, 0.0), step_mm, max_steps);
    const std::vector<Vector2d> right =
        trace_one_way(mesh, solution, start, Vector2d(1.0, 0.0), step_mm, max_steps);
    std::reverse(left.begin(), left.end());
    left.push_back(start);
    left.insert(left.end(), right.begin(), right.end());
    Ray ray;
    ray.depth_mm = a;
    ray.span = span;
    double yc = 0.0;
    double cc = 0.0;
    std::vector<std::pair<double, double>> fitted;
    for (const Vector2d& p : left) {
      const Vector2d q = hung_position(mesh, solution, p);
      if (!std::isfinite(q.x())) {
        continue;
      }
      ray.points_mm.push_back(q);
      const double x = frame.x_mm(q);
      if (std::abs(x) <= 0.5 * frame.span_mm()) {
        const double c = std::cos(std::numbers::pi * x / frame.span_mm());
        const double y = frame.depth_mm(q);
        yc += y * c;
        cc += c * c;
        fitted.emplace_back(y, c);
      }
    }
    ray.fitted_amplitude_mm = cc > 0.0 ? yc / cc : 0.0;
    double squares = 0.0;
    for (const auto& [y, c] : fitted) {
      squares += std::pow(y - ray.fitted_amplitude_mm * c, 2);
    }
    ray.fitted_points = static_cast<int>(fitted.size());
    ray.fit_rms_mm = fitted.empty() ? 0.0 : std::sqrt(squares / static_cast<double>(fitted.size()));
    rays.push_back(std::move(ray));
  }
  return rays;
}

}  // namespace

std::vector<Ray> trace_rays(const Mesh& mesh, const Solution& solution,
                            const std::vector<Vector2d>& targets, int count) {
  if (targets.size() < 2 || count < 1) {
    return {};
  }
  const SupportFrame frame = support_frame(targets);
  if (!(frame.span_mm() > 0.0)) {
    return {};
  }
  return rays_through(mesh, solution, centre_line(mesh, solution, targets), frame, count, 0);
}

bool on_top_edge(const Outline& outline, const Vector2d& at_mm) {
  const double tolerance = 1e-6 * std::max(outline.right_mm() - outline.left_mm(), 1.0);
  // Distance to each segment, so that a point on a step of the edge (two vertices at one x)
  // counts as on it.
  for (std::size_t i = 1; i < outline.top_mm.size(); ++i) {
    const Vector2d a = outline.top_mm[i - 1];
    const Vector2d d = outline.top_mm[i] - a;
    const double length2 = d.squaredNorm();
    const double s = length2 > 0.0 ? std::clamp((at_mm - a).dot(d) / length2, 0.0, 1.0) : 0.0;
    if ((at_mm - (a + s * d)).norm() <= tolerance) {
      return true;
    }
  }
  return false;
}

std::vector<SupportSpan> top_spans(const Mesh& mesh, const Outline& outline) {
  std::vector<int> order;
  for (std::size_t i = 0; i < outline.supports.size() && i < mesh.support_nodes.size(); ++i) {
    if (on_top_edge(outline, outline.supports[i].at_mm)) {
      order.push_back(static_cast<int>(i));
    }
  }
  const auto to = [&](int i) -> const Vector2d& { return outline.supports[i].to_mm; };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return to(a).x() < to(b).x() || (to(a).x() == to(b).x() && to(a).y() < to(b).y());
  });
  std::erase_if(order, [&, previous = -std::numeric_limits<double>::infinity()](int i) mutable {
    const bool same_x = to(i).x() == previous;
    previous = to(i).x();
    return same_x;
  });
  std::vector<SupportSpan> spans;
  for (std::size_t k = 1; k < order.size(); ++k) {
    SupportSpan span;
    span.left_support = order[k - 1];
    span.right_support = order[k];
    span.frame = SupportFrame{to(span.left_support), to(span.right_support)};
    const double flat_left = mesh.nodes_mm[mesh.support_nodes[span.left_support]].x();
    const double flat_right = mesh.nodes_mm[mesh.support_nodes[span.right_support]].x();
    span.flat_x_mm = 0.5 * (flat_left + flat_right);
    spans.push_back(span);
  }
  return spans;
}

std::vector<int> rays_per_span(const std::vector<SupportSpan>& spans, int count) {
  std::vector<int> out(spans.size(), 0);
  if (count < 1 || spans.empty()) {
    return out;
  }
  if (spans.size() == 1) {
    out[0] = count;
    return out;
  }
  double total_mm = 0.0;
  for (const SupportSpan& s : spans) {
    total_mm += s.frame.span_mm();
  }
  std::vector<double> quota(spans.size());
  int given = 0;
  for (std::size_t i = 0; i < spans.size(); ++i) {
    quota[i] = total_mm > 0.0 ? count * spans[i].frame.span_mm() / total_mm
                              : static_cast<double>(count) / static_cast<double>(spans.size());
    out[i] = std::max(2, static_cast<int>(std::floor(quota[i])));
    given += out[i];
  }
  // Largest remainders first up to the count; back down from those most above their quota while
  // the floor of 2 lets them.
  while (given < count) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < spans.size(); ++i) {
      if (quota[i] - out[i] > quota[best] - out[best]) {
        best = i;
      }
    }
    ++out[best];
    ++given;
  }
  while (given > count) {
    std::size_t best = spans.size();
    for (std::size_t i = 0; i < spans.size(); ++i) {
      if (out[i] > 2 && (best == spans.size() || out[i] - quota[i] > out[best] - quota[best])) {
        best = i;
      }
    }
    if (best == spans.size()) {
      break;
    }
    --out[best];
    --given;
  }
  return out;
}

std::vector<Ray> trace_span_rays(const Mesh& mesh, const Solution& solution,
                                 const std::vector<SupportSpan>& spans, int count) {
  std::vector<Ray> rays;
  const std::vector<int> shares = rays_per_span(spans, count);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const SupportSpan& span = spans[i];
    if (!(span.frame.span_mm() > 0.0)) {
      continue;
    }
    const CentreLine centre = column_line(mesh, solution, span.flat_x_mm, span.frame);
    std::vector<Ray> these =
        rays_through(mesh, solution, centre, span.frame, shares[i], static_cast<int>(i));
    std::move(these.begin(), these.end(), std::back_inserter(rays));
  }
  return rays;
}

}  // namespace foldlab::field
