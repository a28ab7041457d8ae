// One way to run work off the frame loop: a thread that runs a callable, which reports its
// progress and looks for a cancel request through a JobToken; the result is taken back on the UI
// thread once the work has returned. The regime map, the calibration window and the photo's fit
// all run through it, so that "busy", progress bars, cancel buttons and waking the sleeping frame
// loop when work finishes mean the same everywhere.
//
// In a build without threads (the browser build: WebAssembly threads need a page served with
// cross-origin isolation headers, which a plain static server or file host does not send) the
// work runs to its end inside start(), on the UI thread: the job is finished when start()
// returns, and everything else behaves as with a thread.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <optional>
#include <thread>
#include <utility>

namespace foldlab::gui {

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kJobsHaveThreads = false;
#else
inline constexpr bool kJobsHaveThreads = true;
#endif

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
  BackgroundJob() = default;
  // Cancels the work and waits for it: the work may read what its owner owns.
  ~BackgroundJob() { stop(); }
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  // Runs `work(token)` on a thread of its own; a job still running is cancelled and waited for
  // first, and a result not yet taken is dropped. `on_done` runs on the job's thread once the
  // work has returned or thrown (and the result can be taken): the frame loop's wake-up.
  template <class Work>
  void start(Work work, std::function<void()> on_done = {}) {
    stop();
    token_.cancel_ = false;
    token_.progress_ = 0.0;
    finished_ = false;
    result_.reset();
    error_ = nullptr;
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
    if (started_) {
      cancel();
      join();
    }
    result_.reset();
    error_ = nullptr;
    finished_ = false;
  }

 private:
  void join() {
    if (thread_.joinable()) {
      thread_.join();
    }
    started_ = false;
  }

  std::thread thread_;    // never started without threads
  bool started_ = false;  // from start() until the result is taken or dropped
  JobToken token_;
  std::atomic<bool> finished_{false};
  std::optional<Result> result_;  // written by the job's thread before finished_
  std::exception_ptr error_;
};

}  // namespace foldlab::gui
