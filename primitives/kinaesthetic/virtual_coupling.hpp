#pragma once
// Virtual coupling (volume paper, eq 3): the spring-damper between the probe and its proxy,
//   f = -k_s (x_probe - x_proxy) - k_d (v_probe - v_proxy).
#include "primitives/shader.hpp"

namespace vimg {

struct CouplingParams {
  double stiffness_N_per_m = 300.0;  // k_s; keep below the device's Kmax
  double damping_N_s_per_m = 0.5;    // k_d
};

Vec3 virtual_coupling_force_N(const CouplingParams& coupling, const Vec3& probe_m,
                              const Vec3& probe_velocity_m_per_s, const Vec3& proxy_m,
                              const Vec3& proxy_velocity_m_per_s);

// Couples the probe to the proxy the caller moves (InteractionState::proxy_position_m and
// proxy_velocity_m_per_s). Stateless.
class VirtualCouplingShader final : public ForceShader {
 public:
  explicit VirtualCouplingShader(CouplingParams coupling) : coupling_(coupling) {}
  void begin_contact(ShaderState& state) const override;
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override;
  bool active(const ShaderState& state) const override;

 private:
  CouplingParams coupling_;
};

}  // namespace vimg
