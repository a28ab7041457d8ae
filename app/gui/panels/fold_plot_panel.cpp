#include "app/gui/panels/fold_plot_panel.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/gui/appearance.hpp"
#include "app/gui/compare.hpp"
#include "app/gui/input_words.hpp"
#include "app/gui/panels/widgets.hpp"
#include "app/gui/presentation_bar.hpp"
#include "core/geometry/geometry.hpp"

namespace foldlab::gui {
namespace {

// B's lines are dashed so that they read apart from A's where the two fabrics fold alike: of every
// kDashPeriod samples (about 15 dashes across the span at 201 samples) the last kDashGap are left
// out.
constexpr std::size_t kDashPeriod = 12;
constexpr std::size_t kDashGap = 4;
// Towards the supports every fold line runs into its neighbours; B's dashes there would merge
// into a grey fence over A's lines. A dash is left out where B's line is closer to a neighbour
// than two line widths (screen pixels, across the line).
constexpr double kMinSeparationPx = 4.0;

// How far apart two lines are on screen at one sample: the vertical gap seen across the first
// line, whose slope there is `dy_dx_px`.
double separation_px(double gap_y_px, double dy_dx_px) {
  return std::abs(gap_y_px) / std::sqrt(1.0 + dy_dx_px * dy_dx_px);
}

}  // namespace

void FoldLineSeries::lines(Plot& plot, Scene& scene, bool compare, bool legend) {
  const FoldLines& lines = scene.fold_lines();
  if (lines_version_ != scene.version(Stage::fold_lines)) {
    lines_version_ = scene.version(Stage::fold_lines);
    xs_.assign(lines.lines.size(), {});
    ys_.assign(lines.lines.size(), {});
    for (std::size_t k = 0; k < lines.lines.size(); ++k) {
      for (const Eigen::Vector3d& p : lines.lines[k].points_mm) {
        xs_[k].push_back(p.x());
        ys_[k].push_back(p.y());
      }
    }
  }
  const FoldColours colours = fold_colours(style_is_light());
  const ImU32 positive_colour = ImGui::ColorConvertFloat4ToU32(colours.positive);
  const ImU32 negative_colour = ImGui::ColorConvertFloat4ToU32(colours.negative);
  // With B pinned the legend tells A's lines from B's in a few words (the fabrics' names are
  // over the 3D view and in Results, too long for a legend).
  const char* positive = !legend ? nullptr : compare ? "A positive fold" : "positive fold";
  const char* negative = !legend ? nullptr : compare ? "A negative fold" : "negative fold";
  // A whole-pixel width lets ImGui draw each line from its baked anti-aliased line texture: two
  // vertices a point instead of four, which is a third of a dragged frame's plot on llvmpipe.
  for (std::size_t k = 0; k < lines.lines.size(); ++k) {
    const bool is_negative = lines.lines[k].sign < 0;
    plot.line(is_negative ? negative : positive, xs_[k], ys_[k],
              is_negative ? negative_colour : positive_colour, 2.0f);
  }
}

void FoldLineSeries::outline_and_supports(Plot& plot, Scene& scene, bool legend) {
  const Solution& s = scene.solution();
  if (scene.fold_lines().lines.empty()) {
    // No folds (no slack, short cloth): show the cloth itself, y = (A + h) cos(pi x / l).
    if (outline_version_ != scene.version(Stage::solution)) {
      outline_version_ = scene.version(Stage::solution);
      outline_xs_.clear();
      outline_ys_.clear();
      const double depth = lowest_point_mm(s, scene.parameters().hanging.height_mm);
      for (int k = 0; k <= 100; ++k) {
        const double x = s.span_mm * (k / 100.0 - 0.5);
        outline_xs_.push_back(x);
        outline_ys_.push_back(depth * std::cos(std::numbers::pi * x / s.span_mm));
      }
    }
    plot.line(legend ? "lower edge of the flat cloth" : nullptr, outline_xs_, outline_ys_,
              ImGui::GetColorU32(ImGuiCol_TextDisabled), 1.2f);
  }
  supports_x_.clear();
  supports_y_.clear();
  for (const Eigen::Vector3d& support : support_points(s.span_mm, scene.parameters().shape)) {
    supports_x_.push_back(support.x());
    supports_y_.push_back(support.y());
  }
  plot.markers(legend ? "supports" : nullptr, supports_x_, supports_y_, kSupportMarker.u32(),
               MarkerShape::Triangle, 6.0f);
}

void FoldPlotPanel::dash_compare_lines(Document& document) {
  Comparison& compare = document.compare();
  Scene& scene = compare.scene(document.scene().grid_nx());
  const FoldLines& lines = scene.fold_lines();
  // The last frame's scale: the lines that stand apart change as the plot zooms.
  const PlotView& view = plot_.view();
  const double x_px_per_mm = (view.max.x - view.min.x) / (view.x_hi - view.x_lo);
  const double y_px_per_mm = (view.max.y - view.min.y) / (view.y_hi - view.y_lo);
  if (compare_changes_ == compare.changes() &&
      compare_lines_version_ == scene.version(Stage::fold_lines) &&
      compare_x_px_per_mm_ == x_px_per_mm && compare_y_px_per_mm_ == y_px_per_mm) {
    return;
  }
  compare_changes_ = compare.changes();
  compare_lines_version_ = scene.version(Stage::fold_lines);
  compare_x_px_per_mm_ = x_px_per_mm;
  compare_y_px_per_mm_ = y_px_per_mm;
  compare_xs_.assign(lines.lines.size(), {});
  compare_ys_.assign(lines.lines.size(), {});
  compare_signs_.clear();
  const double gap = std::nan("");
  const bool scale_known = x_px_per_mm > 0.0 && y_px_per_mm > 0.0;
  for (std::size_t k = 0; k < lines.lines.size(); ++k) {
    compare_signs_.push_back(lines.lines[k].sign);
    const std::vector<Eigen::Vector3d>& points = lines.lines[k].points_mm;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const bool dash = i % kDashPeriod < kDashPeriod - kDashGap || i + 1 == points.size();
      const bool shown =
          dash && (!scale_known || stands_apart(lines, k, i, x_px_per_mm, y_px_per_mm));
      compare_xs_[k].push_back(shown ? points[i].x() : gap);
      compare_ys_[k].push_back(shown ? points[i].y() : gap);
    }
  }
}

