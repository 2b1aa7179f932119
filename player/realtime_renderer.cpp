#include "player/realtime_renderer.hpp"

#include "realtime/clock.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <ctime>

#include <pthread.h>
#include <sched.h>

#include "player/contact_mixer.hpp"
#include "realtime/soft_limit.hpp"

namespace vimg {

namespace {

constexpr std::size_t kSceneQueueCapacity = 4;
constexpr std::size_t kRetiredQueueCapacity = 16;
constexpr std::size_t kMaxScenesInFlight = 8;  // < kRetiredQueueCapacity, so retiring never fails
constexpr double kJitterBucket_s = 10e-6;
constexpr double kRateWindow_s = 0.5;

}  // namespace

struct RealtimeRenderer::Impl {
  Impl(const RealtimeOptions& o, std::size_t block_samples)
      : tracker(o.tracker), a(o.max_contacts), b(o.max_contacts), block(block_samples) {}
  LiveTracker tracker;
  ContactMixer a;
  ContactMixer b;
  ContactMixer* current = &a;
  ContactMixer* fading = &b;
  std::array<FingerStep, LiveTracker::kMaxFingers> steps{};
  std::vector<float> block;
  std::size_t fade_samples = 1;
  std::size_t fade_left = 0;
};

RealtimeRenderer::RealtimeRenderer(DriveSink& sink, const RealtimeOptions& options)
    : sink_(sink),
      options_(options),
      block_samples_(std::max<std::size_t>(
          1, std::min(options.block_samples,
                      static_cast<std::size_t>(std::max(1.0, std::floor(options.sample_rate_hz / 50.0)))))),
      events_(options.event_queue_capacity),
      scene_in_(kSceneQueueCapacity),
      scene_out_(kRetiredQueueCapacity),
      impl_(std::make_unique<Impl>(options, block_samples_)),
      jitter_histogram_(std::make_unique<std::atomic<std::uint32_t>[]>(kJitterBuckets)) {
  impl_->fade_samples =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(options.crossfade_s * options.sample_rate_hz)));
  for (std::size_t i = 0; i < kJitterBuckets; ++i) jitter_histogram_[i].store(0, std::memory_order_relaxed);
}

RealtimeRenderer::~RealtimeRenderer() { stop(); }

std::optional<std::string> RealtimeRenderer::start() {
  if (running()) return std::string("the renderer is already running");
  const double rate = options_.sample_rate_hz;
  if (!(rate >= 1.0 && rate <= 48000.0)) return std::string("sample rate must be within 1..48000 Hz");
  if (options_.block_samples == 0) return std::string("block size must be at least 1 sample");
  stop_requested_.store(false, std::memory_order_release);
  sink_.open(rate);
  running_.store(true, std::memory_order_release);
  thread_ = std::thread([this] { run(); });
  return std::nullopt;
}

