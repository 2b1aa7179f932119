#pragma once
// SVG transforms (SVG 1.1 section 7.6): the `transform` attribute's list of matrix, translate,
// scale, rotate (with an optional centre), skewX and skewY, and the 2-D affine map they compose to.
// Pure: no I/O.
#include <string>
#include <string_view>

#include "primitives/geometry/vec2.hpp"

namespace vimg::svg {

// x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct Affine {
  double a = 1.0, b = 0.0, c = 0.0, d = 1.0, e = 0.0, f = 0.0;

  Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  Vec2 apply_vector(Vec2 v) const { return {a * v.x + c * v.y, b * v.x + d * v.y}; }
  // This map after `inner`: (this * inner)(p) = this(inner(p)).
  Affine operator*(const Affine& inner) const {
    return {a * inner.a + c * inner.b, b * inner.a + d * inner.b, a * inner.c + c * inner.d,
            b * inner.c + d * inner.d, a * inner.e + c * inner.f + e, b * inner.e + d * inner.f + f};
  }
  double determinant() const { return a * d - b * c; }
  // The factor by which lengths grow on average: sqrt(|det|) (exact for similarities).
  double mean_scale() const;
  // No rotation or skew: axes map to axes (scales may be negative).
  bool axis_aligned() const { return b == 0.0 && c == 0.0; }
  // A rotation and a uniform scale, possibly mirrored: circles stay circles.
  bool similarity() const;
  bool finite() const;
};

struct TransformParse {
  Affine transform;
  std::string error;  // empty when the attribute is valid
};

// Parses a transform list; `transform="A B"` applies B first, then A.
TransformParse parse_transform(std::string_view text);

}  // namespace vimg::svg
