// A small 2D plot drawn with ImGui draw lists (ImPlot is not packaged for Debian 12).
//
// Immediate mode, like ImGui itself:
//
//   static foldlab::gui::Plot plot;  // one object per plot keeps its buffers warm
//   if (plot.begin("fold lines", {0, 0}, {"x (mm)"}, {"y (mm)", /*flipped=*/true})) {
//     plot.line("positive fold", xs, ys, IM_COL32(220, 60, 40, 255));
//     plot.markers("supports", sx, sy, IM_COL32(240, 240, 240, 255), MarkerShape::Triangle);
//     if (auto hit = plot.end()) { /* hit->series, hit->index */ }
//   }
//
// Series are only recorded until end(), which lays out, handles input and draws everything:
// the spans must stay valid until end() returns (legend and label strings are copied). The view
// state (visible range, autoscale on/off) lives in the current window's ImGuiStorage under the
// plot's id, so it persists across frames and dies with the ImGui context.
//
// Interaction: the view follows the data (autoscale, with a 5 % margin) until the user zooms or
// pans that axis. Mouse wheel zooms around the cursor (Shift: x only, Ctrl: y only), left drag
// pans, double-click or the right-click menu's "Autoscale" turns autoscale back on. In a window
// that scrolls, the wheel scrolls the window until the plot is clicked (it is then framed) and
// again after a click elsewhere; a wheel turned over a plot that is not clicked shows kWheelHint.
// The data point nearest to the mouse (within 12 px) is highlighted, shown in a tooltip and
// returned.
#pragma once

#include <imgui.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace foldlab::gui {

// Shown over a plot in a scrolling window when the wheel scrolled the window rather than zoom.
inline constexpr const char* kWheelHint = "click the plot to zoom";

struct PlotAxis {
  std::string label;     // title with its unit, e.g. "x (mm)"; tick labels are plain numbers
  bool flipped = false;  // larger values to the left (x) or downward (y: the paper's figures)
  bool log = false;      // log10 scale; values <= 0 are skipped as if they were NaN
  bool whole = false;    // a count (iterates, folds): ticks on whole numbers only
  // How the tooltip names a hovered point's value ("w = 213.9 g/m²"); empty: "label: value", or
  // "x: value" on an axis without a title.
  std::function<std::string(double)> value_text{};
};

enum class MarkerShape { Circle, Square, Diamond, Triangle, Cross, Plus };

// The data point nearest to the mouse. `series` counts line(), steps() and markers() calls in the
// order of this frame's submission (vertical lines are not series); `index` is into its spans.
struct PlotHit {
  int series;
  int index;
  double x;
  double y;
};

// What end() drew this frame: the data rectangle on screen and the visible data ranges.
struct PlotView {
  ImVec2 min{0, 0}, max{0, 0};  // screen rectangle of the data area
  double x_lo = 0, x_hi = 1;    // visible ranges, lo < hi whatever the axis direction
  double y_lo = 0, y_hi = 1;
  bool x_log = false, y_log = false;
  bool x_flipped = false, y_flipped = false;
  bool x_auto = true, y_auto = true;  // the axis follows the data
  int legend_entries = 0;             // after de-duplication by label
  // The legend's screen rectangle: below the x axis title, outside the data area (empty, at the
  // axes' bottom left, when there is no legend).
  ImVec2 legend_min{0, 0}, legend_max{0, 0};

  ImVec2 to_screen(double x, double y) const;
  std::pair<double, double> to_data(ImVec2 screen) const;
};

class Plot {
 public:
  // Starts a plot of `size` under `id` (unique within the window). A size component <= 0 means
  // the available region plus that amount, as in ImGui. Returns false when the plot is clipped
  // or hidden: then call nothing else, not even end().
  bool begin(const char* id, ImVec2 size, const PlotAxis& x, const PlotAxis& y);

  // Series. A null or empty legend adds no legend entry; entries with equal labels show once.
  // Points with a NaN or infinite coordinate are gaps; spans of unequal length use the shorter.
  void line(const char* legend, std::span<const double> xs, std::span<const double> ys,
            ImU32 colour, float thickness = 1.5f);
  // Sampled step function (e.g. the wrinkle count n over a sweep): each sample's value holds up
  // to half-way to its neighbours, since the true jump is only known to lie between two samples.
  void steps(const char* legend, std::span<const double> xs, std::span<const double> ys,
             ImU32 colour, float thickness = 1.5f);
  void markers(const char* legend, std::span<const double> xs, std::span<const double> ys,
               ImU32 colour, MarkerShape shape = MarkerShape::Circle, float radius = 4.0f);
  // A full-height line, e.g. the current value of a sweep; it is included in x autoscale.
  void vertical_line(double x, ImU32 colour, const char* label = nullptr);

