#pragma once
// std::from_chars / std::to_chars for double, in one place for every build. Natively they are the
// standard functions. The WebAssembly build (Emscripten 3.1.6, docs/web.md) ships a libc++ whose
// floating-point from_chars/to_chars are deleted, so there they are written with strtod and
// snprintf on exactly the text the standard functions would accept: an optional '-', digits, an
// optional fraction and exponent (no leading spaces, no '+', no hexadecimal; "inf" and "nan" are not
// read). Both are correctly rounded, so a number reads to the same double in both builds; the
// shortest form written may differ in its spelling (only messages use it there).
#include <charconv>
#include <system_error>

#ifdef __EMSCRIPTEN__
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#endif

namespace vimg {

#ifndef __EMSCRIPTEN__

inline std::from_chars_result decimal_from_chars(const char* first, const char* last, double& value) {
  return std::from_chars(first, last, value, std::chars_format::general);
}

inline std::to_chars_result decimal_to_chars(char* first, char* last, double value) {
  return std::to_chars(first, last, value);
}

#else

namespace decimal_chars_detail {
inline const char* skip_digits(const char* p, const char* last) {
  while (p != last && *p >= '0' && *p <= '9') ++p;
  return p;
}
}  // namespace decimal_chars_detail

inline std::from_chars_result decimal_from_chars(const char* first, const char* last, double& value) {
  using decimal_chars_detail::skip_digits;
  const char* p = first;
  if (p != last && *p == '-') ++p;
  const char* int_end = skip_digits(p, last);
  const char* end = int_end;
  bool digits = int_end != p;
  if (end != last && *end == '.') {
    const char* frac_end = skip_digits(end + 1, last);
    digits = digits || frac_end != end + 1;
    end = frac_end;
  }
  if (!digits) return {first, std::errc::invalid_argument};
  if (end != last && (*end == 'e' || *end == 'E')) {
    const char* q = end + 1;
    if (q != last && (*q == '+' || *q == '-')) ++q;
    const char* exp_end = skip_digits(q, last);
    if (exp_end != q) end = exp_end;
  }
  const std::string text(first, end);
  errno = 0;
  const double parsed = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && std::isinf(parsed)) return {end, std::errc::result_out_of_range};
  value = parsed;
  return {end, std::errc()};
}

inline std::to_chars_result decimal_to_chars(char* first, char* last, double value) {
  char buffer[40];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value || precision == 17) break;
  }
  std::size_t n = 0;
  while (buffer[n] != '\0') ++n;
  if (static_cast<std::size_t>(last - first) < n) return {last, std::errc::value_too_large};
  for (std::size_t i = 0; i < n; ++i) first[i] = buffer[i];
  return {first + n, std::errc()};
}

#endif

}  // namespace vimg
