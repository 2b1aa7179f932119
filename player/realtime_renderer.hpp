#pragma once
// The real-time renderer: a thread that renders blocks of drive at a fixed rate and writes them to
// a DriveSink, paced by absolute deadlines (clock_nanosleep, CLOCK_MONOTONIC, TIMER_ABSTIME).
//
// Threads: one producer thread calls push_event(); one control thread calls start(), stop(),
// set_scene() and collect_retired(); stats() may be read from any thread. Events travel through
// a lock-free SPSC queue; scenes travel as raw pointers through another SPSC queue while the
// control side keeps them alive, and come back through a third one when the renderer is done
// with them. The render thread never allocates, locks or blocks except in the sink's write().
// A scene change cross-fades linearly over crossfade_s (two contact mixers, old and new).
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "player/drive_sink.hpp"
#include "player/live_tracker.hpp"
#include "player/scene.hpp"
#include "realtime/spsc_ring.hpp"
#include "player/touch_event.hpp"

namespace vimg {

struct RealtimeOptions {
  double sample_rate_hz = 8000.0;  // 1 .. 48000
  std::size_t block_samples = 64;  // 8 ms at 8 kHz; fewer at low rates (at most 1/50 s per block)
  double crossfade_s = 0.02;
  std::size_t max_contacts = 512;
  std::size_t event_queue_capacity = 1024;
  LiveTrackerOptions tracker;
  // > 0: ask for SCHED_FIFO at this priority (1..99) for the render thread. Needs the privilege
  // (CAP_SYS_NICE or an rtprio limit); without it the thread keeps normal priority and
  // LoopStats::realtime_priority is false.
  int realtime_priority = 0;
};

struct LoopStats {
  double measured_rate_hz = 0.0;  // output samples per second over the last second
  double jitter_p50_s = 0.0;      // wake-up lateness against the absolute deadline
  double jitter_p99_s = 0.0;
  double jitter_max_s = 0.0;
  std::uint64_t blocks = 0;
  std::uint64_t overruns = 0;        // blocks that started more than one block late
  std::uint64_t dropped_events = 0;  // queue full or stale
  std::uint64_t active_contacts = 0;
  bool realtime_priority = false;  // SCHED_FIFO was granted
};

class RealtimeRenderer {
 public:
  explicit RealtimeRenderer(DriveSink& sink, const RealtimeOptions& options = {});
  ~RealtimeRenderer();  // stops
  RealtimeRenderer(const RealtimeRenderer&) = delete;
  RealtimeRenderer& operator=(const RealtimeRenderer&) = delete;

  // Opens the sink and starts the thread. Returns an error message on a bad option.
  std::optional<std::string> start();
  // Stops the thread and closes the sink (zero drive). Safe to call more than once.
  void stop();
  bool running() const { return running_.load(std::memory_order_acquire); }

  // Producer thread. False when the queue is full (the event is dropped).
  bool push_event(const TouchEvent& event);

  // Control thread: play `scene` from now on, cross-fading from the current one. Returns false
  // (and keeps the current scene) if too many changes are still in flight.
  bool set_scene(std::shared_ptr<const Scene> scene);

  LoopStats stats() const;
  std::size_t block_samples() const { return block_samples_; }
  double sample_rate_hz() const { return options_.sample_rate_hz; }

 private:
  void run();
  void collect_retired();
  void render_block(double block_start_s);

  DriveSink& sink_;
  RealtimeOptions options_;
  std::size_t block_samples_;
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<bool> stop_requested_{false};

  SpscRing<TouchEvent> events_;
  SpscRing<const Scene*> scene_in_;
  SpscRing<const Scene*> scene_out_;
  std::vector<std::shared_ptr<const Scene>> owned_scenes_;  // control thread only

  // Render thread state (preallocated).
  struct Impl;
  std::unique_ptr<Impl> impl_;

  // Published statistics.
  static constexpr std::size_t kJitterBuckets = 2000;  // 10 us buckets up to 20 ms, last = overflow
  std::unique_ptr<std::atomic<std::uint32_t>[]> jitter_histogram_;
  std::atomic<double> measured_rate_hz_{0.0};
  std::atomic<double> jitter_max_s_{0.0};
  std::atomic<std::uint64_t> blocks_{0};
  std::atomic<std::uint64_t> overruns_{0};
  std::atomic<std::uint64_t> dropped_events_{0};
  std::atomic<std::uint64_t> active_contacts_{0};
  std::atomic<bool> realtime_priority_{false};
};

}  // namespace vimg
