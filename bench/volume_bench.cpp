// Volume backend: the cost of one haptic cycle with every shader over a 256^3 scalar volume and
// a 128^3 vector volume (goal <= 20 us, 2 % of a 1 kHz cycle), the safety stack, and the force
// loop holding 1 kHz and 4 kHz (rate, lateness, overruns) with and without SCHED_FIFO.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/force_log.hpp"
#include "player/haptic/haptic_loop.hpp"
#include "primitives/cues/roughness_shader.hpp"
#include "primitives/cues/transition_cue_shader.hpp"
#include "primitives/kinaesthetic/gradient_force.hpp"
#include "primitives/kinaesthetic/vector_guidance.hpp"
#include "primitives/kinaesthetic/yielding_surface.hpp"
#include "primitives/volume/data_fields.hpp"
#include "primitives/volume/modulated_shader.hpp"

namespace vimg {
namespace {

std::shared_ptr<const ScalarGrid> scalar_volume(int n) {
  GridGeometry g;
  g.size = {n, n, n};
  g.spacing_m = {0.0005, 0.0005, 0.0005};
  g.origin_m = {-0.064, -0.064, -0.064};
  std::vector<float> v(g.size.count());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 p = g.voxel_to_world({double(i), double(j), double(k)}) * 1e3;
        v[g.linear_index(i, j, k)] = static_cast<float>(std::sin(0.2 * p.x) + 0.05 * p.z + std::cos(0.1 * p.y));
      }
  return std::make_shared<const ScalarGrid>(g, std::move(v));
}

std::shared_ptr<const VectorGrid> vector_volume(int n) {
  GridGeometry g;
  g.size = {n, n, n};
  g.spacing_m = {0.001, 0.001, 0.001};
  g.origin_m = {-0.064, -0.064, -0.064};
  std::vector<float> c(3 * g.size.count());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::size_t m = 3 * g.linear_index(i, j, k);
        const double a = 0.05 * i;
        c[m] = static_cast<float>(std::cos(a));
        c[m + 1] = 0.1f;
        c[m + 2] = static_cast<float>(std::sin(a));
      }
  return std::make_shared<const VectorGrid>(g, std::move(c));
}

std::unique_ptr<HapticScene> every_shader_scene(std::shared_ptr<const ScalarGrid> s, std::shared_ptr<const VectorGrid> v) {
  std::vector<std::shared_ptr<const ForceShader>> kin, vib;
  kin.push_back(std::make_shared<GradientForceShader>(*s, 1e-4));
  kin.push_back(std::make_shared<YieldingSurfaceShader>(*s, YieldingSurfaceParams{{300.0, 0.5}, 1.5, 0.3, 10.0}));
  kin.push_back(std::make_shared<VectorGuidanceShader>(*v, VectorGuidanceParams{{300.0, 0.5}, 1.5, 0.1, 1e-6}));
  auto omega = std::make_shared<MappedSpatialFrequency>(s, TransferFunction({{-1.0, 0.0004}, {1.0, 0.0025}}),
                                                        MappedSpatialFrequency::Output::period_m);
  RoughnessParams rp;
  rp.amplitude_N = 1.0;
  auto amplitude = std::make_shared<MappedValueField>(s, TransferFunction({{-1.0, 0.6}, {1.0, 0.3}}));
  vib.push_back(std::make_shared<ModulatedShader>(std::make_shared<RoughnessShader>(omega, rp), amplitude));
  vib.push_back(std::make_shared<TransitionCueShader>(std::make_shared<VolumeValueField>(s), TransitionCueParams{}));
  return std::make_unique<HapticScene>(DeviceProfile{}, std::vector<std::shared_ptr<const void>>{s, v}, kin, vib);
}

