// Property tests: random parameters and random paths for every touch shape. Whatever the path,
// the drive stays within the gain, is silent outside the shape (or after the LINE's ring-down),
// and the contact becomes inactive once nothing more can sound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "primitives/geometry/hit_test.hpp"
#include "primitives/touch/dot_shader.hpp"
#include "primitives/touch/line_shader.hpp"
#include "primitives/touch/surface_shader.hpp"
#include "render_helper.hpp"

namespace vimg {
namespace {

struct Random {
  std::mt19937 engine;
  explicit Random(unsigned seed) : engine(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(engine); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(engine); }
};

// A piecewise-linear path through waypoints (mm), with random speeds and pauses.
struct Waypoint {
  double time_s;
  Vec2 position_m;
};

test::Path piecewise_path(const std::vector<Waypoint>& points) {
  return [points](double t) {
    std::size_t i = 0;
    while (i + 2 < points.size() && points[i + 1].time_s <= t) ++i;
    const Waypoint& a = points[i];
    const Waypoint& b = points[i + 1];
    const double span = b.time_s - a.time_s;
    const double u = std::clamp((t - a.time_s) / span, 0.0, 1.0);
    const Vec2 p = lerp(a.position_m, b.position_m, u);
    const Vec2 v = (t >= a.time_s && t <= b.time_s) ? (b.position_m - a.position_m) * (1.0 / span) : Vec2{};
    return test::PathPoint{{p.x, p.y, 0}, {v.x, v.y, 0}, 1.0};
  };
}

// Waypoints chosen among random points, the given special points (vertices, edge points), and
// pauses; ends far outside so every contact must end.
std::vector<Waypoint> random_waypoints(Random& rng, const std::vector<Vec2>& special_m, double duration_s) {
  std::vector<Waypoint> out{{0.0, {-0.05, -0.05}}};
  double t = 0.0;
  while (t < duration_s) {
    Vec2 next;
    const int kind = rng.integer(0, 9);
    if (kind < 4 || special_m.empty()) {
      next = {rng.uniform(-0.025, 0.025), rng.uniform(-0.025, 0.025)};
    } else if (kind < 8) {
      next = special_m[rng.integer(0, static_cast<int>(special_m.size()) - 1)];
    } else {
      next = out.back().position_m;  // a pause
    }
    const double speed = rng.uniform(0.005, 0.6);
    const double distance = norm(next - out.back().position_m);
    t += std::max(distance / speed, rng.uniform(0.005, 0.05));
    out.push_back({t, next});
  }
  out.push_back({t + 0.05, {0.06, 0.06}});
  return out;
}

double path_end_s(const std::vector<Waypoint>& w) { return w.back().time_s; }

Vec2 point_of(const test::Rendered&, const test::Path& path, double t) {
  const Vec3 p = path(t).position_m;
  return {p.x, p.y};
}

TEST(TouchProperties, DotIsBoundedAndSilentOutsideTheDisc) {
  Random rng(1);
  for (int trial = 0; trial < 40; ++trial) {
    const Dot dot{rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(0.5, 8), rng.uniform(0.05, 1.0)};
    TouchContext context;
    context.full_speed_m_per_s = rng.uniform(0.02, 0.3);
    context.carrier_frequency_hz = rng.uniform(140, 250);
    const DotShader shader(dot, context);
    const Vec2 c{dot.x_mm * 1e-3, dot.y_mm * 1e-3};
    const double r = dot.radius_mm * 1e-3;
    const auto waypoints = random_waypoints(rng, {c, c + Vec2{r, 0}, c + Vec2{0, -r}}, 1.0);
    const auto path = piecewise_path(waypoints);
    const auto out = test::render(shader, path, path_end_s(waypoints) + 0.01);
    for (std::size_t k = 0; k < out.drive.size(); ++k) {
      ASSERT_LE(std::abs(out.drive[k]), dot.gain + 1e-12);
      const bool inside = contains(shader.disc_m(), point_of(out, path, out.time_s[k]));
      if (!inside) {
        ASSERT_EQ(out.drive[k], 0.0) << "trial " << trial << " t=" << out.time_s[k];
        ASSERT_FALSE(out.active[k]);
      }
    }
    ASSERT_FALSE(out.active.back());
  }
}

TEST(TouchProperties, LineIsBoundedAndSilentAfterItsRingDown) {
  Random rng(2);
  for (int trial = 0; trial < 40; ++trial) {
    const Line line{rng.uniform(-15, 15), rng.uniform(-15, 15), rng.uniform(-15, 15), rng.uniform(-15, 15),
                    rng.uniform(0.2, 4), rng.uniform(80, 300), rng.uniform(0.01, 0.6), rng.uniform(0.05, 1.0)};
    const LineShader shader(line, TouchContext{});
    const Capsule band = shader.band_m();
    const Vec2 normal_offset = Vec2{0, band.radius};
    const auto waypoints =
        random_waypoints(rng, {band.a, band.b, lerp(band.a, band.b, 0.5) + normal_offset, band.a - normal_offset}, 1.0);
    const auto path = piecewise_path(waypoints);
    const double ring_s = std::log(100.0) / (shader.damping_ratio() * shader.omega_n_rad_per_s());
    const auto out = test::render(shader, path, path_end_s(waypoints) + ring_s + 0.01);
    double last_inside_s = -1e9;
    for (std::size_t k = 0; k < out.drive.size(); ++k) {
      ASSERT_LE(std::abs(out.drive[k]), line.gain + 1e-12);
      const double t = out.time_s[k];
      // Inside at this sample, or somewhere in the step that led to it.
      const double dt = 1.0 / out.sample_rate_hz;
      if (contains(band, point_of(out, path, t)) || contains(band, point_of(out, path, t - 0.5 * dt)) ||
          contains(band, point_of(out, path, t - dt))) {
        last_inside_s = t;
      }
      if (t > last_inside_s + ring_s + dt) {
        ASSERT_EQ(out.drive[k], 0.0) << "trial " << trial << " t=" << t;
        ASSERT_FALSE(out.active[k]);
      }
    }
    ASSERT_FALSE(out.active.back());
  }
}

Surface random_surface(Random& rng, std::vector<Vec2>& special_m) {
  Surface s;
  s.shape = static_cast<SurfaceShape>(rng.integer(0, 2));
  s.period_mm = rng.uniform(0.3, 5);
  s.relief_mm = rng.uniform(0.05, 2);
  s.pattern = static_cast<SurfacePattern>(rng.integer(0, 2));
  s.gain = rng.uniform(0.05, 1.0);
  switch (s.shape) {
    case SurfaceShape::rect:
      s.x_mm = rng.integer(-15, 0);
      s.y_mm = rng.integer(-15, 0);
      s.width_mm = rng.integer(1, 20);
      s.height_mm = rng.integer(1, 20);
      special_m = {{s.x_mm * 1e-3, s.y_mm * 1e-3}, {(s.x_mm + s.width_mm) * 1e-3, s.y_mm * 1e-3}};
      break;
    case SurfaceShape::ellipse:
      s.cx_mm = rng.uniform(-5, 5);
      s.cy_mm = rng.uniform(-5, 5);
      s.rx_mm = rng.uniform(1, 15);
      s.ry_mm = rng.uniform(1, 15);
      special_m = {{(s.cx_mm + s.rx_mm) * 1e-3, s.cy_mm * 1e-3}, {s.cx_mm * 1e-3, (s.cy_mm - s.ry_mm) * 1e-3}};
      break;
    case SurfaceShape::polygon: {
      const int n = rng.integer(3, 8);
      special_m.clear();
      for (int i = 0; i < n; ++i) {
        const Point2Mm p{static_cast<double>(rng.integer(-15, 15)), static_cast<double>(rng.integer(-15, 15))};
        s.points.push_back(p);
        special_m.push_back({p.x_mm * 1e-3, p.y_mm * 1e-3});  // paths through vertices
      }
      for (int i = 0; i < n; ++i) special_m.push_back(lerp(special_m[i], special_m[(i + 1) % n], 0.5));
      break;
    }
  }
  return s;
}

TEST(TouchProperties, SurfaceIsBoundedSilentOutsideAndStillWhenStill) {
  Random rng(3);
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Vec2> special;
    const Surface surface = random_surface(rng, special);
    TouchContext context;
    context.full_speed_m_per_s = rng.uniform(0.02, 0.3);
    context.max_deformation_m = rng.uniform(0.0002, 0.002);
    const SurfaceShader shader(surface, context);
    const auto waypoints = random_waypoints(rng, special, 1.0);
    const auto path = piecewise_path(waypoints);
    const auto out = test::render(shader, path, path_end_s(waypoints) + 0.01);
    for (std::size_t k = 0; k < out.drive.size(); ++k) {
      ASSERT_LE(std::abs(out.drive[k]), surface.gain + 1e-12);
      const auto now = path(out.time_s[k]);
      if (!shader.contains(xy(now.position_m))) {
        ASSERT_EQ(out.drive[k], 0.0) << "trial " << trial << " t=" << out.time_s[k];
        ASSERT_FALSE(out.active[k]);
      }
      if (norm(now.velocity_m_per_s) == 0.0) {
        ASSERT_EQ(out.drive[k], 0.0) << "a still finger renders nothing";
      }
    }
    ASSERT_FALSE(out.active.back());
  }
}

}  // namespace
}  // namespace vimg
