#include "player/haptic/probe_render.hpp"

#include <algorithm>
#include <cmath>

#include "primitives/force_sum.hpp"

namespace vimg {

std::vector<ProbeForceRow> render_probe_path(HapticScene& scene, const std::vector<ProbePathPoint>& path,
                                             double rate_hz, double max_force_N) {
  std::vector<ProbeForceRow> rows;
  if (path.empty() || !(rate_hz > 0.0)) return rows;
  const double t0 = path.front().time_s;
  const double duration = path.back().time_s - t0;
  const auto steps = static_cast<std::size_t>(std::floor(duration * rate_hz + 1e-9)) + 1;
  rows.reserve(steps);
  scene.begin_contact();
  std::size_t segment = 0;
  InteractionState s;
  for (std::size_t n = 0; n < steps; ++n) {
    const double t = t0 + static_cast<double>(n) / rate_hz;
    while (segment + 2 < path.size() && path[segment + 1].time_s <= t) ++segment;
    Vec3 position = path[segment].position_m;
    Vec3 velocity;
    if (path.size() > 1) {
      const ProbePathPoint& a = path[segment];
      const ProbePathPoint& b = path[segment + 1];
      const double u = std::clamp((t - a.time_s) / (b.time_s - a.time_s), 0.0, 1.0);
      position = a.position_m + u * (b.position_m - a.position_m);
      velocity = (b.position_m - a.position_m) / (b.time_s - a.time_s);
    }
    s.previous_position_m = n == 0 ? position : s.position_m;
    s.dt_s = n == 0 ? 0.0 : 1.0 / rate_hz;
    s.position_m = position;
    s.velocity_m_per_s = velocity;
    s.time_s = t;
    s.proxy_position_m = position;
    s.proxy_velocity_m_per_s = velocity;
    const FeedbackParts parts = scene.evaluate(s);
    ForceSum sum;
    sum.add(parts.kinaesthetic_N);
    sum.add(parts.vibrotactile_N);
    rows.push_back({t, position, sum.clamped_N(max_force_N), parts.kinaesthetic_N, parts.vibrotactile_N});
  }
  return rows;
}

}  // namespace vimg
