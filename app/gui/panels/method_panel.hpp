// The Method tab: the solver's iteration one iterate at a time, for teaching. The paper method
// shows L'/L per iterate against its 5 % band; the exact method its fixed-point map over n with
// the staircase from the paper's start to the fixed point. Either method can be viewed whatever
// the model uses, without editing the inputs.
#pragma once

#include <string>
#include <vector>

#include "app/gui/document.hpp"
#include "app/gui/plot_widget.hpp"
#include "core/model/parameters.hpp"
#include "core/model/solver.hpp"

namespace foldlab::gui {

class MethodPanel {
 public:
  void draw(Document& document);

  // The buttons, callable by tests. The first iterate is always shown.
  void step();
  void back();
  void reset();
  void run_to_end();

  int shown() const { return shown_; }  // iterates shown, 1..iterates()
  int iterates() const { return static_cast<int>(trace_.iterates.size()); }
  Method method() const { return method_; }
  const IterationTrace& trace() const { return trace_; }

 private:
  void recompute(const Parameters& current);
  void tolerance_field(Document& document);
  void draw_controls();
  void draw_table();
  void draw_change() const;
  void draw_ratio_plot(float height);
  void draw_map_plot(float height);

  Parameters computed_for_;
  bool computed_ = false;
  Method method_ = Method::paper;
  Method model_method_ = Method::paper;  // the one the model is set to: Results shows its answer
  Method followed_ = Method::paper;  // the model's method when last seen: a change there follows
  bool following_ = false;
  IterationTrace trace_;
  std::vector<CountMapPoint> map_;
  int shown_ = 1;
  static constexpr const char* kToleranceKey = "length_tolerance";
  static constexpr double kPaperTolerance = ModelSettings{}.length_tolerance;  // the paper's 5 %
  char tolerance_text_[32] = {};
  std::string tolerance_problem_;  // a tolerance that is not a number

  // Plot buffers, refilled per frame from the shown iterates.
  std::vector<double> step_x_, ratio_y_, band_x_, band_lo_, band_hi_, one_y_;
  std::vector<double> map_n_, map_count_, map_argument_, diagonal_;
  std::vector<double> stair_x_, stair_y_, visit_x_, visit_y_;
  Plot ratio_plot_, map_plot_;
};

}  // namespace foldlab::gui