  // x autoscale spans at least lo..hi, drawn or not: plots stacked over one axis (a sweep's n, Q
  // and z_max, Q undefined where n = 1) line up.
  void fit_x_to(double lo, double hi) { fit_x_ = {lo, hi}; }
  // This frame, autoscale only widens the axes it fits (while an input plays: the data's change of
  // size shows).
  void grow_only() { grow_only_ = true; }

  // Drawn by end() over the data area's background and under the grid and the series, clipped to
  // the data area, with this frame's view: e.g. a photo that the series are compared with.
  void backdrop(std::function<void(ImDrawList*, const PlotView&)> draw) {
    backdrop_ = std::move(draw);
  }

  // This frame, one unit of x is as many pixels as one of y (a drawing in mm: mm are mm): the
  // axis with pixels to spare shows more about its centre. Linear axes only. `narrow_frame`:
  // a frame wider than the data at that scale is narrowed about its centre instead, so that the
  // x axis spans the data rather than a width of empty paper beside it.
  void equal_scales(bool narrow_frame = false) {
    equal_scales_ = true;
    narrow_frame_ = narrow_frame;
  }
  // This frame, the x title goes on the row of the x tick labels, at its left end (a label it
  // would cover is left out), and the legend inside the data area at its bottom right, over a
  // backing of the background's colour: a view presented to a room keeps two rows for its data.
  void compact() { compact_ = true; }
  // The y tick labels' column at least this wide (px), for plots stacked above one another whose
  // data areas must start at one x. label_width_needed() is what this plot's labels took last.
  void min_label_width(float px) { min_label_width_ = px; }
  float label_width_needed() const { return label_width_needed_; }

  // Fit both axes to the data again, from this frame on (between begin() and end()).
  void request_autoscale() { autoscale_requested_ = true; }

  // Draws axes, grid, ticks, series and legend (below the axes, never over the data), handles
  // zoom/pan/autoscale and returns the data point nearest to the mouse, if any is within 12 px.
  std::optional<PlotHit> end();

  // Valid after end(); the same until the next end().
  const PlotView& view() const { return view_; }
  const std::vector<double>& x_ticks() const { return x_ticks_; }
  const std::vector<double>& y_ticks() const { return y_ticks_; }

 private:
  enum class Kind { Line, Steps, Markers };
  struct Series {
    Kind kind;
    std::span<const double> xs, ys;
    ImU32 colour;
    float size;  // line thickness or marker radius
    MarkerShape shape;
    int legend;  // index into legend_, -1 for none
  };
  struct LegendEntry {
    std::size_t text;  // offset into legend_text_
    Kind kind;
    ImU32 colour;
    MarkerShape shape;
  };
  struct VLine {
    double x;
    ImU32 colour;
    std::size_t text;  // offset into legend_text_, npos for none
  };
  struct LegendRow {
    float x, y;  // offset of the entry from the legend's top left
    float width;
  };
  struct DPoint {
    double x, y;
  };

  void add_series(Kind kind, const char* legend, std::span<const double> xs,
                  std::span<const double> ys, ImU32 colour, float size, MarkerShape shape);
  std::size_t store_text(const char* text);
  void stroke(ImDrawList* dl, ImU32 colour, float thickness, ImVec2 clip_min, ImVec2 clip_max);

