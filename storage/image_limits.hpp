#pragma once
// Limits of the image format and its readers (spec section 1 and docs/format.md).
#include <cstddef>

namespace vimg {

inline constexpr int kFormatMajor = 1;               // the format version this code reads and writes
inline constexpr int kFormatMinor = 0;
inline constexpr double kMaxCanvasMm = 10000.0;      // width and height in (0, kMaxCanvasMm]
inline constexpr double kMaxFrequencyHz = 1000.0;    // line frequency in (0, kMaxFrequencyHz]
inline constexpr int kMaxGroupDepth = 32;            // groups nest at most this deep
inline constexpr std::size_t kMaxFileBytes = 64u * 1024u * 1024u;  // XML text (also inside PNG)
inline constexpr double kMaxPngPixels = 25'000'000.0;  // PNG export: width_px * height_px at most this

}  // namespace vimg
