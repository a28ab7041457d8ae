// One way to run work off the frame loop: a thread that runs a callable, which reports its
// progress and looks for a cancel request through a JobToken; the result is taken back on the UI
// thread once the work has returned. The regime map, the calibration window and the photo's fit
// all run through it, so that "busy", progress bars, cancel buttons and waking the sleeping frame
// loop when work finishes mean the same everywhere.
//
// Work that can be cut into slices (the regime map, a row at a time) is started with
// start_slices(): a step that does one bounded piece and a finish that gives the result. With
// threads the steps run on the job's thread (several at once when the steps say they may);
// without threads (the browser build: WebAssembly threads need a page served with cross-origin
// isolation headers, which a plain static server or file host does not send) the frame loop
// runs them on the UI thread through run_job_slices(), a few milliseconds a frame, so the page
// keeps drawing and shows the progress. Monolithic work (start()) runs to its end inside start()
// there: the job is finished when start() returns, and everything else behaves as with a thread.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace foldlab::gui {

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kJobsHaveThreads = false;
#else
inline constexpr bool kJobsHaveThreads = true;
#endif

class JobToken;

// How a job's work runs: on a thread of its own, or in slices that the frame loop runs on the UI
// thread (run_job_slices). The build's default is the first where there are threads.
enum class JobRunner { thread, frame_slices };
inline constexpr JobRunner kDefaultJobRunner =
    kJobsHaveThreads ? JobRunner::thread : JobRunner::frame_slices;

// The sliced jobs waiting for the UI thread, run by the frame loop. Each entry runs its job's
// steps until a deadline and returns true once the job is finished (and leaves the list).
class JobSlices {
 public:
  using Clock = std::chrono::steady_clock;
  using Run = std::function<bool(Clock::time_point deadline)>;
  static JobSlices& instance() {
    static JobSlices slices;
    return slices;
  }
  std::uint64_t add(Run run) {
    runs_.emplace(next_id_, std::make_shared<Run>(std::move(run)));
    return next_id_++;
  }
  void remove(std::uint64_t id) { runs_.erase(id); }
  bool empty() const { return runs_.empty(); }
  // Runs every waiting job's steps, each getting an equal part of `budget` (at least one step
  // each, so that every job moves on however small the budget).
  void run(Clock::duration budget) {
    if (runs_.empty()) {
      return;
    }
    std::vector<std::uint64_t> ids;
    for (const auto& entry : runs_) {
      ids.push_back(entry.first);
    }
    const Clock::duration share = budget / static_cast<int>(ids.size());
    for (std::uint64_t id : ids) {
      const auto found = runs_.find(id);
      if (found == runs_.end()) {
        continue;  // stopped by a job that ran before it in this loop
      }
      // Held here: a step may stop its own job or start others, which changes the list.
      const std::shared_ptr<Run> run = found->second;
      if ((*run)(Clock::now() + share)) {
        runs_.erase(id);
      }
    }
  }

 private:
  std::map<std::uint64_t, std::shared_ptr<Run>> runs_;  // in the order the jobs started
  std::uint64_t next_id_ = 1;
};

// What the frame loop gives background work each frame where there are no threads: a few
// milliseconds, well inside a 60 Hz frame with the drawing.
inline constexpr std::chrono::milliseconds kJobSliceBudget{6};
// The frame loop's call: runs the sliced jobs for about `budget`. Nothing to do with threads.
inline void run_job_slices(std::chrono::steady_clock::duration budget = kJobSliceBudget) {
  JobSlices::instance().run(budget);
}

// Work cut into slices: `step` does one bounded piece and returns true once nothing is left to
// do, `finish` then gives the result (also after a cancel, with what was done). `parallel` > 1:
// the steps may run on that many threads at once (each claims its own piece), where there are
// threads; the result is finished once every thread has seen nothing left.
template <class Result>
struct JobSteps {
  std::function<bool(JobToken&)> step;
  std::function<Result()> finish;
  unsigned parallel = 1;
};

// What a job's work is given: where it reports how far it is, and whether it should stop.
class JobToken {
 public:
  // A fraction in [0, 1]; read by BackgroundJob::progress() from the UI thread.
  void report(double fraction) { progress_.store(fraction, std::memory_order_relaxed); }
  // True once BackgroundJob::cancel() was called (or the job is being destroyed or restarted):
  // the work should return soon, with whatever it has.
  bool cancelled() const { return cancel_.load(std::memory_order_relaxed); }

 private:
  template <class>
  friend class BackgroundJob;
  std::atomic<double> progress_{0.0};
  std::atomic<bool> cancel_{false};
};

