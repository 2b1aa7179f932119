#include "storage/png_signature.hpp"

#include "storage/diagnostic.hpp"

namespace vimg {
namespace {

constexpr std::string_view kSignature{"\x89PNG\r\n\x1A\n", 8};
constexpr char kHighBitLost = '\x09';  // 0x89 without its high bit

bool is_line_end(char c) { return c == '\r' || c == '\n'; }

// "CR LF", "LF", "CR CR LF".
std::string named(std::string_view run) {
  std::string name;
  for (char c : run) name += std::string(name.empty() ? "" : " ") + (c == '\r' ? "CR" : "LF");
  return name;
}

// A byte as the messages show it: "0x51 'Q'" when printable, else "0x1A".
std::string shown(char c) {
  const auto byte = static_cast<unsigned char>(c);
  std::string text = hex_byte(byte);
  if (byte > 0x20 && byte < 0x7F) text += std::string(" '") + c + "'";
  return text;
}

// 89 (or 09) 'PNG', a run of CR and LF, 1A, a run of CR and LF: the signature after a transfer that
// converted its line endings (of at most 3 bytes each: CR LF doubled at most).
std::optional<std::string> changed_line_endings(std::string_view bytes) {
  if (bytes.size() < 6 || (bytes[0] != kSignature[0] && bytes[0] != kHighBitLost) || bytes.substr(1, 3) != "PNG") {
    return std::nullopt;
  }
  std::size_t i = 4;
  const auto run = [&] {
    const std::size_t start = i;
    while (i < bytes.size() && i - start < 3 && is_line_end(bytes[i])) ++i;
    return bytes.substr(start, i - start);
  };
  const std::string_view first = run();
  if (first.empty() || i >= bytes.size() || bytes[i] != '\x1A') return std::nullopt;
  ++i;
  const std::string_view second = run();
  if (second.empty()) return std::nullopt;
  const bool first_changed = first != "\r\n", second_changed = second != "\n";
  if (!first_changed && !second_changed) return std::nullopt;  // intact line endings: not this damage
  std::string what = "line endings changed by a text-mode transfer (the signature's ";
  if (first_changed) what += "CR LF became " + named(first);
  if (first_changed && second_changed) what += " and its ";
  if (second_changed) what += "LF became " + named(second);
  what += ")";
  if (bytes[0] == kHighBitLost) what += "; its first byte lost its high bit too";
  return what;
}

// The 8 bytes with exactly one of them different.
std::optional<std::string> one_byte_changed(std::string_view bytes) {
  if (bytes.size() < kSignature.size()) return std::nullopt;
  std::size_t changed = kSignature.size();
  for (std::size_t i = 0; i < kSignature.size(); ++i) {
    if (bytes[i] == kSignature[i]) continue;
    if (changed != kSignature.size()) return std::nullopt;  // a second difference
    changed = i;
  }
  if (changed == kSignature.size()) return std::nullopt;  // intact
  if (changed == 0 && bytes[0] == kHighBitLost) {
    return "the first byte lost its high bit (0x09 where a PNG has 0x89), as a 7-bit transfer does";
  }
  return "one byte changed (byte " + std::to_string(changed + 1) + " is " + shown(bytes[changed]) + " where a PNG has " +
         shown(kSignature[changed]) + ")";
}

}  // namespace

std::optional<std::string> damaged_png_signature(std::string_view bytes) {
  if (auto endings = changed_line_endings(bytes)) return endings;
  if (auto one = one_byte_changed(bytes)) return one;
  if (bytes.size() >= 4 && bytes.size() < kSignature.size() && kSignature.starts_with(bytes)) {
    return "the file ends within the signature (" + std::to_string(bytes.size()) + " of its 8 bytes)";
  }
  return std::nullopt;
}

std::string damaged_png_signature_message(const std::string& cause) {
  return "a damaged PNG signature: " + cause + "; copy the file again as binary data";
}

}  // namespace vimg
