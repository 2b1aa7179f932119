#pragma once
// A simulated force device for tests: a probe of mass m held by a hand that follows a scripted
// path through a spring-damper (k_h, b_h), with viscous friction b_dev in the device. The force
// last written acts on the probe until the next one (zero-order hold, like a real device).
//   m x'' = k_h (h(t) - x) + b_h (h'(t) - x') - b_dev x' + F
// read(time_s) integrates up to time_s in sub-steps (semi-implicit Euler); every read that
// advances the device's time is a new measurement (ProbeSample::sequence counts up). It also
// accounts the work the rendered force does on the probe, W = integral F . dx: a passive virtual
// environment never delivers net energy, so W stays <= 0 (up to what it stores and gives back).
//
// Threads: one thread at a time drives it (the haptic loop's); read() and write_force() neither
// allocate, lock nor throw. The test hooks (fail_next_*, freeze_measurements) may be called from
// another thread.
#include <atomic>
#include <vector>

#include "hal/force/force_device.hpp"

namespace vimg {

struct HandPathPoint {
  double time_s = 0.0;
  Vec3 position_m;
};

struct HandModel {
  double probe_mass_kg = 0.045;
  double hand_stiffness_N_per_m = 300.0;
  double hand_damping_N_s_per_m = 2.0;
  double device_damping_N_s_per_m = 0.002;
  double max_substep_s = 1e-4;
};

class SimulatedForceDevice final : public ForceDevice {
 public:
  // The hand starts at the path's first point with the probe on it; the path is held at its ends.
  SimulatedForceDevice(std::vector<HandPathPoint> path, HandModel hand = {}, ForceDeviceLimits limits = {});

  bool read(double time_s, ProbeSample& sample) override;
  bool write_force(const Vec3& force_N) override;
  ForceDeviceLimits limits() const override { return limits_; }

  Vec3 hand_position_m(double time_s) const;
  const Vec3& force_N() const { return force_N_; }
  double environment_work_J() const { return work_J_; }
  // Test hooks: make the next read or write fail (callable from another thread).
  void fail_next_read() { fail_read_ = true; }
  void fail_next_write() { fail_write_ = true; }
  // Test hook: the first read at or after `time_s` (the time the reader asks for) fails, once. Set
  // before the device is driven; deterministic on the reader's clock, whatever the wall clock does.
  void fail_read_at(double time_s) { fail_read_at_s_ = time_s; }
  int writes() const { return writes_; }
  // Test hook: the device stops measuring (reads succeed, the sequence stays put) until resumed.
  void freeze_measurements(bool frozen) { frozen_ = frozen; }

 private:
  std::vector<HandPathPoint> path_;
  HandModel hand_;
  ForceDeviceLimits limits_;
  double time_s_ = 0.0;
  Vec3 position_m_;
  Vec3 velocity_m_per_s_;
  Vec3 force_N_;
  double work_J_ = 0.0;
  std::atomic<bool> fail_read_{false};
  std::atomic<bool> fail_write_{false};
  double fail_read_at_s_ = -1.0;  // < 0: none
  std::atomic<bool> frozen_{false};
  int writes_ = 0;
  std::uint64_t sequence_ = 0;
};

}  // namespace vimg