bool FoldPlotPanel::stands_apart(const FoldLines& lines, std::size_t k, std::size_t i,
                                 double x_px_per_mm, double y_px_per_mm) {
  const FoldLine& line = lines.lines[k];
  const std::vector<Eigen::Vector3d>& points = line.points_mm;
  // The line's slope on screen at the sample, from its neighbouring samples.
  const std::size_t before = i == 0 ? 0 : i - 1;
  const std::size_t after = std::min(i + 1, points.size() - 1);
  const double dx_px = (points[after].x() - points[before].x()) * x_px_per_mm;
  const double dy_px = (points[after].y() - points[before].y()) * y_px_per_mm;
  const double slope = dx_px == 0.0 ? 1e9 : dy_px / dx_px;
  // The neighbours in the same span, sampled at the same x.
  for (const std::size_t other : {k - 1, k + 1}) {
    if (other >= lines.lines.size() || lines.lines[other].span != line.span ||
        lines.lines[other].points_mm.size() != points.size()) {
      continue;
    }
    const double gap_px = (lines.lines[other].points_mm[i].y() - points[i].y()) * y_px_per_mm;
    if (separation_px(gap_px, slope) < kMinSeparationPx) {
      return false;
    }
  }
  return true;
}

void FoldPlotPanel::view_settings(ViewSettings& settings, Document& /*document*/) {
  settings.add_switch("fold_plot_true_scale", &true_scale_, kEveryUse);
  settings.add_switch("fold_plot_presented_true_scale", &presented_true_scale_, kEveryUse);
}

void FoldPlotPanel::report(nlohmann::json& state, PanelContext& /*context*/) const {
  const PlotView& view = plot_.view();
  state["fold_plot"] = {
      {"x_mm", {view.x_lo, view.x_hi}},
      {"y_mm", {view.y_lo, view.y_hi}},
      {"x_auto", view.x_auto},
      {"y_auto", view.y_auto},
      {"x_ticks", plot_.x_ticks().size()},
      {"true_scale", drawn_true_scale_},
      // Whether the legend lies over the data area (presented, it may).
      {"legend_over_data", view.legend_max.x > view.min.x && view.legend_min.x < view.max.x &&
                               view.legend_max.y > view.min.y && view.legend_min.y < view.max.y}};
}

