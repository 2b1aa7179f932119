// Cost per output sample of each primitive model, and of a sum of N shaders.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "primitives/cues/roughness_shader.hpp"
#include "primitives/cues/transition_cue_shader.hpp"
#include "primitives/force_sum.hpp"
#include "primitives/touch/dot_shader.hpp"
#include "primitives/touch/line_shader.hpp"
#include "primitives/touch/surface_shader.hpp"

namespace vimg {
namespace {

constexpr double kRate = 8000.0;
constexpr std::size_t kSteps = 8000;

// One second of a finger circling at 0.1 m/s, radius 4 mm, around (cx, cy) mm, at 8 kHz.
std::vector<InteractionState> circle_steps(double cx_mm, double cy_mm) {
  std::vector<InteractionState> steps(kSteps);
  const double r = 0.004, v = 0.1, w = v / r, dt = 1.0 / kRate;
  auto at = [&](double t) { return Vec3{cx_mm * 1e-3 + r * std::cos(w * t), cy_mm * 1e-3 + r * std::sin(w * t), 0}; };
  for (std::size_t k = 0; k < kSteps; ++k) {
    const double t = static_cast<double>(k + 1) * dt;
    steps[k].position_m = at(t);
    steps[k].previous_position_m = at(t - dt);
    steps[k].velocity_m_per_s = {-v * std::sin(w * t), v * std::cos(w * t), 0};
    steps[k].time_s = t;
    steps[k].dt_s = dt;
  }
  return steps;
}

void run_shader(benchmark::State& bench, const ForceShader& shader, const std::vector<InteractionState>& steps) {
  ShaderState state;
  shader.begin_contact(state);
  std::size_t k = 0;
  for (auto _ : bench) {
    benchmark::DoNotOptimize(shader.force_N(steps[k], state));
    if (++k == steps.size()) {
      k = 0;
      shader.begin_contact(state);
    }
  }
  bench.SetItemsProcessed(bench.iterations());
}

void BM_Dot(benchmark::State& bench) {
  // The circle's centre crosses in and out of a 3 mm dot at its edge.
  run_shader(bench, DotShader(Dot{4.0, 0.0, 3.0, 1.0}, TouchContext{}), circle_steps(0, 0));
}
BENCHMARK(BM_Dot);

void BM_Line(benchmark::State& bench) {
  // A line through the circle: two plucks and ring-downs per turn.
  run_shader(bench, LineShader(Line{-10.0, 0.0, 10.0, 0.0, 1.5, 175.0, 0.05, 1.0}, TouchContext{}),
             circle_steps(0, 0));
}
BENCHMARK(BM_Line);

Surface surface_of(SurfaceShape shape, int polygon_vertices) {
  Surface s;
  s.shape = shape;
  s.x_mm = -20;
  s.y_mm = -20;
  s.width_mm = 40;
  s.height_mm = 40;
  s.rx_mm = 20;
  s.ry_mm = 15;
  for (int i = 0; i < polygon_vertices; ++i) {
    const double a = 2.0 * std::numbers::pi * i / polygon_vertices;
    const double r = (i % 2 == 0) ? 20.0 : 14.0;  // a star: not convex
    s.points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return s;
}

void BM_SurfaceRect(benchmark::State& bench) {
  run_shader(bench, SurfaceShader(surface_of(SurfaceShape::rect, 0), TouchContext{}), circle_steps(0, 0));
}
BENCHMARK(BM_SurfaceRect);

void BM_SurfaceEllipse(benchmark::State& bench) {
  run_shader(bench, SurfaceShader(surface_of(SurfaceShape::ellipse, 0), TouchContext{}), circle_steps(0, 0));
}
BENCHMARK(BM_SurfaceEllipse);

void BM_SurfacePolygon(benchmark::State& bench) {
  run_shader(bench, SurfaceShader(surface_of(SurfaceShape::polygon, static_cast<int>(bench.range(0))), TouchContext{}),
             circle_steps(0, 0));
}
BENCHMARK(BM_SurfacePolygon)->Arg(8)->Arg(64);

void BM_Roughness(benchmark::State& bench) {
  run_shader(bench, RoughnessShader(std::make_shared<ConstantSpatialFrequency>(2.0 * std::numbers::pi / 0.001), {}),
             circle_steps(0, 0));
}
BENCHMARK(BM_Roughness);

class PlaneY final : public ScalarField {
 public:
  double value(const Vec3& p) const override { return p.y; }
};

void BM_TransitionCue(benchmark::State& bench) {
  // The circle crosses the plane y = 0 twice per turn, each crossing located by a root search.
  run_shader(bench, TransitionCueShader(std::make_shared<PlaneY>(), {}), circle_steps(0, 1));
}
BENCHMARK(BM_TransitionCue);

// N shaders (a mix of dots, lines and surfaces around the finger), each with its own contact
// state: evaluate all, sum, clamp once, normalize. One iteration is one output sample.
void BM_SumOfShaders(benchmark::State& bench) {
  const auto n = static_cast<std::size_t>(bench.range(0));
  std::vector<std::unique_ptr<ForceShader>> shaders;
  for (std::size_t i = 0; i < n; ++i) {
    const double offset = static_cast<double>(i % 7) - 3.0;
    switch (i % 3) {
      case 0: shaders.push_back(std::make_unique<DotShader>(Dot{4.0 + offset, 0.0, 3.0, 0.5}, TouchContext{})); break;
      case 1:
        shaders.push_back(std::make_unique<LineShader>(Line{-10.0, offset, 10.0, offset, 1.5, 175.0, 0.05, 0.5},
                                                       TouchContext{}));
        break;
      default: shaders.push_back(std::make_unique<SurfaceShader>(surface_of(SurfaceShape::polygon, 8), TouchContext{}));
    }
  }
  std::vector<ShaderState> states(n);
  for (std::size_t i = 0; i < n; ++i) shaders[i]->begin_contact(states[i]);
  const auto steps = circle_steps(0, 0);
  std::size_t k = 0;
  for (auto _ : bench) {
    ForceSum sum;
    for (std::size_t i = 0; i < n; ++i) sum.add(shaders[i]->force_N(steps[k], states[i]));
    benchmark::DoNotOptimize(sum.clamped_N(1.0).z);  // the component along the actuator axis
    if (++k == steps.size()) {
      k = 0;
      for (std::size_t i = 0; i < n; ++i) shaders[i]->begin_contact(states[i]);
    }
  }
  bench.SetItemsProcessed(bench.iterations());
}
BENCHMARK(BM_SumOfShaders)->Arg(1)->Arg(10)->Arg(100);

}  // namespace
}  // namespace vimg

BENCHMARK_MAIN();
