#include "web/server/terminal_qr.hpp"

#include <qrencode.h>

#include <memory>

namespace vimg::web {

std::optional<QrModules> qr_modules(const std::string& text) {
  const std::unique_ptr<QRcode, void (*)(QRcode*)> code(
      QRcode_encodeString(text.c_str(), 0, QR_ECLEVEL_L, QR_MODE_8, 1), QRcode_free);
  if (!code) return std::nullopt;
  QrModules modules;
  modules.width = code->width;
  modules.dark.resize(static_cast<std::size_t>(code->width) * static_cast<std::size_t>(code->width));
  for (std::size_t i = 0; i < modules.dark.size(); ++i) modules.dark[i] = (code->data[i] & 1) != 0;
  return modules;
}

std::optional<std::string> terminal_qr_code(const std::string& text) {
  const std::optional<QrModules> code = qr_modules(text);
  if (!code) return std::nullopt;
  const int width = code->width;
  const int side = width + 2 * kQrQuietModules;
  // Light (drawn) unless a dark module of the code; the quiet zone is light.
  const auto light = [&](int row, int column) {
    const int r = row - kQrQuietModules, c = column - kQrQuietModules;
    if (r < 0 || c < 0 || r >= width || c >= width) return true;
    return !code->is_dark(r, c);
  };
  std::string drawing;
  for (int row = 0; row < side; row += 2) {
    for (int column = 0; column < side; ++column) {
      const bool top = light(row, column);
      const bool bottom = row + 1 < side ? light(row + 1, column) : false;
      drawing += top && bottom ? "\u2588" : top ? "\u2580" : bottom ? "\u2584" : " ";
    }
    drawing += "\n";
  }
  return drawing;
}

}  // namespace vimg::web
