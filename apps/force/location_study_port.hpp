#pragma once
// The device as a location study sees it: the haptic loop's port to the force device, watching
// button 0 for the participant's mark. The loop reads the device through it every cycle, so the mark
// is taken on the loop thread at the very cycle the button goes down, without a lock:
//
//   - a press is button 0 going down after it has been seen up in this run (a button still held from
//     the previous press does not count), or press() (a key on the terminal standing in for the
//     button, for a device without one), taken at the next cycle;
//   - the mark is the first press only: where the probe was and the loop's time at that cycle.
//
// On a real device the probe's position is the position the device reports. On the simulated device:
//   - the device is read at the loop's own cycle count, n / rate for the n-th read, never the wall
//     clock, so a trial's time, the hand's place on its path and the mark are the same however fast
//     the machine runs (a stall that makes the loop skip deadlines delays the trial, it does not move
//     the hand on);
//   - button 0 goes down at the scripted time (--marks), from the first cycle at or after it;
//   - the mark is the simulated hand's position, the scripted path at that cycle's time: where the
//     participant's hand is, not where the handle is pulled to by the rendered force (the guidance
//     holds the handle up to acrossForce / hand stiffness, about 5 mm, away from the hand).
//
// Threads: read(), write_force() and the rest of the port are the loop thread's (no allocation, lock
// or throw); press(), marked() and mark() may be called from any thread.
#include <atomic>
#include <optional>

#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/haptic_port.hpp"

namespace vimg::force_app {

struct ProbeMark {
  Vec3 position_m;
  double time_s = 0.0;  // the trial's clock at the press: the loop's time (cycles / rate on the simulator)
};

class MarkingPort final : public HapticPort {
 public:
  // A real device: the mark is where the device says the probe is.
  explicit MarkingPort(HapticPort& device) : device_(device) {}
  // The simulated device, read at n / rate_hz (the loop's rate); button 0 goes down at press_time_s
  // (never without).
  MarkingPort(SimulatedForceDevice& device, double rate_hz, std::optional<double> press_time_s)
      : device_(device), simulated_(&device), rate_hz_(rate_hz), press_time_s_(press_time_s) {}
  MarkingPort(const MarkingPort&) = delete;
  MarkingPort& operator=(const MarkingPort&) = delete;

  bool read(double time_s, ProbeSample& sample) override;
  bool write_force(const Vec3& force_N) override { return device_.write_force(force_N); }
  ForceDeviceLimits limits() const override { return device_.limits(); }
  PortFault last_fault() const noexcept override { return device_.last_fault(); }

  // A key stands in for button 0: the next cycle marks (any thread).
  void press() { key_pressed_.store(true, std::memory_order_release); }
  bool marked() const { return marked_.load(std::memory_order_acquire); }
  // The mark, once marked() is true.
  ProbeMark mark() const;
  // The trial's clock: the time of the last read (seconds, the loop's or the simulation's).
  double time_s() const { return clock_s_.load(std::memory_order_relaxed); }

 private:
  HapticPort& device_;
  SimulatedForceDevice* simulated_ = nullptr;
  double rate_hz_ = 0.0;
  std::optional<double> press_time_s_;
  std::uint64_t reads_ = 0;  // loop thread
  bool armed_ = false;       // loop thread: button 0 seen up
  std::atomic<bool> key_pressed_{false};
  std::atomic<bool> marked_{false};
  std::atomic<double> mark_x_{0.0}, mark_y_{0.0}, mark_z_{0.0}, mark_time_s_{0.0};
  std::atomic<double> clock_s_{0.0};
};

}  // namespace vimg::force_app
