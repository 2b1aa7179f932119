// Player engine benchmarks: cost per output sample against the number of primitives and fingers
// (grid index and naive linear scan), event-to-first-sample latency and real-time loop jitter
// with 1 ms (8-sample) and 8 ms (64-sample) blocks, at normal priority and SCHED_FIFO.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "player/contact_mixer.hpp"
#include "player/realtime_renderer.hpp"
#include "player/scene.hpp"
#include "primitives/image.hpp"
#include "realtime/loop_telemetry.hpp"
#include "realtime/realtime_priority.hpp"
#include "realtime/soft_limit.hpp"

namespace {

using namespace vimg;

// N primitives (dots, lines, small rectangles in equal parts) at constant density: about one per
// 25 mm^2 of a square canvas, as a dense real image would have.
Image random_image(int n, std::uint32_t seed = 1) {
  Image img;
  const double side = std::sqrt(static_cast<double>(n) * 25.0);
  img.width_mm = side;
  img.height_mm = side;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, side), unit(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    Element e;
    e.id = "p" + std::to_string(i);
    const double x = pos(rng), y = pos(rng);
    switch (i % 3) {
      case 0: e.body = Dot{x, y, 1.0, 0.5}; break;
      case 1: {
        const double a = unit(rng) * 6.283;
        e.body = Line{x, y, x + 4 * std::cos(a), y + 4 * std::sin(a), 1.0, 175.0, 0.05, 0.5};
        break;
      }
      default: {
        Surface s;
        s.shape = SurfaceShape::rect;
        s.x_mm = x; s.y_mm = y; s.width_mm = 3; s.height_mm = 3; s.gain = 0.3;
        e.body = s;
      }
    }
    img.children.push_back(std::move(e));
  }
  return img;
}

// Fingers moving at 100 mm/s in different directions, bouncing inside the canvas.
struct Fingers {
  Fingers(int n, double side_mm) : side_m(side_mm * 1e-3) {
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> pos(0.1 * side_m, 0.9 * side_m), angle(0, 6.283);
    for (int i = 0; i < n; ++i) {
      FingerStep f;
      f.finger = i;
      f.touch_id = static_cast<std::uint32_t>(i + 1);
      f.position_m = {pos(rng), pos(rng), 0};
      const double a = angle(rng);
      f.velocity_m_per_s = {0.1 * std::cos(a), 0.1 * std::sin(a), 0};
      steps.push_back(f);
    }
  }
  void advance(double dt) {
    for (auto& f : steps) {
      f.previous_position_m = f.position_m;
      f.position_m += f.velocity_m_per_s * dt;
      if (f.position_m.x < 0 || f.position_m.x > side_m) f.velocity_m_per_s.x = -f.velocity_m_per_s.x;
      if (f.position_m.y < 0 || f.position_m.y > side_m) f.velocity_m_per_s.y = -f.velocity_m_per_s.y;
    }
  }
  double side_m;
  std::vector<FingerStep> steps;
};

