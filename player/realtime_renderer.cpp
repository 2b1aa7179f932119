#include "player/realtime_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "player/contact_mixer.hpp"
#include "player/stream_clock.hpp"
#include "realtime/clock.hpp"
#include "realtime/soft_limit.hpp"

namespace vimg {

namespace {

// The render thread takes at most one scene per set_scene() call and retires each one once, so
// the ring holds at most a few between two calls of the control thread.
constexpr std::size_t kRetiredCapacity = 16;
constexpr double kRateWindow_s = 0.5;

bool valid_rate(double rate_hz) { return valid_render_rate(rate_hz); }

std::size_t choose_block_samples(const RealtimeOptions& o, std::size_t sink_min) {
  if (!valid_rate(o.sample_rate_hz)) return std::max<std::size_t>(1, sink_min);
  const auto one_ms = static_cast<std::size_t>(std::max(1L, std::lround(o.sample_rate_hz / 1000.0)));
  const auto longest = static_cast<std::size_t>(std::max(1.0, std::floor(o.sample_rate_hz / 50.0)));
  const std::size_t wanted = o.block_samples > 0 ? o.block_samples : one_ms;
  return std::max({std::size_t{1}, sink_min, std::min(wanted, longest)});
}

}  // namespace

struct RealtimeRenderer::Impl {
  explicit Impl(const RealtimeOptions& o)
      : tracker(o.tracker), a(o.max_contacts), b(o.max_contacts), clock(o.sample_rate_hz) {}
  LiveTracker tracker;
  ContactMixer a;
  ContactMixer b;
  ContactMixer* current = &a;
  ContactMixer* fading = &b;
  SceneEntry* current_entry = nullptr;
  SceneEntry* fading_entry = nullptr;
  std::array<FingerStep, LiveTracker::kMaxFingers> steps{};
  std::vector<float> block;
  std::size_t fade_samples = 1;
  std::size_t fade_left = 0;
  // Stopping: the output ramps to 0 over stop_ramp_samples before the thread ends.
  bool stopping = false;
  std::size_t stop_ramp_samples = 1;
  std::size_t stop_ramp_done = 0;
  // True while the loop should render another block: until stop() and then the ramp are done.
  bool keep_going(const std::atomic<bool>& stop_requested) {
    if (!stopping && stop_requested.load(std::memory_order_acquire)) stopping = true;
    return !stopping || stop_ramp_done < stop_ramp_samples;
  }
  StreamClock clock;
  std::int64_t window_start_ns = 0;
  std::uint64_t window_samples = 0;
};

RealtimeRenderer::RealtimeRenderer(DriveSink& sink, const RealtimeOptions& options)
    : sink_(sink),
      options_(options),
      block_samples_(choose_block_samples(options, 1)),
      events_(options.event_queue_capacity),
      retired_(kRetiredCapacity),
      impl_(std::make_unique<Impl>(options)) {
  const double fade = options.crossfade_s * options.sample_rate_hz;
  impl_->fade_samples = std::isfinite(fade) ? std::max<std::size_t>(1, static_cast<std::size_t>(std::max(0L, std::lround(fade)))) : 1;
}

RealtimeRenderer::~RealtimeRenderer() { stop(); }

std::optional<std::string> RealtimeRenderer::start() {
  if (running()) return std::string("the renderer is already running");
  const double rate = options_.sample_rate_hz;
  if (!valid_rate(rate)) return std::string("sample rate must be within 1..48000 Hz");
  stop_requested_.store(false, std::memory_order_release);
  sink_.open(rate);
  paced_.store(sink_.paces_stream(), std::memory_order_relaxed);
  const std::size_t block = choose_block_samples(options_, sink_.min_block_samples());
  block_samples_.store(block, std::memory_order_relaxed);
  impl_->block.assign(block, 0.0f);
  const TouchCompensation& touch = options_.touch;
  const double panel_s = std::isfinite(touch.panel_latency_s) ? std::clamp(touch.panel_latency_s, 0.0, kMaxTouchPanelLatency_s) : 0.0;
  const double horizon_s = touch.enabled ? panel_s + std::max(0.0, sink_.output_latency_s()) : 0.0;
  impl_->tracker.set_prediction(horizon_s, touch.model);  // before the thread starts
  prediction_horizon_s_.store(impl_->tracker.prediction_horizon_s(), std::memory_order_relaxed);
  telemetry_.reset();
  render_total_ns_.store(0, std::memory_order_relaxed);
  render_max_ns_.store(0, std::memory_order_relaxed);
  measured_rate_hz_.store(0.0, std::memory_order_relaxed);
  stream_offset_s_.store(0.0, std::memory_order_relaxed);
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

void RealtimeRenderer::release(const SceneEntry* entry) {
  for (auto it = owned_.begin(); it != owned_.end(); ++it) {
    if (it->get() == entry) {
      owned_.erase(it);
      return;
    }
  }
}

void RealtimeRenderer::collect_retired() {
  while (auto done = retired_.pop()) release(*done);
}

std::uint64_t RealtimeRenderer::set_scene(std::shared_ptr<const Scene> scene) {
  collect_retired();
  auto entry = std::make_unique<SceneEntry>();
  entry->scene = std::move(scene);
  entry->generation = next_generation_++;
  SceneEntry* const posted = entry.get();
  const std::uint64_t generation = posted->generation;
  owned_.push_back(std::move(entry));
  // The render thread takes the mailbox's scene with an exchange too, so a scene handed back
  // here was never seen by it: the control side releases it.
  if (SceneEntry* replaced = pending_scene_.exchange(posted, std::memory_order_acq_rel)) {
    release(replaced);
    scenes_superseded_.fetch_add(1, std::memory_order_relaxed);
  }
  return generation;
}

void RealtimeRenderer::render_block(double block_start_s, double event_offset_s) {
  Impl& m = *impl_;
  const double rate = options_.sample_rate_hz;
  const double dt = 1.0 / rate;
  while (auto popped = events_.pop()) {
    TouchEvent e = *popped;
    e.time_s += event_offset_s;  // CLOCK_MONOTONIC onto the renderer clock
    if (!m.tracker.apply(e, block_start_s)) dropped_events_.fetch_add(1, std::memory_order_relaxed);
  }
  for (std::size_t i = 0; i < m.block.size(); ++i) {
    if (m.fade_left == 0 && pending_scene_.load(std::memory_order_relaxed) != nullptr) {
      if (SceneEntry* next = pending_scene_.exchange(nullptr, std::memory_order_acq_rel)) {
        std::swap(m.current, m.fading);
        m.fading_entry = m.current_entry;
        m.current_entry = next;
        m.current->set_scene(next->scene.get());
        m.fade_left = m.fade_samples;
        scene_generation_.store(next->generation, std::memory_order_relaxed);
      }
    }
    const double t = block_start_s + static_cast<double>(i) / rate;
    const std::size_t n = m.tracker.steps_at(t, dt, m.steps);
    const std::span<const FingerStep> touching(m.steps.data(), n);
    double d = m.current->step(touching, t, dt);
    if (m.fade_left > 0) {
      const double w = 1.0 - static_cast<double>(m.fade_left) / static_cast<double>(m.fade_samples);
      d = w * d + (1.0 - w) * m.fading->step(touching, t, dt);
      if (--m.fade_left == 0) {
        m.fading->set_scene(nullptr);
        // Cannot fail (see kRetiredCapacity); if it did, the entry would live until destruction.
        if (m.fading_entry != nullptr) retired_.push(m.fading_entry);
        m.fading_entry = nullptr;
      }
    }
    double y = soft_limit(d);
    if (m.stopping) {
      // (R-1)/R, ..., 1/R, 0: the last sample of the ramp, and all after it, are exactly 0.
      const double gain = 1.0 - static_cast<double>(std::min(m.stop_ramp_done + 1, m.stop_ramp_samples)) /
                                    static_cast<double>(m.stop_ramp_samples);
      y *= std::max(0.0, gain);
      ++m.stop_ramp_done;
    }
    m.block[i] = static_cast<float>(y);
  }
  active_contacts_.store(m.current->active_contacts() + m.fading->active_contacts(), std::memory_order_relaxed);
  model_runs_.store(m.tracker.model_runs(), std::memory_order_relaxed);
}

void RealtimeRenderer::publish_rate(std::int64_t now_ns) {
  Impl& m = *impl_;
  m.window_samples += m.block.size();
  const double window_s = static_cast<double>(now_ns - m.window_start_ns) * 1e-9;
  if (window_s >= kRateWindow_s) {
    measured_rate_hz_.store(static_cast<double>(m.window_samples) / window_s, std::memory_order_relaxed);
    m.window_start_ns = now_ns;
    m.window_samples = 0;
  }
}

void RealtimeRenderer::record_render_time(std::int64_t render_ns) {
  // One writer (the render thread): plain load and store, no read-modify-write needed.
  render_total_ns_.store(render_total_ns_.load(std::memory_order_relaxed) + render_ns, std::memory_order_relaxed);
  if (render_ns > render_max_ns_.load(std::memory_order_relaxed)) render_max_ns_.store(render_ns, std::memory_order_relaxed);
}

void RealtimeRenderer::run() {
  const RealtimePriority priority = request_realtime_priority(options_.realtime_priority);
  priority_requested_.store(priority.requested, std::memory_order_relaxed);
  priority_error_.store(priority.error_number, std::memory_order_relaxed);
  priority_granted_.store(priority.granted, std::memory_order_release);
  impl_->window_start_ns = monotonic_ns();
  impl_->window_samples = 0;
  impl_->stopping = false;
  impl_->stop_ramp_done = 0;
  impl_->stop_ramp_samples = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::lround(std::max(0.0, options_.stop_ramp_s) * options_.sample_rate_hz)));
  if (paced_.load(std::memory_order_relaxed)) {
    run_paced_by_sink();
  } else {
    run_on_deadlines();
  }
}