  // end()'s steps, in their order; Frame carries what one step works out for the next.
  struct Frame;
  void fit_view_range(Frame& f) const;
  void lay_out_legend(Frame& f);
  void zoom_and_pan(Frame& f) const;
  void wheel_zoom(Frame& f) const;
  void drag_pan(Frame& f) const;
  void place_ticks(Frame& f);
  void equalise_scales(Frame& f) const;
  void publish_view(const Frame& f);
  void draw_background_and_grid(const Frame& f) const;
  void draw_series(const Frame& f);
  void draw_markers(const Frame& f, const Series& s) const;
  void line_path(const Frame& f, const Series& s);
  void steps_path(const Frame& f, const Series& s);
  void draw_vertical_lines(const Frame& f) const;
  std::optional<PlotHit> hover(const Frame& f) const;
  std::optional<PlotHit> nearest_point(const Frame& f, ImVec2 mouse) const;
  void show_hit(const Frame& f, const PlotHit& hit) const;
  void draw_tick_labels_and_titles(const Frame& f) const;
  float compact_x_title_left(const Frame& f) const;
  void draw_x_tick_labels(const Frame& f) const;
  void draw_y_tick_labels(const Frame& f) const;
  void draw_legend(const Frame& f);
  void draw_wheel_state(const Frame& f) const;
  void store_view_state(const Frame& f) const;

  bool open_ = false;
  bool hovered_ = false, active_ = false, double_clicked_ = false;
  bool autoscale_requested_ = false;
  // The wheel: whether this plot takes it this frame, whether it was clicked since the last
  // click elsewhere, whether its window scrolls, and whether a wheel turned over it scrolled the
  // window instead (then it says how to zoom until the mouse leaves).
  bool wheel_zooms_ = false, focused_ = false, in_scrolling_window_ = false, wheel_hint_ = false;
  ImGuiID keys_[10] = {};
  ImVec2 frame_min_{0, 0}, frame_max_{0, 0};
  PlotAxis x_axis_, y_axis_;
  std::vector<Series> series_;
  std::vector<LegendEntry> legend_;
  std::vector<VLine> vlines_;
  std::optional<std::pair<double, double>> fit_x_;
  bool grow_only_ = false;
  bool equal_scales_ = false;
  bool compact_ = false;
  bool narrow_frame_ = false;
  float min_label_width_ = 0.0f;
  float label_width_needed_ = 0.0f;
  std::vector<LegendRow> legend_rows_;  // per legend entry, laid out in end()
  float legend_height_ = 0;
  std::function<void(ImDrawList*, const PlotView&)> backdrop_;
  std::string legend_text_;  // NUL-separated copies: callers may pass temporaries' c_str()
  // Per-frame scratch, kept here so a long-lived Plot does not allocate once warm.
  std::vector<double> x_ticks_, y_ticks_;
  std::vector<DPoint> path_;
  std::vector<ImVec2> screen_;
  PlotView view_;
};

// "Nice" ticks (1, 2 or 5 × 10^k apart) inside [lo, hi] (either order), about `target` of them,
// ascending. lo == hi gives that one value; a non-finite bound gives none.
std::vector<double> nice_ticks(double lo, double hi, int target);
// Ticks for a log axis over [lo, hi] (positive): decades, with 2 and 5 added when there are few
// decades, every k-th decade when there are many, linear nice ticks inside a single decade.
std::vector<double> log_ticks(double lo, double hi, int target);
// Label for a tick `value` on an axis whose ticks are `step` apart: as many decimals as the step
// needs, exponent notation for very large or small values, never "-0".
std::string format_tick(double value, double step);

// Ticks on whole numbers for a count (folds, iterates) over [lo, hi] (either order): the
// densest of 1, 2, 5 × 10^k apart whose labels keep `gap_px` apart on an axis `length_px` long
// (`extent` as in fitted_ticks) with at most `max_ticks`; when that leaves fewer than three and
// three whole numbers lie in the range, its ends and middle, if their labels fit. A count's axis
// says where it runs from and to, not one value in its middle.
std::vector<double> whole_ticks(double lo, double hi, double length_px,
                                const std::function<float(const std::string&)>& extent,
                                float gap_px, int max_ticks);

// An axis's ticks with their labels (format_tick, each with the step to its nearer neighbour).
struct AxisTicks {
  std::vector<double> values;
  std::vector<std::string> labels;
};
// The most ticks (at most `max_ticks`: 1-2-5 × 10^k steps, or on a log axis decades with 2 and 5
// where there is room) whose labels do not overlap on an axis `length_px` long over [lo, hi]:
// `extent(label)` is a label's size along the axis (its width on an x axis, the line height on a
// y axis) and `gap_px` the least space between two labels. Where not even two fit, the one
// nearest the axis's middle.
AxisTicks fitted_ticks(double lo, double hi, bool log, double length_px,
                       const std::function<float(const std::string&)>& extent, float gap_px,
                       int max_ticks);

}  // namespace foldlab::gui
