#pragma once
// A QR code of a short text (a URL) drawn in a terminal with Unicode half blocks: each line of
// text holds two rows of modules (U+2580 upper half, U+2584 lower half, U+2588 full block), with
// a quiet zone of kQrQuietModules around it. As `qrencode -t UTF8` does, the light modules are
// the drawn ones (for the usual light-on-dark terminal); on a dark-on-light terminal it shows
// inverted, which most phone cameras still read.
#include <optional>
#include <string>
#include <vector>

namespace vimg::web {

inline constexpr int kQrQuietModules = 2;

// The modules of the QR code of `text` (libqrencode, level L, byte mode): `width` x `width`,
// row by row, true for dark; nothing if the text cannot be encoded.
struct QrModules {
  int width = 0;
  std::vector<bool> dark;
  bool is_dark(int row, int column) const { return dark[static_cast<std::size_t>(row * width + column)]; }
};
std::optional<QrModules> qr_modules(const std::string& text);

// The lines of the drawing, each ending in "\n"; nothing if the text cannot be encoded.
std::optional<std::string> terminal_qr_code(const std::string& text);

}  // namespace vimg::web
