// The real-time loop as the live players run it (docs/benchmarks/touch-prediction.md, "Touch prediction in the
// render loop"): RealtimeRenderer over the smiley (assets/examples/smiley.vimg), 1 or 10 fingers
// circling on its face at 120 mm/s with touch events at 60 or 120 Hz, at 8 kHz (the native players' rate) or
// 48 kHz (the page's), 1 ms blocks, touch-latency compensation on (the learned model, 25 ms, the
// players' default) or off. 3 s per repetition, deadlines paced by CLOCK_MONOTONIC (a sink without
// a clock). Counters:
//   render_ns_per_sample  the render thread's own time per sample (LoopStats::render_mean_s: events,
//                         tracker, mixers, limiter; wall time on the render thread, so ask for
//                         SCHED_FIFO, which this machine grants, to keep other work off it)
//   cpu_ns_per_sample     the render thread's CPU time per sample, sleeps and the sink included
//   model_runs_per_s      how often the predictor's model ran, all fingers (0 with compensation off)
// The goal (issue 44): with compensation on, render_ns_per_sample at most 1.2x the same run's with it off.
//   build/release/bench/realtime_prediction_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <time.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "player/contact_mixer.hpp"
#include "player/realtime_renderer.hpp"
#include "player/scene.hpp"
#include "realtime/clock.hpp"
#include "realtime/soft_limit.hpp"
#include "storage/image_io.hpp"

namespace {

using namespace vimg;

std::int64_t thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// Takes the blocks; every 64th reads the render thread's CPU time (a system call, so not every block).
class CpuSink final : public DriveSink {
 public:
  void open(double) override {}
  void close() override {}
  void write(std::span<const float> drive, double) override {
    ++blocks_;
    samples_ += drive.size();
    if (blocks_ % 64 != 0) return;
    const std::int64_t now_ns = thread_cpu_ns();
    if (first_ns_.load(std::memory_order_relaxed) < 0) {
      first_ns_.store(now_ns, std::memory_order_relaxed);
      first_samples_ = samples_;
    }
    last_ns_.store(now_ns, std::memory_order_relaxed);
    measured_samples_.store(samples_ - first_samples_, std::memory_order_release);
  }
  // After stop(): the render thread's CPU time per sample between the first and the last reading.
  double cpu_ns_per_sample() const {
    const std::uint64_t n = measured_samples_.load(std::memory_order_acquire);
    return n == 0 ? 0.0 : static_cast<double>(last_ns_.load() - first_ns_.load()) / static_cast<double>(n);
  }

