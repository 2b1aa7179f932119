#pragma once
// The compact compiled image (.vsc, layout in vsc_format.hpp): an image and the actuator response
// it is played with, written by the native site builder and read by the WebAssembly renderer.
#include <optional>
#include <string>
#include <string_view>

#include "primitives/actuator/response_params.hpp"
#include "primitives/image.hpp"

namespace vimg {

struct VscImage {
  Image image;               // only what renderable_part() keeps
  ResponseParams actuator;   // actuator.resonance_hz is the DOT carrier
};

inline bool operator==(const ResponseParams& a, const ResponseParams& b) {
  return a.model == b.model && a.resonance_hz == b.resonance_hz && a.q == b.q && a.low_hz == b.low_hz &&
         a.high_hz == b.high_hz && a.spin_up_s == b.spin_up_s && a.spin_down_s == b.spin_down_s;
}
inline bool operator==(const VscImage& a, const VscImage& b) { return a.image == b.image && a.actuator == b.actuator; }

// What a .vsc keeps of an image: the canvas, the interaction parameters and the primitive tree,
// without meta data, unknown elements, unknown attributes and source lines.
Image renderable_part(const Image& image);

// The .vsc bytes of renderable_part(v.image) and v.actuator.
std::string write_vsc(const VscImage& v);

struct VscReadResult {
  std::optional<VscImage> image;  // set only when there is no error
  std::string error;              // "NAME: error: byte N: problem"
};

// Bounds-checked: any input gives either an image whose numbers are all in their ranges, or an error.
VscReadResult read_vsc(std::string_view bytes, const std::string& name);

}  // namespace vimg
