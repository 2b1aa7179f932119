#pragma once
// Counts the bytes that gzip (or zlib) and bzip2 data inflate to, without keeping them: the
// output goes through one small buffer, and inflation stops one byte past `limit`. A NRRD reader
// uses it to refuse compressed data that inflates to more than the header declares (a
// "compression bomb") or to less (truncated), before anything is allocated for the data.
#include <cstddef>
#include <string>
#include <string_view>

namespace vimg {

enum class Compression { gzip, bzip2 };

struct InflateCount {
  std::size_t bytes = 0;  // inflated bytes, at most limit + 1
  std::string problem;    // "" when the data is a complete stream (or was stopped past the limit)
};

InflateCount count_inflated(std::string_view compressed, Compression compression, std::size_t limit);

}  // namespace vimg
