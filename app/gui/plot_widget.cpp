#include "app/gui/plot_widget.hpp"

#include "app/gui/appearance.hpp"
#include "app/gui/panels/widgets.hpp"

#include <imgui_internal.h>  // SetItemUsingMouseWheel: without it the window scrolls as we zoom

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>

namespace foldlab::gui {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kHoverRadius = 12.0f;
constexpr double kAutoscaleMargin = 0.05;
constexpr double kWheelZoom = 1.25;  // range factor per wheel notch
// Zooming further than this relative span only shows floating-point noise.
constexpr double kMinRelativeSpan = 1e-12;
constexpr double kMaxLinear = 1e300;
constexpr double kMaxLogExponent = 300;
constexpr float kMinWidth = 64.0f, kMinHeight = 48.0f;

// ImGuiStorage holds ints, floats and pointers only; a double takes two int slots so that the
// view survives deep zooms without float rounding.
enum Slot { kXLo = 0, kXHi = 2, kYLo = 4, kYHi = 6, kFlags = 8, kLabelWidth = 9, kSlotCount = 10 };
enum StateFlags { kHasRange = 1, kManualX = 2, kManualY = 4 };

// std::bit_cast, which the browser build's standard library (libc++ 14) does not have yet.
template <class To, class From>
To bits_as(const From& from) {
  static_assert(sizeof(To) == sizeof(From));
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

double load_double(const ImGuiStorage* st, const ImGuiID* keys, int slot) {
  const auto lo = bits_as<std::uint32_t>(st->GetInt(keys[slot]));
  const auto hi = bits_as<std::uint32_t>(st->GetInt(keys[slot + 1]));
  return bits_as<double>((std::uint64_t{hi} << 32) | lo);
}

void store_double(ImGuiStorage* st, const ImGuiID* keys, int slot, double v) {
  const auto bits = bits_as<std::uint64_t>(v);
  st->SetInt(keys[slot], bits_as<int>(static_cast<std::uint32_t>(bits)));
  st->SetInt(keys[slot + 1], bits_as<int>(static_cast<std::uint32_t>(bits >> 32)));
}

// Axis coordinate ("t"): the value itself, or its log10. Zoom, pan, margins and ticks work in t.
double to_t(double v, bool log) {
  if (!log)
    return v;
  return v > 0 ? std::log10(v) : kNaN;
}
double from_t(double t, bool log) {
  return log ? std::pow(10.0, t) : t;
}

// Linear map from t to one screen coordinate; px0 is where t0 lands, so flipping is just
// swapping the pixel ends.
struct AxisMap {
  double t0, t1, px0, scale;
  bool log;
  AxisMap(double lo_t, double hi_t, double px_lo, double px_hi, bool log_axis)
      : t0(lo_t), t1(hi_t), px0(px_lo), scale((px_hi - px_lo) / (hi_t - lo_t)), log(log_axis) {}
  double px_of_t(double t) const { return px0 + (t - t0) * scale; }
  double px(double v) const { return px_of_t(to_t(v, log)); }
  double t_at(double p) const { return t0 + (p - px0) / scale; }
};

AxisMap x_map(double t0, double t1, ImVec2 min, ImVec2 max, bool log, bool flipped) {
  return flipped ? AxisMap(t0, t1, max.x, min.x, log) : AxisMap(t0, t1, min.x, max.x, log);
}
// Screen y grows downward, so an unflipped axis puts t0 at the bottom.
AxisMap y_map(double t0, double t1, ImVec2 min, ImVec2 max, bool log, bool flipped) {
  return flipped ? AxisMap(t0, t1, min.y, max.y, log) : AxisMap(t0, t1, max.y, min.y, log);
}

struct Bounds {
  double lo = kInf, hi = -kInf;
  void add(double t) {
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  bool valid() const { return lo <= hi; }
};

double min_span(double t0, double t1) {
  return std::max({std::abs(t0), std::abs(t1), 1e-300}) * kMinRelativeSpan;
}

// Keeps a t-range finite, ordered and wide enough to map to pixels.
void sanitize(double& t0, double& t1, bool log) {
  const double limit = log ? kMaxLogExponent : kMaxLinear;
  t0 = std::clamp(t0, -limit, limit);
  t1 = std::clamp(t1, -limit, limit);
  if (t1 < t0)
    std::swap(t0, t1);
  const double need = min_span(t0, t1);
  if (t1 - t0 < need) {
    const double mid = t0 / 2 + t1 / 2;
    t0 = mid - need;
    t1 = mid + need;
  }
}

void fit(const Bounds& b, bool log, double& t0, double& t1) {
  if (!b.valid()) {
    t0 = 0;  // [0, 1], or [1, 10] on a log axis
    t1 = 1;
  } else if (b.hi - b.lo <= min_span(b.lo, b.hi)) {
    // All values equal: centre them in a range that still shows their magnitude.
    const double pad = log ? 0.5 : (b.lo == 0 ? 1.0 : std::abs(b.lo) * 0.1);
    t0 = b.lo - pad;
    t1 = b.hi + pad;
  } else {
    const double margin = (b.hi - b.lo) * kAutoscaleMargin;
    t0 = b.lo - margin;
    t1 = b.hi + margin;
  }
  sanitize(t0, t1, log);
}

double nice_step(double raw) {
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / mag;
  const double nice = norm < 1.5 ? 1 : norm < 3 ? 2 : norm < 7 ? 5 : 10;
  return nice * mag;
}

// k·m·10^e rounded once: dividing by an exact power of ten keeps 0.6 from becoming
// 0.6000000000000001, which would otherwise show up in the labels.
double scaled(double k, int e) {
  return e >= 0 ? k * std::pow(10.0, e) : k / std::pow(10.0, -e);
}

void nice_ticks_into(double lo, double hi, int target, std::vector<double>& out) {
  out.clear();
  if (!std::isfinite(lo) || !std::isfinite(hi))
    return;
  if (lo > hi)
    std::swap(lo, hi);
  if (lo == hi) {
    out.push_back(lo);
    return;
  }
  target = std::max(target, 1);
  // Divided first so that [-DBL_MAX, DBL_MAX] does not overflow.
  const double step = nice_step(hi / target - lo / target);
  if (!(step > 0) || !std::isfinite(step)) {
    out.push_back(lo);
    return;
  }
  const int e = static_cast<int>(std::floor(std::log10(step) + 1e-9));
  const double mantissa = std::round(step / std::pow(10.0, e));  // 1, 2, 5 or 10
  const double k0 = std::ceil(lo / step - 1e-9), k1 = std::floor(hi / step + 1e-9);
  // Beyond 2^53 consecutive k are no longer distinct doubles: the range is below resolution.
  if (!(std::abs(k0) < 1e15 && std::abs(k1) < 1e15) || k1 - k0 > 10.0 * target + 10) {
    out.push_back(lo);
    out.push_back(hi);
    return;
  }
  for (double k = k0; k <= k1; k += 1) {
    double v = scaled(k * mantissa, e);
    if (std::abs(v) < step * 1e-9)
      v = 0;
    if (out.empty() || v > out.back())
      out.push_back(v);
  }
}

void log_ticks_into(double lo, double hi, int target, std::vector<double>& out) {
  out.clear();
  if (!std::isfinite(lo) || !std::isfinite(hi))
    return;
  if (lo > hi)
    std::swap(lo, hi);
  if (hi <= 0)
    return;
  lo = std::max(lo, std::numeric_limits<double>::min());
  if (lo == hi) {
    out.push_back(lo);
    return;
  }
  target = std::max(target, 1);
  const double e0 = std::log10(lo), e1 = std::log10(hi);
  const auto inside = [&](double v) { return v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9); };
  const int d_first = static_cast<int>(std::floor(e0)), d_last = static_cast<int>(std::ceil(e1));

  // 1, 2, 5 per decade while that is not too many.
  const double limit = std::max(3.0, target * 1.5);
  int count = 0;
  for (int d = d_first; d <= d_last && count <= limit; ++d) {
    for (const double m : {1.0, 2.0, 5.0})
      count += inside(scaled(m, d)) ? 1 : 0;
  }
  if (count >= 2 && count <= limit) {
    for (int d = d_first; d <= d_last; ++d) {
      for (const double m : {1.0, 2.0, 5.0}) {
        if (inside(scaled(m, d)))
          out.push_back(scaled(m, d));
      }
    }
    return;
  }
  const int decades = static_cast<int>(std::floor(e1 + 1e-9) - std::ceil(e0 - 1e-9)) + 1;
  if (decades >= 2) {
    const int every = std::max(1, (decades + target - 1) / target);
    for (int d = d_first; d <= d_last; ++d) {
      if (((d % every) + every) % every == 0 && inside(scaled(1, d)))
        out.push_back(scaled(1, d));
    }
    if (out.size() >= 2)
      return;
    out.clear();
    for (int d = d_first; d <= d_last; ++d) {
      if (inside(scaled(1, d)))
        out.push_back(scaled(1, d));
    }
    return;
  }
  // Within about one decade the log scale is nearly linear: plain nice ticks read best.
  nice_ticks_into(lo, hi, target, out);
  std::erase_if(out, [](double v) { return !(v > 0); });
}

void format_tick_into(char* buf, std::size_t size, double value, double step) {
  step = std::abs(step);
  if (!std::isfinite(value)) {
    std::snprintf(buf, size, "%g", value);
    return;
  }
  if (!(step > 0) || !std::isfinite(step))
    step = value != 0 ? std::abs(value) : 1.0;
  if (std::abs(value) < step * 1e-6) {  // rounding noise, and -0
    std::snprintf(buf, size, "0");
    return;
  }
  const double mag = std::abs(value);
  const double step_exp = std::floor(std::log10(step) + 1e-9);
  if (mag >= 1e6 || mag < 1e-4) {
    const double digits = std::floor(std::log10(mag) + 1e-9) - step_exp + 1;
    const int decimals = static_cast<int>(std::clamp(digits - 1, 0.0, 15.0));
    std::snprintf(buf, size, "%.*e", decimals, value);
    // "1.50e+09" -> "1.5e+09": trailing zeros of the mantissa carry no information here.
    char* e = std::strchr(buf, 'e');
    if (e != nullptr && std::strchr(buf, '.') != nullptr) {
      char* end = e;
      while (end[-1] == '0')
        --end;
      if (end[-1] == '.')
        --end;
      std::memmove(end, e, std::strlen(e) + 1);
    }
    return;
  }
  const int decimals = static_cast<int>(std::clamp(-step_exp, 0.0, 15.0));
  std::snprintf(buf, size, "%.*f", decimals, value);
}

// The label step for tick i: its distance to the nearer neighbour, so that log ticks 1, 2, 5 get
// no decimals while linear ticks all share the same precision.
double tick_step(const std::vector<double>& ticks, std::size_t i) {
  double step = kInf;
  if (i > 0)
    step = std::min(step, ticks[i] - ticks[i - 1]);
  if (i + 1 < ticks.size())
    step = std::min(step, ticks[i + 1] - ticks[i]);
  if (std::isfinite(step))
    return step;
  // A lone tick has no neighbour to give its precision: the largest power of ten it is a whole
  // multiple of, so that 1.4 reads "1.4" and not "1".
  const double value = std::abs(ticks[i]);
  if (!(value > 0) || !std::isfinite(value))
    return 1.0;
  for (double power = std::pow(10.0, std::floor(std::log10(value))); power > value * 1e-12;
       power /= 10.0) {
    const double multiple = value / power;
    if (std::abs(multiple - std::round(multiple)) < 1e-9 * multiple)
      return power;
  }
  return value;
}

void axis_ticks(double t0, double t1, bool log, int target, std::vector<double>& out) {
  if (log)
    log_ticks_into(from_t(t0, true), from_t(t1, true), target, out);
  else
    nice_ticks_into(t0, t1, target, out);
}

// Liang-Barsky: clips segment a-b to the box; reports whether each end moved.
bool clip_segment(double& ax, double& ay, double& bx, double& by, const double box[4],
                  bool& a_moved, bool& b_moved) {
  const double dx = bx - ax, dy = by - ay;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {ax - box[0], box[2] - ax, ay - box[1], box[3] - ay};
  double u0 = 0, u1 = 1;
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0)
        return false;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0) {
      if (r > u1)
        return false;
      u0 = std::max(u0, r);
    } else {
      if (r < u0)
        return false;
      u1 = std::min(u1, r);
    }
  }
  a_moved = u0 > 0;
  b_moved = u1 < 1;
  const double x0 = ax, y0 = ay;
  if (b_moved) {
    bx = x0 + u1 * dx;
    by = y0 + u1 * dy;
  }
  if (a_moved) {
    ax = x0 + u0 * dx;
    ay = y0 + u0 * dy;
  }
  return true;
}

