#pragma once
// Playing mode: the document compiled into a scene, played by the real-time renderer to the
// chosen output through a DriveTap, with the finger trail and the gesture being recorded.
// The render thread asks for SCHED_FIFO as vimg-player's does (kDefaultRealtimePriority unless
// told otherwise); priority_description() says what it got. Every document edit reaches the
// renderer (RealtimeRenderer::set_scene never refuses); latest_edit_playing() says when it plays.
// Threads: everything here on the GUI thread.
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/core/gesture_recorder.hpp"
#include "editor/core/drive_tap.hpp"
#include "editor/core/play_output.hpp"
#include "player/drive_sink.hpp"
#include "player/realtime_renderer.hpp"
#include "primitives/image.hpp"

namespace vimg::editor {

struct TrailPoint {
  double x_mm = 0.0;
  double y_mm = 0.0;
  double time_s = 0.0;  // monotonic
};

class PlaySession {
 public:
  // Makes the output the renderer drives, anew for every start (see output_choice.hpp).
  using OutputFactory = std::function<std::unique_ptr<PlayOutput>(std::string& error)>;
  static constexpr int kDefaultRealtimePriority = 80;
  // realtime_priority: SCHED_FIFO priority of the render thread (1..99), 0 for normal scheduling.
  PlaySession(OutputFactory make_output, double sample_rate_hz, int realtime_priority = kDefaultRealtimePriority);
  ~PlaySession();

  // Starts playing `image`. Returns an error message on failure.
  std::optional<std::string> start(const Image& image);
  // Touch-latency compensation for the next start() (docs/latency.md); off until set.
  void set_touch_compensation(const TouchCompensation& touch) { touch_ = touch; }
  // Plays the changed document from now on (the renderer cross-fades; never refused).
  void update(const Image& image);
  // The last start() or update() is what the renderer plays (false while it waits for a running
  // cross-fade to end, at most 20 ms).
  bool latest_edit_playing() const;
  // Stops the renderer and completes the output (a WAV file is written here).
  void stop();
  bool playing() const { return renderer_ && renderer_->running(); }
  // What the output's device said since the last call (faults, a device gone and back), also after
  // stop() (its last faults); nothing before the first start.
  std::vector<std::string> take_device_messages() { return output_ ? output_->take_messages() : std::vector<std::string>{}; }

  // Input from the GUI thread; time on the renderer's clock (monotonic_s()).
  void touch(int finger, TouchPhase phase, double x_mm, double y_mm, double time_s);

  // Fingers currently down, by finger index: their last position.
  const std::vector<std::optional<TrailPoint>>& fingers() const { return fingers_; }
  const std::deque<TrailPoint>& trail() const { return trail_; }
  void forget_trail_older_than(double time_s);

  // The tap of the current (or last) run; null before the first start.
  const DriveTap* tap() const { return tap_.get(); }
  LoopStats stats() const { return renderer_ ? renderer_->stats() : LoopStats{}; }
  // "SCHED_FIFO 80", or "normal priority (SCHED_FIFO 80 refused: ...)": for the status display.
  std::string priority_description() const { return describe(stats().priority); }

  // Gesture recording. The recorder holds renderer-clock times (RealtimeRenderer::renderer_time_s
  // of each event: with an output that paces the stream, its stream time); recorded_gesture()
  // gives them on the output's time axis (0 = the first sample written), as a file of the take
  // would be read.
  void set_recording(bool on);
  bool recording() const { return recording_; }
  const GestureRecorder& recorder() const { return recorder_; }
  GestureRecorder recorded_gesture() const;

 private:
  OutputFactory make_output_;
  std::unique_ptr<PlayOutput> output_;
  std::unique_ptr<DriveTap> tap_;
  std::unique_ptr<RealtimeRenderer> renderer_;
  TouchCompensation touch_;
  double sample_rate_hz_;
  int realtime_priority_;
  std::uint64_t latest_generation_ = 0;
  std::vector<std::optional<TrailPoint>> fingers_;
  std::deque<TrailPoint> trail_;
  GestureRecorder recorder_;
  bool recording_ = false;
  double start_time_s_ = 0.0;
};

}  // namespace vimg::editor
