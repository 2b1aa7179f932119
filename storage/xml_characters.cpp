#include "storage/xml_characters.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>

#include "storage/diagnostic.hpp"

namespace vimg {

std::size_t find_forbidden_control_byte(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x20 && b != '\t' && b != '\n' && b != '\r' && b != 0) return i;
  }
  return std::string_view::npos;
}

namespace {

bool is_xml_char(std::uint32_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) ||
         (c >= 0x10000 && c <= 0x10FFFF);
}

// A character of a reference's body: a name character ('#' and digits included) or UTF-8.
bool reference_char(char c) {
  const auto b = static_cast<unsigned char>(c);
  return b >= 0x80 || (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || c == '#' ||
         c == '_' || c == ':' || c == '.' || c == '-';
}

}  // namespace

std::optional<std::string> reference_error(std::string_view text) {
  std::size_t semicolon = 1;  // the body runs over reference characters up to a ';' (linear: it stops at any other)
  while (semicolon < text.size() && reference_char(text[semicolon])) ++semicolon;
  if (semicolon == text.size() || text[semicolon] != ';') {
    const std::string shown = "'" + escape_input(text.substr(0, std::max<std::size_t>(semicolon, 10))) + "'";
    return "a '&' that starts no reference (" + shown + "); write '&amp;' for the character itself";
  }
  const std::string shown = "'" + escape_input(text.substr(0, semicolon + 1)) + "'";
  const std::string_view body = text.substr(1, semicolon - 1);
  if (body == "lt" || body == "gt" || body == "amp" || body == "apos" || body == "quot") return std::nullopt;
  if (!body.starts_with('#')) {
    return "the entity " + shown + " is not defined (this format has no DTD: only &lt; &gt; &amp; &apos; &quot;)";
  }
  const bool hex = body.size() > 1 && body[1] == 'x';
  const std::string_view digits = body.substr(hex ? 2 : 1);
  std::uint32_t code = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), code, hex ? 16 : 10);
  if (digits.empty() || digits.front() == '-' || digits.front() == '+' || ec == std::errc::invalid_argument ||
      end != digits.data() + digits.size()) {
    return "the character reference " + shown + " is malformed";
  }
  if (ec == std::errc::result_out_of_range || !is_xml_char(code)) {
    return "the character reference " + shown + " names a character XML does not allow";
  }
  return std::nullopt;
}

}  // namespace vimg
