#include "player/haptic/haptic_loop.hpp"

#include <algorithm>
#include <cmath>

#include "realtime/catch_up.hpp"
#include "realtime/clock.hpp"

namespace vimg {

const char* describe(LoopState state) noexcept {
  switch (state) {
    case LoopState::idle: return "idle";
    case LoopState::running: return "running";
    case LoopState::stopped: return "stopped";
    case LoopState::faulted: return "fault";
  }
  return "unknown";
}

HapticLoop::HapticLoop(HapticPort& port, HapticLoopConfig config)
    : port_(port),
      config_(config),
      cycle_(port.limits(), config.safety, HapticCycleConfig{config.crossfade_time_s},
             config.rate_hz > 0.0 ? 1.0 / config.rate_hz : 1e-3) {
  if (config_.log_capacity_rows > 0) log_ = std::make_unique<SpscRing<ForceCycleRecord>>(config_.log_capacity_rows);
}

// owned_ is the one owner of every scene, the pending one included: the atomic slots only lend.
HapticLoop::~HapticLoop() { stop(); }

void HapticLoop::forget(HapticScene* scene) {
  owned_.erase(std::remove_if(owned_.begin(), owned_.end(), [&](const auto& p) { return p.get() == scene; }), owned_.end());
}

void HapticLoop::release_retired() {
  if (HapticScene* r = retired_.exchange(nullptr)) forget(r);
}

void HapticLoop::submit_scene(std::unique_ptr<HapticScene> scene) {
  release_retired();
  HapticScene* raw = scene.get();
  owned_.push_back(std::move(scene));
  // A scene the loop never took is replaced: it can go at once.
  if (HapticScene* unseen = pending_.exchange(raw)) forget(unseen);
}

bool HapticLoop::start() {
  if (thread_.joinable() || !(config_.rate_hz >= 100.0 && config_.rate_hz <= 4000.0)) return false;
  // No loop thread runs: everything the loop writes can be reset here.
  telemetry_.reset();
  cycle_.reset();
  stop_requested_ = false;
  fault_ = ForceFault::none;
  port_fault_ = PortFault::none;
  cycles_ = 0;
  flags_ = 0;
  max_force_N_ = 0.0;
  clamp_hits_ = 0;
  log_dropped_ = 0;
  state_.store(LoopState::running, std::memory_order_release);
  thread_ = std::thread([this] { run(); });
  return true;
}

void HapticLoop::stop() {
  stop_requested_ = true;
  if (thread_.joinable()) thread_.join();
  LoopState running = LoopState::running;
  state_.compare_exchange_strong(running, LoopState::stopped);
  release_retired();
}

Vec3 HapticLoop::last_sent_N() const {
  return {sent_x_.load(std::memory_order_relaxed), sent_y_.load(std::memory_order_relaxed), sent_z_.load(std::memory_order_relaxed)};
}

Vec3 HapticLoop::last_position_m() const {
  return {probe_x_.load(std::memory_order_relaxed), probe_y_.load(std::memory_order_relaxed), probe_z_.load(std::memory_order_relaxed)};
}

RealtimePriority HapticLoop::realtime_priority() const {
  RealtimePriority p;
  p.requested = priority_requested_.load(std::memory_order_acquire);
  p.granted = priority_granted_.load(std::memory_order_acquire);
  p.error_number = priority_errno_.load(std::memory_order_acquire);
  return p;
}

HapticLoopStatus HapticLoop::status() const {
  HapticLoopStatus s;
  s.state = state();
  s.fault = fault();
  s.port_fault = port_fault();
  s.cycles = cycles();
  s.position_m = last_position_m();
  s.force_N = last_sent_N();
  s.flags = last_flags();
  s.max_force_N = max_sent_N();
  s.clamp_hits = clamp_hits();
  s.log_rows_dropped = log_rows_dropped();
  s.timing = timing();
  return s;
}

std::string HapticLoop::fault_text() const {
  switch (fault()) {
    case ForceFault::none: return {};
    case ForceFault::device_read: return std::string("device read failed: ") + describe(port_fault());
    case ForceFault::device_write: return std::string("device write failed: ") + describe(port_fault());
    case ForceFault::stale_input:
      return "stale input: the device sent no new probe position for " + std::to_string(safety().stale_limit_cycles()) +
             " cycles";
    case ForceFault::overruns:
      return std::to_string(safety().overrun_limit_cycles()) +
             " overruns in a row: the cycle's work took longer than the loop's period";
  }
  return "unknown fault";
}

std::size_t HapticLoop::take_log_rows(std::span<ForceCycleRecord> out) { return log_ ? log_->pop_some(out) : 0; }

void HapticLoop::publish(const ForceCycleRecord& r, bool last) {
  sent_x_.store(r.force_N.x, std::memory_order_relaxed);
  sent_y_.store(r.force_N.y, std::memory_order_relaxed);
  sent_z_.store(r.force_N.z, std::memory_order_relaxed);
  probe_x_.store(r.position_m.x, std::memory_order_relaxed);
  probe_y_.store(r.position_m.y, std::memory_order_relaxed);
  probe_z_.store(r.position_m.z, std::memory_order_relaxed);
  flags_.store(r.flags, std::memory_order_relaxed);
  const double magnitude = norm(r.force_N);
  if (magnitude > max_force_N_.load(std::memory_order_relaxed)) max_force_N_.store(magnitude, std::memory_order_relaxed);
  if ((r.flags & safety_flag::clamp) != 0) clamp_hits_.fetch_add(1, std::memory_order_relaxed);
  if (log_) {
    // Ordinary rows leave one slot free, so that the last row always fits.
    const bool room = last ? log_->push(r) : (log_->size() + 1 < log_->capacity() && log_->push(r));
    if (!room) log_dropped_.fetch_add(1, std::memory_order_relaxed);
  }
  cycles_.fetch_add(1, std::memory_order_release);
}

void HapticLoop::run() {
  const RealtimePriority priority = request_realtime_priority(config_.realtime_priority);
  priority_requested_.store(priority.requested, std::memory_order_release);
  priority_granted_.store(priority.granted, std::memory_order_release);
  priority_errno_.store(priority.error_number, std::memory_order_release);

  const auto period_ns = static_cast<std::int64_t>(std::llround(1e9 / config_.rate_hz));
  // The catch-up rule (realtime/catch_up.hpp): half the overrun limit; the watchdog counts only
  // work that does not fit in the period, never the cycles caught up after a stall.
  const std::int64_t start_ns = monotonic_ns();
  PacedSchedule schedule{period_ns, haptic_catch_up_periods(cycle_.safety().overrun_limit_cycles()), start_ns};
  bool overran_last = false;
  for (;;) {
    sleep_until_ns(next_deadline_ns(schedule));
    const std::int64_t woke_ns = monotonic_ns();
    telemetry_.record_wake(woke_ns, schedule.deadline_ns);
    if (on_wake(schedule, woke_ns).skipped) telemetry_.record_skip();
    const std::int64_t deadline_ns = schedule.deadline_ns;
    // The loop's time goes on from the previous run's last cycle: a port never sees it go back.
    const double time_s = previous_runs_s_ + static_cast<double>(deadline_ns - start_ns) * 1e-9;

    // A faded-out scene goes back to the owner; while the slot is full it waits here, and no
    // new scene is taken, so at most three scenes are ever in play.
    if (!unreturned_) unreturned_ = cycle_.render().take_retired();
    if (unreturned_) {
      HapticScene* empty = nullptr;
      if (retired_.compare_exchange_strong(empty, unreturned_)) unreturned_ = nullptr;
    }
    if (!cycle_.render().fading() && !unreturned_) {
      if (HapticScene* next = pending_.exchange(nullptr)) cycle_.render().set_scene(next, time_s);
    }

    if (stop_requested_.load(std::memory_order_acquire)) {
      publish(cycle_.stop(port_, time_s), true);
      previous_runs_s_ = time_s;
      state_.store(LoopState::stopped, std::memory_order_release);
      return;
    }
    const ForceCycleRecord record = cycle_.step(port_, time_s, overran_last);
    if (record.fault != ForceFault::none) {
      port_fault_.store(record.port_fault, std::memory_order_release);
      fault_.store(record.fault, std::memory_order_release);
      publish(record, true);
      previous_runs_s_ = time_s;
      state_.store(LoopState::faulted, std::memory_order_release);
      return;
    }
    publish(record, false);
    const std::int64_t finished_ns = monotonic_ns();
    // The telemetry counts every cycle that finished behind its schedule; the watchdog only work
    // that did not fit in the period (realtime/catch_up.hpp).
    const CycleEnd end = on_finish(schedule, woke_ns, finished_ns);
    if (end.behind) telemetry_.record_overrun();
    overran_last = end.work_overran;
  }
}

}  // namespace vimg
