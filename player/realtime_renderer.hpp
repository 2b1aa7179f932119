#pragma once
// The real-time renderer: a thread that renders blocks of drive at a fixed sample rate and writes
// them to a DriveSink.
//
// Pacing: one clock per stream.
//   - A sink without a clock (file, memory, I2C driver): block k starts at the absolute deadline
//     start + k * block / rate on CLOCK_MONOTONIC (sleep_until_ns). A loop that falls more than
//     kSkipAfterLag_s behind skips ahead rather than burst (LoopStats::skips); block times are
//     the deadlines, so the renderer clock is CLOCK_MONOTONIC.
//   - A sink that paces the stream (DriveSink::paces_stream(), e.g. a sound card): the thread
//     renders the next block as soon as write() returns and never sleeps on CLOCK_MONOTONIC; it
//     never skips. Block times are stream times (samples written / rate, anchored at start), and
//     touch events, stamped with monotonic_s(), are mapped onto them by StreamClock's slowly
//     corrected offset (see player/stream_clock.hpp: the mapping lags a drifting device clock by
//     drift * 0.25 s, bounded). renderer_time_s() does the same mapping for other threads.
//
// Blocks are 1 ms by default (8 samples at 8 kHz), never smaller than the sink's
// min_block_samples() and, unless the sink needs it, never longer than 1/50 s.
//
// Scenes: set_scene() never refuses. The control side puts the scene in a one-slot mailbox; a
// scene still waiting there is replaced by the newer one and released on the control side
// (LoopStats::scenes_superseded). The render thread takes the mailbox's scene when no
// cross-fade is running (so within crossfade_s of the newest edit) and cross-fades linearly over
// crossfade_s from what plays then (two contact mixers, old and new). The scene it leaves comes
// back through an SPSC ring and is released on the control thread. LoopStats::scene_generation
// tells which set_scene() call is playing.
//
// Threads: one producer thread calls push_event(); one control thread calls start(), stop() and
// set_scene(); stats() and renderer_time_s() may be called from any thread. The render thread
// never allocates, frees, locks or blocks except in the sink's write(); it asks for SCHED_FIFO
// with request_realtime_priority() and publishes the outcome, which describe() (allocating, on
// the display thread) turns into text.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "player/drive_sink.hpp"
#include "player/live_tracker.hpp"
#include "player/render_defaults.hpp"
#include "player/scene.hpp"
#include "player/touch_event.hpp"
#include "primitives/touch_prediction/touch_latency_defaults.hpp"
#include "realtime/loop_telemetry.hpp"
#include "realtime/realtime_priority.hpp"
#include "realtime/spsc_ring.hpp"

namespace vimg {

// Touch-latency compensation (docs/latency.md): each finger is predicted to the moment its
// samples reach the actuator, panel_latency_s + the sink's output_latency_s() after the step time.
struct TouchCompensation {
  bool enabled = false;  // the library renders what it is told; the players turn it on (docs/latency.md)
  double panel_latency_s = kDefaultTouchPanelLatency_s;  // 0 .. kMaxTouchPanelLatency_s
  TouchPredictionModel model = kDefaultTouchPredictionModel;
};

struct RealtimeOptions {
  double sample_rate_hz = kDefaultRenderRateHz;  // kMinRenderRateHz .. kMaxRenderRateHz
  // Samples per block; 0: 1 ms worth (8 at 8 kHz), at least 1. Raised to the sink's
  // min_block_samples(); otherwise at most 1/50 s.
  std::size_t block_samples = 0;
  double crossfade_s = 0.02;
  // stop() does not cut the drive: the last stop_ramp_s ramp it linearly to exactly 0 first.
  double stop_ramp_s = 0.005;
  std::size_t max_contacts = 512;
  std::size_t event_queue_capacity = 1024;
  LiveTrackerOptions tracker;
  TouchCompensation touch;
  // > 0: ask for SCHED_FIFO at this priority (1..99) for the render thread. Needs the privilege
  // (CAP_SYS_NICE or an rtprio limit); without it the thread keeps normal priority and
  // LoopStats::priority says why (describe()).
  int realtime_priority = 0;
};

struct LoopStats {
  double measured_rate_hz = 0.0;  // output samples per second over the last 0.5 s window
  // Wake-up lateness (LoopTelemetry's nearest-rank percentiles): against the absolute deadline,
  // or with a pacing sink against the block's time on the stream clock (which then includes the
  // device taking whole buffers at a time).
  double jitter_p50_s = 0.0;
  double jitter_p99_s = 0.0;
  double jitter_max_s = 0.0;
  std::uint64_t blocks = 0;
  std::uint64_t overruns = 0;        // blocks whose rendering ended after the next block's time
  std::uint64_t skips = 0;           // times the deadline loop moved its schedule forward
  std::uint64_t dropped_events = 0;  // queue full or stale
  std::uint64_t active_contacts = 0;
  bool realtime_priority = false;  // SCHED_FIFO was granted (priority.granted)
  RealtimePriority priority;       // what was asked and what happened: describe(priority)
  bool paced_by_sink = false;      // the sink's clock paces the stream
  std::size_t block_samples = 0;
  double stream_offset_s = 0.0;    // renderer clock minus CLOCK_MONOTONIC (0 with deadlines)
  // CPU time of one block's rendering (events, tracker, mixers, limiter; not the sink's write()),
  // wall clock on the render thread: compare with the block's duration.
  double render_mean_s = 0.0;
  double render_max_s = 0.0;
  std::uint64_t scene_generation = 0;   // the set_scene() call now playing (0: none yet)
  std::uint64_t scenes_superseded = 0;  // replaced in the mailbox before the render thread took them
  // How far ahead fingers are predicted: the panel's latency plus the sink's output latency (0: off).
  double prediction_horizon_s = 0.0;
  std::uint64_t model_runs = 0;  // the predictor's model runs so far, all fingers (LiveTracker::model_runs)
};

class RealtimeRenderer {
 public:
  // Lateness beyond which the deadline loop skips ahead (two 8 ms blocks, as before 1 ms blocks).
  static constexpr double kSkipAfterLag_s = 0.016;

