#include "player/haptic/safety_stack.hpp"

#include <algorithm>
#include <cmath>

#include "realtime/catch_up.hpp"

namespace vimg {
namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

double positive_or(double v, double fallback) { return std::isfinite(v) && v > 0.0 ? v : fallback; }

}  // namespace

std::string safety_flag_names(std::uint32_t flags) {
  static constexpr struct {
    std::uint32_t bit;
    const char* name;
  } kNames[] = {{safety_flag::gate, "gate"},       {safety_flag::wall, "wall"},       {safety_flag::clamp, "clamp"},
                {safety_flag::slew, "slew"},       {safety_flag::stale, "stale"},     {safety_flag::overrun, "overrun"},
                {safety_flag::device, "device"},   {safety_flag::stop, "stop"}};
  std::string text;
  for (const auto& n : kNames) {
    if ((flags & n.bit) == 0) continue;
    if (!text.empty()) text += '|';
    text += n.name;
  }
  return text;
}

SafetyStack::SafetyStack(const SafetySettings& settings, const ForceDeviceLimits& device, double period_s) noexcept {
  // A missing or nonsensical limit never loosens anything: the clamp falls to zero force.
  const double device_max = std::isfinite(device.max_force_N) ? std::max(0.0, device.max_force_N) : 0.0;
  const double scene_max = std::isfinite(settings.max_force_N) ? std::max(0.0, settings.max_force_N) : 0.0;
  clamp_N_ = std::min(device_max, scene_max);
  slew_N_per_ms_ = positive_or(device.max_slew_N_per_ms, kDefaultMaxSlew_N_per_ms);
  const double kmax = std::isfinite(device.max_stiffness_N_per_m) ? std::max(0.0, device.max_stiffness_N_per_m) : 0.0;
  wall_k_ = std::clamp(std::isfinite(settings.wall_stiffness_N_per_m) ? settings.wall_stiffness_N_per_m : 0.0, 0.0, kmax);
  workspace_m_ = {std::fabs(device.workspace_m.x), std::fabs(device.workspace_m.y), std::fabs(device.workspace_m.z)};
  const double smallest_half = 0.5 * std::min({workspace_m_.x, workspace_m_.y, workspace_m_.z});
  margin_m_ = std::clamp(std::isfinite(settings.wall_margin_m) ? settings.wall_margin_m : 0.0, 0.0, smallest_half);
  gate_force_N_ = std::isfinite(settings.gate_force_N) ? settings.gate_force_N : 0.0;
  ramp_time_s_ = std::isfinite(settings.ramp_time_s) ? std::max(0.0, settings.ramp_time_s) : 0.0;
  stale_limit_ = std::max(1, settings.stale_limit_cycles);
  overrun_limit_ = std::max(1, settings.overrun_limit_cycles);
  period_s_ = positive_or(period_s, 1e-3);
}

void SafetyStack::reset() noexcept {
  gated_ = true;
  ramp_start_s_ = 0.0;
  have_last_ = false;
  last_time_s_ = 0.0;
  last_N_ = {};
  have_sequence_ = false;
  last_sequence_ = 0;
  stale_cycles_ = 0;
  overruns_in_row_ = 0;
  fault_ = ForceFault::none;
}

Vec3 SafetyStack::wall_force_N(const Vec3& p) const noexcept {
  auto axis = [&](double position, double extent) {
    const double inner = 0.5 * extent - margin_m_;
    const double depth = std::fabs(position) - inner;
    if (!(depth > 0.0)) return 0.0;
    return -wall_k_ * depth * (position > 0.0 ? 1.0 : -1.0);
  };
  return {axis(p.x, workspace_m_.x), axis(p.y, workspace_m_.y), axis(p.z, workspace_m_.z)};
}

SafetyOutput SafetyStack::zero(std::uint32_t flags) noexcept {
  last_N_ = {};
  SafetyOutput out;
  out.flags = flags;
  out.fault = fault_;
  return out;
}

SafetyOutput SafetyStack::stop() noexcept { return zero(safety_flag::stop); }

SafetyOutput SafetyStack::device_fault(ForceFault which) noexcept {
  if (fault_ == ForceFault::none) fault_ = which;
  return zero(safety_flag::device);
}

SafetyOutput SafetyStack::apply(const SafetyInput& in) noexcept {
  const double dt_s = have_last_ ? std::max(0.0, in.time_s - last_time_s_) : period_s_;
  have_last_ = true;
  last_time_s_ = in.time_s;

  // 5 and 6 are counted every cycle, so that a fault trips on the cycle it happens, and a
  // latched fault keeps the force at zero.
  if (!have_sequence_ || in.sequence != last_sequence_) {
    stale_cycles_ = 0;
  } else {
    ++stale_cycles_;
  }
  have_sequence_ = true;
  last_sequence_ = in.sequence;
  overruns_in_row_ = count_overruns_in_row(overruns_in_row_, in.previous_overran);
  if (fault_ == ForceFault::stale_input) return zero(safety_flag::stale);
  if (fault_ == ForceFault::overruns) return zero(safety_flag::overrun);
  if (fault_ != ForceFault::none) return zero(safety_flag::device);

  std::uint32_t flags = 0;
  // 1. Start-up gate.
  Vec3 f;
  if (gated_ && norm(in.scene_N) < gate_force_N_) {
    gated_ = false;
    ramp_start_s_ = in.time_s;
  }
  if (gated_) {
    flags |= safety_flag::gate;
  } else {
    const double ramp = ramp_time_s_ > 0.0 ? std::clamp((in.time_s - ramp_start_s_) / ramp_time_s_, 0.0, 1.0) : 1.0;
    if (ramp < 1.0) flags |= safety_flag::gate;
    f = ramp * in.scene_N;
  }
  // 2. Soft wall.
  if (finite(in.position_m)) {
    const Vec3 wall = wall_force_N(in.position_m);
    if (wall != Vec3{}) {
      flags |= safety_flag::wall;
      f += wall;
    }
  }
  // 3. Clamp.
  if (!finite(f)) {
    f = {};
    flags |= safety_flag::clamp;
  } else {
    const double magnitude = norm(f);
    if (magnitude > clamp_N_) {
      f = clamp_N_ > 0.0 ? f * (clamp_N_ / magnitude) : Vec3{};
      flags |= safety_flag::clamp;
    }
  }
  // 4. Slew limit.
  const double max_step_N = slew_N_per_ms_ * dt_s * 1e3;
  const Vec3 step = f - last_N_;
  const double step_N = norm(step);
  if (step_N > max_step_N) {
    f = last_N_ + step * (max_step_N / step_N);
    flags |= safety_flag::slew;
  }
  // 5. Stale input.
  if (stale_cycles_ >= stale_limit_) {
    fault_ = ForceFault::stale_input;
    return zero(flags | safety_flag::stale);
  }
  // 6. Overruns.
  if (overrun_watchdog_trips(overruns_in_row_, overrun_limit_)) {
    fault_ = ForceFault::overruns;
    return zero(flags | safety_flag::overrun);
  }
  last_N_ = f;
  SafetyOutput out;
  out.force_N = f;
  out.flags = flags;
  return out;
}

}  // namespace vimg
