#include "player/scene.hpp"

namespace vimg {

namespace {

std::vector<Bounds2M> boxes_of(const std::vector<ScenePrimitive>& primitives) {
  std::vector<Bounds2M> boxes;
  boxes.reserve(primitives.size());
  for (const auto& p : primitives) boxes.push_back(p.bounds);
  return boxes;
}

}  // namespace

Scene::Scene(std::vector<ScenePrimitive> primitives, const Vec3& axis, double full_scale_force_N)
    : primitives_(std::move(primitives)),
      axis_(normalized(axis)),
      full_scale_force_N_(full_scale_force_N),
      inv_full_scale_(full_scale_force_N > 0.0 ? 1.0 / full_scale_force_N : 0.0),
      grid_(boxes_of(primitives_)) {}

}  // namespace vimg