// `Result` is what the work returns. Not thread-safe itself: call its members from one thread
// (the UI's); only the work and `on_done` run on the job's thread.
template <class Result>
class BackgroundJob {
 public:
  explicit BackgroundJob(JobRunner runner = kDefaultJobRunner) : runner_(runner) {}
  // Cancels the work and waits for it: the work may read what its owner owns.
  ~BackgroundJob() { stop(); }
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  // Runs `work(token)` on a thread of its own; a job still running is cancelled and waited for
  // first, and a result not yet taken is dropped. `on_done` runs on the job's thread once the
  // work has returned or thrown (and the result can be taken): the frame loop's wake-up.
  template <class Work>
  void start(Work work, std::function<void()> on_done = {}) {
    restart();
    auto run = [this, work = std::move(work), on_done = std::move(on_done)]() mutable {
      try {
        result_.emplace(work(token_));
      } catch (...) {
        error_ = std::current_exception();
      }
      finished_.store(true, std::memory_order_release);
      if (on_done) {
        on_done();
      }
    };
    started_ = true;
    if constexpr (kJobsHaveThreads) {
      thread_ = std::thread(std::move(run));
    } else {
      run();
    }
  }

  // Runs `steps` (see JobSteps) as start() runs its work: on the job's thread, or a slice a frame
  // through run_job_slices() for a JobRunner::frame_slices job. `on_done` as for start().
  void start_slices(JobSteps<Result> steps, std::function<void()> on_done = {}) {
    if (runner_ == JobRunner::thread) {
      start(
          [steps = std::move(steps)](JobToken& token) {
            const auto work = [&] {
              while (!token.cancelled() && !steps.step(token)) {
              }
            };
            std::vector<std::thread> helpers;
            for (unsigned t = 1; t < steps.parallel; ++t) {
              helpers.emplace_back(work);
            }
            work();
            for (std::thread& helper : helpers) {
              helper.join();
            }
            return steps.finish();
          },
          std::move(on_done));
      return;
    }
    restart();
    started_ = true;
    slices_id_ =
        JobSlices::instance().add([this, steps = std::move(steps), on_done = std::move(on_done)](
                                      JobSlices::Clock::time_point deadline) {
          try {
            bool done = token_.cancelled();
            while (!done) {
              done = steps.step(token_) || token_.cancelled();
              if (JobSlices::Clock::now() >= deadline) {
                break;
              }
            }
            if (!done) {
              return false;
            }
            result_.emplace(steps.finish());
          } catch (...) {
            error_ = std::current_exception();
          }
          slices_id_ = 0;
          finished_.store(true, std::memory_order_release);
          if (on_done) {
            on_done();
          }
          return true;
        });
  }

  // From start() until the work has returned.
  bool running() const { return started_ && !finished(); }
  // The work has returned and its result waits for take_result().
  bool finished() const { return started_ && finished_.load(std::memory_order_acquire); }
  // running() or finished(): there is work whose outcome the owner has not seen yet.
  bool pending() const { return started_; }
  // The last fraction the work reported (0 at the start).
  double progress() const { return token_.progress_.load(std::memory_order_relaxed); }
  // Asks the work to stop; it still finishes (with what it has) and its result is taken as usual.
  void cancel() { token_.cancel_ = true; }
  bool cancel_requested() const { return token_.cancelled(); }

  // Once finished(): the work's result (rethrowing what it threw), and the job is idle again.
  // nullopt while it runs or when there is nothing to take.
  std::optional<Result> take_result() {
    if (!finished()) {
      return std::nullopt;
    }
    join();
    if (std::exception_ptr error = std::exchange(error_, nullptr)) {
      result_.reset();
      std::rethrow_exception(error);
    }
    return std::exchange(result_, std::nullopt);
  }

  // Cancels the work, waits for it and drops its result.
  void stop() {
    if (slices_id_ != 0) {
      // Sliced work not finished never runs again.
      JobSlices::instance().remove(std::exchange(slices_id_, 0));
      started_ = false;
    }
    if (started_) {
      cancel();
      join();
    }
    result_.reset();
    error_ = nullptr;
    finished_ = false;
  }

 private:
  // A job still running is cancelled and waited for, and what it left is dropped.
  void restart() {
    stop();
    token_.cancel_ = false;
    token_.progress_ = 0.0;
    finished_ = false;
    result_.reset();
    error_ = nullptr;
  }

  void join() {
    if (thread_.joinable()) {
      thread_.join();
    }
    started_ = false;
  }

  JobRunner runner_;
  std::uint64_t slices_id_ = 0;  // in JobSlices while sliced work waits for its next step
  std::thread thread_;           // never started without threads
  bool started_ = false;         // from start() until the result is taken or dropped
  JobToken token_;
  std::atomic<bool> finished_{false};
  std::optional<Result> result_;  // written by the job's thread before finished_
  std::exception_ptr error_;
};

}  // namespace foldlab::gui
