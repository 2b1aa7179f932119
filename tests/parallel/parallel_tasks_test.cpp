// run_tasks (storage/parallel_tasks.hpp): every task once, on the threads asked for, at once, and
// the first failure reported after every thread has stopped. Runs under TSan (label threaded).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <latch>
#include <stdexcept>
#include <thread>
#include <vector>

#include "storage/parallel_tasks.hpp"

namespace vimg {
namespace {

TEST(ParallelTasks, EveryTaskRunsExactlyOnceOnAKnownWorker) {
  for (const int threads : {1, 2, 3, 8}) {
    constexpr std::size_t kCount = 2000;
    std::vector<std::atomic<int>> runs(kCount);
    std::vector<std::atomic<int>> by_worker(static_cast<std::size_t>(threads));
    std::atomic<int> bad_worker{0};
    run_tasks(kCount, threads, [&](std::size_t index, int worker) {
      runs[index].fetch_add(1);
      if (worker < 0 || worker >= threads) {
        bad_worker.fetch_add(1);
      } else {
        by_worker[static_cast<std::size_t>(worker)].fetch_add(1);
      }
    });
    for (std::size_t i = 0; i < kCount; ++i) ASSERT_EQ(runs[i].load(), 1) << "task " << i << ", " << threads << " threads";
    EXPECT_EQ(bad_worker.load(), 0);
  }
}

TEST(ParallelTasks, TasksRunAtTheSameTime) {
  // Each of three tasks waits for the other two; on fewer threads they would wait in vain.
  std::latch all_started(3);
  std::atomic<int> met{0};
  run_tasks(3, 3, [&](std::size_t, int) {
    all_started.count_down();
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!all_started.try_wait() && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
    if (all_started.try_wait()) met.fetch_add(1);
  });
  EXPECT_EQ(met.load(), 3);
}

TEST(ParallelTasks, TheFirstFailureIsRethrownAndLaterTasksAreSkipped) {
  // One thread: exactly the tasks up to the failing one ran.
  std::atomic<int> ran{0};
  const auto fail_at_10 = [&](std::size_t index, int) {
    ran.fetch_add(1);
    if (index == 10) throw std::runtime_error("band 10 failed");
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  };
  try {
    run_tasks(5000, 1, fail_at_10);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "band 10 failed");
  }
  EXPECT_EQ(ran.load(), 11);
  // Two threads: the other one stops soon after (all 5000 tasks would take over a second).
  ran = 0;
  EXPECT_THROW(run_tasks(5000, 2, fail_at_10), std::runtime_error);
  EXPECT_LT(ran.load(), 2500);
}

TEST(ParallelTasks, NoTasksAndOneThreadWork) {
  int ran = 0;
  run_tasks(0, 4, [&](std::size_t, int) { ++ran; });
  EXPECT_EQ(ran, 0);
  std::vector<std::size_t> order;
  run_tasks(5, 1, [&](std::size_t index, int worker) {
    EXPECT_EQ(worker, 0);
    order.push_back(index);
  });
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4}));  // one thread: in order, on the caller
}

TEST(ParallelTasks, ThreadCountIsClampedAndDefaultsToTheCores) {
  EXPECT_EQ(worker_thread_count(3), 3);
  EXPECT_EQ(worker_thread_count(1000), kMaxWorkerThreads);
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  EXPECT_EQ(worker_thread_count(0), std::clamp(cores, 1, kMaxWorkerThreads));
  EXPECT_EQ(worker_thread_count(-2), worker_thread_count(0));
}

}  // namespace
}  // namespace vimg
