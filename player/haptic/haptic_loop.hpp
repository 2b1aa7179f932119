#pragma once
// The haptic loop: a thread that runs one SafeHapticCycle (read, render, safety stack, write) per
// period, at 1 kHz by default and 100..4000 Hz, on the real-time core (realtime/):
//   - pacing: absolute deadlines start + n * period on CLOCK_MONOTONIC (sleep_until_ns), so
//     lateness never accumulates. After a stall the loop catches up, running the missed cycles
//     back to back, while it is fewer than half SafetySettings::overrun_limit_cycles periods
//     behind; further behind it skips: the schedule moves forward to the latest deadline passed
//     (the rule: realtime/catch_up.hpp). Caught-up cycles keep the slew limit over wall time: the
//     force changes by at most the slew limit times the periods that passed;
//   - priority: request_realtime_priority on the loop thread (SCHED_FIFO when granted);
//   - telemetry: LoopTelemetry (lateness p50/p99/max, overruns, skips, rate). An overrun there is
//     a cycle whose work finished after the next deadline (caught-up cycles too);
//   - the overrun watchdog: the safety stack faults after SafetySettings::overrun_limit_cycles
//     cycles in a row whose own work, from wake-up to end, took longer than a period: work that
//     does not fit. A late wake-up and the cycles caught up after it never count, however many
//     stalls come close together (a thread at normal priority is woken late now and then), so a
//     stall never trips it; a stall inside a cycle's work counts once.
//
// Every cycle's record {time, probe position, force sent, safety flags} goes into an SPSC ring
// (when log_capacity_rows > 0) that another thread drains (ForceLogWriter); a full ring never
// blocks the loop, it counts a dropped row. One slot is kept free for the last row, so the zero
// force sent at stop or at a fault is always logged.
//
// Scenes arrive lock-free: submit_scene stores a pointer in an atomic slot; the loop takes it when
// no cross-fade runs. A faded-out scene goes back through a second atomic slot and is deleted on
// the caller's thread (at the next submit_scene or at stop). The loop object is the one owner of
// every scene it was given; the slots only lend them.
//
// On stop the loop sends zero force (flag stop) before it returns; on a fault (a device read or
// write failed, stale input, overruns) it sends zero on that same cycle and ends (state faulted).
//
// Threads: the loop thread never allocates, locks or throws. The control thread calls
// submit_scene, start, stop and the destructor. Every accessor below may be called from any
// thread (a GUI thread, a status line) while the loop runs; take_log_rows from one consumer thread.
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "player/haptic/safe_haptic_cycle.hpp"
#include "realtime/loop_telemetry.hpp"
#include "realtime/realtime_priority.hpp"
#include "realtime/spsc_ring.hpp"

namespace vimg {

struct HapticLoopConfig {
  double rate_hz = 1000.0;  // 100 .. 4000
  double crossfade_time_s = 0.1;
  SafetySettings safety;
  // SCHED_FIFO priority for the loop thread (1..99), or 0 for normal scheduling. If the system
  // refuses (no CAP_SYS_NICE or rtprio limit), the loop runs at normal priority; see
  // realtime_priority().
  int realtime_priority = 0;
  // Rows the per-cycle log ring holds (0: no log). A second at the loop's rate is plenty when a
  // writer drains it every few milliseconds.
  std::size_t log_capacity_rows = 0;
};

enum class LoopState : std::uint8_t { idle, running, stopped, faulted };
const char* describe(LoopState state) noexcept;  // "idle", "running", "stopped", "fault"

// A consistent-enough view of the loop for a display (each field is read atomically on its own).
struct HapticLoopStatus {
  LoopState state = LoopState::idle;
  ForceFault fault = ForceFault::none;
  PortFault port_fault = PortFault::none;
  std::uint64_t cycles = 0;
  Vec3 position_m;  // the probe, last cycle
  Vec3 force_N;     // the force sent, last cycle
  std::uint32_t flags = 0;  // safety flags, last cycle
  double max_force_N = 0.0;  // the largest |F| sent so far
  std::uint64_t clamp_hits = 0;  // cycles in which the clamp acted
  std::uint64_t log_rows_dropped = 0;
  LoopTimingStats timing;
};

class HapticLoop {
 public:
  HapticLoop(HapticPort& port, HapticLoopConfig config);
  ~HapticLoop();  // stops the loop
  HapticLoop(const HapticLoop&) = delete;
  HapticLoop& operator=(const HapticLoop&) = delete;

