#pragma once
// The haptic loop: a thread that reads the device, runs one HapticCycle and sends the force, at
// 1 kHz by default and up to 4 kHz, paced by absolute deadlines on CLOCK_MONOTONIC
// (clock_nanosleep with TIMER_ABSTIME), so lateness never accumulates.
//
// Real time: the cycle neither allocates nor locks. Scenes arrive through an atomic pointer
// (submit_scene) and are cross-faded in; a faded-out scene goes back through a second atomic
// pointer and is deleted on the caller's thread (at the next submit_scene or at stop). On stop or
// on a device error the loop sends zero force before anything else.
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "player/haptic/haptic_cycle.hpp"

namespace vimg {

struct HapticLoopConfig {
  double rate_hz = 1000.0;  // 100 .. 4000
  HapticCycleConfig cycle;
  // SCHED_FIFO priority for the loop thread (1..99), or 0 for normal scheduling. If the system
  // refuses (no CAP_SYS_NICE or rtprio limit), the loop runs at normal priority; see realtime().
  int realtime_priority = 0;
};

// Wake-up lateness of the loop against its deadlines, in microseconds.
struct JitterStats {
  std::uint64_t cycles = 0;
  double p50_us = 0.0;
  double p99_us = 0.0;
  double max_us = 0.0;
};

class HapticLoop {
 public:
  HapticLoop(HapticPort& port, HapticLoopConfig config);
  ~HapticLoop();  // stops the loop
  HapticLoop(const HapticLoop&) = delete;
  HapticLoop& operator=(const HapticLoop&) = delete;

  // Hands a scene to the loop; it cross-fades from the current one. Call from one thread.
  void submit_scene(std::unique_ptr<HapticScene> scene);

  // Starts the thread. False if the rate is outside 100..4000 Hz or it already runs.
  bool start();
  // Stops the thread; the device has received zero force when this returns.
  void stop();
  bool running() const { return running_.load(); }

  std::uint64_t cycles() const { return cycles_.load(); }
  // The last sent force (for display), written every cycle.
  Vec3 last_sent_N() const;
  // Set when a device read or write failed; the loop then stopped after zeroing the force.
  bool failed() const { return failed_.load(); }
  // True if the loop thread got the requested SCHED_FIFO priority.
  bool realtime() const { return realtime_.load(); }
  // Valid after stop().
  JitterStats jitter() const;

 private:
  void run();
  void release_retired();

  static constexpr std::size_t kHistogramBins = 20000;  // 1 us bins up to 20 ms

  HapticPort& port_;
  HapticLoopConfig config_;
  HapticCycle cycle_;
  std::atomic<HapticScene*> pending_{nullptr};
  std::atomic<HapticScene*> retired_{nullptr};
  HapticScene* unreturned_ = nullptr;  // loop thread only
  std::vector<std::unique_ptr<HapticScene>> owned_;
  std::atomic<bool> stop_requested_{false};
  std::atomic<bool> running_{false};
  std::atomic<bool> failed_{false};
  std::atomic<bool> realtime_{false};
  std::atomic<std::uint64_t> cycles_{0};
  std::atomic<double> sent_x_{0.0}, sent_y_{0.0}, sent_z_{0.0};
  std::vector<std::uint32_t> histogram_;
  double max_late_us_ = 0.0;
  std::thread thread_;
};

}  // namespace vimg
