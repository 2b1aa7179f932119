#pragma once
// Runs independent tasks on a few threads: the PNG encoder draws and compresses bands of the
// picture and parts of the XML text at once (docs/benchmarks/storage.md, "PNG export").
//
// Threads: run_tasks() blocks its caller, which works as one of the threads. `task` runs on
// several threads at once, for different task indices; `worker` (0 .. threads-1) says which thread
// runs it, so that each thread can keep its own scratch memory. Not for real-time threads: it
// starts threads and allocates.
#include <cstddef>
#include <functional>

namespace vimg {

inline constexpr int kMaxWorkerThreads = 16;

// The threads to use for `requested` (<= 0: one per core), between 1 and kMaxWorkerThreads.
int worker_thread_count(int requested);

// Calls task(index, worker) once for every index in [0, count), claimed in increasing order. When a
// task throws, tasks not yet started are skipped, and the first exception is rethrown here after
// every thread has stopped. When a thread cannot be started, fewer threads do the work.
void run_tasks(std::size_t count, int threads, const std::function<void(std::size_t index, int worker)>& task);

}  // namespace vimg