  // Hands a scene to the loop; it cross-fades from the current one. Control thread.
  void submit_scene(std::unique_ptr<HapticScene> scene);

  // Starts the thread (the safety stack re-armed: gate, watchdogs, no fault). The loop's time (the
  // time_s the port and the scenes see) goes on from the previous run's last cycle, so it never
  // goes back. False if the rate is outside 100..4000 Hz or it already runs.
  bool start();
  // Stops the thread; the device has received zero force when this returns.
  void stop();

  LoopState state() const { return state_.load(std::memory_order_acquire); }
  bool running() const { return state() == LoopState::running; }
  bool failed() const { return state() == LoopState::faulted; }
  ForceFault fault() const { return fault_.load(std::memory_order_acquire); }
  PortFault port_fault() const { return port_fault_.load(std::memory_order_acquire); }
  // "stale input: no new probe position for 20 cycles", ... ("" without a fault). Allocates.
  std::string fault_text() const;

  std::uint64_t cycles() const { return cycles_.load(std::memory_order_acquire); }
  Vec3 last_sent_N() const;
  Vec3 last_position_m() const;
  std::uint32_t last_flags() const { return flags_.load(std::memory_order_relaxed); }
  double max_sent_N() const { return max_force_N_.load(std::memory_order_relaxed); }
  std::uint64_t clamp_hits() const { return clamp_hits_.load(std::memory_order_relaxed); }
  std::uint64_t log_rows_dropped() const { return log_dropped_.load(std::memory_order_relaxed); }
  // What the loop thread got when it asked for SCHED_FIFO (all zero before the thread asked).
  RealtimePriority realtime_priority() const;
  // Lateness, overruns, skips and rate since start() (from LoopTelemetry). Allocates once per
  // calling thread.
  LoopTimingStats timing() const { return telemetry_.snapshot(); }
  HapticLoopStatus status() const;

  // The effective limits of the safety stack (constant).
  double rate_hz() const { return config_.rate_hz; }
  const SafetyStack& safety() const { return cycle_.safety(); }

  // The per-cycle log (when log_capacity_rows > 0): fills the front of `out` with the oldest rows
  // not yet taken and returns how many. One consumer thread.
  bool logging() const { return log_ != nullptr; }
  std::size_t take_log_rows(std::span<ForceCycleRecord> out);

 private:
  void run();
  void publish(const ForceCycleRecord& record, bool last);
  void release_retired();
  void forget(HapticScene* scene);

  HapticPort& port_;
  HapticLoopConfig config_;
  SafeHapticCycle cycle_;
  LoopTelemetry telemetry_;
  std::unique_ptr<SpscRing<ForceCycleRecord>> log_;
  std::atomic<HapticScene*> pending_{nullptr};
  std::atomic<HapticScene*> retired_{nullptr};
  HapticScene* unreturned_ = nullptr;  // loop thread only
  double previous_runs_s_ = 0.0;  // the loop's time at the last run's end (loop thread while it runs)
  std::vector<std::unique_ptr<HapticScene>> owned_;  // control thread only: the one owner
  std::atomic<bool> stop_requested_{false};
  std::atomic<LoopState> state_{LoopState::idle};
  std::atomic<ForceFault> fault_{ForceFault::none};
  std::atomic<PortFault> port_fault_{PortFault::none};
  std::atomic<std::uint64_t> cycles_{0};
  std::atomic<double> sent_x_{0.0}, sent_y_{0.0}, sent_z_{0.0};
  std::atomic<double> probe_x_{0.0}, probe_y_{0.0}, probe_z_{0.0};
  std::atomic<std::uint32_t> flags_{0};
  std::atomic<double> max_force_N_{0.0};
  std::atomic<std::uint64_t> clamp_hits_{0};
  std::atomic<std::uint64_t> log_dropped_{0};
  std::atomic<int> priority_requested_{0};
  std::atomic<bool> priority_granted_{false};
  std::atomic<int> priority_errno_{0};
  std::thread thread_;
};

}  // namespace vimg
