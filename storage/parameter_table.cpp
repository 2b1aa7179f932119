// The parameter table (storage/parameter_table.hpp): every attribute of the image format, from the
// spec (section 1) and docs/format.md; limits from storage/limits.hpp.
#include "storage/parameter_table.hpp"

#include <limits>

#include "storage/limits.hpp"

namespace vimg {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using O = ParameterOwner;

struct Range {
  double min;
  double max;
  bool min_open;
  bool max_open;
};
constexpr Range kAnyFinite{-kInf, kInf, true, true};
constexpr Range kPositive{0.0, kInf, true, true};
constexpr Range kUnitClosed{0.0, 1.0, false, false};
constexpr Range kUnitOpen{0.0, 1.0, true, true};

// A number with a default.
constexpr ParameterSpec optional_number(O owner, std::string_view name, std::string_view unit, double default_value,
                                        Range range, double step, NumberField field, std::string_view meaning) {
  ParameterSpec s;
  s.owner = owner;
  s.name = name;
  s.kind = ParameterKind::number;
  s.unit = unit;
  s.default_value = default_value;
  s.min = range.min;
  s.max = range.max;
  s.min_open = range.min_open;
  s.max_open = range.max_open;
  s.step = step;
  s.field = field;
  s.meaning = meaning;
  return s;
}

// A number a file must give; `shape` for a surface's geometry.
constexpr ParameterSpec required_number(O owner, std::string_view shape, std::string_view name, Range range,
                                        NumberField field, std::string_view meaning) {
  ParameterSpec s = optional_number(owner, name, "mm", 0.0, range, 0.1, field, meaning);
  s.shape = shape;
  s.required = true;
  return s;
}

constexpr ParameterSpec other(O owner, std::string_view shape, std::string_view name, ParameterKind kind, bool required,
                              std::string_view default_text, std::string_view choices, std::string_view meaning) {
  ParameterSpec s;
  s.owner = owner;
  s.shape = shape;
  s.name = name;
  s.kind = kind;
  s.required = required;
  s.default_text = default_text;
  s.choices = choices;
  s.meaning = meaning;
  return s;
}

constexpr ParameterSpec id_of(O owner) {
  return other(owner, "", "id", ParameterKind::id, false, "", "",
               "the element's name, unique in the document (a writer gives one to an element without)");
}

constexpr ParameterSpec gain_of(O owner, double Dot::*dot, double Line::*line, double Surface::*surface) {
  NumberField field;
  if (dot != nullptr) field = dot;
  if (line != nullptr) field = line;
  if (surface != nullptr) field = surface;
  return optional_number(owner, "gain", "1", 1.0, kUnitClosed, 0.01, field,
                         "strength of the element relative to full drive");
}

constexpr Range kCanvas{0.0, kMaxCanvasMm, true, false};
constexpr Range kFrequency{0.0, kMaxFrequencyHz, true, false};

const ParameterSpec kTable[] = {
    other(O::canvas, "", "version", ParameterKind::version, true, "", "",
          "format version MAJOR.MINOR; major 1 is read with any minor"),
    required_number(O::canvas, "", "width", kCanvas, &Image::width_mm, "canvas width"),
    required_number(O::canvas, "", "height", kCanvas, &Image::height_mm, "canvas height"),

    optional_number(O::interaction, "mass", "kg", InteractionParams{}.mass_kg, kPositive, 0.001,
                    &InteractionParams::mass_kg, "virtual mass of the interaction point (the finger)"),
    optional_number(O::interaction, "fullSpeed", "mm/s", InteractionParams{}.full_speed_mm_per_s, kPositive, 1.0,
                    &InteractionParams::full_speed_mm_per_s,
                    "finger speed at which impulse and texture amplitude saturate"),
    optional_number(O::interaction, "maxDeformation", "mm", InteractionParams{}.max_deformation_mm, kPositive, 0.1,
                    &InteractionParams::max_deformation_mm, "finger deformation at full pressure"),

    id_of(O::dot),
    required_number(O::dot, "", "x", kAnyFinite, &Dot::x_mm, "centre, from the left edge"),
    required_number(O::dot, "", "y", kAnyFinite, &Dot::y_mm, "centre, from the top edge"),
    optional_number(O::dot, "radius", "mm", Dot{}.radius_mm, kPositive, 0.1, &Dot::radius_mm,
                    "the dot is felt while the finger is this close to the centre"),
    gain_of(O::dot, &Dot::gain, nullptr, nullptr),

    id_of(O::line),
    required_number(O::line, "", "x1", kAnyFinite, &Line::x1_mm, "first end, from the left edge"),
    required_number(O::line, "", "y1", kAnyFinite, &Line::y1_mm, "first end, from the top edge"),
    required_number(O::line, "", "x2", kAnyFinite, &Line::x2_mm, "second end, from the left edge"),
    required_number(O::line, "", "y2", kAnyFinite, &Line::y2_mm, "second end, from the top edge"),
    optional_number(O::line, "width", "mm", Line{}.width_mm, kPositive, 0.1, &Line::width_mm,
                    "contact band: width/2 either side of the segment"),
    optional_number(O::line, "frequency", "Hz", Line{}.frequency_hz, kFrequency, 1.0, &Line::frequency_hz,
                    "natural frequency f_N of the ring-down after the finger crosses"),
    optional_number(O::line, "damping", "1", Line{}.damping, kUnitOpen, 0.001, &Line::damping,
                    "damping ratio of the ring-down: larger stops sooner"),
    gain_of(O::line, nullptr, &Line::gain, nullptr),

    id_of(O::surface),
    other(O::surface, "", "shape", ParameterKind::choice, true, "", "rect|ellipse|polygon",
          "the outline, which decides the geometry attributes"),
    required_number(O::surface, "rect", "x", kAnyFinite, &Surface::x_mm, "left edge"),
    required_number(O::surface, "rect", "y", kAnyFinite, &Surface::y_mm, "top edge"),
    required_number(O::surface, "rect", "width", kPositive, &Surface::width_mm, "width of the rectangle"),
    required_number(O::surface, "rect", "height", kPositive, &Surface::height_mm, "height of the rectangle"),
    required_number(O::surface, "ellipse", "cx", kAnyFinite, &Surface::cx_mm, "centre, from the left edge"),
    required_number(O::surface, "ellipse", "cy", kAnyFinite, &Surface::cy_mm, "centre, from the top edge"),
    required_number(O::surface, "ellipse", "rx", kPositive, &Surface::rx_mm, "horizontal radius"),
    required_number(O::surface, "ellipse", "ry", kPositive, &Surface::ry_mm, "vertical radius"),
    other(O::surface, "polygon", "points", ParameterKind::points, true, "", "",
          "vertices \"x,y x,y ...\" in mm, at least 3, joined back to the first"),
    optional_number(O::surface, "period", "mm", Surface{}.period_mm, kPositive, 0.1, &Surface::period_mm,
                    "spatial period of the texture: felt at speed/period Hz"),
    optional_number(O::surface, "relief", "mm", Surface{}.relief_mm, kPositive, 0.1, &Surface::relief_mm,
                    "height of the texture pattern"),
    other(O::surface, "", "pattern", ParameterKind::choice, false, "sine", "sine|square|triangle",
          "profile of the texture across its stripes"),
    gain_of(O::surface, nullptr, nullptr, &Surface::gain),

    id_of(O::group),
    other(O::group, "", "name", ParameterKind::text, false, "", "", "a label for the group, shown in the editor"),
};

}  // namespace