ImVec2 vec(double x, double y) {
  return ImVec2(static_cast<float>(x), static_cast<float>(y));
}

void draw_marker(ImDrawList* dl, ImVec2 c, float r, ImU32 col, MarkerShape shape) {
  constexpr float th = 1.5f;
  const float h = r * 0.7071f;  // half-diagonal of the cross, same extent as the circle
  switch (shape) {
    case MarkerShape::Circle:
      dl->AddCircle(c, r, col, 12, th);
      break;
    case MarkerShape::Square:
      dl->AddRect({c.x - r, c.y - r}, {c.x + r, c.y + r}, col, 0.0f, 0, th);
      break;
    case MarkerShape::Diamond:
      dl->AddQuad({c.x, c.y - r}, {c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}, col, th);
      break;
    case MarkerShape::Triangle:
      dl->AddTriangle({c.x, c.y - r}, {c.x + r * 0.866f, c.y + r * 0.5f},
                      {c.x - r * 0.866f, c.y + r * 0.5f}, col, th);
      break;
    case MarkerShape::Cross:
      dl->AddLine({c.x - h, c.y - h}, {c.x + h, c.y + h}, col, th);
      dl->AddLine({c.x - h, c.y + h}, {c.x + h, c.y - h}, col, th);
      break;
    case MarkerShape::Plus:
      dl->AddLine({c.x - r, c.y}, {c.x + r, c.y}, col, th);
      dl->AddLine({c.x, c.y - r}, {c.x, c.y + r}, col, th);
      break;
  }
}

struct Layout {
  ImVec2 min, max;
};

// Space around the data area: y tick labels on the left, x tick labels and the x title below,
// the y title above (horizontal text: ImGui cannot rotate it).
Layout layout(ImVec2 fmin, ImVec2 fmax, float y_label_width, bool x_title, bool y_title,
              float font) {
  const float pad = std::round(font * 0.35f);
  Layout l;
  l.min.x = fmin.x + y_label_width + 2 * pad;
  l.max.x = fmax.x - font;  // half of the last x tick label may stick out
  l.min.y = fmin.y + (y_title ? font + pad : std::round(font * 0.5f) + 1);
  l.max.y = fmax.y - (font + pad) - (x_title ? font + pad : 0);
  l.max.x = std::max(l.max.x, l.min.x + 1);
  l.max.y = std::max(l.max.y, l.min.y + 1);
  return l;
}

