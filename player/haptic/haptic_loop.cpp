#include "player/haptic/haptic_loop.hpp"

#include "realtime/clock.hpp"

#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <cerrno>

namespace vimg {

HapticLoop::HapticLoop(HapticPort& port, HapticLoopConfig config)
    : port_(port), config_(config), cycle_(config.cycle), histogram_(kHistogramBins + 1, 0) {
  config_.cycle.max_force_N = std::min(config_.cycle.max_force_N, port.max_force_N());
  cycle_ = HapticCycle(config_.cycle);
}

// owned_ is the one owner of every scene, the pending one included: the atomic pointers only lend.
HapticLoop::~HapticLoop() { stop(); }

void HapticLoop::release_retired() {
  if (HapticScene* r = retired_.exchange(nullptr)) {
    owned_.erase(std::remove_if(owned_.begin(), owned_.end(), [&](const auto& p) { return p.get() == r; }), owned_.end());
  }
}

void HapticLoop::submit_scene(std::unique_ptr<HapticScene> scene) {
  release_retired();
  HapticScene* raw = scene.get();
  owned_.push_back(std::move(scene));
  // A scene the loop never took is replaced: it can go at once.
  if (HapticScene* unseen = pending_.exchange(raw)) {
    owned_.erase(std::remove_if(owned_.begin(), owned_.end(), [&](const auto& p) { return p.get() == unseen; }), owned_.end());
  }
}

bool HapticLoop::start() {
  if (running_.load() || thread_.joinable() || !(config_.rate_hz >= 100.0 && config_.rate_hz <= 4000.0)) return false;
  stop_requested_ = false;
  failed_ = false;
  running_ = true;
  thread_ = std::thread([this] { run(); });
  return true;
}

void HapticLoop::stop() {
  stop_requested_ = true;
  if (thread_.joinable()) thread_.join();
  running_ = false;
  release_retired();
}

Vec3 HapticLoop::last_sent_N() const { return {sent_x_.load(), sent_y_.load(), sent_z_.load()}; }

void HapticLoop::run() {
  if (config_.realtime_priority > 0) {
    sched_param param{};
    param.sched_priority = std::min(config_.realtime_priority, 99);
    realtime_ = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
  }
  const auto period_ns = static_cast<std::int64_t>(1e9 / config_.rate_hz);
  const std::int64_t start_ns = monotonic_ns();
  std::int64_t deadline_ns = start_ns;
  ProbeSample probe;
  while (!stop_requested_.load(std::memory_order_relaxed)) {
    deadline_ns += period_ns;
    sleep_until_ns(deadline_ns);
    const std::int64_t woke_ns = monotonic_ns();
    const double late_us = static_cast<double>(std::max<std::int64_t>(0, woke_ns - deadline_ns)) * 1e-3;
    ++histogram_[std::min<std::size_t>(static_cast<std::size_t>(late_us), kHistogramBins)];
    max_late_us_ = std::max(max_late_us_, late_us);
    if (woke_ns - deadline_ns > 10 * period_ns) deadline_ns = woke_ns;  // far behind: skip, never burst

    const double time_s = static_cast<double>(deadline_ns - start_ns) * 1e-9;
    // A faded-out scene goes back to the owner; while the slot is full it waits here, and no
    // new scene is taken, so at most three scenes are ever in play.
    if (!unreturned_) unreturned_ = cycle_.take_retired();
    if (unreturned_) {
      HapticScene* empty = nullptr;
      if (retired_.compare_exchange_strong(empty, unreturned_)) unreturned_ = nullptr;
    }
    if (!cycle_.fading() && !unreturned_) {
      if (HapticScene* next = pending_.exchange(nullptr)) cycle_.set_scene(next, time_s);
    }
    if (!port_.read(time_s, probe)) {
      failed_ = true;
      break;
    }
    const CycleOutput out = cycle_.step(probe, time_s);
    if (!port_.write_force(out.sent_N)) {
      failed_ = true;
      break;
    }
    sent_x_.store(out.sent_N.x, std::memory_order_relaxed);
    sent_y_.store(out.sent_N.y, std::memory_order_relaxed);
    sent_z_.store(out.sent_N.z, std::memory_order_relaxed);
    cycles_.fetch_add(1, std::memory_order_relaxed);
  }
  // Zero force first, on stop and on error alike.
  port_.write_force({});
  sent_x_ = sent_y_ = sent_z_ = 0.0;
  running_ = false;
}

JitterStats HapticLoop::jitter() const {
  JitterStats stats;
  std::uint64_t total = 0;
  for (auto n : histogram_) total += n;
  stats.cycles = total;
  stats.max_us = max_late_us_;
  if (total == 0) return stats;
  auto percentile = [&](double q) {
    const auto target = static_cast<std::uint64_t>(q * static_cast<double>(total - 1));
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < histogram_.size(); ++i) {
      seen += histogram_[i];
      if (seen > target) return static_cast<double>(i);
    }
    return static_cast<double>(kHistogramBins);
  };
  stats.p50_us = percentile(0.50);
  stats.p99_us = percentile(0.99);
  return stats;
}

}  // namespace vimg
