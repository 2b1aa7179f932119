#pragma once
// One SVG shape element to vibroimage primitives (docs/import.md, "SVG"): filled closed outlines
// become a SURFACE (a rect or ellipse when the transform keeps it one, else a polygon of the
// flattened outline, holes bridged), stroked outlines and every open subpath become LINE chains
// with the stroke width, and a circle of radius at most `dot_max_radius_mm` becomes a DOT.
// Coordinates come in user units and leave in mm through `ctm`. Pure: no I/O.
#include <cstddef>
#include <string>
#include <vector>

#include "primitives/image.hpp"
#include "storage/import/svg_attributes.hpp"
#include "storage/import/svg_path.hpp"
#include "storage/import/svg_transform.hpp"

namespace vimg::svg {

struct ShapeGeometry {
  std::vector<Subpath> subpaths;  // user units
  enum class Native { none, rect, ellipse };
  Native native = Native::none;   // what the element was, when a primitive can keep that shape
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;  // rect
  double cx = 0.0, cy = 0.0, rx = 0.0, ry = 0.0;       // ellipse or circle
  bool lines_only = false;        // <line>, <polyline>: LINE chains whatever the fill
};

struct ShapeSettings {
  Affine ctm;                     // user units to mm
  Style style;
  double tolerance_mm = 0.05;
  double dot_max_radius_mm = 2.0;
  std::size_t max_points = 0;     // points of one flattened element, at most
  std::size_t points_left = static_cast<std::size_t>(-1);      // points the whole import may still flatten
  std::size_t primitives_left = static_cast<std::size_t>(-1);  // primitives the whole import may still give
  std::size_t outline_tests_left = static_cast<std::size_t>(-1);  // kMaxImportOutlineTests the import has left
};

struct ShapeOutput {
  std::vector<Element> primitives;  // in paint order: the surface, then its outline
  std::vector<std::string> warnings;
  std::string error;                // a limit was exceeded; primitives are then incomplete
  std::size_t points = 0;           // points flattened, counted as they were produced
  bool over_primitives = false;     // stopped at primitives_left: primitives are then incomplete
  std::size_t outline_tests = 0;    // outline vertices and boxes visited placing subpaths
};

ShapeOutput convert_shape(const ShapeGeometry& geometry, const ShapeSettings& settings);

// The outline of a rect (rounded when rx or ry > 0) and of an ellipse, as path subpaths.
std::vector<Subpath> rect_outline(double x, double y, double width, double height, double rx, double ry);
std::vector<Subpath> ellipse_outline(double cx, double cy, double rx, double ry);

}  // namespace vimg::svg
