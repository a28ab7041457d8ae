// The one helper for work off the frame loop: start, progress, cancel, the result (or what the
// work threw), the wake-up when it finishes, and a destructor that waits for the work.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "app/gui/background_job.hpp"

namespace foldlab::gui {
namespace {

using namespace std::chrono_literals;

// Spins until `done` (or 10 s pass, which fails the test that waits).
template <class Done>
bool wait_until(Done done) {
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) {
      return false;
    }
    std::this_thread::sleep_for(1ms);
  }
  return true;
}

TEST(BackgroundJob, RunsTheWorkAndHandsBackItsResultOnce) {
  BackgroundJob<int> job;
  EXPECT_FALSE(job.running());
  EXPECT_FALSE(job.pending());
  EXPECT_EQ(job.take_result(), std::nullopt);
  std::atomic<bool> release{false};
  job.start([&](JobToken& token) {
    token.report(0.5);
    while (!release) {
      std::this_thread::sleep_for(1ms);
    }
    return 42;
  });
  EXPECT_TRUE(job.running());
  EXPECT_TRUE(job.pending());
  ASSERT_TRUE(wait_until([&] { return job.progress() == 0.5; }));
  EXPECT_EQ(job.take_result(), std::nullopt) << "nothing to take while it runs";
  release = true;
  ASSERT_TRUE(wait_until([&] { return job.finished(); }));
  EXPECT_FALSE(job.running());
  EXPECT_TRUE(job.pending()) << "until the result is taken";
  EXPECT_EQ(job.take_result(), 42);
  EXPECT_FALSE(job.pending());
  EXPECT_EQ(job.take_result(), std::nullopt) << "taken once";
}

TEST(BackgroundJob, CancelAsksTheWorkToStopAndItsResultStillComesBack) {
  BackgroundJob<int> job;
  job.start([](JobToken& token) {
    while (!token.cancelled()) {
      std::this_thread::sleep_for(1ms);
    }
    return -1;
  });
  EXPECT_FALSE(job.cancel_requested());
  job.cancel();
  EXPECT_TRUE(job.cancel_requested());
  ASSERT_TRUE(wait_until([&] { return job.finished(); }));
  EXPECT_EQ(job.take_result(), -1);
}

TEST(BackgroundJob, WhatTheWorkThrowsComesBackFromTakeResult) {
  BackgroundJob<int> job;
  job.start([](JobToken&) -> int { throw std::runtime_error("no data"); });
  ASSERT_TRUE(wait_until([&] { return job.finished(); }));
  EXPECT_THROW(job.take_result(), std::runtime_error);
  EXPECT_FALSE(job.pending());
}

TEST(BackgroundJob, AFinishedJobCallsItsWakeUpOnce) {
  BackgroundJob<int> job;
  std::atomic<int> wakes{0};
  job.start([](JobToken&) { return 7; }, [&] { ++wakes; });
  ASSERT_TRUE(wait_until([&] { return wakes.load() == 1; }));
  ASSERT_TRUE(wait_until([&] { return job.finished(); }));
  EXPECT_EQ(job.take_result(), 7);
  EXPECT_EQ(wakes.load(), 1);
}

TEST(BackgroundJob, StartingAgainCancelsAndReplacesTheRunningWork) {
  BackgroundJob<int> job;
  std::atomic<bool> first_cancelled{false};
  job.start([&](JobToken& token) {
    while (!token.cancelled()) {
      std::this_thread::sleep_for(1ms);
    }
    first_cancelled = true;
    return 1;
  });
  job.start([](JobToken& token) {
    EXPECT_FALSE(token.cancelled()) << "a new start has a fresh token";
    return 2;
  });
  EXPECT_TRUE(first_cancelled) << "the first work was stopped and waited for";
  ASSERT_TRUE(wait_until([&] { return job.finished(); }));
  EXPECT_EQ(job.take_result(), 2);
}

TEST(BackgroundJob, TheDestructorCancelsAndWaitsForTheWork) {
  std::atomic<bool> returned{false};
  std::atomic<bool> started{false};
  {
    BackgroundJob<int> job;
    job.start([&](JobToken& token) {
      started = true;
      while (!token.cancelled()) {
        std::this_thread::sleep_for(1ms);
      }
      std::this_thread::sleep_for(20ms);  // still reads what its owner owns
      returned = true;
      return 0;
    });
    ASSERT_TRUE(wait_until([&] { return started.load(); }));
  }
  EXPECT_TRUE(returned) << "the work ended before the job was gone";
}

}  // namespace
}  // namespace foldlab::gui

