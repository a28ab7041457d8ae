// "Fit to measurements": the explorer's window for `foldlab calibrate` (core/calibration.hpp). It
// loads a measurements file, runs the calibration on a background thread with a progress bar and
// a cancel button, shows the fit beside its held-out figures, and applies the fitted constants to
// the current parameters with one button. It also says which constants the preset carries and
// whether eq. 7 is the paper's form or the calibrated one.
#pragma once

#include <atomic>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "app/gui/renderer.hpp"
#include "core/analysis/calibration.hpp"
#include "core/io/measurements.hpp"
#include "core/io/preset.hpp"

namespace foldlab::gui {

// The paper's Tables 1-2 and Fig. 4 as shipped (data/ beside the `presets` folder), empty when
// not found.
std::filesystem::path shipped_measurements_file(std::filesystem::path presets);

class CalibrationPanel {
 public:
  CalibrationPanel();
  // Cancels a running calibration and waits for its thread: it reads this object's members.
  ~CalibrationPanel();
  CalibrationPanel(const CalibrationPanel&) = delete;
  CalibrationPanel& operator=(const CalibrationPanel&) = delete;

  // A small button that opens the window, with the current model's form beside it (for the
  // Presets panel).
  void open_button(const Parameters& current);

  // The window, when open. `edited` are the explorer's parameters: "Apply" writes the fitted K
  // (as c at their Poisson ratio) and p into them and returns true, so that the explorer commits
  // them as it does a slider. `loaded` is the preset as loaded, whose constants are shown.
  bool draw(Parameters& edited, const Preset& loaded, Renderer& renderer);
  // From the start of a run until the window has taken its result.
  bool running() const { return worker_.joinable(); }

 private:
  void load_data();
  void start(const Parameters& base);
  void collect_finished_run();
  void results_section();
  bool apply_section(Parameters& edited);

  bool open_ = false;
  bool focus_on_open_ = false;
  char data_path_[1024] = {};
  std::optional<MeasurementSet> data_;
  std::string data_message_;
  bool data_message_is_error_ = false;
  int fit_choice_ = 0;  // 0: K alone, 1: K and p

  // The background run. The worker writes progress_ and, under mutex_, finished_*; the UI thread
  // reads them and joins the worker once running_ is false.
  std::thread worker_;
  std::atomic<bool> running_{false};
  std::atomic<bool> cancel_requested_{false};
  std::atomic<double> progress_{0.0};
  std::mutex mutex_;
  std::optional<CalibrationReport> finished_report_;
  std::string finished_error_;

  std::optional<CalibrationReport> report_;  // the last completed run, shown
  std::string run_message_;
  bool run_message_is_error_ = false;
};

}  // namespace foldlab::gui
