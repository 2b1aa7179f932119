#include "primitives/touch/dot_shader.hpp"

#include <cmath>

#include "primitives/geometry/segment_overlap.hpp"
#include "primitives/touch/touch_math.hpp"

namespace vimg {
namespace {

struct DotState {
  bool inside;
  double entry_time_s;  // alpha, exact to the interpolated path
  double amplitude;     // gain * f_N(I) of the current crossing
};

}  // namespace

DotShader::DotShader(const Dot& dot, const TouchContext& context)
    : disc_{{dot.x_mm * 1e-3, dot.y_mm * 1e-3}, dot.radius_mm * 1e-3}, gain_(dot.gain), context_(context) {}

void DotShader::begin_contact(ShaderState& state) const { state.emplace<DotState>(); }

Vec3 DotShader::force_N(const InteractionState& interaction, ShaderState& state) const {
  auto& s = state.get<DotState>();
  const auto hit = overlap(disc_, xy(interaction.previous_position_m), xy(interaction.position_m));
  if (hit) {
    if (!s.inside) {
      s.entry_time_s = interaction.time_s - interaction.dt_s * (1.0 - hit->begin);
      s.amplitude = gain_ * touch::full_speed_fraction(touch::planar_speed_m_per_s(interaction), context_);
    }
    s.inside = hit->end >= 1.0;
  } else {
    s.inside = false;
  }
  if (!s.inside) return Vec3{};
  const double drive =
      s.amplitude * std::sin(touch::kTwoPi * context_.carrier_frequency_hz * (interaction.time_s - s.entry_time_s));
  return touch::drive_to_force_N(drive, context_);
}

bool DotShader::active(const ShaderState& state) const { return state.get<DotState>().inside; }

}  // namespace vimg
