// The Sweep tab: n, Q and z_max against one input, with the paper's printed rows overlaid. It
// computes nothing while its tab is hidden, and again only when the inputs or the axis change.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/view_toolbar.hpp"
#include "app/gui/plot_widget.hpp"
#include "app/gui/renderer.hpp"
#include "core/analysis/sweep.hpp"
#include "core/io/preset.hpp"

namespace foldlab::gui {

// The three plots of a sweep, n, Q and z_max, with the room their y tick labels took last frame
// (so that the three data areas start at one x): the tab's own, or a picture's.
struct SweepPlots {
  Plot plots[3];
  float shared_label_width = 0.0f;
};

class SweepPanel {
 public:
  ViewToolbar& toolbar() { return toolbar_row_; }
  explicit SweepPanel(std::filesystem::path presets_dir);
  // `side_by_side`: the three plots in a row, each with its x title, and the settings folded into
  // the title bar (presented on a wide screen, where stacked they would be strips); else one over
  // another under the settings.
  void draw(Document& document, bool side_by_side = false);
  // Where the last frame drew the three plots' data areas, all three within it.
  const DrawnArea& drawn_area() const { return drawn_; }
  // The axis swept: a `foldlab picture sweep`'s --param, --from, --to (drops the paper's points).
  void set_axis(const SweepAxis& axis);
  SweepAxis axis() const { return SweepAxis{key_, from_, to_, steps_, logarithmic_}; }
  // The curves for the axis and the fabrics as they are now (A's, and B's while pinned), again
  // only when they changed; the axis's problem when it has one.
  std::optional<std::string> compute(Document& document);
  // The keys above the plots (A and B while B is pinned, the shaded bands) and the three plots,
  // each `height_px` tall, after compute(): the tab's own plots, or a picture's. A `width_px`
  // above zero puts them side by side, each that wide. `title_row_px` above zero: the bands' key
  // may stand on the first plot's title row, that wide, rather than a row of its own.
  void draw_keys(Document& document, float title_row_px = 0.0f) const;
  void draw_plots(Document& document, SweepPlots& plots, float height_px, float width_px = 0.0f);
  // Where the last frame drew plot `which`'s sample nearest `shown_x` (in the unit the axis
  // shows), skipping gaps; none without one.
  std::optional<ImVec2> screen_point(int which, double shown_x) const;
  // One click's worth: 0 Table 1, 1 Table 2, 2 Fig. 4 (loads the preset, sweeps, overlays).
  void select_paper_case(int which, Document& document);
  static constexpr int kPaperCases = 3;

  // The swept input's key and the paper's points over it (empty without an overlay).
  const std::string& key() const { return key_; }
  const std::vector<double>& overlay_x() const { return overlay_x_; }
  const std::vector<RegimeBand>& bands() const { return bands_; }
  const SweepCurves& curves() const { return curves_; }
  // Where the last frame drew the n, Q and z_max plots' data (0, 1, 2).
  const PlotView& plot_view(int which) const { return plots_.plots[which].view(); }
  const Plot& plot(int which) const { return plots_.plots[which]; }
  // B's curves over the same axis while a fabric is pinned as B (null otherwise), and how many
  // curves the n plot drew last frame (A's, then B's).
  const SweepCurves* compare_curves() const {
    return compare_computed_ ? &compare_curves_ : nullptr;
  }
  int curves_drawn() const { return curves_drawn_; }

 private:
  void recompute(const Parameters& current);
  // draw()'s steps: the input, range, scale and steps; the paper's cases; whether the paper's
  // points belong to the axis shown.
  void draw_axis_controls(Document& document);
  void draw_paper_case_buttons(Document& document);
  bool overlay_shown() const;
  // What each shade of band over the plots means, a line for each kind shown.
  void draw_band_key() const;
  // The same, each kind's name only (its meaning a hover away), at the right end of the first
  // plot's title row `row_px` wide, taking no row: false, drawing nothing, where they do not fit.
  bool band_key_on_title_row(float row_px) const;
  // One of the three plots: its id, y title, the symbol and unit its tooltip gives a value in,
  // the model's values, the paper's points, and B's values while pinned.
  struct Quantity {
    const char* id;
    const char* label;
    const char* symbol;
    const char* unit;
    const std::vector<double>& ys;
    const std::vector<double>& paper_x;
    const std::vector<double>& paper_y;
    bool steps;
    const std::vector<double>* compare_ys;
  };
  // Draws one plot, the x title only when `last`; false when it is clipped (nothing drawn).
  bool draw_quantity(Document& document, Plot& plot, const Quantity& q, bool last,
                     ImVec2 size_px) const;
  // B's curves over the axis A's were computed on, again only when B or the axis changes.
  void recompute_compare(Document& document);
  // The paper's rows for `prefix` (e.g. "paper-table1-") as points over `key`.
  void load_overlay(const std::string& prefix, const std::string& label);

  std::filesystem::path presets_dir_;
  std::string key_ = "h";
  double from_ = 500.0;
  double to_ = 3000.0;
  int steps_ = 200;
  bool logarithmic_ = false;

  Parameters computed_for_;
  SweepAxis computed_axis_;
  bool computed_ = false;
  SweepCurves curves_;
  // The x values as plotted: in the unit the swept input's slider shows (w in g/m²).
  std::vector<double> shown_x_;
  std::vector<RegimeBand> bands_;
  bool compare_computed_ = false;
  Parameters compare_computed_for_;
  SweepAxis compare_axis_;
  SweepCurves compare_curves_;
  int curves_drawn_ = 0;
  DrawnArea drawn_;
  // The input, range and paper's cases: above the plots, or presented in the title bar.
  ViewToolbar toolbar_row_;
  void clear_overlay();
  // Shades the bands over the data area of the plot just ended; names them when `label`.
  void draw_bands(const Plot& plot, const std::string& key, bool label) const;
  // The paper's printed rows beside the model's at the same inputs.
  void draw_comparison(const Parameters& current);

  std::string overlay_label_;
  std::uint64_t overlay_load_ = 0;  // Document::loads() when the overlay's case was loaded
  std::string overlay_key_;
  std::vector<double> overlay_x_, overlay_n_, overlay_Q_, overlay_z_;
  std::vector<double> overlay_Q_x_;    // rows without a printed Q are left out of the Q plot
  std::vector<double> overlay_row_Q_;  // per row of overlay_x_, NaN where the paper prints no Q
  std::vector<double> overlay_shown_x_, overlay_Q_shown_x_;  // as plotted, like shown_x_
  SweepPlots plots_;
};

}  // namespace foldlab::gui
