// Independent tasks on a few threads, with progress and cancellation on the calling thread: the
// row tabulations and the many small fits of a calibration and its coverage check.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace foldlab {

// `requested` threads, or std::thread::hardware_concurrency() (at least 1) when <= 0.
int resolve_thread_count(int requested);

// Runs task(i, stop) for every i in [0, count) on resolve_thread_count(threads) threads, handing
// out i in order. The calling thread only waits: after each task ends it calls
// progress(tasks done / count), so progress need not be thread-safe. When progress returns false,
// no further task starts and `stop` turns true for the running ones to poll; run_tasks then returns
// false once every thread has stopped. A task's exception stops the rest the same way and is
// rethrown here. Each task must write only its own results: which thread runs it is not fixed.
bool run_tasks(std::size_t count, int threads,
               const std::function<void(std::size_t, const std::atomic<bool>& stop)>& task,
               const std::function<bool(double)>& progress = {});

}  // namespace foldlab
