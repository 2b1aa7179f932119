#pragma once
// Whether bytes are text: the one UTF-8 decoder of the messages (diagnostic.cpp escapes what is not
// printable with it) and the test the line readers use to tell a text file from binary data.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace vimg {

// The length of the valid UTF-8 sequence starting at text[i] (1 for ASCII) and its code point, or 0
// when the byte starts none (a stray continuation byte, an overlong form, a surrogate, beyond
// U+10FFFF, a sequence cut short by the end of `text`).
std::size_t utf8_sequence(std::string_view text, std::size_t i, std::uint32_t& code_point);

// The offset of the first byte of `text` that no text file holds: a NUL, another ASCII control
// character but tab, line feed, vertical tab, form feed, carriage return and escape (terminal
// captures keep their colours), DEL, or a byte that is not part of valid UTF-8. npos when there is
// none.
std::size_t first_binary_byte(std::string_view text);

}  // namespace vimg