  explicit RealtimeRenderer(DriveSink& sink, const RealtimeOptions& options = {});
  ~RealtimeRenderer();  // stops
  RealtimeRenderer(const RealtimeRenderer&) = delete;
  RealtimeRenderer& operator=(const RealtimeRenderer&) = delete;

  // Opens the sink and starts the thread. Returns an error message on a bad option; lets the
  // sink's exception through if it cannot open.
  std::optional<std::string> start();
  // Stops the thread and closes the sink (zero drive). Safe to call more than once.
  void stop();
  bool running() const { return running_.load(std::memory_order_acquire); }

  // Producer thread. False when the queue is full (the event is dropped). Event times are
  // monotonic_s().
  bool push_event(const TouchEvent& event);

  // Control thread: play `scene` (nullptr: silence) from now on, cross-fading from what plays.
  // Never refused. Returns this scene's generation (1 for the first call, then 2, 3, ...).
  std::uint64_t set_scene(std::shared_ptr<const Scene> scene);

  // Any thread: a CLOCK_MONOTONIC time (e.g. a touch event's) on the renderer clock, the time
  // base of the block times the sink receives. The identity unless the sink paces the stream.
  double renderer_time_s(double monotonic_time_s) const {
    return monotonic_time_s + stream_offset_s_.load(std::memory_order_relaxed);
  }

  LoopStats stats() const;
  // Final after start(); before it, the size for a sink that takes any block.
  std::size_t block_samples() const { return block_samples_.load(std::memory_order_relaxed); }
  double sample_rate_hz() const { return options_.sample_rate_hz; }

 private:
  struct SceneEntry {
    std::shared_ptr<const Scene> scene;
    std::uint64_t generation = 0;
  };

  void run();
  void run_on_deadlines();
  void run_paced_by_sink();
  void render_block(double block_start_s, double event_offset_s);
  void publish_rate(std::int64_t now_ns);
  void record_render_time(std::int64_t render_ns);
  void collect_retired();
  void release(const SceneEntry* entry);

  DriveSink& sink_;
  RealtimeOptions options_;
  // Set by start() before the thread starts; read anywhere.
  std::atomic<std::size_t> block_samples_;
  std::atomic<bool> paced_{false};
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<bool> stop_requested_{false};

  SpscRing<TouchEvent> events_;
  std::atomic<SceneEntry*> pending_scene_{nullptr};  // the mailbox
  SpscRing<SceneEntry*> retired_;                     // render thread -> control thread
  std::vector<std::unique_ptr<SceneEntry>> owned_;    // control thread only
  std::uint64_t next_generation_ = 1;                 // control thread only

  // Render thread state (preallocated).
  struct Impl;
  std::unique_ptr<Impl> impl_;

  // Published statistics.
  LoopTelemetry telemetry_;
  std::atomic<double> measured_rate_hz_{0.0};
  std::atomic<double> stream_offset_s_{0.0};
  std::atomic<std::int64_t> render_total_ns_{0};
  std::atomic<std::int64_t> render_max_ns_{0};
  std::atomic<std::uint64_t> dropped_events_{0};
  std::atomic<std::uint64_t> active_contacts_{0};
  std::atomic<std::uint64_t> scene_generation_{0};
  std::atomic<std::uint64_t> scenes_superseded_{0};
  std::atomic<int> priority_requested_{0};
  std::atomic<int> priority_error_{0};
  std::atomic<bool> priority_granted_{false};
  std::atomic<double> prediction_horizon_s_{0.0};
  std::atomic<std::uint64_t> model_runs_{0};
};

}  // namespace vimg
