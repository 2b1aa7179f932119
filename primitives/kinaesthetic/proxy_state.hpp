#pragma once
// The per-contact state of a proxy-based shader: where the proxy is and how fast it moved.
#include "primitives/shader_state.hpp"
#include "primitives/vec3.hpp"

namespace vimg {

struct ProxyState {
  Vec3 proxy_m;
  Vec3 proxy_velocity_m_per_s;
  bool placed = false;  // false until the first step puts the proxy on the probe
};

// The contact's proxy, put at rest on the probe on the contact's first step.
inline ProxyState& proxy_placed_at(ShaderState& state, const Vec3& probe_m) {
  ProxyState& s = state.get<ProxyState>();
  if (!s.placed) {
    s.proxy_m = probe_m;
    s.proxy_velocity_m_per_s = {};
    s.placed = true;
  }
  return s;
}

}  // namespace vimg
