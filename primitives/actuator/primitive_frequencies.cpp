#include "primitives/actuator/primitive_frequencies.hpp"

namespace vimg {

namespace {

void collect(const std::vector<Element>& elements, double full_speed_mm_per_s, double dot_carrier_hz,
             std::vector<PrimitiveFrequency>& out) {
  for (const Element& e : elements) {
    if (const auto* surface = std::get_if<Surface>(&e.body)) {
      out.push_back({&e, "surface", full_speed_mm_per_s / surface->period_mm});
    } else if (const auto* line = std::get_if<Line>(&e.body)) {
      out.push_back({&e, "line", line->frequency_hz});
    } else if (std::holds_alternative<Dot>(e.body)) {
      out.push_back({&e, "dot", dot_carrier_hz});
    } else if (const auto* group = std::get_if<Group>(&e.body)) {
      collect(group->children, full_speed_mm_per_s, dot_carrier_hz, out);
    }
  }
}

}  // namespace

std::vector<PrimitiveFrequency> primitive_frequencies(const Image& image, double dot_carrier_hz) {
  std::vector<PrimitiveFrequency> out;
  collect(image.children, image.effective_interaction().full_speed_mm_per_s, dot_carrier_hz, out);
  return out;
}

}  // namespace vimg
