#pragma once
// Counts of what an image holds, for `vimg info` and tools.
#include "primitives/image.hpp"

namespace vimg {

struct ImageSummary {
  int dots = 0;
  int lines = 0;
  int surfaces = 0;
  int groups = 0;
  int max_group_depth = 0;   // 0 when there are no groups
  int unknown_elements = 0;  // kept verbatim, anywhere in the tree (including inside primitives)
  int primitives() const { return dots + lines + surfaces; }
};

ImageSummary summarize(const Image& image);

}  // namespace vimg
