// "Fit to measurements": the explorer's window for `foldlab calibrate` (core/calibration.hpp). It
// loads a measurements file, runs the calibration in the background (app/gui/calibration_job.hpp:
// on a thread, or a slice a frame in the browser) with a progress bar and
// a cancel button, shows the fit beside its held-out figures, and applies the fitted constants to
// the current parameters with one button. It also says which constants the preset carries and
// whether eq. 7 is the paper's form or the calibrated one.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "app/gui/background_job.hpp"
#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/file_dialog.hpp"
#include "core/analysis/calibration.hpp"
#include "core/io/measurements.hpp"
#include "core/io/preset.hpp"

namespace foldlab::gui {

// The paper's Tables 1-2 and Fig. 4 as shipped (data/ beside the `presets` folder), empty when
// not found.
std::filesystem::path shipped_measurements_file(std::filesystem::path presets);

class CalibrationPanel : public Panel {
 public:
  CalibrationPanel();
  // Cancels a running calibration and waits for its thread (the job does).
  ~CalibrationPanel();
  CalibrationPanel(const CalibrationPanel&) = delete;
  CalibrationPanel& operator=(const CalibrationPanel&) = delete;

  // A small button that opens the window, with the current model's form beside it (for the
  // Presets panel).
  void open_button(const Parameters& current);

  // The file dialog's title for "Choose...": a measurements file.
  static constexpr const char* kChooseDataModal = "Choose a measurements file";

  const char* name() const override { return "Fit to measurements"; }
  const char* key() const override { return "calibration"; }
  // The window, when open. "Apply" sets the fitted K (as c at the edited Poisson ratio) and p
  // through Document::apply, one undo step; the preset as loaded shows its own constants.
  void draw(PanelContext& context) override;
  bool busy() const override { return running(); }
  // From the start of a run until the window has taken its result.
  bool running() const { return job_.pending(); }
  // For `gui --report`: {"calibration": {open, data_path, data_rows (null when nothing is
  // loaded), data_message, data_message_is_error}}.
  nlohmann::json report() const;
  void report(nlohmann::json& state, PanelContext& context) const override;

 private:
  void load_data();
  void start(const Parameters& base, const std::function<void()>& wake);
  void collect_finished_run();
  void place_window();
  void constants_section(const Parameters& edited, const Preset& loaded);
  void measurements_section(FileDialog& files, UiStatus& status);
  void fit_section(const Parameters& edited, const std::function<void()>& wake);
  void results_section();
  void apply_section(Document& document);

  bool open_ = false;
  bool focus_on_open_ = false;
  char data_path_[1024] = {};
  std::optional<MeasurementSet> data_;
  std::string data_message_;
  bool data_message_is_error_ = false;
  int fit_choice_ = 0;  // 0: K alone, 1: K and p

  BackgroundJob<CalibrationReport> job_;  // the run, with its progress and cancel

  std::optional<CalibrationReport> report_;  // the last completed run, shown
  std::string run_message_;
  bool run_message_is_error_ = false;
};

}  // namespace foldlab::gui
