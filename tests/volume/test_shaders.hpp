#pragma once
// Small shaders for loop and cycle tests.
#include <cmath>

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

// A force that flips across a plane: +A on the side n points to, -A on the other. Discontinuous,
// so a probe crossing the plane asks for a step of 2|A|.
class StepShader final : public ForceShader {
 public:
  StepShader(Vec3 point_m, Vec3 normal, Vec3 force_N) : point_m_(point_m), normal_(normal), force_N_(force_N) {}
  void begin_contact(ShaderState&) const override {}
  Vec3 force_N(const InteractionState& s, ShaderState&) const override {
    return dot(s.position_m - point_m_, normal_) > 0.0 ? force_N_ : -force_N_;
  }
  bool active(const ShaderState&) const override { return true; }

 private:
  Vec3 point_m_;
  Vec3 normal_;
  Vec3 force_N_;
};

// A vibration in time: A sin(2 pi f t).
class VibrationShader final : public ForceShader {
 public:
  VibrationShader(Vec3 amplitude_N, double frequency_hz) : amplitude_N_(amplitude_N), frequency_hz_(frequency_hz) {}
  void begin_contact(ShaderState&) const override {}
  Vec3 force_N(const InteractionState& s, ShaderState&) const override {
    return std::sin(2.0 * 3.141592653589793 * frequency_hz_ * s.time_s) * amplitude_N_;
  }
  bool active(const ShaderState&) const override { return true; }

 private:
  Vec3 amplitude_N_;
  double frequency_hz_;
};

}  // namespace vimg::testing