bool inside(ImVec2 p, ImVec2 min, ImVec2 max) {
  return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> out;
  nice_ticks_into(lo, hi, target, out);
  return out;
}

std::vector<double> log_ticks(double lo, double hi, int target) {
  std::vector<double> out;
  log_ticks_into(lo, hi, target, out);
  return out;
}

std::string format_tick(double value, double step) {
  char buf[64];
  format_tick_into(buf, sizeof buf, value, step);
  return buf;
}

AxisTicks fitted_ticks(double lo, double hi, bool log, double length_px,
                       const std::function<float(const std::string&)>& extent, float gap_px,
                       int max_ticks) {
  AxisTicks ticks;
  if (lo > hi)
    std::swap(lo, hi);
  const double t_lo = to_t(lo, log), t_hi = to_t(hi, log);
  const auto px = [&](double v) { return (to_t(v, log) - t_lo) / (t_hi - t_lo) * length_px; };
  char buf[64];
  for (int target = std::max(max_ticks, 1); target >= 1; --target) {
    ticks.values.clear();
    ticks.labels.clear();
    axis_ticks(t_lo, t_hi, log, target, ticks.values);
    for (std::size_t i = 0; i < ticks.values.size(); ++i) {
      format_tick_into(buf, sizeof buf, ticks.values[i], tick_step(ticks.values, i));
      ticks.labels.emplace_back(buf);
    }
    bool fits = true;
    for (std::size_t i = 1; i < ticks.values.size() && fits; ++i) {
      const double room = std::abs(px(ticks.values[i]) - px(ticks.values[i - 1]));
      fits = room >= 0.5 * (extent(ticks.labels[i]) + extent(ticks.labels[i - 1])) + gap_px;
    }
    // One label alone ("0") says nothing of the axis's span: the ends of a denser set below may.
    if (fits && ticks.values.size() >= 2)
      return ticks;
    if (ticks.values.size() <= 2)
      break;
  }
  // Not even two neighbours fit: the ends of a denser set, farther apart than any two
  // neighbours, so that the axis still reads from where to where (a 1300 mm cloth's -500 and 500
  // at 200 % text in a tile).
  for (int target = std::max(max_ticks, 3); target >= 3; --target) {
    AxisTicks dense;
    axis_ticks(t_lo, t_hi, log, target, dense.values);
    if (dense.values.size() < 3) {
      continue;
    }
    AxisTicks ends;
    for (const double v : {dense.values.front(), dense.values.back()}) {
      format_tick_into(buf, sizeof buf, v, dense.values[1] - dense.values[0]);
      ends.values.push_back(v);
      ends.labels.emplace_back(buf);
    }
    const double room = std::abs(px(ends.values[1]) - px(ends.values[0]));
    if (room >= 0.5 * (extent(ends.labels[0]) + extent(ends.labels[1])) + gap_px) {
      return ends;
    }
  }
  // Not even two labels fit: the one nearest the axis's middle alone.
  if (ticks.values.size() == 2) {
    const std::size_t keep = std::abs(px(ticks.values[0]) - 0.5 * length_px) <=
                                     std::abs(px(ticks.values[1]) - 0.5 * length_px)
                                 ? 0
                                 : 1;
    ticks.values = {ticks.values[keep]};
    ticks.labels = {ticks.labels[keep]};
  }
  return ticks;
}

std::vector<double> whole_ticks(double lo, double hi, double length_px,
                                const std::function<float(const std::string&)>& extent,
                                float gap_px, int max_ticks) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    return {};
  }
  if (lo > hi) {
    std::swap(lo, hi);
  }
  const double first = std::ceil(lo - 1e-9);
  const double last = std::floor(hi + 1e-9);
  if (first > last) {
    return {};
  }
  const double span = hi > lo ? hi - lo : 1.0;
  const auto px = [&](double v) { return (v - lo) / span * length_px; };
  const auto fit = [&](const std::vector<double>& ticks) {
    for (std::size_t i = 1; i < ticks.size(); ++i) {
      const std::string a = format_tick(ticks[i - 1], 1.0);
      const std::string b = format_tick(ticks[i], 1.0);
      if (px(ticks[i]) - px(ticks[i - 1]) < 0.5 * (extent(a) + extent(b)) + gap_px) {
        return false;
      }
    }
    return true;
  };
  std::vector<double> chosen;
  for (double decade = 1.0; decade <= 1e15 && chosen.empty(); decade *= 10.0) {
    for (const double m : {1.0, 2.0, 5.0}) {
      const double step = m * decade;
      std::vector<double> ticks;
      for (double v = std::ceil(first / step) * step; v <= last; v += step) {
        ticks.push_back(v);
      }
      if (ticks.empty()) {
        break;
      }
      if (static_cast<int>(ticks.size()) <= std::max(max_ticks, 3) && fit(ticks)) {
        chosen = std::move(ticks);
        break;
      }
    }
  }
  if (chosen.size() < 3 && last - first >= 2.0) {
    const std::vector<double> ends_and_middle = {first, std::round(0.5 * (first + last)), last};
    if (fit(ends_and_middle)) {
      return ends_and_middle;
    }
  }
  if (chosen.empty()) {
    chosen = {std::round(0.5 * (first + last))};
  }
  return chosen;
}

ImVec2 PlotView::to_screen(double x, double y) const {
  const AxisMap xm = x_map(to_t(x_lo, x_log), to_t(x_hi, x_log), min, max, x_log, x_flipped);
  const AxisMap ym = y_map(to_t(y_lo, y_log), to_t(y_hi, y_log), min, max, y_log, y_flipped);
  return vec(xm.px(x), ym.px(y));
}

std::pair<double, double> PlotView::to_data(ImVec2 screen) const {
  const AxisMap xm = x_map(to_t(x_lo, x_log), to_t(x_hi, x_log), min, max, x_log, x_flipped);
  const AxisMap ym = y_map(to_t(y_lo, y_log), to_t(y_hi, y_log), min, max, y_log, y_flipped);
  return {from_t(xm.t_at(screen.x), x_log), from_t(ym.t_at(screen.y), y_log)};
}

