#include "storage/image_summary.hpp"

#include <algorithm>

namespace vimg {

namespace {

void count(const std::vector<Element>& elements, int depth, ImageSummary& s) {
  for (const Element& e : elements) {
    s.unknown_elements += static_cast<int>(e.unknown_children.size());
    if (std::holds_alternative<Dot>(e.body)) ++s.dots;
    if (std::holds_alternative<Line>(e.body)) ++s.lines;
    if (std::holds_alternative<Surface>(e.body)) ++s.surfaces;
    if (std::holds_alternative<UnknownElement>(e.body)) ++s.unknown_elements;
    if (const auto* g = std::get_if<Group>(&e.body)) {
      ++s.groups;
      s.max_group_depth = std::max(s.max_group_depth, depth + 1);
      count(g->children, depth + 1, s);
    }
  }
}

}  // namespace

ImageSummary summarize(const Image& image) {
  ImageSummary s;
  count(image.children, 0, s);
  if (image.meta) s.unknown_elements += static_cast<int>(image.meta->unknown_children.size());
  return s;
}

}  // namespace vimg
