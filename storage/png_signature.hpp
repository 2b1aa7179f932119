#pragma once
// A PNG signature damaged on its way. The 8 bytes 89 50 4E 47 0D 0A 1A 0A ("\x89PNG\r\n\x1A\n")
// were chosen to show the usual damage of a transfer (PNG specification, section 12.12): a
// text-mode transfer changes the line endings (CR LF becomes LF, LF becomes CR LF, ...), a 7-bit
// channel drops the high bit of the first byte. A file that starts like a PNG with such damage is
// named for it, with the likely cause, rather than left to a reader that calls it text or UTF-16.
#include <optional>
#include <string>
#include <string_view>

namespace vimg {

// What damaged the PNG signature at the start of `bytes`, or nothing when the signature is intact
// or the bytes do not start like a PNG:
//   - its CR LF and LF changed into other runs of CR and LF: "line endings changed by a text-mode
//     transfer (the signature's CR LF became LF)" (and "; its first byte lost its high bit" when
//     that happened too);
//   - one of the 8 bytes changed: "the first byte lost its high bit (0x09 where a PNG has 0x89),
//     as a 7-bit transfer does" or "one byte changed (byte 2 is 0x51 'Q' where a PNG has 0x50 'P')";
//   - a file shorter than the signature that starts like it: "the file ends within the signature
//     (5 of its 8 bytes)".
std::optional<std::string> damaged_png_signature(std::string_view bytes);

// The whole message for such a file: "a damaged PNG signature: CAUSE; copy the file again as
// binary data".
std::string damaged_png_signature_message(const std::string& cause);

}  // namespace vimg
