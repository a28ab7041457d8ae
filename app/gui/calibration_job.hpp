// A calibration as a background job's steps (BackgroundJob::start_slices): a row's tabulation
// or a fit each, so that the page, which has no threads, runs it a few milliseconds a frame and
// keeps drawing, while the desktop runs the same steps on its job's thread (each step on every
// core). Set up in the first step, so that what the calibration refuses (CalibrationError) comes
// back from take_result as the work's exception.
#pragma once

#include <memory>
#include <utility>

#include "app/gui/background_job.hpp"
#include "core/analysis/calibration.hpp"
#include "core/io/measurements.hpp"

namespace foldlab::gui {

class CalibrationJob {
 public:
  CalibrationJob(MeasurementSet data, Parameters base, CalibrationOptions options)
      : data_(std::move(data)), base_(std::move(base)), options_(options) {}

  // True once every step has run.
  bool step(JobToken& token) {
    if (!steps_) {
      steps_ = std::make_unique<CalibrationSteps>(data_, base_, options_);
      return false;
    }
    finished_ = steps_->step();
    token.report(steps_->fraction_done());
    return finished_;
  }
  bool finished() const { return finished_; }
  // What calibrate() returns; marked cancelled when not every step ran.
  CalibrationReport report() const {
    if (!steps_) {
      CalibrationReport cancelled;
      cancelled.cancelled = true;
      return cancelled;
    }
    return steps_->report();
  }

 private:
  MeasurementSet data_;
  Parameters base_;
  CalibrationOptions options_;
  std::unique_ptr<CalibrationSteps> steps_;
  bool finished_ = false;
};

// The job's steps for a calibration of `data` on `base`.
inline JobSteps<CalibrationReport> calibration_steps(MeasurementSet data, Parameters base,
                                                     CalibrationOptions options) {
  auto job = std::make_shared<CalibrationJob>(std::move(data), std::move(base), options);
  JobSteps<CalibrationReport> steps;
  steps.step = [job](JobToken& token) { return job->step(token); };
  steps.finish = [job] { return job->report(); };
  return steps;
}

}  // namespace foldlab::gui
