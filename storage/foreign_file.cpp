#include "storage/foreign_file.hpp"

#include <array>

#include "storage/diagnostic.hpp"
#include "storage/png_codec.hpp"
#include "storage/png_signature.hpp"

namespace vimg {
namespace {

struct Magic {
  std::string_view bytes;
  std::size_t offset;
  std::string_view what;
};

constexpr std::array<Magic, 15> kMagics{{
    {"NRRD000", 0, "a NRRD volume (volumes are explored through a volume scene: vimg volume probe, vimg-force)"},
    {"\xFF\xD8\xFF", 0, "a JPEG picture (import a picture with vimg import)"},
    {"GIF8", 0, "a GIF picture"},
    {"\x8AMNG\r\n\x1A\n", 0, "an MNG animation"},
    {"\x8BJNG\r\n\x1A\n", 0, "a JNG picture"},
    {"%PDF-", 0, "a PDF document"},
    {"PK\x03\x04", 0, "a ZIP archive (or a document packed as one)"},
    {"\x1F\x8B", 0, "gzip-compressed data"},
    {"BZh", 0, "bzip2-compressed data"},
    {"\xFD" "7zXZ", 0, "xz-compressed data"},
    {"WAVE", 8, "a WAV sound"},
    {"WEBP", 8, "a WebP picture"},
    {"\x7F" "ELF", 0, "a program (ELF)"},
    {"II*\0", 0, "a TIFF picture"},
    {"MM\0*", 0, "a TIFF picture"},
}};

bool starts_with_at(std::string_view bytes, std::size_t offset, std::string_view magic) {
  return bytes.size() >= offset + magic.size() && bytes.substr(offset, magic.size()) == magic;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

}  // namespace

std::optional<ForeignKind> foreign_file_kind(std::string_view bytes) {
  if (looks_like_png(bytes)) return std::nullopt;
  if (const auto damage = damaged_png_signature(bytes)) return ForeignKind{damaged_png_signature_message(*damage), 1, true};
  for (const Magic& m : kMagics) {
    if (starts_with_at(bytes, m.offset, m.bytes)) return ForeignKind{std::string(m.what), 1};
  }
  if (starts_with_at(bytes, 0, "\xEF\xBB\xBF")) bytes.remove_prefix(3);
  int line = 1;
  std::size_t i = 0;
  for (; i < bytes.size() && is_blank(bytes[i]); ++i) line += bytes[i] == '\n' ? 1 : 0;
  if (i == bytes.size()) return std::nullopt;
  const auto first = static_cast<unsigned char>(bytes[i]);
  // '<' may be XML; NUL, byte order marks and other bytes outside printable ASCII are for the XML
  // reader, which names them (UTF-16, a NUL at an offset, bytes that are not UTF-8).
  if (first == '<' || first < 0x20 || first >= 0x7F) return std::nullopt;
  const std::string_view rest = bytes.substr(i);
  const std::string_view first_line = rest.substr(0, rest.find_first_of("\r\n"));
  const std::string start = "'" + escape_input(first_line, 40) + "'";
  if (first == '{' || first == '[') return ForeignKind{"JSON or other text that is not XML, starting with " + start, line};
  return ForeignKind{"text that is not XML, starting with " + start, line};
}

}  // namespace vimg
