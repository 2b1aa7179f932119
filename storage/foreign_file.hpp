#pragma once
// What a file is when it is plainly not an image: an image file is XML text or a PNG picture, and
// a user who hands `vimg` or the editor a volume, a photo, an archive or a table should hear what
// that file is rather than an XML parser's complaint about its first byte.
#include <optional>
#include <string>
#include <string_view>

namespace vimg {

// The kind of `bytes` ("a NRRD volume", "a JPEG picture", "text that is not XML, starting with
// 'time_s,x_mm'"...) with the 1-based line where that shows, or nothing when the bytes may be XML
// (their first character after blanks and a UTF-8 byte order mark is '<'), are empty, start with a
// UTF-16/UTF-32 byte order mark or a NUL, or are a PNG: the XML and PNG readers say what is wrong
// with those. A PNG whose signature was damaged on its way (png_signature.hpp) is named as such:
// `what` is then the whole message ("a damaged PNG signature: line endings changed by a text-mode
// transfer (...); ...") and `damaged_png` is set.
struct ForeignKind {
  std::string what;
  int line = 1;
  bool damaged_png = false;
};
std::optional<ForeignKind> foreign_file_kind(std::string_view bytes);

}  // namespace vimg
