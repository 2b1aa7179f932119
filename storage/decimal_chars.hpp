#pragma once
// std::from_chars / std::to_chars for double, in one place for every build. Natively they are the
// standard functions. The WebAssembly build (Emscripten 3.1.6, docs/web-building.md) ships a libc++ whose
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

// Clinger's exact case (1990): significant digits m <= 2^53 and a power of ten |e| <= 22 are
// both exact doubles, so m * 10^e (or m / 10^-e) is one correctly rounded operation, the double
// strtod gives, without musl's long-double (software) arithmetic and a copy of the text. Digits in
// [p, int_end) and [frac, frac_end); the exponent's digits in [exp, exp_end) after its sign. False
// outside that case.
inline bool exact_decimal(const char* p, const char* int_end, const char* frac, const char* frac_end, bool exp_negative,
                          const char* exp, const char* exp_end, double& value) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  unsigned long long m = 0;
  int significant = 0;
  auto take = [&](const char* q, const char* end) {
    for (; q != end; ++q) {
      if (m == 0 && *q == '0') continue;  // a leading zero
      if (++significant > 16) return false;  // 16 digits cannot overflow m
      m = m * 10 + static_cast<unsigned long long>(*q - '0');
    }
    return true;
  };
  if (!take(p, int_end) || !take(frac, frac_end) || m > (1ULL << 53) || exp_end - exp > 3) return false;
  int e = 0;
  for (const char* q = exp; q != exp_end; ++q) e = e * 10 + (*q - '0');
  e = (exp_negative ? -e : e) - static_cast<int>(frac_end - frac);
  if (e < -22 || e > 22) return false;
  const auto mantissa = static_cast<double>(m);
  value = e < 0 ? mantissa / kPow10[-e] : mantissa * kPow10[e];
  return true;
}
}  // namespace decimal_chars_detail

inline std::from_chars_result decimal_from_chars(const char* first, const char* last, double& value) {
  using decimal_chars_detail::skip_digits;
  const char* p = first;
  if (p != last && *p == '-') ++p;
  const char* int_end = skip_digits(p, last);
  const char* end = int_end;
  const char* frac = int_end;
  const char* frac_end = int_end;
  bool digits = int_end != p;
  if (end != last && *end == '.') {
    frac = end + 1;
    frac_end = skip_digits(frac, last);
    digits = digits || frac_end != frac;
    end = frac_end;
  }
  if (!digits) return {first, std::errc::invalid_argument};
  const char* exp = end;
  bool exp_negative = false;
  if (end != last && (*end == 'e' || *end == 'E')) {
    const char* q = end + 1;
    if (q != last && (*q == '+' || *q == '-')) exp_negative = *q++ == '-';
    const char* exp_end = skip_digits(q, last);
    if (exp_end != q) {
      exp = q;
      end = exp_end;
    }
  }
  if (double exact = 0.0; decimal_chars_detail::exact_decimal(p, int_end, frac, frac_end, exp_negative, exp, end, exact)) {
    value = p != first ? -exact : exact;
    return {end, std::errc()};
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
