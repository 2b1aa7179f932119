#include "primitives/touch/surface_shader.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "primitives/geometry/hit_test.hpp"
#include "primitives/geometry/segment_overlap.hpp"
#include "primitives/touch/touch_math.hpp"

namespace vimg {
namespace {

struct SurfaceState {
  bool inside;
  double phase_rad;  // kept in [0, 2 pi)
};

std::variant<Rect, Ellipse, Polygon> region_of(const Surface& surface) {
  switch (surface.shape) {
    case SurfaceShape::rect: {
      const Vec2 a{surface.x_mm * 1e-3, surface.y_mm * 1e-3};
      const Vec2 b = a + Vec2{surface.width_mm * 1e-3, surface.height_mm * 1e-3};
      return Rect{{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
    }
    case SurfaceShape::ellipse:
      return Ellipse{{surface.cx_mm * 1e-3, surface.cy_mm * 1e-3}, surface.rx_mm * 1e-3, surface.ry_mm * 1e-3};
    case SurfaceShape::polygon:
      break;
  }
  Polygon polygon;
  polygon.vertices.reserve(surface.points.size());
  for (const Point2Mm& p : surface.points) polygon.vertices.push_back({p.x_mm * 1e-3, p.y_mm * 1e-3});
  return polygon;
}

// Unit-amplitude patterns of the phase, all zero at phase 0 and rising.
double pattern_value(SurfacePattern pattern, double phase_rad) {
  switch (pattern) {
    case SurfacePattern::square:
      return phase_rad < std::numbers::pi ? 1.0 : -1.0;
    case SurfacePattern::triangle: {
      const double u = phase_rad / touch::kTwoPi;  // [0, 1)
      if (u < 0.25) return 4.0 * u;
      if (u < 0.75) return 2.0 - 4.0 * u;
      return 4.0 * u - 4.0;
    }
    case SurfacePattern::sine:
      break;
  }
  return std::sin(phase_rad);
}

}  // namespace

SurfaceShader::SurfaceShader(const Surface& surface, const TouchContext& context)
    : region_(region_of(surface)),
      period_m_(surface.period_mm * 1e-3),
      relief_m_(surface.relief_mm * 1e-3),
      pattern_(surface.pattern),
      gain_(surface.gain),
      context_(context) {}

Box2 SurfaceShader::bounding_box_m() const {
  return std::visit([](const auto& shape) { return bounding_box(shape); }, region_);
}

bool SurfaceShader::contains(const Vec2& point_m) const {
  return std::visit([&](const auto& shape) { return vimg::contains(shape, point_m); }, region_);
}

void SurfaceShader::begin_contact(ShaderState& state) const { state.emplace<SurfaceState>(); }

Vec3 SurfaceShader::force_N(const InteractionState& interaction, ShaderState& state) const {
  auto& s = state.get<SurfaceState>();
  const Vec2 p0 = xy(interaction.previous_position_m);
  const Vec2 p1 = xy(interaction.position_m);
  const SegmentOverlap step = std::visit(
      [&](const auto& shape) {
        if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, Polygon>) {
          return overlap_summary(shape, p0, p1);
        } else {
          return summarize(overlap(shape, p0, p1));
        }
      },
      region_);
  s.inside = step.inside_at_end;
  if (!(period_m_ > 0.0) || !(relief_m_ > 0.0)) return Vec3{};
  // Phase follows the distance travelled inside the shape only.
  const double inside_distance_m = norm(p1 - p0) * step.inside_fraction;
  s.phase_rad = std::fmod(s.phase_rad + touch::kTwoPi * inside_distance_m / period_m_, touch::kTwoPi);
  if (!s.inside) return Vec3{};

  const double deformation_m = std::clamp(interaction.pressure, 0.0, 1.0) * context_.max_deformation_m;
  const double clip = std::min(deformation_m, relief_m_) / relief_m_;
  const double speed_fade = touch::full_speed_fraction(touch::planar_speed_m_per_s(interaction), context_);
  const double drive = gain_ * clip * speed_fade * pattern_value(pattern_, s.phase_rad);
  return touch::drive_to_force_N(drive, context_);
}

bool SurfaceShader::active(const ShaderState& state) const { return state.get<SurfaceState>().inside; }

}  // namespace vimg
