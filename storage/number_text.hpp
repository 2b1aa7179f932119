#pragma once
// Locale-independent decimal numbers for the image format (spec section 1, "Coordinates and
// numbers"): read with std::from_chars, written with std::to_chars in the shortest form that
// reads back to the same double.
#include <string>
#include <string_view>
#include <variant>

namespace vimg {

// Either the value or a reason the text is not an acceptable number ("is not a number", ...).
using ParsedNumber = std::variant<double, std::string>;

// Accepts exactly a decimal number: optional '-', digits, optional fraction and exponent.
// Rejects surrounding spaces, '+', ',' as separator, hexadecimal, NaN and infinities.
ParsedNumber parse_decimal(std::string_view text);

// The shortest decimal text that parse_decimal reads back to exactly `value` (finite values).
std::string format_decimal(double value);
// The same text, appended to `out` without a temporary string (writers of large files).
void append_decimal(std::string& out, double value);

}  // namespace vimg