void RealtimeRenderer::run_on_deadlines() {
  const double rate = options_.sample_rate_hz;
  const std::size_t block = impl_->block.size();
  const double block_ns = static_cast<double>(block) * 1e9 / rate;
  const auto lag_ns = static_cast<std::int64_t>(std::max(kSkipAfterLag_s * 1e9, 2.0 * block_ns));
  const std::int64_t start_ns = monotonic_ns();
  const double start_s = static_cast<double>(start_ns) * 1e-9;
  auto deadline_of = [&](std::uint64_t k) {
    return start_ns + static_cast<std::int64_t>(std::llround(static_cast<double>(k) * block_ns));
  };
  std::uint64_t k = 0;
  while (impl_->keep_going(stop_requested_)) {
    const std::int64_t deadline_ns = deadline_of(k);
    sleep_until_ns(deadline_ns);
    const std::int64_t woke_ns = monotonic_ns();
    telemetry_.record_wake(woke_ns, deadline_ns);
    const double t = start_s + static_cast<double>(k * block) / rate;
    render_block(t, 0.0);
    record_render_time(monotonic_ns() - woke_ns);
    sink_.write(impl_->block, t);
    ++k;
    const std::int64_t after_ns = monotonic_ns();
    const std::int64_t next_ns = deadline_of(k);
    if (after_ns > next_ns) telemetry_.record_overrun();
    if (after_ns - next_ns > lag_ns) {  // far behind: skip ahead rather than burst to catch up
      k = static_cast<std::uint64_t>(static_cast<double>(after_ns - start_ns) / block_ns);
      telemetry_.record_skip();
    }
    publish_rate(after_ns);
  }
}

