#include "primitives/touch/line_shader.hpp"

#include <algorithm>
#include <cmath>

#include "primitives/geometry/segment_overlap.hpp"
#include "primitives/touch/touch_math.hpp"

namespace vimg {
namespace {

enum class LinePhase : unsigned char { idle, touching, ringing };

struct LineState {
  LinePhase phase;
  double entry_time_s;    // alpha: the carrier's phase reference, kept across the release
  double release_time_s;  // beta: start of the ring-down envelope
  double amplitude;       // A0
};

// The damping ratio a file may give is (0, 1); keep the model defined at the ends.
constexpr double kMinDamping = 1e-4;
constexpr double kMaxDamping = 0.9999;

}  // namespace

LineShader::LineShader(const Line& line, const TouchContext& context)
    : band_{{line.x1_mm * 1e-3, line.y1_mm * 1e-3}, {line.x2_mm * 1e-3, line.y2_mm * 1e-3}, 0.5 * line.width_mm * 1e-3},
      omega_n_(touch::kTwoPi * line.frequency_hz),
      zeta_(std::clamp(line.damping, kMinDamping, kMaxDamping)),
      omega_d_(omega_n_ * std::sqrt(1.0 - zeta_ * zeta_)),
      ring_duration_s_(omega_n_ > 0.0 ? std::log(1.0 / kRingDownEndRatio) / (zeta_ * omega_n_) : 0.0),
      gain_(line.gain),
      context_(context) {}

void LineShader::begin_contact(ShaderState& state) const { state.emplace<LineState>(); }

Vec3 LineShader::force_N(const InteractionState& interaction, ShaderState& state) const {
  auto& s = state.get<LineState>();
  const double step_start_s = interaction.time_s - interaction.dt_s;
  const auto hit = overlap(band_, xy(interaction.previous_position_m), xy(interaction.position_m));
  if (hit) {
    if (s.phase != LinePhase::touching) {  // a new pluck, also while still ringing
      s.phase = LinePhase::touching;
      s.entry_time_s = step_start_s + hit->begin * interaction.dt_s;
      s.amplitude = gain_ * touch::full_speed_fraction(touch::planar_speed_m_per_s(interaction), context_);
    }
    if (hit->end < 1.0) {
      s.phase = LinePhase::ringing;
      s.release_time_s = step_start_s + hit->end * interaction.dt_s;
    }
  } else if (s.phase == LinePhase::touching) {
    s.phase = LinePhase::ringing;
    s.release_time_s = step_start_s;
  }

  double envelope = 0.0;
  if (s.phase == LinePhase::touching) {
    envelope = 1.0;
  } else if (s.phase == LinePhase::ringing) {
    const double since_release_s = interaction.time_s - s.release_time_s;
    if (since_release_s >= ring_duration_s_ || s.amplitude == 0.0) {
      s.phase = LinePhase::idle;
    } else {
      envelope = std::exp(-zeta_ * omega_n_ * since_release_s);
    }
  }
  if (envelope == 0.0) return Vec3{};
  const double drive = s.amplitude * envelope * std::sin(omega_d_ * (interaction.time_s - s.entry_time_s));
  return touch::drive_to_force_N(drive, context_);
}

bool LineShader::active(const ShaderState& state) const {
  return state.get<LineState>().phase != LinePhase::idle;
}

}  // namespace vimg
