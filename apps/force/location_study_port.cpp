#include "apps/force/location_study_port.hpp"

namespace vimg::force_app {

bool MarkingPort::read(double time_s, ProbeSample& sample) {
  double clock_s = time_s;
  if (simulated_) {
    ++reads_;
    clock_s = static_cast<double>(reads_) / rate_hz_;  // 3300 / 1000 is 3.3, where 3300 x 0.001 is not
  }
  if (!device_.read(clock_s, sample)) return false;
  clock_s_.store(clock_s, std::memory_order_relaxed);
  if (simulated_) {
    if (press_time_s_ && clock_s >= *press_time_s_) {
      sample.buttons |= 1u;
    } else {
      sample.buttons &= ~1u;
    }
  }
  const bool down = (sample.buttons & 1u) != 0;
  const bool key = key_pressed_.exchange(false, std::memory_order_acq_rel);
  const bool pressed = key || (armed_ && down);
  if (!down) armed_ = true;
  if (pressed && !marked_.load(std::memory_order_relaxed)) {
    const Vec3 at = simulated_ ? simulated_->hand_position_m(clock_s) : sample.position_m;
    mark_x_.store(at.x, std::memory_order_relaxed);
    mark_y_.store(at.y, std::memory_order_relaxed);
    mark_z_.store(at.z, std::memory_order_relaxed);
    mark_time_s_.store(clock_s, std::memory_order_relaxed);
    marked_.store(true, std::memory_order_release);
  }
  return true;
}

ProbeMark MarkingPort::mark() const {
  ProbeMark m;
  if (!marked()) return m;
  m.position_m = {mark_x_.load(std::memory_order_relaxed), mark_y_.load(std::memory_order_relaxed),
                  mark_z_.load(std::memory_order_relaxed)};
  m.time_s = mark_time_s_.load(std::memory_order_relaxed);
  return m;
}

}  // namespace vimg::force_app
