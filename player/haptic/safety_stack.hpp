#pragma once
// The one safety stack of the force loop: every force the loop sends has gone through it, in this
// order (each layer sets its flag in the cycle's flags when it acts):
//
//   1. gate     start-up gate: none of the scene's force until |F_scene| < gate_force_N, then the
//               scene's force ramps in linearly over ramp_time_s (flag while held or ramping);
//   2. wall     soft wall: within wall_margin_m of a face of the device workspace (a box centred on
//               the origin), a spring pushes the probe back inward, on each axis i past the inner
//               face at h_i = extent_i / 2 - margin:  F_i -= k (|p_i| - h_i) sign(p_i),
//               with k = min(wall_stiffness_N_per_m, the device's Kmax);
//   3. clamp    |F| <= clamp_N = min(the device's Fmax, the scene's max_force_N), scaling the whole
//               vector; a non-finite force becomes zero;
//   4. slew     |F(n) - F(n-1)| <= max_slew_N_per_ms * dt_ms, dt from the cycle times (the nominal
//               period on the first cycle, which starts from zero force);
//   5. stale    stale-input watchdog: the probe's sequence unchanged (no new position) for
//               stale_limit_cycles cycles in a row: zero force and the stale_input fault;
//   6. overrun  overrun_limit_cycles overruns in a row (SafetyInput::previous_overran; the loop
//               passes cycles whose own work took longer than a period): zero force and the
//               overruns fault.
//
// A fault latches: every later apply() returns zero with the fault's flag, until reset(). stop()
// and device_fault() return zero at once too (flags stop, device).
//
// Safety wins over smoothness: on a fault or a stop, zero is sent on that very cycle in one step,
// even when the step exceeds the slew limit. Every other cycle, the gate ramp included, keeps both
// |F| <= clamp_N and the slew limit (the slew step moves from one force inside the clamp ball
// towards another, so it stays inside).
//
// Threads: pure and allocation-free; one thread at a time (the loop thread) calls it.
#include <cstdint>
#include <string>

#include "player/haptic/haptic_port.hpp"

namespace vimg {

// One bit per layer and per reason for zero force.
namespace safety_flag {
inline constexpr std::uint32_t gate = 1u << 0;
inline constexpr std::uint32_t wall = 1u << 1;
inline constexpr std::uint32_t clamp = 1u << 2;
inline constexpr std::uint32_t slew = 1u << 3;
inline constexpr std::uint32_t stale = 1u << 4;
inline constexpr std::uint32_t overrun = 1u << 5;
inline constexpr std::uint32_t device = 1u << 6;  // zero: a device read or write failed
inline constexpr std::uint32_t stop = 1u << 7;    // zero: the loop stopped
}  // namespace safety_flag

// "gate|clamp|slew" in layer order, "" for none (allocates: not for the loop thread).
std::string safety_flag_names(std::uint32_t flags);

// Why the loop must stop.
enum class ForceFault : std::uint8_t {
  none = 0,
  device_read,   // the device read failed (PortFault says how)
  device_write,  // the device write failed
  stale_input,   // the watchdog: no new probe position for too many cycles
  overruns,      // too many overruns in a row
};

// What the scene and the program ask for; the device's limits cap them (see SafetyStack).
struct SafetySettings {
  double max_force_N = 3.3;  // the scene's limit (DeviceProfile::max_force_N)
  double gate_force_N = 0.2;
  double ramp_time_s = 0.5;
  double wall_margin_m = 0.010;
  double wall_stiffness_N_per_m = 200.0;  // capped to the device's Kmax
  int stale_limit_cycles = 20;            // 20 ms at 1 kHz
  int overrun_limit_cycles = 10;         // cycles in a row whose work took longer than a period
};

struct SafetyInput {
  double time_s = 0.0;
  Vec3 scene_N;                 // the scene's force this cycle (summed, cross-faded)
  Vec3 position_m;              // the probe
  std::uint64_t sequence = 0;   // ProbeSample::sequence
  bool previous_overran = false;  // the previous cycle's work took longer than a period (catch_up.hpp)
};

struct SafetyOutput {
  Vec3 force_N;  // what to send
  std::uint32_t flags = 0;
  ForceFault fault = ForceFault::none;  // set on the cycle a fault trips and after
};

class SafetyStack {
 public:
  // period_s: the loop's nominal period (the first cycle's dt for the slew limit).
  SafetyStack(const SafetySettings& settings, const ForceDeviceLimits& device, double period_s) noexcept;

  SafetyOutput apply(const SafetyInput& input) noexcept;
  // Zero at once (flag stop): the loop is stopping.
  SafetyOutput stop() noexcept;
  // Zero at once (flag device), latched: a device read or write failed (`which` says which).
  SafetyOutput device_fault(ForceFault which) noexcept;
  // Back to the start: gated, no fault, counters cleared, last force zero.
  void reset() noexcept;

  ForceFault fault() const noexcept { return fault_; }
  const Vec3& last_force_N() const noexcept { return last_N_; }

  // The effective limits.
  double clamp_N() const noexcept { return clamp_N_; }
  double max_slew_N_per_ms() const noexcept { return slew_N_per_ms_; }
  double wall_stiffness_N_per_m() const noexcept { return wall_k_; }
  double wall_margin_m() const noexcept { return margin_m_; }
  const Vec3& workspace_m() const noexcept { return workspace_m_; }
  int stale_limit_cycles() const noexcept { return stale_limit_; }
  int overrun_limit_cycles() const noexcept { return overrun_limit_; }

  // The soft wall's force at a probe position (layer 2 alone).
  Vec3 wall_force_N(const Vec3& position_m) const noexcept;

 private:
  SafetyOutput zero(std::uint32_t flags) noexcept;

  // Limits.
  double clamp_N_;
  double slew_N_per_ms_;
  double wall_k_;
  double margin_m_;
  Vec3 workspace_m_;
  double gate_force_N_;
  double ramp_time_s_;
  int stale_limit_;
  int overrun_limit_;
  double period_s_;
  // State.
  bool gated_ = true;
  double ramp_start_s_ = 0.0;
  bool have_last_ = false;
  double last_time_s_ = 0.0;
  Vec3 last_N_;
  bool have_sequence_ = false;
  std::uint64_t last_sequence_ = 0;
  int stale_cycles_ = 0;
  int overruns_in_row_ = 0;
  ForceFault fault_ = ForceFault::none;
};

}  // namespace vimg