bool Plot::begin(const char* id, ImVec2 size, const PlotAxis& x, const PlotAxis& y) {
  open_ = false;
  autoscale_requested_ = false;
  series_.clear();
  legend_.clear();
  vlines_.clear();
  fit_x_.reset();
  grow_only_ = false;
  equal_scales_ = false;
  compact_ = false;
  legend_text_.clear();
  backdrop_ = nullptr;

  const ImVec2 avail = ImGui::GetContentRegionAvail();
  if (size.x <= 0)
    size.x = std::max(avail.x + size.x, kMinWidth);
  if (size.y <= 0)
    size.y = std::max(avail.y + size.y, kMinHeight);
  if (!ImGui::IsRectVisible(size)) {
    ImGui::Dummy(size);  // keeps the layout (and the scroll extent) the same as when visible
    return false;
  }

  ImGui::PushID(id);
  for (int i = 0; i < kSlotCount; ++i) {
    keys_[i] = ImGui::GetID(reinterpret_cast<const void*>(static_cast<std::uintptr_t>(i + 1)));
  }
  ImGui::PopID();

  ImGui::InvisibleButton(id, size);
  hovered_ = ImGui::IsItemHovered();
  active_ = ImGui::IsItemActive();
  double_clicked_ = hovered_ && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
  frame_min_ = ImGui::GetItemRectMin();
  frame_max_ = ImGui::GetItemRectMax();
  // In a panel that scrolls, the wheel scrolls the panel until the plot is clicked: a plot met
  // on the way down a panel must not catch the wheel. A click elsewhere gives the wheel back.
  if (hovered_ && (ImGui::IsMouseClicked(ImGuiMouseButton_Left) ||
                   ImGui::IsMouseClicked(ImGuiMouseButton_Right)))
    focused_ = true;
  else if (!hovered_ && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
    focused_ = false;
  in_scrolling_window_ = ImGui::GetScrollMaxY() > 0.0f;
  wheel_zooms_ = hovered_ && (focused_ || !in_scrolling_window_);
  if (wheel_zooms_)
    ImGui::SetItemUsingMouseWheel();
  if (!hovered_)
    wheel_hint_ = false;
  else if (ImGui::GetIO().MouseWheel != 0.0f && !wheel_zooms_)
    wheel_hint_ = true;
  // Keyed to the button's id (not a string) so that two plots in a window get two menus.
  if (ImGui::BeginPopupContextItem(nullptr)) {
    begin_touch_rows();
    if (ImGui::MenuItem("Autoscale"))
      autoscale_requested_ = true;
    end_touch_rows();
    ImGui::EndPopup();
  }

  x_axis_ = x;
  y_axis_ = y;
  open_ = true;
  return true;
}

std::size_t Plot::store_text(const char* text) {
  const std::size_t offset = legend_text_.size();
  legend_text_.append(text);
  legend_text_.push_back('\0');
  return offset;
}

void Plot::add_series(Kind kind, const char* legend, std::span<const double> xs,
                      std::span<const double> ys, ImU32 colour, float size, MarkerShape shape) {
  if (!open_)
    return;
  const std::size_t n = std::min(xs.size(), ys.size());
  int entry = -1;
  if (legend != nullptr && legend[0] != '\0') {
    for (std::size_t i = 0; i < legend_.size() && entry < 0; ++i) {
      if (std::strcmp(legend_text_.c_str() + legend_[i].text, legend) == 0) {
        entry = static_cast<int>(i);
      }
    }
    if (entry < 0) {
      entry = static_cast<int>(legend_.size());
      legend_.push_back({store_text(legend), kind, colour, shape});
    }
  }
  series_.push_back({kind, xs.first(n), ys.first(n), colour, size, shape, entry});
}

void Plot::line(const char* legend, std::span<const double> xs, std::span<const double> ys,
                ImU32 colour, float thickness) {
  add_series(Kind::Line, legend, xs, ys, colour, thickness, MarkerShape::Circle);
}

void Plot::steps(const char* legend, std::span<const double> xs, std::span<const double> ys,
                 ImU32 colour, float thickness) {
  add_series(Kind::Steps, legend, xs, ys, colour, thickness, MarkerShape::Circle);
}

void Plot::markers(const char* legend, std::span<const double> xs, std::span<const double> ys,
                   ImU32 colour, MarkerShape shape, float radius) {
  add_series(Kind::Markers, legend, xs, ys, colour, radius, shape);
}

void Plot::vertical_line(double x, ImU32 colour, const char* label) {
  if (!open_)
    return;
  const std::size_t text =
      (label != nullptr && label[0] != '\0') ? store_text(label) : std::string::npos;
  vlines_.push_back({x, colour, text});
}

constexpr float kShortestSegmentPx = 3.0f;

// Draws path_ (screen coordinates, NaN = gap) as polylines, cut to the clip box grown by the
// line width. ImGui's clip rect alone would hide the overhang, but far-off vertices would still
// be emitted, and zoomed-in coordinates can exceed what float vertices represent.
void Plot::stroke(ImDrawList* dl, ImU32 colour, float thickness, ImVec2 clip_min, ImVec2 clip_max) {
  const double pad = thickness + 1.0;
  const double box[4] = {clip_min.x - pad, clip_min.y - pad, clip_max.x + pad, clip_max.y + pad};
  screen_.clear();
  const auto flush = [&] {
    if (screen_.size() >= 2) {
      dl->AddPolyline(screen_.data(), static_cast<int>(screen_.size()), colour, ImDrawFlags_None,
                      thickness);
    }
    screen_.clear();
  };
  for (std::size_t i = 1; i < path_.size(); ++i) {
    double ax = path_[i - 1].x, ay = path_[i - 1].y, bx = path_[i].x, by = path_[i].y;
    bool a_moved = false, b_moved = false;
    if (!(std::isfinite(ax) && std::isfinite(ay) && std::isfinite(bx) && std::isfinite(by)) ||
        !clip_segment(ax, ay, bx, by, box, a_moved, b_moved)) {
      flush();
      continue;
    }
    if (a_moved)
      flush();
    if (screen_.empty())
      screen_.push_back(vec(ax, ay));
    // A zero-length segment has no direction and pinches the anti-aliased joint around it. A
    // point closer than kShortestSegmentPx to the one before that is replaced by the next: a
    // software rasterizer pays for each segment, and a dense curve loses nothing a pixel shows
    // (each kept point is on the curve, the run's ends are kept).
    const ImVec2 b = vec(bx, by);
    const std::size_t n = screen_.size();
    const bool repeated = b.x == screen_.back().x && b.y == screen_.back().y;
    const bool last_is_short =
        n >= 2 && std::hypot(screen_[n - 1].x - screen_[n - 2].x,
                             screen_[n - 1].y - screen_[n - 2].y) < kShortestSegmentPx;
    if (repeated) {
      // nothing to add
    } else if (last_is_short) {
      screen_.back() = b;
    } else {
      screen_.push_back(b);
    }
    if (b_moved)
      flush();
  }
  flush();
}

// What end() works out, step by step: the visible range, the legend's and the axes' layout, the
// ticks, and the maps from data to screen that the drawing steps share.
struct Plot::Frame {
  ImGuiStorage* storage = nullptr;
  ImDrawList* draw_list = nullptr;
  const ImGuiIO* io = nullptr;
  float font = 0;
  float swatch = 0, row = 0, pad = 0;  // legend swatch width, legend row height, padding
  float weight = 1;                    // lines and markers grow with the text, never thinner
  bool x_log = false, y_log = false;
  bool x_title = false, y_title = false;
  bool x_title_row = false;  // the x title on a row of its own under the tick labels
  double xt0 = 0, xt1 = 1, yt0 = 0, yt1 = 1;  // the visible range in axis coordinates
  bool manual_x = false, manual_y = false;    // the user zoomed or panned that axis
  ImVec2 axes_max{0, 0};                      // the frame's bottom right above the legend
  float label_width = 0;                      // of the y tick labels
  Layout lay{};
  AxisMap xm{0, 1, 0, 1, false}, ym{0, 1, 0, 1, false};
  ImU32 col_grid = 0, col_border = 0, col_text = 0;
};

std::optional<PlotHit> Plot::end() {
  if (!open_)
    return std::nullopt;
  open_ = false;

  Frame f;
  f.storage = ImGui::GetStateStorage();
  f.draw_list = ImGui::GetWindowDrawList();
  f.io = &ImGui::GetIO();
  f.font = ImGui::GetFontSize();
  f.swatch = f.font * 1.6f;
  // A series' size is given for the usual text size: at 200 % for a room, or in a picture of a
  // few thousand pixels, a 2 px line would be a hair beside the text.
  f.weight = std::max(1.0f, f.font / kUiFontPx);
  f.row = f.font + 2;
  f.pad = std::round(f.font * 0.35f);
  f.x_log = x_axis_.log;
  f.y_log = y_axis_.log;
  f.x_title = !x_axis_.label.empty();
  f.y_title = !y_axis_.label.empty();
  f.x_title_row = f.x_title && !compact_;

  fit_view_range(f);
  lay_out_legend(f);
  zoom_and_pan(f);
  place_ticks(f);
  publish_view(f);

  f.col_grid = ImGui::GetColorU32(ImGuiCol_Text, 0.12f);
  f.col_border = ImGui::GetColorU32(ImGuiCol_Border);
  f.col_text = ImGui::GetColorU32(ImGuiCol_Text);
  draw_background_and_grid(f);
  f.draw_list->PushClipRect(f.lay.min, f.lay.max, true);
  draw_series(f);
  draw_vertical_lines(f);
  const std::optional<PlotHit> hit = hover(f);
  f.draw_list->PopClipRect();
  f.draw_list->AddRect(f.lay.min, f.lay.max, f.col_border);
  draw_tick_labels_and_titles(f);
  draw_legend(f);
  draw_wheel_state(f);
  store_view_state(f);
  return hit;
}

// The view range: stored (the user zoomed or panned) or fitted to the data.
void Plot::fit_view_range(Frame& f) const {
  int flags = f.storage->GetInt(keys_[kFlags], 0);
  if (autoscale_requested_ || double_clicked_)
    flags &= ~(kManualX | kManualY);
  f.manual_x = (flags & kHasRange) && (flags & kManualX);
  f.manual_y = (flags & kHasRange) && (flags & kManualY);
  if (f.manual_x) {
    f.xt0 = to_t(load_double(f.storage, keys_, kXLo), f.x_log);
    f.xt1 = to_t(load_double(f.storage, keys_, kXHi), f.x_log);
    f.manual_x = std::isfinite(f.xt0) && std::isfinite(f.xt1) && f.xt0 < f.xt1;
  }
  if (f.manual_y) {
    f.yt0 = to_t(load_double(f.storage, keys_, kYLo), f.y_log);
    f.yt1 = to_t(load_double(f.storage, keys_, kYHi), f.y_log);
    f.manual_y = std::isfinite(f.yt0) && std::isfinite(f.yt1) && f.yt0 < f.yt1;
  }
  if (f.manual_x && f.manual_y)
    return;
  // With one axis fixed by the user, fit the other to what is visible of the data; all of it
  // when no sample is visible (zoomed in between two samples).
  Bounds bx, by, all_x, all_y;
  for (const Series& s : series_) {
    for (std::size_t i = 0; i < s.xs.size(); ++i) {
      const double tx = to_t(s.xs[i], f.x_log), ty = to_t(s.ys[i], f.y_log);
      if (!std::isfinite(tx) || !std::isfinite(ty))
        continue;
      all_x.add(tx);
      all_y.add(ty);
      if (f.manual_x && (tx < f.xt0 || tx > f.xt1))
        continue;
      if (f.manual_y && (ty < f.yt0 || ty > f.yt1))
        continue;
      bx.add(tx);
      by.add(ty);
    }
  }
  for (const VLine& v : vlines_) {
    const double tx = to_t(v.x, f.x_log);
    if (std::isfinite(tx))
      bx.add(tx);
  }
  if (fit_x_) {
    for (const double x : {fit_x_->first, fit_x_->second}) {
      if (const double tx = to_t(x, f.x_log); std::isfinite(tx))
        bx.add(tx);
    }
  }
  if (!f.manual_x)
    fit(bx.valid() ? bx : all_x, f.x_log, f.xt0, f.xt1);
  if (!f.manual_y)
    fit(by.valid() ? by : all_y, f.y_log, f.yt0, f.yt1);
  if (grow_only_ && (flags & kHasRange)) {
    const auto widen = [](double& t0, double& t1, double lo, double hi, bool log) {
      const double last0 = to_t(lo, log), last1 = to_t(hi, log);
      if (std::isfinite(last0) && std::isfinite(last1)) {
        t0 = std::min(t0, last0);
        t1 = std::max(t1, last1);
      }
    };
    if (!f.manual_x)
      widen(f.xt0, f.xt1, view_.x_lo, view_.x_hi, f.x_log);
    if (!f.manual_y)
      widen(f.yt0, f.yt1, view_.y_lo, view_.y_hi, f.y_log);
  }
}

// The legend: rows under the x title, outside the data area, so that it never hides data.
void Plot::lay_out_legend(Frame& f) {
  legend_rows_.clear();
  if (compact_) {
    // One entry a row, laid over the data area's bottom right corner by draw_legend.
    for (std::size_t i = 0; i < legend_.size(); ++i) {
      const float w =
          f.swatch + f.pad + ImGui::CalcTextSize(legend_text_.c_str() + legend_[i].text).x;
      legend_rows_.push_back({0.0f, static_cast<float>(i) * f.row, w});
    }
    legend_height_ = 0.0f;
    f.axes_max = frame_max_;
    return;
  }
  const float frame_w = frame_max_.x - frame_min_.x;
  float x = 0;
  int rows = legend_.empty() ? 0 : 1;
  for (const LegendEntry& e : legend_) {
    const float w = f.swatch + f.pad + ImGui::CalcTextSize(legend_text_.c_str() + e.text).x;
    if (x > 0 && x + w > frame_w) {
      ++rows;
      x = 0;
    }
    legend_rows_.push_back({x, static_cast<float>(rows - 1) * f.row, w});
    x += w + 2 * f.font;
  }
  legend_height_ = rows > 0 ? static_cast<float>(rows) * f.row + f.pad : 0.0f;
  // A plot too short for its titles, tick labels, two lines of data and the legend drops the
  // legend rather than draw it over the x labels (the tooltip still names each series).
  const float axes_need = (f.y_title ? f.font + f.pad : f.font / 2) + (f.font + f.pad) +
                          (f.x_title ? f.font + f.pad : 0.0f) + 2 * f.font;
  if (frame_max_.y - frame_min_.y - legend_height_ < axes_need) {
    legend_rows_.clear();
    legend_height_ = 0.0f;
  }
  f.axes_max = {frame_max_.x, std::max(frame_min_.y + 1, frame_max_.y - legend_height_)};
}

// Wheel zoom and drag pan, in the layout the user saw last frame.
void Plot::zoom_and_pan(Frame& f) const {
  f.label_width = f.storage->GetFloat(keys_[kLabelWidth], 0.0f);
  f.lay = layout(frame_min_, f.axes_max, f.label_width, f.x_title_row, f.y_title, f.font);
  if (wheel_zooms_ && f.io->MouseWheel != 0)
    wheel_zoom(f);
  if (active_)
    drag_pan(f);
}

// Around the cursor; Shift zooms x only, Ctrl y only.
void Plot::wheel_zoom(Frame& f) const {
  const ImGuiIO& io = *f.io;
  const bool zoom_x = !(io.KeyCtrl && !io.KeyShift), zoom_y = !(io.KeyShift && !io.KeyCtrl);
  const double factor = std::pow(kWheelZoom, -static_cast<double>(io.MouseWheel));
  const auto zoom = [factor](double& t0, double& t1, double c, bool log) {
    double n0 = c + (t0 - c) * factor, n1 = c + (t1 - c) * factor;
    if (n1 - n0 < min_span(n0, n1))
      return;  // as far in as is meaningful
    sanitize(n0, n1, log);
    t0 = n0;
    t1 = n1;
  };
  if (zoom_x) {
    const AxisMap m = x_map(f.xt0, f.xt1, f.lay.min, f.lay.max, f.x_log, x_axis_.flipped);
    zoom(f.xt0, f.xt1, m.t_at(io.MousePos.x), f.x_log);
    f.manual_x = true;
  }
  if (zoom_y) {
    const AxisMap m = y_map(f.yt0, f.yt1, f.lay.min, f.lay.max, f.y_log, y_axis_.flipped);
    zoom(f.yt0, f.yt1, m.t_at(io.MousePos.y), f.y_log);
    f.manual_y = true;
  }
}

void Plot::drag_pan(Frame& f) const {
  const ImGuiIO& io = *f.io;
  // Only real motion counts, so that the clicks of a double-click do not end autoscale.
  if (io.MouseDelta.x != 0) {
    const AxisMap m = x_map(f.xt0, f.xt1, f.lay.min, f.lay.max, f.x_log, x_axis_.flipped);
    const double dt = -io.MouseDelta.x / m.scale;
    f.xt0 += dt;
    f.xt1 += dt;
    sanitize(f.xt0, f.xt1, f.x_log);
    f.manual_x = true;
  }
  if (io.MouseDelta.y != 0) {
    const AxisMap m = y_map(f.yt0, f.yt1, f.lay.min, f.lay.max, f.y_log, y_axis_.flipped);
    const double dt = -io.MouseDelta.y / m.scale;
    f.yt0 += dt;
    f.yt1 += dt;
    sanitize(f.yt0, f.yt1, f.y_log);
    f.manual_y = true;
  }
}

namespace {

// The smallest step of 1, 2 or 5 times a power of ten whose labels ("-500" beside "0"), `scale`
// px a unit apart, keep half a font's height apart, as fitted_ticks asks of them.
double least_tick_step(double scale, float font) {
  const float zero_px = ImGui::CalcTextSize("0").x;
  for (double decade = 1e-3; decade < 1e12; decade *= 10.0) {
    for (const double mantissa : {1.0, 2.0, 5.0}) {
      const double step = mantissa * decade;
      char label[32];
      std::snprintf(label, sizeof label, "%g", -step);
      if (step * scale >= 0.5 * (ImGui::CalcTextSize(label).x + zero_px) + 0.5 * font) {
        return step;
      }
    }
  }
  return 1e12;
}

}  // namespace

void Plot::equalise_scales(Frame& f) const {
  if (!equal_scales_ || f.x_log || f.y_log) {
    return;
  }
  const double width_px = f.lay.max.x - f.lay.min.x;
  const double height_px = f.lay.max.y - f.lay.min.y;
  const double x_scale = width_px / (f.xt1 - f.xt0);
  const double y_scale = height_px / (f.yt1 - f.yt0);
  const auto widen = [](double& t0, double& t1, double half) {
    const double centre = 0.5 * (t0 + t1);
    t0 = centre - half;
    t1 = centre + half;
  };
  if (x_scale > y_scale && narrow_frame_) {
    // No narrower than three ticks need, at the smallest round step whose labels do not meet at
    // this scale: a cloth much taller than wide would leave room for one, "0", and the x axis
    // would say nothing of its width. What that adds shows more of the paper beside the cloth.
    const float keep_px = static_cast<float>(
        std::max(std::min(width_px, 3.0 * least_tick_step(y_scale, f.font) * y_scale),
                 y_scale * (f.xt1 - f.xt0)));
    const float centre = 0.5f * (f.lay.min.x + f.lay.max.x);
    f.lay.min.x = std::floor(centre - 0.5f * keep_px);
    f.lay.max.x = std::ceil(centre + 0.5f * keep_px);
    widen(f.xt0, f.xt1, 0.5 * (f.lay.max.x - f.lay.min.x) / y_scale);
  } else if (x_scale > y_scale) {
    widen(f.xt0, f.xt1, 0.5 * width_px / y_scale);
  } else {
    widen(f.yt0, f.yt1, 0.5 * height_px / x_scale);
  }
}

// The ticks, the y tick labels' width and with it the final layout and the maps to the screen.
// Equal scales are set in the layout before the ticks and again in the final one, whose y labels
// may be wider.
void Plot::place_ticks(Frame& f) {
  equalise_scales(f);
  const float plot_h = f.lay.max.y - f.lay.min.y;
  const float gap = f.font * 0.5f;
  const auto line_height = [&f](const std::string&) { return f.font; };
  // A count's ticks between whole numbers (2.5 iterates) mean nothing.
  const auto ticks_for = [](const PlotAxis& axis, double lo, double hi, bool log, float length,
                            const std::function<float(const std::string&)>& extent, float gap_px,
                            int max_ticks) {
    return axis.whole && !log ? whole_ticks(lo, hi, length, extent, gap_px, max_ticks)
                              : fitted_ticks(lo, hi, log, length, extent, gap_px, max_ticks).values;
  };
  y_ticks_ =
      ticks_for(y_axis_, from_t(f.yt0, f.y_log), from_t(f.yt1, f.y_log), f.y_log, plot_h,
                line_height, gap, std::clamp(static_cast<int>(plot_h / (f.font * 2.0f)), 2, 12));
  float needed = 0;
  char buf[64];
  for (std::size_t i = 0; i < y_ticks_.size(); ++i) {
    format_tick_into(buf, sizeof buf, y_ticks_[i], tick_step(y_ticks_, i));
    needed = std::max(needed, ImGui::CalcTextSize(buf).x);
  }
  label_width_needed_ = needed;
  if (min_label_width_ > 0.0f) {
    f.label_width = std::max(needed, min_label_width_);  // shared with the plots beside it
  } else if (needed > f.label_width || needed < f.label_width - f.font) {
    // Hysteresis: a label width that flickers by a digit would make the whole plot jitter.
    f.label_width = needed;
  }
  f.lay = layout(frame_min_, f.axes_max, f.label_width, f.x_title_row, f.y_title, f.font);
  equalise_scales(f);
  const float plot_w = f.lay.max.x - f.lay.min.x;
  const auto text_width = [](const std::string& label) {
    return ImGui::CalcTextSize(label.c_str()).x;
  };
  x_ticks_ =
      ticks_for(x_axis_, from_t(f.xt0, f.x_log), from_t(f.xt1, f.x_log), f.x_log, plot_w,
                text_width, gap, std::clamp(static_cast<int>(plot_w / (f.font * 2.5f)), 2, 12));
  f.xm = x_map(f.xt0, f.xt1, f.lay.min, f.lay.max, f.x_log, x_axis_.flipped);
  f.ym = y_map(f.yt0, f.yt1, f.lay.min, f.lay.max, f.y_log, y_axis_.flipped);
}

// The view, for the backdrop and the caller.
void Plot::publish_view(const Frame& f) {
  view_.min = f.lay.min;
  view_.max = f.lay.max;
  view_.x_lo = from_t(f.xt0, f.x_log);
  view_.x_hi = from_t(f.xt1, f.x_log);
  view_.y_lo = from_t(f.yt0, f.y_log);
  view_.y_hi = from_t(f.yt1, f.y_log);
  view_.x_log = f.x_log;
  view_.y_log = f.y_log;
  view_.x_flipped = x_axis_.flipped;
  view_.y_flipped = y_axis_.flipped;
  view_.x_auto = !f.manual_x;
  view_.y_auto = !f.manual_y;
  view_.legend_entries = static_cast<int>(legend_.size());
}

// The data area's background, the caller's backdrop over it, and the grid lines at the ticks.
void Plot::draw_background_and_grid(const Frame& f) const {
  ImDrawList* dl = f.draw_list;
  const ImU32 col_grid = f.col_grid;
  dl->AddRectFilled(f.lay.min, f.lay.max, ImGui::GetColorU32(ImGuiCol_FrameBg));
  if (backdrop_) {
    dl->PushClipRect(f.lay.min, f.lay.max, true);
    backdrop_(dl, view_);
    dl->PopClipRect();
  }
  for (const double v : x_ticks_) {
    const float px = static_cast<float>(f.xm.px(v));
    dl->AddLine({px, f.lay.min.y}, {px, f.lay.max.y}, col_grid);
  }
  for (const double v : y_ticks_) {
    const float py = static_cast<float>(f.ym.px(v));
    dl->AddLine({f.lay.min.x, py}, {f.lay.max.x, py}, col_grid);
  }
}

// Every series in its submission order: markers one by one, lines and steps as polylines.
void Plot::draw_series(const Frame& f) {
  for (const Series& s : series_) {
    if (s.kind == Kind::Markers) {
      draw_markers(f, s);
      continue;
    }
    if (s.kind == Kind::Line)
      line_path(f, s);
    else
      steps_path(f, s);
    stroke(f.draw_list, s.colour, s.size * f.weight, f.lay.min, f.lay.max);
  }
}

void Plot::draw_markers(const Frame& f, const Series& s) const {
  const double size = s.size * f.weight;
  for (std::size_t i = 0; i < s.xs.size(); ++i) {
    const double px = f.xm.px(s.xs[i]), py = f.ym.px(s.ys[i]);
    if (!(px >= f.lay.min.x - size && px <= f.lay.max.x + size && py >= f.lay.min.y - size &&
          py <= f.lay.max.y + size)) {
      continue;  // also skips NaN
    }
    draw_marker(f.draw_list, vec(px, py), static_cast<float>(size), s.colour, s.shape);
  }
}

// A line's samples on screen, into path_.
void Plot::line_path(const Frame& f, const Series& s) {
  const AxisMap xm = f.xm, ym = f.ym;  // copies: path_'s writes cannot alias them
  path_.clear();
  for (std::size_t i = 0; i < s.xs.size(); ++i)
    path_.push_back({xm.px(s.xs[i]), ym.px(s.ys[i])});
}

// A step function on screen, into path_: each sample's value held from half-way to the sample
// before to half-way to the next (to the sample itself beside a gap or at an end).
void Plot::steps_path(const Frame& f, const Series& s) {
  const AxisMap xm = f.xm, ym = f.ym;
  path_.clear();
  const std::size_t n = s.xs.size();
  const auto px_at = [&](std::size_t i) {
    const double px = xm.px(s.xs[i]);
    return std::isfinite(px) && std::isfinite(ym.px(s.ys[i])) ? px : kNaN;
  };
  double prev = kNaN, cur = n > 0 ? px_at(0) : kNaN;
  for (std::size_t i = 0; i < n; ++i) {
    const double next = i + 1 < n ? px_at(i + 1) : kNaN;
    if (std::isnan(cur)) {
      path_.push_back({kNaN, kNaN});
    } else {
      const double py = ym.px(s.ys[i]);
      path_.push_back({std::isnan(prev) ? cur : (prev + cur) / 2, py});
      path_.push_back({std::isnan(next) ? cur : (cur + next) / 2, py});
    }
    prev = cur;
    cur = next;
  }
}

void Plot::draw_vertical_lines(const Frame& f) const {
  for (const VLine& v : vlines_) {
    const double px = f.xm.px(v.x);
    if (!(px >= f.lay.min.x && px <= f.lay.max.x))
      continue;
    const float fx = static_cast<float>(px);
    f.draw_list->AddLine({fx, f.lay.min.y}, {fx, f.lay.max.y}, v.colour, 1.5f * f.weight);
    if (v.text != std::string::npos) {
      f.draw_list->AddText({fx + f.pad, f.lay.min.y + f.pad}, v.colour,
                           legend_text_.c_str() + v.text);
    }
  }
}

// The point nearest to the mouse, highlighted and shown in a tooltip; none while dragging.
std::optional<PlotHit> Plot::hover(const Frame& f) const {
  const ImGuiIO& io = *f.io;
  if (!hovered_ || (active_ && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) ||
      !inside(io.MousePos, f.lay.min, f.lay.max)) {
    return std::nullopt;
  }
  const std::optional<PlotHit> hit = nearest_point(f, io.MousePos);
  if (hit)
    show_hit(f, *hit);
  return hit;
}

// Nearest on screen, not in data units, since the axes' scales differ.
std::optional<PlotHit> Plot::nearest_point(const Frame& f, ImVec2 mouse) const {
  const AxisMap xm = f.xm, ym = f.ym;
  std::optional<PlotHit> hit;
  double best = static_cast<double>(kHoverRadius) * kHoverRadius;
  for (std::size_t si = 0; si < series_.size(); ++si) {
    const Series& s = series_[si];
    for (std::size_t i = 0; i < s.xs.size(); ++i) {
      const double dx = xm.px(s.xs[i]) - mouse.x, dy = ym.px(s.ys[i]) - mouse.y;
      const double d2 = dx * dx + dy * dy;
      if (d2 < best) {  // false for NaN
        best = d2;
        hit = PlotHit{static_cast<int>(si), static_cast<int>(i), s.xs[i], s.ys[i]};
      }
    }
  }
  return hit;
}

void Plot::show_hit(const Frame& f, const PlotHit& hit) const {
  const Series& s = series_[static_cast<std::size_t>(hit.series)];
  const ImVec2 p = vec(f.xm.px(hit.x), f.ym.px(hit.y));
  f.draw_list->AddCircleFilled(p, 3.5f, s.colour, 12);
  f.draw_list->AddCircle(p, 7.0f, f.col_text, 16, 1.5f);
  ImGui::BeginTooltip();
  if (s.legend >= 0) {
    ImGui::TextUnformatted(legend_text_.c_str() + legend_[static_cast<std::size_t>(s.legend)].text);
  }
  const auto value_line = [](const PlotAxis& axis, bool titled, const char* name, double value) {
    if (axis.value_text) {
      ImGui::TextUnformatted(axis.value_text(value).c_str());
    } else {
      ImGui::Text("%s: %.6g", titled ? axis.label.c_str() : name, value);
    }
  };
  value_line(x_axis_, f.x_title, "x", hit.x);
  value_line(y_axis_, f.y_title, "y", hit.y);
  ImGui::EndTooltip();
}

// Compact, the x title ends where the data area starts (under the y tick labels), however far
// a frame narrowed to its data (equal scales) leaves that from the frame's left edge.
float Plot::compact_x_title_left(const Frame& f) const {
  const float width = ImGui::CalcTextSize(x_axis_.label.c_str()).x;
  return std::max(frame_min_.x, f.lay.min.x - f.pad - width);
}

// Tick labels and titles may use the whole frame but not spill onto neighbouring widgets.
void Plot::draw_tick_labels_and_titles(const Frame& f) const {
  f.draw_list->PushClipRect(frame_min_, frame_max_, true);
  draw_x_tick_labels(f);
  draw_y_tick_labels(f);
  const ImU32 col_text = f.col_text;
  // A title wider than the axes (equal scales make a tall cloth's plot narrow) moves over the
  // tick labels' side rather than past the frame's edge.
  const auto within_frame = [this](float left, float width) {
    return std::max(frame_min_.x, std::min(left, frame_max_.x - width));
  };
  if (f.x_title_row) {
    const float w = ImGui::CalcTextSize(x_axis_.label.c_str()).x;
    f.draw_list->AddText({within_frame((f.lay.min.x + f.lay.max.x - w) / 2, w),
                          f.lay.max.y + f.pad + f.font + f.pad / 2},
                         col_text, x_axis_.label.c_str());
  } else if (f.x_title) {
    f.draw_list->AddText({compact_x_title_left(f), f.lay.max.y + f.pad}, col_text,
                         x_axis_.label.c_str());
  }
  // Above the axis rather than beside the tick labels, where the top label could collide.
  if (f.y_title) {
    const float w = ImGui::CalcTextSize(y_axis_.label.c_str()).x;
    f.draw_list->AddText({within_frame(f.lay.min.x, w), frame_min_.y}, col_text,
                         y_axis_.label.c_str());
  }
  f.draw_list->PopClipRect();
}

// Tick marks below the axis, and the labels that do not overlap the one drawn before.
void Plot::draw_x_tick_labels(const Frame& f) const {
  const ImU32 col_border = f.col_border, col_text = f.col_text;
  char buf[64];
  float edge = 0;  // screen edge of the last drawn x label, facing the next one
  // The x title at the row's left end (compact) keeps its place: a label it would meet is left
  // out.
  const float title_end =
      f.x_title && !f.x_title_row
          ? compact_x_title_left(f) + ImGui::CalcTextSize(x_axis_.label.c_str()).x
          : -std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < x_ticks_.size(); ++i) {
    const float px = static_cast<float>(f.xm.px(x_ticks_[i]));
    f.draw_list->AddLine({px, f.lay.max.y}, {px, f.lay.max.y + f.pad}, col_border);
    format_tick_into(buf, sizeof buf, x_ticks_[i], tick_step(x_ticks_, i));
    const float w = ImGui::CalcTextSize(buf).x;
    const float left = px - w / 2, right = px + w / 2, gap = f.font * 0.5f;
    if (left < title_end + gap)
      continue;
    // Ticks ascend in value, which runs right to left on a flipped axis.
    const bool overlaps = i > 0 && (x_axis_.flipped ? right > edge - gap : left < edge + gap);
    if (overlaps)
      continue;
    f.draw_list->AddText({left, f.lay.max.y + f.pad}, col_text, buf);
    edge = x_axis_.flipped ? left : right;
  }
}

