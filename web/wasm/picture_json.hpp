#pragma once
// The picture the page draws, as JSON: every primitive in paint order (groups flattened as the
// scene compile does, so index i is scene primitive i), with its geometry in mm and its look from
// the PNG palette (storage/palette.hpp): colour, opacity, and for a surface its stripe opacities
// sampled across x. The page only strokes and fills what this says.
#include <string>

#include "primitives/image.hpp"

namespace vimg {

std::string picture_json(const Image& image);

}  // namespace vimg
