#pragma once
// A QR code of a short text (a URL) drawn in a terminal with Unicode half blocks: each line of
// text holds two rows of modules (U+2580 upper half, U+2584 lower half, U+2588 full block), with
// a quiet zone of kQrQuietModules around it. As `qrencode -t UTF8` does, the light modules are
// the drawn ones (for the usual light-on-dark terminal); on a dark-on-light terminal it shows
// inverted, which most phone cameras still read.
#include <optional>
#include <string>

namespace vimg::web {

inline constexpr int kQrQuietModules = 2;

// The lines of the drawing, each ending in "\n"; nothing if the text cannot be encoded.
std::optional<std::string> terminal_qr_code(const std::string& text);

}  // namespace vimg::web
