#include "hal/force/simulated_force_device.hpp"

#include <algorithm>
#include <cmath>

#include "primitives/force_sum.hpp"

namespace vimg {

SimulatedForceDevice::SimulatedForceDevice(std::vector<HandPathPoint> path, HandModel hand, ForceDeviceLimits limits)
    : path_(std::move(path)), hand_(hand), limits_(limits) {
  if (!path_.empty()) {
    time_s_ = path_.front().time_s;
    position_m_ = path_.front().position_m;
  }
}

Vec3 SimulatedForceDevice::hand_position_m(double time_s) const {
  if (path_.empty()) return {};
  if (time_s <= path_.front().time_s) return path_.front().position_m;
  if (time_s >= path_.back().time_s) return path_.back().position_m;
  const auto upper = std::upper_bound(path_.begin(), path_.end(), time_s,
                                      [](double t, const HandPathPoint& p) { return t < p.time_s; });
  const auto lower = upper - 1;
  const double u = (time_s - lower->time_s) / (upper->time_s - lower->time_s);
  return lower->position_m + u * (upper->position_m - lower->position_m);
}

bool SimulatedForceDevice::read(double time_s, ProbeSample& sample) {
  if (fail_read_.exchange(false)) return false;
  if (fail_read_at_s_ >= 0.0 && time_s >= fail_read_at_s_) {
    fail_read_at_s_ = -1.0;
    return false;
  }
  const double span = time_s - time_s_;
  if (span > 0.0 && !frozen_.load(std::memory_order_relaxed)) {
    const int steps = std::max(1, static_cast<int>(std::ceil(span / hand_.max_substep_s)));
    const double h = span / steps;
    for (int n = 0; n < steps; ++n) {
      const double t = time_s_ + (n + 1) * h;
      const Vec3 hand = hand_position_m(t);
      const Vec3 hand_velocity = (hand_position_m(t) - hand_position_m(t - h)) / h;
      const Vec3 f = hand_.hand_stiffness_N_per_m * (hand - position_m_) +
                     hand_.hand_damping_N_s_per_m * (hand_velocity - velocity_m_per_s_) -
                     hand_.device_damping_N_s_per_m * velocity_m_per_s_ + force_N_;
      velocity_m_per_s_ += (h / hand_.probe_mass_kg) * f;
      const Vec3 step = h * velocity_m_per_s_;
      work_J_ += dot(force_N_, step);
      position_m_ += step;
    }
    time_s_ = time_s;
    ++sequence_;
  }
  sample.position_m = position_m_;
  sample.velocity_m_per_s = velocity_m_per_s_;
  sample.buttons = 0;
  sample.sequence = sequence_;
  return true;
}

bool SimulatedForceDevice::write_force(const Vec3& force_N) {
  if (fail_write_.exchange(false)) {
    force_N_ = {};
    return false;
  }
  ++writes_;
  force_N_ = clamp_magnitude(force_N, limits_.max_force_N);
  return true;
}

}  // namespace vimg
