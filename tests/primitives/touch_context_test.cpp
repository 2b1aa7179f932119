#include "primitives/touch/touch_context.hpp"

#include <gtest/gtest.h>

#include "primitives/touch/dot_shader.hpp"
#include "primitives/touch/line_shader.hpp"
#include "primitives/touch/surface_shader.hpp"

namespace vimg {
namespace {

TEST(TouchContext, ConvertsTheDocumentsMillimetresToMetres) {
  InteractionParams params;
  params.mass_kg = 0.02;
  params.full_speed_mm_per_s = 150.0;
  params.max_deformation_mm = 0.7;
  const TouchContext c = make_touch_context(params, 205.0);
  EXPECT_EQ(c.mass_kg, 0.02);
  EXPECT_DOUBLE_EQ(c.full_speed_m_per_s, 0.15);
  EXPECT_DOUBLE_EQ(c.max_deformation_m, 0.0007);
  EXPECT_EQ(c.carrier_frequency_hz, 205.0);
  EXPECT_EQ(make_touch_context(InteractionParams{}).carrier_frequency_hz, 175.0);
  // The defaults of the document and of the context agree.
  const TouchContext d = make_touch_context(InteractionParams{});
  const TouchContext plain;
  EXPECT_DOUBLE_EQ(d.full_speed_m_per_s, plain.full_speed_m_per_s);
  EXPECT_DOUBLE_EQ(d.max_deformation_m, plain.max_deformation_m);
  EXPECT_EQ(d.mass_kg, plain.mass_kg);
}

TEST(TouchShaders, BoundingBoxesAreInMetres) {
  const DotShader dot(Dot{10.0, 20.0, 2.0, 1.0}, TouchContext{});
  EXPECT_NEAR(dot.bounding_box_m().min.x, 0.008, 1e-15);
  EXPECT_NEAR(dot.bounding_box_m().max.y, 0.022, 1e-15);
  const LineShader line(Line{0.0, 0.0, 10.0, 0.0, 2.0, 175.0, 0.05, 1.0}, TouchContext{});
  EXPECT_NEAR(line.bounding_box_m().min.x, -0.001, 1e-15);
  EXPECT_NEAR(line.bounding_box_m().max.x, 0.011, 1e-15);
  EXPECT_NEAR(line.bounding_box_m().max.y, 0.001, 1e-15);
  Surface rect;
  rect.x_mm = 5;
  rect.y_mm = 6;
  rect.width_mm = 10;
  rect.height_mm = 4;
  const SurfaceShader surface(rect, TouchContext{});
  EXPECT_NEAR(surface.bounding_box_m().min.x, 0.005, 1e-15);
  EXPECT_NEAR(surface.bounding_box_m().max.y, 0.010, 1e-15);
  EXPECT_TRUE(surface.contains({0.015, 0.010}));  // a corner: boundary is inside
  EXPECT_FALSE(surface.contains({0.0151, 0.010}));
}

TEST(TouchShaders, AFreshContactIsInactiveUntilTheFingerEnters) {
  const DotShader dot(Dot{0.0, 0.0, 1.0, 1.0}, TouchContext{});
  const LineShader line(Line{-5.0, 0.0, 5.0, 0.0, 1.0, 175.0, 0.05, 1.0}, TouchContext{});
  Surface s;
  s.shape = SurfaceShape::ellipse;
  s.rx_mm = 1.0;
  s.ry_mm = 1.0;
  const SurfaceShader surface(s, TouchContext{});
  for (const ForceShader* shader : {static_cast<const ForceShader*>(&dot), static_cast<const ForceShader*>(&line),
                                    static_cast<const ForceShader*>(&surface)}) {
    ShaderState state;
    shader->begin_contact(state);
    EXPECT_FALSE(shader->active(state));
    InteractionState near;  // 1.5 mm away, moving but not entering
    near.previous_position_m = {0.0, 0.002, 0};
    near.position_m = {0.0, 0.0015, 0};
    near.velocity_m_per_s = {0, -0.1, 0};
    near.time_s = 0.001;
    near.dt_s = 0.001;
    EXPECT_EQ(shader->force_N(near, state), Vec3{});
    EXPECT_FALSE(shader->active(state));
    InteractionState enter = near;  // into all three
    enter.previous_position_m = near.position_m;
    enter.position_m = {0.0, 0.0, 0};
    enter.time_s = 0.002;
    shader->force_N(enter, state);
    EXPECT_TRUE(shader->active(state));
  }
}

}  // namespace
}  // namespace vimg
