#pragma once
// SURFACE (DESIGN section 4): a periodic texture. The phase grows with the distance travelled
// inside the shape, phi += 2 pi |dx| / period, and the drive is
// gain * min(deformation, relief) / relief * min(1, v / fullSpeed) * pattern(phi),
// deformation = pressure * maxDeformation, pattern one of sine, square, triangle.
#include <variant>

#include "primitives/geometry/box2.hpp"
#include "primitives/geometry/shapes.hpp"
#include "primitives/image.hpp"
#include "primitives/shader.hpp"
#include "primitives/touch/touch_context.hpp"

namespace vimg {

class SurfaceShader final : public ForceShader {
 public:
  SurfaceShader(const Surface& surface, const TouchContext& context);

  void begin_contact(ShaderState& state) const override;
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override;
  bool active(const ShaderState& state) const override;

  Box2 bounding_box_m() const;
  bool contains(const Vec2& point_m) const;

 private:
  std::variant<Rect, Ellipse, Polygon> region_;
  double period_m_;
  double relief_m_;
  SurfacePattern pattern_;
  double gain_;
  TouchContext context_;
};

}  // namespace vimg
