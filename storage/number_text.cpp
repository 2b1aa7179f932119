#include "storage/number_text.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <system_error>

#include "storage/decimal_chars.hpp"

namespace vimg {

namespace {

bool looks_hexadecimal(std::string_view text) {
  if (!text.empty() && text.front() == '-') text.remove_prefix(1);
  return text.size() >= 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
}

}  // namespace

ParsedNumber parse_decimal(std::string_view text) {
  if (text.empty()) return std::string("is empty, expected a number");
  if (looks_hexadecimal(text)) return std::string("is hexadecimal, expected a decimal number");
  double value = 0.0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto [ptr, ec] = decimal_from_chars(begin, end, value);
  if (ec == std::errc::result_out_of_range) return std::string("is out of the range of a number");
  if (ec != std::errc() || ptr != end) {
    if (text.find(',') != std::string_view::npos && ec == std::errc())
      return std::string("is not a number (the decimal separator is '.')");
    return std::string("is not a number");
  }
  if (std::isnan(value)) return std::string("is NaN, expected a finite number");
  if (std::isinf(value)) return std::string("is infinite, expected a finite number");
  return value;
}

void append_decimal(std::string& out, double value) {
  std::array<char, 64> buffer{};
  const auto [ptr, ec] = decimal_to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (ec != std::errc()) {
    out += '0';
    return;
  }
  out.append(buffer.data(), ptr);
}

std::string format_decimal(double value) {
  std::string text;
  append_decimal(text, value);
  return text;
}

}  // namespace vimg