namespace foldlab::gui {
namespace {

// Sums 0..count-1 one number a step: what a row of the regime map is to its map.
JobSteps<long> counting_steps(int count, std::atomic<int>& next, std::atomic<long>& sum) {
  JobSteps<long> steps;
  steps.step = [count, &next, &sum](JobToken& token) {
    const int i = next++;
    if (i >= count) {
      return true;
    }
    sum += i;
    token.report(static_cast<double>(i + 1) / count);
    return i + 1 >= count;
  };
  steps.finish = [&sum] { return sum.load(); };
  return steps;
}

TEST(BackgroundJobSlices, FrameSlicesRunOnlyWhenTheFrameLoopGivesThemTime) {
  BackgroundJob<long> job(JobRunner::frame_slices);
  std::atomic<int> next{0};
  std::atomic<long> sum{0};
  int woken = 0;
  job.start_slices(counting_steps(1000, next, sum), [&woken] { ++woken; });
  EXPECT_TRUE(job.running());
  EXPECT_EQ(next.load(), 0);  // nothing runs inside start_slices
  // No time at all still gives one step per frame.
  run_job_slices(std::chrono::nanoseconds(0));
  EXPECT_EQ(next.load(), 1);
  EXPECT_TRUE(job.running());
  EXPECT_DOUBLE_EQ(job.progress(), 0.001);
  int frames = 1;
  while (job.running() && frames < 100000) {
    run_job_slices(std::chrono::nanoseconds(0));
    ++frames;
  }
  EXPECT_EQ(frames, 1000);
  EXPECT_EQ(woken, 1);
  EXPECT_EQ(job.take_result(), 999L * 1000L / 2L);
  EXPECT_TRUE(JobSlices::instance().empty());
}

TEST(BackgroundJobSlices, ThreadsAndFrameSlicesGiveTheSameResult) {
  std::atomic<int> next_threaded{0};
  std::atomic<long> sum_threaded{0};
  BackgroundJob<long> threaded(JobRunner::thread);
  JobSteps<long> steps = counting_steps(5000, next_threaded, sum_threaded);
  steps.parallel = 3;
  threaded.start_slices(std::move(steps));
  ASSERT_TRUE(wait_until([&] { return threaded.finished(); }));

  std::atomic<int> next_sliced{0};
  std::atomic<long> sum_sliced{0};
  BackgroundJob<long> sliced(JobRunner::frame_slices);
  sliced.start_slices(counting_steps(5000, next_sliced, sum_sliced));
  while (sliced.running()) {
    run_job_slices(std::chrono::milliseconds(1));
  }
  const long expected = 4999L * 5000L / 2L;
  EXPECT_EQ(threaded.take_result(), expected);
  EXPECT_EQ(sliced.take_result(), expected);
}

TEST(BackgroundJobSlices, StopAndRestartDropTheSlicedWork) {
  std::atomic<int> next{0};
  std::atomic<long> sum{0};
  {
    BackgroundJob<long> job(JobRunner::frame_slices);
    job.start_slices(counting_steps(10, next, sum));
    run_job_slices(std::chrono::nanoseconds(0));
    job.stop();
    EXPECT_FALSE(job.pending());
    EXPECT_TRUE(JobSlices::instance().empty());
    run_job_slices(std::chrono::milliseconds(5));
    EXPECT_EQ(next.load(), 1);  // never ran again
    job.start_slices(counting_steps(10, next, sum));
  }  // the destructor stops it too
  EXPECT_TRUE(JobSlices::instance().empty());
}

TEST(BackgroundJobSlices, ACancelledSlicedJobFinishesWithWhatItHas) {
  std::atomic<int> next{0};
  std::atomic<long> sum{0};
  BackgroundJob<long> job(JobRunner::frame_slices);
  job.start_slices(counting_steps(100, next, sum));
  run_job_slices(std::chrono::nanoseconds(0));
  run_job_slices(std::chrono::nanoseconds(0));
  job.cancel();
  run_job_slices(std::chrono::milliseconds(5));
  ASSERT_TRUE(job.finished());
  EXPECT_EQ(job.take_result(), 0L + 1L);
}

}  // namespace
}  // namespace foldlab::gui
