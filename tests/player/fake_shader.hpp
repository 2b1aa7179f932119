#pragma once
#include <memory>
#include <vector>

#include "player/scene.hpp"
// A test double for ForceShader: a box that outputs a constant drive while the finger's current
// position is inside, then rings for `ring_steps` steps after it leaves. Counts begin_contact calls.
#include <atomic>

#include "player/bounds.hpp"
#include "primitives/shader.hpp"

namespace vimg::test {

struct FakeState {
  bool inside;
  int ring_left;
};

class FakeShader final : public ForceShader {
 public:
  FakeShader(Bounds2M box, double drive, int ring_steps = 0) : box_(box), drive_(drive), ring_steps_(ring_steps) {}
  void begin_contact(ShaderState& s) const override {
    s.emplace<FakeState>();
    begins.fetch_add(1);
  }
  Vec3 force_N(const InteractionState& in, ShaderState& state) const override {
    auto& s = state.get<FakeState>();
    const bool inside = in.position_m.x >= box_.min_x_m && in.position_m.x <= box_.max_x_m &&
                        in.position_m.y >= box_.min_y_m && in.position_m.y <= box_.max_y_m;
    if (s.inside && !inside) s.ring_left = ring_steps_;
    s.inside = inside;
    if (inside) return {0, 0, drive_};
    if (s.ring_left > 0) {
      --s.ring_left;
      return {0, 0, drive_};
    }
    return {};
  }
  bool active(const ShaderState& state) const override {
    const auto& s = state.get<FakeState>();
    return s.inside || s.ring_left > 0;
  }
  mutable std::atomic<int> begins{0};

 private:
  Bounds2M box_;
  double drive_;
  int ring_steps_;
};

// A scene of one FakeShader over the square (0, 0)-(1, 1) m that drives `drive` while touched.
inline std::shared_ptr<const Scene> constant_scene(double drive) {
  std::vector<ScenePrimitive> prims;
  const Bounds2M box{0.0, 0.0, 1.0, 1.0};
  prims.push_back({std::make_unique<FakeShader>(box, drive), box, "all"});
  return std::make_shared<const Scene>(std::move(prims), Vec3{0, 0, 1}, 1.0);
}

}  // namespace vimg::test
