#pragma once
// Small shaders for loop and cycle tests.
#include "primitives/shader.hpp"

namespace vimg::testing {

// Always the same force.
class ConstantForceShader final : public ForceShader {
 public:
  explicit ConstantForceShader(Vec3 force_N) : force_N_(force_N) {}
  void begin_contact(ShaderState&) const override {}
  Vec3 force_N(const InteractionState&, ShaderState&) const override { return force_N_; }
  bool active(const ShaderState&) const override { return true; }

 private:
  Vec3 force_N_;
};

// A spring to a fixed anchor: f = -k (x - anchor). Passive in continuous time.
class AnchorSpringShader final : public ForceShader {
 public:
  AnchorSpringShader(Vec3 anchor_m, double k) : anchor_m_(anchor_m), k_(k) {}
  void begin_contact(ShaderState&) const override {}
  Vec3 force_N(const InteractionState& s, ShaderState&) const override { return -k_ * (s.position_m - anchor_m_); }
  bool active(const ShaderState&) const override { return true; }

 private:
  Vec3 anchor_m_;
  double k_;
};

// Negative damping, f = +b v: an active (energy-producing) environment, the negative control.
class ActiveDamperShader final : public ForceShader {
 public:
  explicit ActiveDamperShader(double b) : b_(b) {}
  void begin_contact(ShaderState&) const override {}
  Vec3 force_N(const InteractionState& s, ShaderState&) const override { return b_ * s.velocity_m_per_s; }
  bool active(const ShaderState&) const override { return true; }

 private:
  double b_;
};

}  // namespace vimg::testing