void RealtimeRenderer::run_paced_by_sink() {
  const std::size_t block = impl_->block.size();
  const double block_ns = static_cast<double>(block) * 1e9 / options_.sample_rate_hz;
  StreamClock& clock = impl_->clock;
  clock.start(monotonic_s());
  std::uint64_t sample = 0;
  while (impl_->keep_going(stop_requested_)) {
    const std::int64_t woke_ns = monotonic_ns();
    clock.observe(sample, static_cast<double>(woke_ns) * 1e-9);
    stream_offset_s_.store(clock.offset_s(), std::memory_order_relaxed);
    const double t = clock.sample_time_s(sample);
    const auto expected_ns = static_cast<std::int64_t>(std::llround(clock.to_monotonic_s(t) * 1e9));
    telemetry_.record_wake(woke_ns, expected_ns);
    render_block(t, clock.offset_s());
    const std::int64_t rendered_ns = monotonic_ns();
    record_render_time(rendered_ns - woke_ns);
    if (static_cast<double>(rendered_ns - expected_ns) > block_ns) telemetry_.record_overrun();
    sink_.write(impl_->block, t);  // blocks on the device: its clock paces the stream
    sample += block;
    publish_rate(monotonic_ns());
  }
}

LoopStats RealtimeRenderer::stats() const {
  const LoopTimingStats t = telemetry_.snapshot();
  LoopStats s;
  s.measured_rate_hz = measured_rate_hz_.load(std::memory_order_relaxed);
  s.jitter_p50_s = t.jitter_p50_us * 1e-6;
  s.jitter_p99_s = t.jitter_p99_us * 1e-6;
  s.jitter_max_s = t.jitter_max_us * 1e-6;
  s.blocks = t.cycles;
  s.overruns = t.overruns;
  s.skips = t.skips;
  s.dropped_events = dropped_events_.load(std::memory_order_relaxed);
  s.active_contacts = active_contacts_.load(std::memory_order_relaxed);
  s.priority.granted = priority_granted_.load(std::memory_order_acquire);
  s.priority.requested = priority_requested_.load(std::memory_order_relaxed);
  s.priority.error_number = priority_error_.load(std::memory_order_relaxed);
  s.realtime_priority = s.priority.granted;
  s.paced_by_sink = paced_.load(std::memory_order_relaxed);
  s.block_samples = block_samples();
  s.stream_offset_s = stream_offset_s_.load(std::memory_order_relaxed);
  if (t.cycles > 0) {
    s.render_mean_s = static_cast<double>(render_total_ns_.load(std::memory_order_relaxed)) * 1e-9 / static_cast<double>(t.cycles);
  }
  s.render_max_s = static_cast<double>(render_max_ns_.load(std::memory_order_relaxed)) * 1e-9;
  s.scene_generation = scene_generation_.load(std::memory_order_relaxed);
  s.scenes_superseded = scenes_superseded_.load(std::memory_order_relaxed);
  s.prediction_horizon_s = prediction_horizon_s_.load(std::memory_order_relaxed);
  s.model_runs = model_runs_.load(std::memory_order_relaxed);
  return s;
}

}  // namespace vimg
