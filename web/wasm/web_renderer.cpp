#include "web/wasm/web_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "player/actuator_sink.hpp"
#include "storage/gesture_csv.hpp"
#include "player/offline_render.hpp"
#include "realtime/soft_limit.hpp"
#include "storage/limits.hpp"

namespace vimg {

namespace {

class MemorySink final : public DriveSink {
 public:
  explicit MemorySink(std::vector<float>& out) : out_(out) {}
  void open(double) override { out_.clear(); }
  void write(std::span<const float> drive, double) override { out_.insert(out_.end(), drive.begin(), drive.end()); }
  void close() override {}

 private:
  std::vector<float>& out_;
};

std::shared_ptr<const Scene> compile(const VscImage& v) {
  SceneOptions options;
  options.carrier_frequency_hz = v.actuator.resonance_hz;  // as `vimg render --actuator P` does
  return compile_scene(v.image, options);
}

}  // namespace

bool WebRenderer::load_vsc(std::string_view bytes) {
  VscReadResult r = read_vsc(bytes, "image.vsc");
  if (!r.image) {
    error_ = r.error;
    return false;
  }
  image_ = std::move(*r.image);
  scene_ = compile(image_);
  mixer_.set_scene(scene_.get());
  return true;
}

bool WebRenderer::render_gesture(std::string_view csv, double rate_hz) {
  if (!scene_) {
    error_ = "no image is loaded";
    return false;
  }
  if (!(rate_hz >= 1.0 && rate_hz <= 48000.0)) {
    error_ = "the render rate must be in [1, 48000] Hz";
    return false;
  }
  const GestureParseResult gesture = parse_gesture_csv(csv, "gesture.csv");
  if (!gesture.ok()) {
    error_ = gesture.errors.empty() ? "gesture.csv: error: cannot read the gesture" : gesture.errors.front();
    return false;
  }
  const double span_s = std::max(0.0, gesture.gesture->end_time_s()) - std::min(0.0, gesture.gesture->start_time_s());
  if (span_s > kMaxGestureDurationS) {
    error_ = "gesture.csv: error: the render would last longer than the limit from time 0";
    return false;
  }
  MemorySink memory(rendered_);
  ActuatorSink shaped(memory, image_.actuator, OutputSignal::drive, false);
  OfflineRenderOptions options;
  options.sample_rate_hz = rate_hz;
  const OfflineRenderResult result = vimg::render_gesture(*scene_, *gesture.gesture, shaped, options);
  rendered_start_s_ = result.start_time_s;
  return true;
}

void WebRenderer::live_start(double rate_hz) {
  live_rate_hz_ = rate_hz;
  live_time_s_ = 0.0;
  live_samples_ = 0;
  tracker_ = LiveTracker();
  tracker_.set_prediction(live_horizon_s_);
  queued_ = 0;
  mixer_.set_scene(scene_.get());
}

void WebRenderer::apply_live_event(TouchEvent event) {
  event.time_s = std::max(event.time_s, live_time_s_ - kOldestLiveEventS);
  tracker_.apply(event, live_time_s_);
}

void WebRenderer::live_event_at(const TouchEvent& event) {
  if (!std::isfinite(event.time_s)) {
    TouchEvent now = event;
    now.time_s = live_time_s_;
    apply_live_event(now);
    return;
  }
  if (queued_ == kMaxQueuedLiveEvents) {
    apply_live_event(event);
    return;
  }
  std::size_t at = queued_;
  while (at > 0 && queue_[at - 1].time_s > event.time_s) {
    queue_[at] = queue_[at - 1];
    --at;
  }
  queue_[at] = event;
  ++queued_;
}

const std::vector<float>& WebRenderer::live_render(std::size_t frames) {
  live_block_.resize(frames);
  std::array<FingerStep, LiveTracker::kMaxFingers> steps{};
  const double dt = 1.0 / live_rate_hz_;
  std::size_t applied = 0;
  for (std::size_t i = 0; i < frames; ++i) {
    live_time_s_ = static_cast<double>(live_samples_) * dt;
    while (applied < queued_ && queue_[applied].time_s <= live_time_s_) apply_live_event(queue_[applied++]);
    const std::size_t n = tracker_.steps_at(live_time_s_, dt, steps);
    const double d = mixer_.step(std::span<const FingerStep>(steps.data(), n), live_time_s_, dt);
    live_block_[i] = static_cast<float>(soft_limit(d));
    ++live_samples_;
  }
  live_time_s_ = static_cast<double>(live_samples_) * dt;
  std::copy(queue_.begin() + static_cast<std::ptrdiff_t>(applied), queue_.begin() + static_cast<std::ptrdiff_t>(queued_),
            queue_.begin());
  queued_ -= applied;
  return live_block_;
}

}  // namespace vimg
