#pragma once
// A field or a line of text without the blanks around it: spaces and tabs at both ends, and the
// carriage return a file written on Windows leaves at the end of each line.
#include <string_view>

namespace vimg {

inline std::string_view trim_blanks(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

}  // namespace vimg
