#include "storage/parallel_tasks.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace vimg {

int worker_thread_count(int requested) {
  if (requested <= 0) requested = static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(requested, 1, kMaxWorkerThreads);
}

void run_tasks(std::size_t count, int threads, const std::function<void(std::size_t index, int worker)>& task) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex first_error_mutex;
  std::exception_ptr first_error;
  const auto work = [&](int worker) {
    for (;;) {
      if (failed.load(std::memory_order_relaxed)) return;
      const std::size_t index = next.fetch_add(1, std::memory_order_relaxed);
      if (index >= count) return;
      try {
        task(index, worker);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(first_error_mutex);
        if (!first_error) first_error = std::current_exception();
        failed.store(true, std::memory_order_relaxed);
      }
    }
  };
  const int helpers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(worker_thread_count(threads)), count)) - 1;
  std::vector<std::thread> started;
  started.reserve(static_cast<std::size_t>(std::max(helpers, 0)));
  for (int worker = 1; worker <= helpers; ++worker) {
    try {
      started.emplace_back(work, worker);
    } catch (const std::system_error&) {
      break;  // the threads already started and this one do the work
    }
  }
  work(0);
  for (std::thread& thread : started) thread.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace vimg
