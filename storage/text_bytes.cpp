#include "storage/text_bytes.hpp"

#include <string_view>

namespace vimg {

std::size_t utf8_sequence(std::string_view text, std::size_t i, std::uint32_t& code_point) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  std::size_t n = 0;
  unsigned char low = 0x80, high = 0xBF;  // allowed range of the second byte
  if (b < 0x80) {
    code_point = b;
    return 1;
  }
  if (b >= 0xC2 && b <= 0xDF) {
    n = 2;
    code_point = b & 0x1Fu;
  } else if (b >= 0xE0 && b <= 0xEF) {
    n = 3;
    code_point = b & 0x0Fu;
    if (b == 0xE0) low = 0xA0;
    if (b == 0xED) high = 0x9F;
  } else if (b >= 0xF0 && b <= 0xF4) {
    n = 4;
    code_point = b & 0x07u;
    if (b == 0xF0) low = 0x90;
    if (b == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const unsigned char c = byte(i + k);
    if (k == 1 ? (c < low || c > high) : (c & 0xC0) != 0x80) return 0;
    code_point = (code_point << 6) | (c & 0x3Fu);
  }
  return n;
}

std::size_t first_binary_byte(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x80) {
      const bool allowed_control = (b >= '\t' && b <= '\r') || b == 0x1B;
      if ((b < 0x20 && !allowed_control) || b == 0x7F) return i;
      ++i;
      continue;
    }
    std::uint32_t code_point = 0;
    const std::size_t n = utf8_sequence(text, i, code_point);
    if (n == 0) return i;
    i += n;
  }
  return std::string_view::npos;
}

}  // namespace vimg