void Plot::draw_y_tick_labels(const Frame& f) const {
  const ImU32 col_border = f.col_border, col_text = f.col_text;
  char buf[64];
  for (std::size_t i = 0; i < y_ticks_.size(); ++i) {
    const float py = static_cast<float>(f.ym.px(y_ticks_[i]));
    f.draw_list->AddLine({f.lay.min.x - f.pad, py}, {f.lay.min.x, py}, col_border);
    format_tick_into(buf, sizeof buf, y_ticks_[i], tick_step(y_ticks_, i));
    const ImVec2 sz = ImGui::CalcTextSize(buf);
    f.draw_list->AddText({f.lay.min.x - f.pad - sz.x, py - sz.y / 2}, col_text, buf);
  }
}

// Legend entries flow left to right below the axes, centred when they fit on one row.
void Plot::draw_legend(const Frame& f) {
  view_.legend_min = view_.legend_max = ImVec2(frame_min_.x, f.axes_max.y);
  if (legend_rows_.empty())
    return;
  float widest = 0;
  for (const LegendRow& r : legend_rows_) {
    widest = std::max(widest, r.x + r.width);
  }
  float left =
      legend_rows_.back().y == 0 ? (frame_min_.x + frame_max_.x - widest) / 2 : frame_min_.x;
  float top = f.axes_max.y + f.pad;
  const ImU32 col_text = f.col_text;
  ImDrawList* dl = f.draw_list;
  if (compact_) {
    const float height = legend_rows_.back().y + f.row;
    left = f.lay.max.x - f.pad - widest;
    top = f.lay.max.y - f.pad - height;
    // A frame narrowed to its data (equal scales) has paper beside it: the legend goes there,
    // off the data, when it fits.
    if (frame_max_.x - f.lay.max.x >= widest + 3.0f * f.pad) {
      left = f.lay.max.x + 2.0f * f.pad;
    }
    const ImVec2 box_max{left + widest + f.pad - 1, f.lay.max.y - 1};
    dl->AddRectFilled({left - f.pad, top - f.pad}, box_max,
                      ImGui::ColorConvertFloat4ToU32(plot_background(style_is_light())));
    dl->AddRect({left - f.pad, top - f.pad}, box_max, f.col_border);
  }
  dl->PushClipRect(frame_min_, frame_max_, true);
  for (std::size_t i = 0; i < legend_.size(); ++i) {
    const LegendEntry& e = legend_[i];
    const LegendRow& r = legend_rows_[i];
    const ImVec2 mid{left + r.x + f.swatch / 2, top + r.y + f.row / 2};
    if (e.kind == Kind::Markers) {
      draw_marker(dl, mid, std::min(4.0f, f.row / 2 - 1), e.colour, e.shape);
    } else {
      dl->AddLine({mid.x - f.swatch / 2, mid.y}, {mid.x + f.swatch / 2, mid.y}, e.colour,
                  2.0f * f.weight);
    }
    dl->AddText({left + r.x + f.swatch + f.pad, top + r.y + 1}, col_text,
                legend_text_.c_str() + e.text);
  }
  dl->PopClipRect();
  view_.legend_min = ImVec2(left, top);
  view_.legend_max = ImVec2(std::min(left + widest, frame_max_.x),
                            std::min(top + legend_rows_.back().y + f.row, frame_max_.y));
}