void RealtimeRenderer::stop() {
  stop_requested_.store(true, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
  if (running_.exchange(false)) sink_.close();
  collect_retired();
}

bool RealtimeRenderer::push_event(const TouchEvent& event) {
  if (events_.push(event)) return true;
  dropped_events_.fetch_add(1, std::memory_order_relaxed);
  return false;
}

void RealtimeRenderer::collect_retired() {
  while (auto p = scene_out_.pop()) {
    const Scene* done = *p;
    for (auto it = owned_scenes_.begin(); it != owned_scenes_.end(); ++it) {
      if (it->get() == done) {
        owned_scenes_.erase(it);
        break;
      }
    }
  }
}

bool RealtimeRenderer::set_scene(std::shared_ptr<const Scene> scene) {
  collect_retired();
  if (!scene || owned_scenes_.size() >= kMaxScenesInFlight) return false;
  if (!scene_in_.push(scene.get())) return false;
  owned_scenes_.push_back(std::move(scene));
  return true;
}

void RealtimeRenderer::render_block(double block_start_s) {
  Impl& m = *impl_;
  const double dt = 1.0 / options_.sample_rate_hz;
  while (auto e = events_.pop()) {
    if (!m.tracker.apply(*e, block_start_s)) dropped_events_.fetch_add(1, std::memory_order_relaxed);
  }
  for (std::size_t i = 0; i < m.block.size(); ++i) {
    if (m.fade_left == 0) {
      if (auto next = scene_in_.pop()) {
        std::swap(m.current, m.fading);
        m.current->set_scene(*next);
        m.fade_left = m.fade_samples;
      }
    }
    const double t = block_start_s + static_cast<double>(i) * dt;
    const std::size_t n = m.tracker.steps_at(t, dt, m.steps);
    const std::span<const FingerStep> touching(m.steps.data(), n);
    double d = m.current->step(touching, t, dt);
    if (m.fade_left > 0) {
      const double w = 1.0 - static_cast<double>(m.fade_left) / static_cast<double>(m.fade_samples);
      d = w * d + (1.0 - w) * m.fading->step(touching, t, dt);
      if (--m.fade_left == 0) {
        if (const Scene* old = m.fading->scene()) scene_out_.push(old);
        m.fading->set_scene(nullptr);
      }
    }
    m.block[i] = static_cast<float>(soft_limit(d));
  }
  active_contacts_.store(m.current->active_contacts() + m.fading->active_contacts(), std::memory_order_relaxed);
}

void RealtimeRenderer::run() {
  if (options_.realtime_priority > 0) {
    sched_param param{};
    param.sched_priority = std::clamp(options_.realtime_priority, 1, 99);
    realtime_priority_.store(pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0,
                             std::memory_order_relaxed);
  }
  const double rate = options_.sample_rate_hz;
  const double block_s = static_cast<double>(block_samples_) / rate;
  const std::int64_t start_ns = monotonic_ns();
  const double start_s = static_cast<double>(start_ns) * 1e-9;
  std::uint64_t k = 0;
  std::int64_t window_start_ns = start_ns;
  std::uint64_t window_samples = 0;
  while (!stop_requested_.load(std::memory_order_acquire)) {
    const auto deadline_ns = start_ns + static_cast<std::int64_t>(std::llround(static_cast<double>(k) * block_s * 1e9));
    sleep_until_ns(deadline_ns);
    const std::int64_t woke_ns = monotonic_ns();
    const double late_s = static_cast<double>(woke_ns - deadline_ns) * 1e-9;
    const auto bucket = std::min<std::size_t>(kJitterBuckets - 1, static_cast<std::size_t>(std::max(0.0, late_s) / kJitterBucket_s));
    jitter_histogram_[bucket].fetch_add(1, std::memory_order_relaxed);
    if (late_s > jitter_max_s_.load(std::memory_order_relaxed)) jitter_max_s_.store(late_s, std::memory_order_relaxed);
    if (late_s > block_s) overruns_.fetch_add(1, std::memory_order_relaxed);

    render_block(start_s + static_cast<double>(k) * block_s);
    sink_.write(impl_->block, start_s + static_cast<double>(k) * block_s);
    blocks_.fetch_add(1, std::memory_order_relaxed);

    window_samples += block_samples_;
    const std::int64_t after_ns = monotonic_ns();
    if (static_cast<double>(after_ns - window_start_ns) * 1e-9 >= kRateWindow_s) {
      measured_rate_hz_.store(static_cast<double>(window_samples) / (static_cast<double>(after_ns - window_start_ns) * 1e-9),
                              std::memory_order_relaxed);
      window_start_ns = after_ns;
      window_samples = 0;
    }
    ++k;
    // Far behind (more than two blocks): skip ahead rather than burst to catch up.
    const std::int64_t next_ns = start_ns + static_cast<std::int64_t>(std::llround(static_cast<double>(k) * block_s * 1e9));
    if (static_cast<double>(after_ns - next_ns) * 1e-9 > 2.0 * block_s) {
      k = static_cast<std::uint64_t>(static_cast<double>(after_ns - start_ns) * 1e-9 / block_s);
    }
  }
}

LoopStats RealtimeRenderer::stats() const {
  LoopStats s;
  s.measured_rate_hz = measured_rate_hz_.load(std::memory_order_relaxed);
  s.jitter_max_s = jitter_max_s_.load(std::memory_order_relaxed);
  s.blocks = blocks_.load(std::memory_order_relaxed);
  s.overruns = overruns_.load(std::memory_order_relaxed);
  s.dropped_events = dropped_events_.load(std::memory_order_relaxed);
  s.active_contacts = active_contacts_.load(std::memory_order_relaxed);
  s.realtime_priority = realtime_priority_.load(std::memory_order_relaxed);
  std::uint64_t total = 0;
  std::array<std::uint32_t, kJitterBuckets> counts{};
  for (std::size_t i = 0; i < kJitterBuckets; ++i) total += counts[i] = jitter_histogram_[i].load(std::memory_order_relaxed);
  auto percentile = [&](double p) {
    if (total == 0) return 0.0;
    const auto target = static_cast<std::uint64_t>(std::ceil(p * static_cast<double>(total)));
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < kJitterBuckets; ++i) {
      seen += counts[i];
      if (seen >= target) return (static_cast<double>(i) + 0.5) * kJitterBucket_s;
    }
    return static_cast<double>(kJitterBuckets) * kJitterBucket_s;
  };
  s.jitter_p50_s = percentile(0.5);
  s.jitter_p99_s = percentile(0.99);
  return s;
}

}  // namespace vimg
