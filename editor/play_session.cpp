#include "editor/play_session.hpp"

#include <cmath>
#include <exception>

#include "player/scene.hpp"

namespace vimg::editor {
namespace {
constexpr int kMaxFingers = kMaxLiveFingers;
constexpr std::size_t kMaxTrail = 4096;
}  // namespace

PlaySession::PlaySession(OutputFactory make_output, double sample_rate_hz, int realtime_priority)
    : make_output_(std::move(make_output)), sample_rate_hz_(sample_rate_hz), realtime_priority_(realtime_priority) {
  fingers_.resize(kMaxFingers);
}

PlaySession::~PlaySession() { stop(); }

std::optional<std::string> PlaySession::start(const Image& image) {
  stop();
  std::string error;
  auto output = make_output_(error);
  if (!output) return error;
  renderer_.reset();
  tap_.reset();
  output_ = std::move(output);
  tap_ = std::make_unique<DriveTap>(*output_);
  RealtimeOptions options;
  options.sample_rate_hz = sample_rate_hz_;
  options.realtime_priority = realtime_priority_;
  options.touch = touch_;
  renderer_ = std::make_unique<RealtimeRenderer>(*tap_, options);
  latest_generation_ = renderer_->set_scene(compile_scene(image));
  start_time_s_ = monotonic_s();
  std::optional<std::string> start_error;
  try {
    start_error = renderer_->start();
  } catch (const std::exception& e) {  // the device would not open
    start_error = e.what();
  }
  if (start_error) {
    renderer_.reset();
    return start_error;
  }
  for (auto& f : fingers_) f.reset();
  trail_.clear();
  return std::nullopt;
}

void PlaySession::update(const Image& image) {
  if (renderer_) latest_generation_ = renderer_->set_scene(compile_scene(image));
}

bool PlaySession::latest_edit_playing() const {
  return renderer_ && renderer_->stats().scene_generation == latest_generation_;
}

void PlaySession::stop() {
  if (!renderer_) return;
  // Lift every finger so the output ends at rest.
  const double now = monotonic_s();
  for (int i = 0; i < kMaxFingers; ++i) {
    if (fingers_[i]) touch(i, TouchPhase::up, fingers_[i]->x_mm, fingers_[i]->y_mm, now);
  }
  renderer_->stop();
  renderer_.reset();
}

void PlaySession::touch(int finger, TouchPhase phase, double x_mm, double y_mm, double time_s) {
  if (!renderer_ || finger < 0 || finger >= kMaxFingers) return;
  TouchEvent event;
  event.time_s = time_s;
  event.finger = finger;
  event.phase = phase;
  event.x_mm = x_mm;
  event.y_mm = y_mm;
  tap_->note_event(time_s);
  renderer_->push_event(event);
  const double renderer_time_s = renderer_->renderer_time_s(time_s);
  if (phase == TouchPhase::up) {
    fingers_[finger].reset();
  } else {
    fingers_[finger] = TrailPoint{x_mm, y_mm, time_s};
    trail_.push_back(TrailPoint{x_mm, y_mm, time_s});
    if (trail_.size() > kMaxTrail) trail_.pop_front();
  }
  if (recording_) {
    const GesturePhase gp = phase == TouchPhase::down ? GesturePhase::down
                            : phase == TouchPhase::up ? GesturePhase::up
                                                      : GesturePhase::move;
    recorder_.add(GestureSample{renderer_time_s, finger, x_mm, y_mm, std::nullopt, gp});
  }
}

void PlaySession::forget_trail_older_than(double time_s) {
  while (!trail_.empty() && trail_.front().time_s < time_s) trail_.pop_front();
}

GestureRecorder PlaySession::recorded_gesture() const {
  GestureRecorder out;
  for (GestureSample s : recorder_.samples()) {
    s.time_s = tap_ ? tap_->output_time_s(s.time_s) : s.time_s - start_time_s_;
    out.add(s);
  }
  return out;
}

void PlaySession::set_recording(bool on) {
  if (on && !recording_) recorder_.clear();
  recording_ = on;
}

}  // namespace vimg::editor