void BM_HapticCycleEveryShader(benchmark::State& state) {
  static const auto s = scalar_volume(256);
  static const auto v = vector_volume(128);
  auto scene = every_shader_scene(s, v);
  HapticCycle cycle({0.1});
  cycle.set_scene(scene.get(), 0.0);
  ProbeSample probe;
  double t = 0.0;
  for (auto _ : state) {
    t += 1e-3;
    // A probe circling at about 0.1 m/s through the data, crossing isosurfaces now and then.
    probe.position_m = {0.03 * std::cos(3.0 * t), 0.02 * std::sin(3.0 * t), 0.03 * std::sin(1.3 * t)};
    probe.velocity_m_per_s = {-0.09 * std::sin(3.0 * t), 0.06 * std::cos(3.0 * t), 0.039 * std::cos(1.3 * t)};
    benchmark::DoNotOptimize(cycle.step(probe, t));
  }
}
BENCHMARK(BM_HapticCycleEveryShader)->Unit(benchmark::kMicrosecond);

// The safety stack alone (gate, wall, clamp, slew, watchdogs) on a force that keeps it busy.
void BM_SafetyStack(benchmark::State& state) {
  SafetySettings settings;
  settings.gate_force_N = 1e9;
  SafetyStack stack(settings, ForceDeviceLimits{}, 1e-3);
  SafetyInput in;
  for (auto _ : state) {
    in.time_s += 1e-3;
    ++in.sequence;
    in.scene_N = {4.0 * std::sin(40.0 * in.time_s), 2.0, -1.0};
    in.position_m = {0.075 * std::sin(3.0 * in.time_s), 0.0, 0.0};
    benchmark::DoNotOptimize(stack.apply(in));
  }
}
BENCHMARK(BM_SafetyStack)->Unit(benchmark::kNanosecond);

// The force loop as vimg-force runs it: the simulated device, the every-shader scene over 64^3
// volumes, the safety stack with its default watchdogs, the per-cycle log drained to a file by
// the writer thread; 3 s at the given rate, at normal priority or asking for SCHED_FIFO. The
// label says what scheduling the loop got (a refused SCHED_FIFO says so).
void BM_ForceLoop(benchmark::State& state) {
  const double rate = static_cast<double>(state.range(0));
  const int priority = static_cast<int>(state.range(1));
  for (auto _ : state) {
    SimulatedForceDevice device(std::vector<HandPathPoint>{{0.0, Vec3{}}, {3.0, Vec3{0.05, 0.0, 0.0}}});
    HapticLoopConfig config;
    config.rate_hz = rate;
    config.realtime_priority = priority;
    config.log_capacity_rows = static_cast<std::size_t>(rate);
    HapticLoop loop(device, config);
    loop.submit_scene(every_shader_scene(scalar_volume(64), vector_volume(64)));
    // Never committed: the temporary file is removed when the writer goes.
    ForceLogWriter log(loop, std::filesystem::temp_directory_path() / "volume_bench_force_log.csv");
    log.start();
    loop.start();
    for (int i = 0; i < 300 && loop.running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    loop.stop();
    const LoopTimingStats t = loop.timing();
    state.counters["rate_hz"] = t.rate_hz;
    state.counters["target_hz"] = rate;
    state.counters["p50_us"] = t.jitter_p50_us;
    state.counters["p99_us"] = t.jitter_p99_us;
    state.counters["max_us"] = t.jitter_max_us;
    state.counters["overruns"] = static_cast<double>(t.overruns);
    state.counters["skips"] = static_cast<double>(t.skips);
    state.counters["cycles"] = static_cast<double>(t.cycles);
    state.counters["fifo"] = loop.realtime_priority().granted ? 1.0 : 0.0;
    state.counters["faulted"] = loop.failed() ? 1.0 : 0.0;
    state.counters["log_dropped"] = static_cast<double>(loop.log_rows_dropped());
    state.SetLabel(describe(loop.realtime_priority()) + (loop.failed() ? "; " + loop.fault_text() : ""));
  }
}
// Args: rate (Hz), SCHED_FIFO priority (0: normal scheduling).
BENCHMARK(BM_ForceLoop)->Args({1000, 0})->Args({4000, 0})->Args({1000, 80})->Args({4000, 80})->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace vimg

BENCHMARK_MAIN();
