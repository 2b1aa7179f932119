#pragma once
// A scene: an image compiled for playing. Groups are flattened (a group only organises the
// drawing; every primitive inside contributes on its own), each primitive becomes a ForceShader
// with its bounding box in metres, and a uniform grid indexes the boxes. Immutable once built, so
// the real-time thread can read it while the control thread prepares the next one.
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "player/bounds.hpp"
#include "player/spatial_grid.hpp"
#include "primitives/image.hpp"
#include "primitives/shader.hpp"
#include "primitives/vec3.hpp"

namespace vimg {

struct ScenePrimitive {
  std::unique_ptr<const ForceShader> shader;
  Bounds2M bounds;     // where the shader can be touched, metres
  std::string id;      // the element id, for messages and tools
};

class Scene {
 public:
  // `axis` is the actuator axis q; a shader's drive is dot(force, axis) / full_scale_force_N.
  Scene(std::vector<ScenePrimitive> primitives, const Vec3& axis, double full_scale_force_N);

  std::size_t size() const { return primitives_.size(); }
  const ForceShader& shader(std::size_t i) const { return *primitives_[i].shader; }
  const Bounds2M& bounds(std::size_t i) const { return primitives_[i].bounds; }
  const std::string& id(std::size_t i) const { return primitives_[i].id; }
  const Vec3& axis() const { return axis_; }
  double full_scale_force_N() const { return full_scale_force_N_; }

  // Normalized drive of one force contribution (not yet limited).
  double drive_of(const Vec3& force_N) const { return dot(force_N, axis_) * inv_full_scale_; }

  // Broad phase: candidates whose box may meet `query` (may repeat; callers test bounds()).
  template <class F>
  void for_each_candidate(const Bounds2M& query, F&& f) const {
    grid_.for_each_candidate(query, std::forward<F>(f));
  }
  const SpatialGrid& grid() const { return grid_; }

 private:
  std::vector<ScenePrimitive> primitives_;
  Vec3 axis_;
  double full_scale_force_N_;
  double inv_full_scale_;
  SpatialGrid grid_;
};

struct SceneOptions {
  double carrier_frequency_hz = 175.0;  // the actuator resonance, used as the DOT carrier
};

// Compiles an image: flattens groups in paint order, builds DOT/LINE/SURFACE shaders from the
// image's effective interaction parameters, and indexes them. Unknown elements are skipped.
std::shared_ptr<const Scene> compile_scene(const Image& image, const SceneOptions& options = {});

}  // namespace vimg