// Args: primitives, fingers, linear scan (0/1).
void BM_RenderSample(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int fingers = static_cast<int>(state.range(1));
  const bool linear = state.range(2) != 0;
  const Image img = random_image(n);
  const auto scene = compile_scene(img);
  ContactMixer mixer(512);
  mixer.set_scene(scene.get());
  mixer.use_linear_scan(linear);
  Fingers f(fingers, img.width_mm);
  const double dt = 1.0 / 8000.0;
  double t = 0.0, sink = 0.0;
  const int samples_per_iteration = linear ? 8 : 64;
  for (auto _ : state) {
    for (int i = 0; i < samples_per_iteration; ++i) {
      f.advance(dt);
      t += dt;
      sink += soft_limit(mixer.step(f.steps, t, dt));
    }
  }
  benchmark::DoNotOptimize(sink);
  state.counters["per_sample"] = benchmark::Counter(static_cast<double>(state.iterations()) * samples_per_iteration,
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["contacts"] = static_cast<double>(mixer.active_contacts());
}
BENCHMARK(BM_RenderSample)
    ->ArgNames({"prims", "fingers", "linear"})
    ->Args({100, 1, 0})->Args({10000, 1, 0})->Args({100000, 1, 0})
    ->Args({100, 10, 0})->Args({10000, 10, 0})->Args({100000, 10, 0})
    ->Args({100, 10, 1})->Args({10000, 10, 1})->Args({100000, 10, 1})
    ->Unit(benchmark::kMicrosecond);

// Records when the first non-zero block arrives after being armed.
class LatencySink final : public DriveSink {
 public:
  void open(double) override {}
  void close() override {}
  void write(std::span<const float> drive, double) override {
    bool nonzero = false;
    for (float v : drive) nonzero |= v != 0.0f;
    if (nonzero && armed.load(std::memory_order_acquire)) {
      seen_s.store(monotonic_s(), std::memory_order_release);
      armed.store(false, std::memory_order_release);
    }
    silent.store(!nonzero, std::memory_order_release);
  }
  std::atomic<bool> armed{false};
  std::atomic<bool> silent{true};
  std::atomic<double> seen_s{0.0};
};

// p50 / p99 by the project's one definition (nearest rank on 1 us bins, realtime/loop_telemetry).
struct Percentiles {
  void add(double value_s) {
    const auto us = static_cast<std::size_t>(std::max(0.0, value_s * 1e6));
    ++bins[std::min(bins.size() - 1, us)];
    max_s = std::max(max_s, value_s);
  }
  double percentile_s(double q) const { return nearest_rank_percentile(bins.data(), bins.size(), q) * 1e-6; }
  std::vector<std::uint32_t> bins = std::vector<std::uint32_t>(LoopTelemetry::kBins, 0);
  double max_s = 0.0;
};

// Labels a result with the scheduling the render thread really had.
void label_priority(benchmark::State& state, const LoopStats& s) {
  state.SetLabel(describe(s.priority));
  state.counters["fifo"] = s.realtime_priority ? 1.0 : 0.0;
}

// Time from push_event() of a touch onto a surface to the sink receiving the first block that
// reflects it (the first affected drive sample exists then), touches placed at random phases of
// the block; manual time. Args: block samples at 8 kHz, SCHED_FIFO priority (0: normal).
void BM_EventToFirstSampleLatency(benchmark::State& state) {
  Image img;
  Surface s;
  s.shape = SurfaceShape::rect;
  s.x_mm = 0; s.y_mm = 0; s.width_mm = 100; s.height_mm = 100;
  s.gain = 0.5;
  img.children.push_back(Element{"s", s, {}, {}, 0});
  LatencySink sink;
  RealtimeOptions o;
  o.sample_rate_hz = 8000.0;
  o.block_samples = static_cast<std::size_t>(state.range(0));
  o.realtime_priority = static_cast<int>(state.range(1));
  RealtimeRenderer r(sink, o);
  r.set_scene(compile_scene(img));
  if (r.start()) {
    state.SkipWithError("cannot start");
    return;
  }
  const auto block_us = static_cast<int>(1e6 * static_cast<double>(r.block_samples()) / r.sample_rate_hz());
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> wait_us(0, block_us);
  Percentiles latency;
  for (auto _ : state) {
    while (!sink.silent.load()) std::this_thread::sleep_for(std::chrono::microseconds(200));
    std::this_thread::sleep_for(std::chrono::microseconds(wait_us(rng)));  // random phase in the block
    sink.armed.store(true);
    const double t0 = monotonic_s();
    // A moving touch: down then a move 2 ms later in time (velocity 100 mm/s), both pushed now.
    TouchEvent down{t0 - 0.002, 0, TouchPhase::down, 50.0, 50.0, 1.0};
    TouchEvent move{t0, 0, TouchPhase::move, 50.2, 50.0, 1.0};
    r.push_event(down);
    r.push_event(move);
    while (sink.armed.load()) std::this_thread::sleep_for(std::chrono::microseconds(20));
    const double latency_s = sink.seen_s.load() - t0;
    latency.add(latency_s);
    state.SetIterationTime(latency_s);
    TouchEvent up{monotonic_s(), 0, TouchPhase::up, 50.2, 50.0, 1.0};
    r.push_event(up);
  }
  const LoopStats stats = r.stats();
  r.stop();
  state.counters["p50_ms"] = latency.percentile_s(0.50) * 1e3;
  state.counters["p99_ms"] = latency.percentile_s(0.99) * 1e3;
  state.counters["max_ms"] = latency.max_s * 1e3;
  state.counters["block_ms"] = 1e3 * static_cast<double>(r.block_samples()) / r.sample_rate_hz();
  label_priority(state, stats);
}
BENCHMARK(BM_EventToFirstSampleLatency)
    ->ArgNames({"block", "fifo_priority"})
    ->Args({8, 0})->Args({8, 80})->Args({64, 0})->Args({64, 80})
    ->UseManualTime()->Iterations(500)->Unit(benchmark::kMillisecond);

class NullSink final : public DriveSink {
 public:
  void open(double) override {}
  void write(std::span<const float>, double) override {}
  void close() override {}
};

// The real-time loop for 3 s at 8 kHz over 10 000 primitives with 10 fingers moving (120 Hz
// events): wake-up lateness against the absolute deadlines, and the render thread's own time per
// block. Args: block samples, SCHED_FIFO priority (0: normal scheduling).
void BM_RealtimeLoopJitter(benchmark::State& state) {
  const Image img = random_image(10000);
  NullSink sink;
  RealtimeOptions o;
  o.sample_rate_hz = 8000.0;
  o.block_samples = static_cast<std::size_t>(state.range(0));
  o.realtime_priority = static_cast<int>(state.range(1));
  RealtimeRenderer r(sink, o);
  r.set_scene(compile_scene(img));
  for (auto _ : state) {
    if (r.start()) {
      state.SkipWithError("cannot start");
      return;
    }
    const double t0 = monotonic_s();
    for (int f = 0; f < 10; ++f) r.push_event({t0, f, TouchPhase::down, 20.0 + 40 * f, 100.0, 1.0});
    for (int k = 1; k <= 360; ++k) {
      std::this_thread::sleep_for(std::chrono::microseconds(8333));
      const double t = monotonic_s();
      for (int f = 0; f < 10; ++f)
        r.push_event({t, f, TouchPhase::move, 20.0 + 40 * f + 100.0 * (t - t0), 100.0 + 10 * f, 1.0});
    }
    const LoopStats s = r.stats();
    r.stop();
    state.counters["rate_hz"] = s.measured_rate_hz;
    state.counters["jitter_p50_us"] = s.jitter_p50_s * 1e6;
    state.counters["jitter_p99_us"] = s.jitter_p99_s * 1e6;
    state.counters["jitter_max_us"] = s.jitter_max_s * 1e6;
    state.counters["overruns"] = static_cast<double>(s.overruns);
    state.counters["skips"] = static_cast<double>(s.skips);
    state.counters["blocks"] = static_cast<double>(s.blocks);
    state.counters["render_mean_us"] = s.render_mean_s * 1e6;
    state.counters["render_max_us"] = s.render_max_s * 1e6;
    state.counters["render_per_sample_us"] = s.render_mean_s * 1e6 / static_cast<double>(s.block_samples);
    state.counters["contacts"] = static_cast<double>(s.active_contacts);
    label_priority(state, s);
  }
}
BENCHMARK(BM_RealtimeLoopJitter)
    ->ArgNames({"block", "fifo_priority"})
    ->Args({8, 0})->Args({8, 80})->Args({64, 0})->Args({64, 80})
    ->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
