#pragma once
// The per-contact state of a proxy-based shader: where the proxy is and how fast it moved.
#include "primitives/vec3.hpp"

namespace vimg {

struct ProxyState {
  Vec3 proxy_m;
  Vec3 proxy_velocity_m_per_s;
  bool placed = false;  // false until the first step puts the proxy on the probe
};

}  // namespace vimg
