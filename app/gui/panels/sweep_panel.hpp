// The Sweep tab: n, Q and z_max against one input, with the paper's printed rows overlaid. It
// computes nothing while its tab is hidden, and again only when the inputs or the axis change.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "app/gui/document.hpp"
#include "app/gui/plot_widget.hpp"
#include "app/gui/renderer.hpp"
#include "core/analysis/sweep.hpp"
#include "core/io/preset.hpp"

namespace foldlab::gui {

class SweepPanel {
 public:
  explicit SweepPanel(std::filesystem::path presets_dir);
  void draw(Document& document);
  // One click's worth: 0 Table 1, 1 Table 2, 2 Fig. 4 (loads the preset, sweeps, overlays).
  void select_paper_case(int which, Document& document);
  static constexpr int kPaperCases = 3;

  // The swept input's key and the paper's points over it (empty without an overlay).
  const std::string& key() const { return key_; }
  const std::vector<double>& overlay_x() const { return overlay_x_; }
  const std::vector<RegimeBand>& bands() const { return bands_; }
  const SweepCurves& curves() const { return curves_; }
  // Where the last frame drew the n, Q and z_max plots' data (0, 1, 2).
  const PlotView& plot_view(int which) const {
    return which == 0 ? n_plot_.view() : which == 1 ? Q_plot_.view() : z_plot_.view();
  }
  // B's curves over the same axis while a fabric is pinned as B (null otherwise), and how many
  // curves the n plot drew last frame (A's, then B's).
  const SweepCurves* compare_curves() const {
    return compare_computed_ ? &compare_curves_ : nullptr;
  }
  int curves_drawn() const { return curves_drawn_; }

 private:
  void recompute(const Parameters& current);
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
  Plot n_plot_, Q_plot_, z_plot_;
  float shared_label_width_ = 0.0f;  // the widest y tick labels of the three, last frame
};

}  // namespace foldlab::gui
