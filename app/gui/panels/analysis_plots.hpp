// The analysis tabs: sweep plots (n, Q, z_max against one input, the paper's tables overlaid) and
// the regime map (n or z_max over two inputs, computed in the background). Both draw into the
// current ImGui window and compute nothing while their tab is hidden.
#pragma once

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
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

 private:
  void recompute(const Parameters& current);
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
  std::vector<double> xs_, n_, Q_, z_;
  std::string overlay_label_;
  std::string overlay_key_;
  std::vector<double> overlay_x_, overlay_n_, overlay_Q_, overlay_z_;
  std::vector<double> overlay_Q_x_;  // rows without a printed Q are left out of the Q plot
  Plot n_plot_, Q_plot_, z_plot_;
};

class RegimeMapPanel {
 public:
  RegimeMapPanel();
  ~RegimeMapPanel();
  RegimeMapPanel(const RegimeMapPanel&) = delete;
  RegimeMapPanel& operator=(const RegimeMapPanel&) = delete;

  void draw(Document& document, Renderer& renderer);

  const std::string& x_key() const { return x_key_; }
  const std::string& y_key() const { return y_key_; }
  // For tests and the docs' figure: the last completed map's size and time.
  double last_map_ms() const { return last_map_ms_; }
  // True from a (re)start until every row has been computed.
  bool computing() const;

 private:
  struct Job;
  void restart(const Parameters& base);
  void stop();
  void update_image(Renderer& renderer);

  std::string x_key_ = "h";
  std::string y_key_ = "w";
  double x_from_ = 300.0, x_to_ = 3000.0;
  double y_from_ = 3e-7, y_to_ = 1e-5;
  int resolution_ = 256;
  bool show_z_ = false;

  std::shared_ptr<Job> job_;
  std::vector<std::thread> workers_;
  Parameters job_base_;
  bool job_started_ = false;
  int image_ = -1;  // the renderer's image of the map
  int image_size_ = 0;
  std::vector<std::uint32_t> pixels_;
  int rows_shown_ = -1;
  double last_map_ms_ = 0.0;
};

}  // namespace foldlab::gui
