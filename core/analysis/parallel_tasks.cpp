#include "core/analysis/parallel_tasks.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/model/hardware_threads.hpp"

namespace foldlab {

int resolve_thread_count(int requested) {
  return requested > 0 ? requested : hardware_threads();
}

bool run_tasks(std::size_t count, int threads,
               const std::function<void(std::size_t, const std::atomic<bool>& stop)>& task,
               const std::function<bool(double)>& progress) {
  if (count == 0) {
    return !progress || progress(1.0);
  }
  if (resolve_thread_count(threads) <= 1 || count == 1) {
    // On the calling thread: the only way in a build without threads, and no pool for one task.
    const std::atomic<bool> stop{false};
    for (std::size_t i = 0; i < count; ++i) {
      task(i, stop);
      if (progress && !progress(static_cast<double>(i + 1) / static_cast<double>(count))) {
        return false;
      }
    }
    return true;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::condition_variable finished_one;
  std::size_t done = 0;
  std::exception_ptr error;
  auto work = [&] {
    while (!stop.load()) {
      const std::size_t i = next.fetch_add(1);
      if (i >= count) {
        return;
      }
      try {
        task(i, stop);
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!error) {
          error = std::current_exception();
        }
        stop.store(true);
      }
      {
        const std::lock_guard lock(mutex);
        ++done;
      }
      finished_one.notify_one();
    }
  };
  const auto pool_size = std::min(static_cast<std::size_t>(resolve_thread_count(threads)), count);
  bool cancelled = false;
  {
    // Joined when the block ends, however it ends (std::jthread, which not every standard
    // library has yet).
    struct Pool {
      std::vector<std::thread> threads;
      ~Pool() {
        for (std::thread& thread : threads) {
          thread.join();
        }
      }
    } pool;
    for (std::size_t k = 0; k < pool_size; ++k) {
      pool.threads.emplace_back(work);
    }
    std::unique_lock lock(mutex);
    std::size_t reported = 0;
    while (reported < count && !stop.load()) {
      finished_one.wait(lock, [&] { return done != reported || stop.load(); });
      reported = done;
      lock.unlock();
      if (progress && !stop.load() &&
          !progress(static_cast<double>(reported) / static_cast<double>(count))) {
        cancelled = true;
        stop.store(true);
      }
      lock.lock();
    }
  }  // the pool joins here
  if (error) {
    std::rethrow_exception(error);
  }
  return !cancelled;
}

}  // namespace foldlab
