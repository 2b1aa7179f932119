#include "primitives/cues/transition_cue_shader.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace vimg {
namespace {

struct TransitionCueState {
  bool ringing;
  bool has_crossing;
  double crossing_time_s;
  Vec3 crossing_position_m;
};

// The cue ends when its envelope falls below this fraction of its start (-40 dB).
constexpr double kCueEndRatio = 0.01;

// The fraction s in [0, 1] of the segment p0 -> p1 where g(s) = field - iso changes sign, given
// g(0) and g(1) of opposite signs. Illinois false position, with a bisection step whenever the
// bracket fails to halve, until the bracket is shorter than the tolerance.
double locate_crossing(const ScalarField& field, double iso, const Vec3& p0, const Vec3& p1, double g0,
                       double g1, double tolerance_m) {
  const double length_m = norm(p1 - p0);
  double a = 0.0;
  double b = 1.0;
  double ga = g0;
  double gb = g1;
  int retained_side = 0;
  for (int iteration = 0; iteration < 200 && (b - a) * length_m > tolerance_m; ++iteration) {
    const double width = b - a;
    double c = (a * gb - b * ga) / (gb - ga);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double gc = field.value(p0 + (p1 - p0) * c) - iso;
    if (gc == 0.0) return c;
    if ((gc < 0.0) == (ga < 0.0)) {
      a = c;
      ga = gc;
      if (retained_side == -1) gb *= 0.5;
      retained_side = -1;
    } else {
      b = c;
      gb = gc;
      if (retained_side == 1) ga *= 0.5;
      retained_side = 1;
    }
    if (b - a > 0.5 * width) {  // slow progress: bisect once
      const double m = 0.5 * (a + b);
      const double gm = field.value(p0 + (p1 - p0) * m) - iso;
      if (gm == 0.0) return m;
      if ((gm < 0.0) == (ga < 0.0)) {
        a = m;
        ga = gm;
      } else {
        b = m;
        gb = gm;
      }
      retained_side = 0;
    }
  }
  // The root lies in [a, b]; interpolate linearly inside the final bracket.
  return gb != ga ? a + (b - a) * (ga / (ga - gb)) : 0.5 * (a + b);
}

}  // namespace

TransitionCueShader::TransitionCueShader(std::shared_ptr<const ScalarField> field, const TransitionCueParams& params)
    : field_(std::move(field)),
      params_(params),
      beta_(params.decay_time_s > 0.0 ? 1.0 / params.decay_time_s : 0.0),
      omega_d_(0.0),
      duration_s_(0.0) {
  const double omega0 = 2.0 * std::numbers::pi * params.frequency_hz;
  // Underdamped only: an overdamped cue has no oscillation to feel, so it renders nothing.
  if (beta_ > 0.0 && omega0 > beta_) {
    omega_d_ = std::sqrt(omega0 * omega0 - beta_ * beta_);
    duration_s_ = std::log(1.0 / kCueEndRatio) / beta_;
  }
}

void TransitionCueShader::begin_contact(ShaderState& state) const { state.emplace<TransitionCueState>(); }

Vec3 TransitionCueShader::force_N(const InteractionState& interaction, ShaderState& state) const {
  auto& s = state.get<TransitionCueState>();
  if (!field_) return Vec3{};
  const Vec3& p0 = interaction.previous_position_m;
  const Vec3& p1 = interaction.position_m;
  const double g0 = field_->value(p0) - params_.iso_value;
  const double g1 = field_->value(p1) - params_.iso_value;
  if ((g0 < 0.0) != (g1 < 0.0)) {  // "below" is < iso, "above" is >= iso
    const double fraction =
        locate_crossing(*field_, params_.iso_value, p0, p1, g0, g1, params_.position_tolerance_m);
    s.has_crossing = true;
    s.ringing = duration_s_ > 0.0;
    s.crossing_time_s = interaction.time_s - interaction.dt_s * (1.0 - fraction);
    s.crossing_position_m = p0 + (p1 - p0) * fraction;
  }
  if (!s.ringing) return Vec3{};
  const double since_s = interaction.time_s - s.crossing_time_s;
  if (since_s >= duration_s_) {
    s.ringing = false;
    return Vec3{};
  }
  const double value = params_.amplitude_N * std::exp(-beta_ * since_s) * std::sin(omega_d_ * since_s);
  return params_.direction * value;
}

bool TransitionCueShader::active(const ShaderState&) const { return true; }

bool TransitionCueShader::last_crossing(const ShaderState& state, Vec3& position_m, double& time_s) const {
  const auto& s = state.get<TransitionCueState>();
  if (!s.has_crossing) return false;
  position_m = s.crossing_position_m;
  time_s = s.crossing_time_s;
  return true;
}

}  // namespace vimg
