#pragma once
// A 2-vector in metres: the touchscreen plane. Shaders project Vec3 positions onto it (z ignored).
#include <cmath>

#include "primitives/vec3.hpp"

namespace vimg {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2& operator+=(const Vec2& o) { x += o.x; y += o.y; return *this; }
  constexpr Vec2& operator-=(const Vec2& o) { x -= o.x; y -= o.y; return *this; }
  constexpr Vec2& operator*=(double s) { x *= s; y *= s; return *this; }
  friend constexpr Vec2 operator+(Vec2 a, const Vec2& b) { return a += b; }
  friend constexpr Vec2 operator-(Vec2 a, const Vec2& b) { return a -= b; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return a *= s; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return a *= s; }
  friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
};

constexpr double dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
// z component of the 3-D cross product: > 0 when b turns counter-clockwise from a.
constexpr double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
inline double norm(const Vec2& a) { return std::sqrt(dot(a, a)); }
constexpr Vec2 lerp(const Vec2& a, const Vec2& b, double t) { return a + (b - a) * t; }
constexpr Vec2 xy(const Vec3& v) { return {v.x, v.y}; }

}  // namespace vimg
