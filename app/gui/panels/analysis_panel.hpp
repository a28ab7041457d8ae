// The Analysis panel: four tabs, of which only the selected one draws (so a hidden sweep or map
// computes nothing): the equations with today's numbers, the method's iteration step by step, the
// sweep plots and the regime map.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/method_panel.hpp"
#include "app/gui/panels/regime_map_panel.hpp"
#include "app/gui/panels/sweep_panel.hpp"
#include "app/gui/renderer.hpp"

namespace foldlab::gui {

// Eqs. 7-10 with the current numbers, and why n last changed.
class EquationsTab {
 public:
  void draw(Document& document);
  // Every frame, shown or not: follows the fabric's n, so that "n changed from" tells the change
  // the fabric made, wherever it was made (another view presented, a played input).
  void follow(const Solution& s);

 private:
  // Eq. 10 with the numbers, and why n last changed (the n shown is kept from frame to frame).
  void draw_fold_count(const Solution& s, const Parameters& p, bool even);

  int previous_n_ = -1;
  int shown_n_ = -1;
};

class AnalysisPanel : public Panel {
 public:
  // `initial_tab`: "equations", "method", "sweep" or "map", selected at the first frame.
  AnalysisPanel(std::filesystem::path presets_dir, std::string initial_tab);
  const char* name() const override { return "Analysis"; }
  const char* introduction() const override {
    return "the equations with today's numbers, the solver step by step (Method), how "
           "the answer changes with one input (Sweep) or two (Regime map).";
  }
  const char* key() const override { return "analysis"; }
  void draw(PanelContext& context) override;
  void presented_menu_items(PanelContext& context) override;
  void begin_frame(PanelContext& context) override;
  // While the regime map is being computed.
  bool busy() const override { return regime_map_.computing(); }
  // Selects the Sweep tab with one of the paper's cases (0 Table 1, 1 Table 2, 2 Fig. 4).
  void show_paper_case(int which, Document& document);
  // sweep=table1|table2|fig4: the Sweep tab with one of the paper's cases.
  void view_settings(ViewSettings& settings, Document& document) override;
  // The regime map ("regime_map", "regime_map_ms") and the Method tab's stepper ("method_step").
  void report(nlohmann::json& state, PanelContext& context) const override;
  // "sweep" (the three plots' data areas, all within it) and "regime_map" (its cells), each
  // while its tab is shown.
  void drawing_areas(DrawingAreas& areas) const override;
  static constexpr PictureOffer kPictures[] = {
      {PictureView::sweep, "sweep", "Export sweep picture", "Sweep picture (.png)...",
       "Sweep picture, any size (.png)...",
       "The sweep's n, Q and z_max over the input and range the Sweep tab has now.", "sweep"}};
  std::span<const PictureOffer> pictures() const override { return kPictures; }
  std::optional<std::string> picture_unavailable(PictureView view, const Document& document,
                                                 bool as_drawn) const override;
  // "sweep_n", "sweep_Q", "sweep_z_max" at x = at[0] in the swept input's shown unit: where the
  // Sweep tab's plot draws that point.
  std::optional<ImVec2> locate(std::string_view target, std::span<const double> at) const override;

  const SweepPanel& sweep() const { return sweep_; }
  SweepPanel& sweep() { return sweep_; }
  const MethodPanel& method() const { return method_; }
  MethodPanel& method() { return method_; }
  const RegimeMapPanel& regime_map() const { return regime_map_; }
  // True when the last frame drew the Sweep tab's plots.
  bool sweep_shown() const { return sweep_shown_; }

 private:
  // The tab `tab` ("equations", "method", "sweep", "map") under the tab bar or the title bar.
  void draw_tab(PanelContext& context, std::string_view tab, bool presented);

  std::string initial_tab_;
  std::string shown_tab_;  // the tab drawn at the last frame, by its --tab name
  bool sweep_shown_ = false;
  bool tab_selected_ = false;
  bool tabs_in_title_bar_ = false;
  EquationsTab equations_;
  MethodPanel method_;
  SweepPanel sweep_;
  RegimeMapPanel regime_map_;
};

}  // namespace foldlab::gui
