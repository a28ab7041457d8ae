// The Regime map tab: n or z_max over two inputs, computed row by row on every core in the
// background and shown as an image as the rows arrive; a click moves the sliders there.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/gui/background_job.hpp"
#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/view_toolbar.hpp"
#include "app/gui/plot_widget.hpp"
#include "app/gui/renderer.hpp"
#include "core/analysis/sweep.hpp"

namespace foldlab::gui {

class RegimeMapPanel {
 public:
  ViewToolbar& toolbar() { return toolbar_row_; }
  RegimeMapPanel();
  ~RegimeMapPanel();
  RegimeMapPanel(const RegimeMapPanel&) = delete;
  RegimeMapPanel& operator=(const RegimeMapPanel&) = delete;

  // `presented`: the Analysis panel is presented to a room; the settings fold into its title
  // bar and the map takes the room they had.
  void draw(PanelContext& context, bool presented = false);

  const std::string& x_key() const { return x_key_; }
  const std::string& y_key() const { return y_key_; }
  // For tests and the docs' figure: the last completed map's size and time.
  double last_map_ms() const { return last_map_ms_; }
  // True from a (re)start until every row has been computed.
  bool computing() const { return job_.running(); }
  // Whether the axes and cells are folded behind a "map settings..." button (a small panel).
  bool toolbar_folded() const { return toolbar_row_.folded(); }
  // For the report: the axes, how far the map is, and a digest of its cells (null before the
  // tab was first shown).
  nlohmann::json report() const;
  // Where the map's cells were drawn last (display pixels), and at which ImGui frame.
  const DrawnArea& drawn_area() const { return drawn_; }

 private:
  struct Cells;
  // Where the map was drawn this frame: its top-left corner, width and height, and the margin on
  // its left that holds the y labels.
  struct Placement {
    ImVec2 origin;
    float width = 0.0f;
    float height = 0.0f;
    float left_margin = 0.0f;
    // Presented: the x title on the row of the x tick labels, and the swatches on the y title's
    // row when they fit there (swatches_at: where they start).
    bool compact = false;
    ImVec2 swatches_at{0.0f, 0.0f};
    bool swatches_on_title_row = false;
  };

  // The axes, their ranges, the cell count and what is shown; true when the map must restart.
  bool controls(const Parameters& current);
  // True when an input other than the two axes changed since the map was started.
  bool other_inputs_changed(const Parameters& current) const;
  // Says what is wrong with the axes, if anything; true when nothing can be drawn.
  bool axes_refused() const;
  void restart(const Parameters& base, const std::function<void()>& wake);
  void update_image(Renderer& renderer);
  // The progress bar while rows arrive, else the last map's time and the hint.
  void status_line();
  void timing_text() const;
  // The map's side and margins for the space left in the panel, and its y title.
  Placement place_map(bool compact);
  static AxisTicks map_ticks(const SweepAxis& axis, float length_px, bool horizontal);
  void axis_labels(const Placement& at) const;
  void colour_bar(const Placement& at) const;
  void regime_swatches(const Placement& at) const;
  void current_point(const Placement& at, const Parameters& current) const;
  // The hovered cell's tooltip; a click moves both sliders there as one undo step.
  void hover_and_click(const Placement& at, Document& document, bool clicked) const;

  ViewToolbar toolbar_row_;
  DrawnArea drawn_;
  std::string x_key_ = "h";
  std::string y_key_ = "w";
  double x_from_ = 300.0, x_to_ = 3000.0;
  double y_from_ = 3e-7, y_to_ = 1e-5;
  int resolution_ = 256;
  bool show_z_ = false;

  std::shared_ptr<Cells> cells_;  // the running or last map, row by row as they arrive
  BackgroundJob<double> job_;     // fills cells_; returns its wall time in ms
  unsigned threads_ = 1;
  Parameters job_base_;
  bool job_started_ = false;
  int image_ = -1;  // the renderer's image of the map
  int image_size_ = 0;
  std::vector<std::uint32_t> pixels_;
  int rows_shown_ = -1;
  double last_map_ms_ = 0.0;
};

}  // namespace foldlab::gui