std::span<const ParameterSpec> parameter_table() { return kTable; }

const ParameterSpec* find_parameter(ParameterOwner owner, std::string_view name) {
  for (const ParameterSpec& s : kTable) {
    if (s.owner == owner && s.name == name) return &s;
  }
  return nullptr;
}

std::string_view owner_tag(ParameterOwner owner) {
  switch (owner) {
    case O::canvas: return "vibroimage";
    case O::interaction: return "interaction";
    case O::dot: return "dot";
    case O::line: return "line";
    case O::surface: return "surface";
    case O::group: return "group";
  }
  return "";
}

std::string_view shape_name(SurfaceShape shape) {
  switch (shape) {
    case SurfaceShape::rect: return "rect";
    case SurfaceShape::ellipse: return "ellipse";
    case SurfaceShape::polygon: return "polygon";
  }
  return "";
}

std::string_view pattern_name(SurfacePattern pattern) {
  switch (pattern) {
    case SurfacePattern::sine: return "sine";
    case SurfacePattern::square: return "square";
    case SurfacePattern::triangle: return "triangle";
  }
  return "";
}

bool applies_to_shape(const ParameterSpec& spec, SurfaceShape shape) {
  return spec.shape.empty() || spec.shape == shape_name(shape);
}

}  // namespace vimg
