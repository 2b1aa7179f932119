#pragma once
// SVG attribute values the importer reads: lengths with units, the viewBox, preserveAspectRatio,
// and the inherited painting properties (fill, stroke, stroke-width, fill-rule, display,
// visibility) from presentation attributes and the `style` attribute. Pure: no I/O.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/import/svg_transform.hpp"

namespace vimg::svg {

inline constexpr double kMmPerInch = 25.4;
inline constexpr double kPxPerInch = 96.0;  // CSS px: a user unit without a viewBox

struct Length {
  double value = 0.0;
  enum class Unit { none, px, mm, cm, in, pt, pc, percent, em, ex } unit = Unit::none;
};

// "12", "12.5mm", "1e1px", "50%". Nothing when the text is not a length.
std::optional<Length> parse_length(std::string_view text);

// The length in mm, with a unit-less number or px taken at 96 px per inch. Nothing for %, em, ex.
std::optional<double> length_mm(const Length& length);
// The length in user units (CSS px) of a coordinate attribute: mm, cm, in, pt, pc convert at
// 96 px per inch. Nothing for %, em, ex.
std::optional<double> length_user(const Length& length);

struct ViewBox {
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
};
std::optional<ViewBox> parse_view_box(std::string_view text);

// The map from the viewBox to a viewport of `width` x `height` at the origin, following
// preserveAspectRatio (default "xMidYMid meet"; "none"; x{Min,Mid,Max}Y{Min,Mid,Max} meet|slice).
// Nothing when the attribute does not parse.
std::optional<Affine> view_box_transform(const ViewBox& box, double width, double height,
                                         std::string_view preserve_aspect_ratio);

// The painting properties that reach an element (SVG defaults at the root).
struct Style {
  bool fill = true;               // fill is not "none" (black by default)
  bool stroke = false;            // stroke is not "none"
  bool fill_is_server = false;    // fill refers to a gradient or pattern (url(...))
  bool stroke_is_server = false;
  double stroke_width = 1.0;      // user units
  bool even_odd = false;          // fill-rule
  bool displayed = true;          // display is not "none" (not inherited: applies to the subtree)
  bool visible = true;            // visibility is not hidden or collapse
  bool dashed = false;            // stroke-dasharray is not "none"
};

// A property value as the element states it: from its `style` attribute, else its presentation
// attribute; empty when it states none.
struct DeclaredProperties {
  std::vector<std::pair<std::string, std::string>> values;  // name, value (trimmed)
  std::optional<std::string> get(std::string_view name) const;
};

// Parses `style="a: b; c: d"` after the presentation attributes (the style attribute wins).
DeclaredProperties declared_properties(const std::vector<std::pair<std::string, std::string>>& attributes,
                                       std::string_view style_attribute);

// The style of an element from its parent's and its own declarations. Problems (values that do
// not parse) are appended to `problems` as message text.
Style cascade(const Style& parent, const DeclaredProperties& declared, std::vector<std::string>& problems);

}  // namespace vimg::svg