// In a scrolling panel: a frame round the data area while the plot takes the wheel, and after
// a wheel turned over it that scrolled the panel instead, how to zoom.
void Plot::draw_wheel_state(const Frame& f) const {
  if (!in_scrolling_window_)
    return;
  if (focused_)
    f.draw_list->AddRect(f.lay.min, f.lay.max, f.col_text, 0.0f, 0, 1.5f);
  if (!wheel_hint_ || focused_)
    return;
  // Wrapped to the data area: a small plot is the usual place for it.
  const float wrap = std::max(f.lay.max.x - f.lay.min.x - 2 * f.pad, f.font);
  const ImVec2 size = ImGui::CalcTextSize(kWheelHint, nullptr, false, wrap);
  const ImVec2 at{(f.lay.min.x + f.lay.max.x - size.x) / 2, f.lay.min.y + f.pad};
  f.draw_list->AddRectFilled({at.x - f.pad, at.y - f.pad / 2},
                             {at.x + size.x + f.pad, at.y + size.y + f.pad / 2},
                             ImGui::GetColorU32(ImGuiCol_PopupBg, 1.0f));
  f.draw_list->AddText(ImGui::GetFont(), f.font, at, f.col_text, kWheelHint, nullptr, wrap);
}

// The view and the label width, kept for the next frame.
void Plot::store_view_state(const Frame& f) const {
  ImGuiStorage* st = f.storage;
  store_double(st, keys_, kXLo, view_.x_lo);
  store_double(st, keys_, kXHi, view_.x_hi);
  store_double(st, keys_, kYLo, view_.y_lo);
  store_double(st, keys_, kYHi, view_.y_hi);
  st->SetInt(keys_[kFlags], kHasRange | (f.manual_x ? kManualX : 0) | (f.manual_y ? kManualY : 0));
  st->SetFloat(keys_[kLabelWidth], f.label_width);
}

}  // namespace foldlab::gui
