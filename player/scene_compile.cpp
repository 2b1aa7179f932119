// Image -> Scene: flatten groups, build touch shaders, index their boxes.
#include <memory>
#include <variant>

#include "player/scene.hpp"
#include "primitives/touch/dot_shader.hpp"
#include "primitives/touch/line_shader.hpp"
#include "primitives/touch/surface_shader.hpp"
#include "primitives/touch/touch_context.hpp"

namespace vimg {

namespace {

Bounds2M to_bounds(const Box2& b) { return {b.min.x, b.min.y, b.max.x, b.max.y}; }

void flatten(const std::vector<Element>& elements, const TouchContext& context,
             std::vector<ScenePrimitive>& out) {
  for (const Element& e : elements) {
    if (const auto* dot = std::get_if<Dot>(&e.body)) {
      auto s = std::make_unique<DotShader>(*dot, context);
      const Bounds2M b = to_bounds(s->bounding_box_m());
      out.push_back({std::move(s), b, e.id});
    } else if (const auto* line = std::get_if<Line>(&e.body)) {
      auto s = std::make_unique<LineShader>(*line, context);
      const Bounds2M b = to_bounds(s->bounding_box_m());
      out.push_back({std::move(s), b, e.id});
    } else if (const auto* surface = std::get_if<Surface>(&e.body)) {
      auto s = std::make_unique<SurfaceShader>(*surface, context);
      const Bounds2M b = to_bounds(s->bounding_box_m());
      out.push_back({std::move(s), b, e.id});
    } else if (const auto* group = std::get_if<Group>(&e.body)) {
      flatten(group->children, context, out);  // a group only organises; its members all play
    }
    // Unknown elements have no tactile meaning in this version: they are kept by storage, not played.
  }
}

}  // namespace

std::shared_ptr<const Scene> compile_scene(const Image& image, const SceneOptions& options) {
  const TouchContext context = make_touch_context(image.effective_interaction(), options.carrier_frequency_hz);
  std::vector<ScenePrimitive> primitives;
  flatten(image.children, context, primitives);
  return std::make_shared<const Scene>(std::move(primitives), context.axis, context.full_scale_force_N);
}

}  // namespace vimg
