#pragma once
// SVG path data (SVG 1.1 section 8.3, SVG 2 "Path data"): the `d` attribute parsed into subpaths of
// straight and cubic segments in user units. Every command (M L H V C S Q T A Z, absolute and
// relative) with implicit repeats, numbers such as `1e-3`, `.5.5` and `-.5-.5`, and arc flags
// written without separators (`a1 1 0 00.5.5`). Quadratics become the exact equivalent cubics;
// arcs become cubics of at most 45 degrees each (radial error below 5e-6 of the radius, so under
// 0.05 mm for radii up to 10 m, the largest canvas) or a line when a radius is zero. Pure: no I/O.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/geometry/vec2.hpp"

namespace vimg::svg {

struct PathSegment {
  enum class Kind { line, cubic };
  Kind kind = Kind::line;
  Vec2 c1;   // cubic only: first control point
  Vec2 c2;   // cubic only: second control point
  Vec2 end;  // the end point of the segment
};

struct Subpath {
  Vec2 start;
  std::vector<PathSegment> segments;
  bool closed = false;  // ended by Z (the closing line, if any, is the last segment)
};

struct PathParse {
  std::vector<Subpath> subpaths;  // what was read up to the error, as SVG renderers draw it
  std::string error;              // empty when the whole text is valid
  std::size_t error_offset = 0;   // byte offset of the error in the text
};

// Parses `d`. At most `max_segments` segments are produced (arcs count one per cubic); beyond
// that the parse stops with an error naming the limit.
PathParse parse_path_data(std::string_view d, std::size_t max_segments);

// Scans one SVG number at `pos` (after optional whitespace and at most one comma when
// `allow_comma`). On success sets `value`, advances `pos` and returns true. Shared with the
// attribute lists of <polyline>, <polygon>, viewBox and transform.
bool scan_number(std::string_view text, std::size_t& pos, double& value, bool allow_comma);

// Skips whitespace and at most one comma with whitespace around it.
void skip_comma_wsp(std::string_view text, std::size_t& pos);

}  // namespace vimg::svg
