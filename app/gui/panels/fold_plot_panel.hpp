// The "Fold lines (2D)" panel: the fold lines in the x-y plane coloured by sign, the supports, and
// the flat cloth's lower edge when there are no folds, over a photo when one is loaded. Hidden,
// it computes nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/photo_overlay.hpp"
#include "app/gui/panels/view_toolbar.hpp"
#include "app/gui/plot_widget.hpp"
#include "app/gui/renderer.hpp"

namespace foldlab::gui {

// The fold plot's axes: the paper's figures, y down from the supports.
inline const PlotAxis kFoldPlotX{"x (mm)", false, false};
inline const PlotAxis kFoldPlotY{"y (mm, down)", true, false};

// A's fold lines as the plot's series, for the panel and for its picture (picture.hpp). Kept
// between frames, since the plot keeps pointers into them until end(), and rebuilt only when
// the lines change.
class FoldLineSeries {
 public:
  // A's fold lines, coloured by sign; with `legend` named "positive fold" and "negative fold"
  // ("A ..." while B is pinned, `compare`). The series' indices are the lines' indices.
  void lines(Plot& plot, Scene& scene, bool compare, bool legend);
  // With no folds (no slack, short cloth) the flat cloth's lower edge, and the supports.
  void outline_and_supports(Plot& plot, Scene& scene, bool legend);

 private:
  std::uint64_t lines_version_ = ~std::uint64_t{0};
  std::vector<std::vector<double>> xs_;
  std::vector<std::vector<double>> ys_;
  std::uint64_t outline_version_ = ~std::uint64_t{0};
  std::vector<double> outline_xs_;
  std::vector<double> outline_ys_;
  std::vector<double> supports_x_;
  std::vector<double> supports_y_;
};

class FoldPlotPanel : public Panel {
 public:
  const char* name() const override { return "Fold lines (2D)"; }
  const char* introduction() const override {
    return "the fold lines seen from the front, y down from the supports: "
           "blue folds bulge one way out of the plane (z > 0), red ones the other.";
  }
  const char* key() const override { return "fold_plot"; }
  // The context's photo adds its buttons, its backdrop and its clicks to the plot.
  void draw(PanelContext& context) override;
  void presented_menu_items(PanelContext& /*context*/) override { toolbar_row_.menu_item(); }
  void view_settings(ViewSettings& settings, Document& document) override;
  // "fold_plot": the visible ranges, x_mm and y_mm as [lo, hi], whether each follows the
  // data (a pan or zoom turns that off), and whether it was drawn at true scale.
  void report(nlohmann::json& state, PanelContext& context) const override;
  // "fold_plot": the plot's data area.
  void drawing_areas(DrawingAreas& areas) const override {
    if (const std::optional<PanelRect> rect = drawn_.recent()) {
      areas.emplace_back(key(), *rect);
    }
  }
  static constexpr PictureOffer kPictures[] = {
      {PictureView::fold_plot, "fold_plot", "Export fold plot picture",
       "Fold plot picture (.png)...", "Fold plot picture, any size (.png)...",
       "The fold plot alone, millimetres alike across and down.", "fold-plot"}};
  std::span<const PictureOffer> pictures() const override { return kPictures; }
  // Whether a mm of x is as many pixels as a mm of y (on by default: the sag as it hangs).
  bool true_scale() const { return true_scale_; }
  static constexpr const char* kTrueScaleLabel = "true scale";
  // Where the plot was drawn last (its data area and legend, screen pixels).
  const PlotView& plot_view() const { return plot_.view(); }
  // Whether the settings above the plot are folded behind a "settings..." button.
  bool toolbar_folded() const { return toolbar_row_.folded(); }
  // The fold lines of B drawn in the last frame, and their points (0 while no B is pinned).
  int compare_lines_drawn() const { return compare_lines_drawn_; }
  std::size_t compare_points_drawn() const { return compare_points_drawn_; }

 private:
  Plot plot_;
  bool autoscale_ = false;
  ViewToolbar toolbar_row_;
  DrawnArea drawn_;
  bool true_scale_ = true;
  bool presented_true_scale_ = false;  // the same switch while the plot is presented
  bool drawn_true_scale_ = true;       // which of the two the last frame drew with
  FoldLineSeries series_;
  // B's fold lines, dashed (a gap is a run of NaN points) and left out where they run into each
  // other by the supports: rebuilt when B, its lines or the plot's scale change.
  void dash_compare_lines(Document& document);
  // Whether sample i of B's line k is clear of its neighbours on screen at the given scale.
  static bool stands_apart(const FoldLines& lines, std::size_t k, std::size_t i, double x_px_per_mm,
                           double y_px_per_mm);
  std::uint64_t compare_changes_ = ~std::uint64_t{0};
  std::uint64_t compare_lines_version_ = ~std::uint64_t{0};
  double compare_x_px_per_mm_ = 0.0;
  double compare_y_px_per_mm_ = 0.0;
  std::vector<std::vector<double>> compare_xs_;
  std::vector<std::vector<double>> compare_ys_;
  std::vector<int> compare_signs_;
  int compare_lines_drawn_ = 0;
  std::size_t compare_points_drawn_ = 0;
};

}  // namespace foldlab::gui