// Below this the plot's axis labels and legend squash it: the panel scrolls instead, and the
// settings above it fold away first.
constexpr float kLeastPlotHeightEms = 14.0f;

void FoldPlotPanel::draw(PanelContext& context) {
  Document& document = context.document;
  Renderer& renderer = context.renderer;
  PhotoOverlay& photo = context.panel<PhotoOverlay>();
  if (!begin(renderer)) {
    ImGui::End();
    return;  // hidden: the fold lines are not even computed
  }
  stale_mark(document);
  Scene& scene = document.scene();
  const FoldLines& lines = scene.fold_lines();
  const Solution& s = scene.solution();
  // Presented to a room, the plot fills the window unless asked for true scale there too: a cloth
  // about as tall as it is wide, drawn true to scale in a wide window, leaves most of it empty. A
  // phone, which always shows one view, is tall enough for the tiles' own switch and rows.
  const bool presented = context.presented == this;
  const bool to_a_room = presented && !shows_one_view();
  bool& true_scale = to_a_room ? presented_true_scale_ : true_scale_;
  drawn_true_scale_ = true_scale;
  if (toolbar_row_.begin("plot settings...", kLeastPlotHeightEms * ImGui::GetFontSize(),
                         presented)) {
    photo.toolbar(context);
    if (small_button("autoscale")) {
      autoscale_ = true;
    }
    same_line_if_fits(checkbox_width(kTrueScaleLabel));
    ImGui::Checkbox(kTrueScaleLabel, &true_scale);
    help_marker_and_hint(
        "A mm across is as many pixels as a mm down, so that the sag looks as deep as it "
        "hangs. Off, each axis fills the plot: shallow folds spread apart.",
        hint_words(Hint::fold_plot));
    toolbar_row_.end();
  }
  if (lines.stride > 1) {
    ImGui::TextColored(kDimText, "every %d-th of %d lines drawn", lines.stride, s.n + 1);
  }
  // At a large UI scale in a small window the panel scrolls rather than squash the plot under its
  // own axis labels and legend.
  const float height = std::max(ems(kLeastPlotHeightEms), ImGui::GetContentRegionAvail().y);
  if (plot_.begin("fold lines", ImVec2(0.0f, height), kFoldPlotX, kFoldPlotY)) {
    if (autoscale_) {
      plot_.request_autoscale();
      autoscale_ = false;
    }
    if (context.holding_frame) {
      plot_.grow_only();
    }
    if (to_a_room) {
      plot_.compact();
    }
    if (true_scale) {
      plot_.equal_scales(/*narrow_frame=*/true);
    }
    const bool compare = document.compare().pinned();
    series_.lines(plot_, scene, compare, true);
    compare_lines_drawn_ = 0;
    compare_points_drawn_ = 0;
    if (compare) {
      dash_compare_lines(document);
      for (std::size_t k = 0; k < compare_xs_.size(); ++k) {
        const bool negative = compare_signs_[k] < 0;
        plot_.line(negative ? "B negative fold (dashed)" : "B positive fold (dashed)",
                   compare_xs_[k], compare_ys_[k],
                   negative ? kCompareBNegative.u32() : kCompareB.u32(), 2.0f);
        ++compare_lines_drawn_;
        compare_points_drawn_ += compare_xs_[k].size();
      }
    }
    series_.outline_and_supports(plot_, scene, true);
    photo.plot_items(plot_, document);
    const std::optional<PlotHit> hit = plot_.end();
    drawn_.mark(PanelRect{plot_.view().min, ImVec2(plot_.view().max.x - plot_.view().min.x,
                                                   plot_.view().max.y - plot_.view().min.y)});
    photo.handle_click(plot_, context.status);
    if (hit && hit->series < static_cast<int>(lines.lines.size())) {
      const FoldLine& line = lines.lines[static_cast<std::size_t>(hit->series)];
      const Eigen::Vector3d& p = line.points_mm[static_cast<std::size_t>(hit->index)];
      ImGui::SetTooltip("fold line %d (%s)\nx = %.1f mm\ny = %.1f mm\nz = %+.1f mm", line.index,
                        line.sign < 0 ? "negative" : "positive", p.x(), p.y(), p.z());
    }
  }
  ImGui::End();
}

}  // namespace foldlab::gui
