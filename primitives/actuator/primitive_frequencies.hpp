#pragma once
// The temporal frequency each primitive of an image is felt at when touched at fullSpeed
// (docs/actuators.md): a SURFACE fullSpeed / period, a LINE its natural frequency, a DOT the
// actuator's carrier. Groups are walked in paint order.
#include <string_view>
#include <vector>

#include "primitives/image.hpp"

namespace vimg {

struct PrimitiveFrequency {
  const Element* element = nullptr;  // points into the image
  std::string_view kind;             // "dot", "line" or "surface"
  double frequency_hz = 0.0;
};

std::vector<PrimitiveFrequency> primitive_frequencies(const Image& image, double dot_carrier_hz);

}  // namespace vimg
