// Fuzzes SVG path data (storage/import/svg_path) and its flattening: any text gives subpaths and
// at most an error, never a crash, a hang or undefined behaviour; the error offset lies in the
// text, the segment limit holds, and flattening stays within its point budget.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "storage/import/svg_flatten.hpp"
#include "storage/import/svg_path.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view d(reinterpret_cast<const char*>(data), size);
  constexpr std::size_t kMaxSegments = 2000;
  const vimg::svg::PathParse parsed = vimg::svg::parse_path_data(d, kMaxSegments);
  if (!parsed.error.empty() && parsed.error_offset > size) std::abort();
  std::size_t segments = 0;
  for (const auto& s : parsed.subpaths) segments += s.segments.size();
  if (segments > kMaxSegments) std::abort();
  const vimg::svg::Affine transform{0.26, 0.01, -0.02, 0.25, 3.0, -4.0};
  std::vector<vimg::Vec2> points;
  for (const auto& s : parsed.subpaths) {
    points.clear();
    vimg::svg::flatten_subpath(s, transform, 0.05, 5000, points);
    if (points.size() > 5000) std::abort();
  }
  return 0;
}