 private:
  std::uint64_t blocks_ = 0, samples_ = 0, first_samples_ = 0;  // render thread only
  std::atomic<std::int64_t> first_ns_{-1}, last_ns_{0};
  std::atomic<std::uint64_t> measured_samples_{0};
};

// Finger f circles its own centre on a 2 x 5 grid inside the face (radius 8 mm, 120 mm/s), as
// bench/ten_finger_gesture.py's gesture does.
TouchEvent finger_event(int f, double t0_s, double t_s, TouchPhase phase) {
  const double cx = 25.0 + 20.0 * (f % 2), cy = 46.0 + 12.0 * (f / 2);
  const double a = 15.0 * (t_s - t0_s) + 0.7 * f;
  return {t_s, f, phase, cx + 8.0 * std::cos(a), cy + 8.0 * std::sin(a), 1.0};
}

// Args: fingers, sample rate (Hz), events per second, compensation (0 off, 1 on), the tracker's
// prediction interval in us (LiveTrackerOptions::prediction_interval_s; 0: the model at every sample,
// as before issue 44).
void BM_RealtimeLoopPrediction(benchmark::State& state) {
  const LoadResult image = load_image_file(VIMG_SOURCE_DIR "/assets/examples/smiley.vimg");
  if (!image.ok()) {
    state.SkipWithError("cannot load assets/examples/smiley.vimg");
    return;
  }
  const int fingers = static_cast<int>(state.range(0));
  const auto event_period = std::chrono::microseconds(1000000 / state.range(2));
  RealtimeOptions o;
  o.sample_rate_hz = static_cast<double>(state.range(1));
  o.realtime_priority = 80;
  o.touch.enabled = state.range(3) != 0;
  o.tracker.prediction_interval_s = static_cast<double>(state.range(4)) * 1e-6;
  const auto scene = compile_scene(*image.image);
  double render_ns = 0.0, cpu_ns = 0.0, runs_per_s = 0.0;
  for (auto _ : state) {
    CpuSink sink;
    RealtimeRenderer r(sink, o);
    r.set_scene(scene);
    if (r.start()) {
      state.SkipWithError("cannot start");
      return;
    }
    const double t0 = monotonic_s();
    for (int f = 0; f < fingers; ++f) r.push_event(finger_event(f, t0, t0, TouchPhase::down));
    const auto start = std::chrono::steady_clock::now();
    for (auto next = start + event_period; next < start + std::chrono::seconds(3); next += event_period) {
      std::this_thread::sleep_until(next);
      const double t = monotonic_s();
      for (int f = 0; f < fingers; ++f) r.push_event(finger_event(f, t0, t, TouchPhase::move));
    }
    const LoopStats s = r.stats();
    const double run_s = monotonic_s() - t0;
    r.stop();
    render_ns = s.render_mean_s * 1e9 / static_cast<double>(s.block_samples);
    cpu_ns = sink.cpu_ns_per_sample();
    runs_per_s = static_cast<double>(s.model_runs) / run_s;
    state.SetLabel(describe(s.priority));
    state.counters["overruns"] = static_cast<double>(s.overruns);
    state.counters["contacts"] = static_cast<double>(s.active_contacts);
  }
  state.counters["render_ns_per_sample"] = render_ns;
  state.counters["cpu_ns_per_sample"] = cpu_ns;
  state.counters["model_runs_per_s"] = runs_per_s;
}
BENCHMARK(BM_RealtimeLoopPrediction)
    ->ArgNames({"fingers", "rate_hz", "events_hz", "compensation", "interval_us"})
    ->ArgsProduct({{1, 10}, {8000, 48000}, {120}, {0, 1}, {10000}})
    ->Args({10, 8000, 60, 0, 10000})->Args({10, 8000, 60, 1, 10000})
    ->Args({10, 8000, 120, 1, 0})->Args({10, 48000, 120, 1, 0})
    ->Iterations(1)->Unit(benchmark::kMillisecond);

// The same work without the thread, the sleeps and the sink: one second of stream per iteration,
// events applied at their sample as the render thread applies them at its block's start, CPU time
// (warm caches: the real loop sleeps between blocks, so its model runs start colder). Args as above.
void BM_LivePathPrediction(benchmark::State& state) {
  const LoadResult image = load_image_file(VIMG_SOURCE_DIR "/assets/examples/smiley.vimg");
  if (!image.ok()) {
    state.SkipWithError("cannot load assets/examples/smiley.vimg");
    return;
  }
  const int fingers = static_cast<int>(state.range(0));
  const double rate_hz = static_cast<double>(state.range(1)), event_period_s = 1.0 / static_cast<double>(state.range(2));
  const auto scene = compile_scene(*image.image);
  LiveTrackerOptions options;
  options.prediction_interval_s = static_cast<double>(state.range(4)) * 1e-6;
  LiveTracker tracker(options);
  tracker.set_prediction(state.range(3) != 0 ? kDefaultTouchPanelLatency_s : 0.0);
  ContactMixer mixer;
  mixer.set_scene(scene.get());
  std::array<FingerStep, LiveTracker::kMaxFingers> steps{};
  for (int f = 0; f < fingers; ++f) tracker.apply(finger_event(f, 0.0, 0.0, TouchPhase::down), 0.0);
  const auto samples = static_cast<long>(rate_hz);
  long sample = 0;
  double next_event_s = event_period_s, sum = 0.0;
  for (auto _ : state) {
    for (long i = 0; i < samples; ++i, ++sample) {
      const double t = static_cast<double>(sample) / rate_hz;
      for (; next_event_s <= t; next_event_s += event_period_s) {
        for (int f = 0; f < fingers; ++f) tracker.apply(finger_event(f, 0.0, next_event_s, TouchPhase::move), t);
      }
      const std::size_t n = tracker.steps_at(t, 1.0 / rate_hz, steps);
      sum += soft_limit(mixer.step(std::span<const FingerStep>(steps.data(), n), t, 1.0 / rate_hz));
    }
  }
  benchmark::DoNotOptimize(sum);
  state.counters["ns_per_sample"] = benchmark::Counter(static_cast<double>(state.iterations() * samples),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert,
                                                        benchmark::Counter::OneK::kIs1000);
  state.counters["model_runs_per_s"] = static_cast<double>(tracker.model_runs()) * rate_hz / static_cast<double>(sample);
}
BENCHMARK(BM_LivePathPrediction)
    ->ArgNames({"fingers", "rate_hz", "events_hz", "compensation", "interval_us"})
    ->ArgsProduct({{1, 10}, {8000, 48000}, {120}, {0, 1}, {10000}})
    ->Args({10, 8000, 120, 1, 0})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
