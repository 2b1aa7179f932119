#pragma once
// The one table of the image format's attributes (spec section 1): for every attribute of the
// canvas, the finger (<interaction>) and every primitive kind, its kind, unit, default, range and a
// one-line meaning. The XML reader takes its defaults and range checks from it, the writer its
// attributes and their order, the editor's inspector its field labels, ranges and help lines, and
// docs/format.md its parameter table (a test compares them). Plain constant data, no I/O.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "primitives/image.hpp"
#include "storage/number_range.hpp"

namespace vimg {

// The element an attribute belongs to.
enum class ParameterOwner { canvas, interaction, dot, line, surface, group };

enum class ParameterKind {
  number,   // a decimal number with a range
  choice,   // one word of `choices`
  points,   // "x,y x,y ..." (polygon vertices)
  id,       // [A-Za-z_][A-Za-z0-9_.-]*
  text,     // free text
  version,  // MAJOR.MINOR
};

// Where a number lives in the document model.
using NumberField = std::variant<std::monostate, double Image::*, double InteractionParams::*, double Dot::*,
                                 double Line::*, double Surface::*>;

struct ParameterSpec {
  ParameterOwner owner = ParameterOwner::dot;
  std::string_view shape;  // a surface attribute of one shape only ("rect", "ellipse", "polygon"); "" for all
  std::string_view name;   // the XML attribute
  ParameterKind kind = ParameterKind::number;
  std::string_view unit;   // "mm", "Hz", "kg", "mm/s", "1" for a ratio; "" when not a number
  bool required = false;   // no default: a file must give it
  double default_value = 0.0;     // numbers that are not required
  std::string_view default_text;  // choices that are not required
  double min = 0.0;        // numbers: -infinity when unbounded below
  double max = 0.0;        // numbers: +infinity when unbounded above
  bool min_open = false;   // min itself is outside the range
  bool max_open = false;
  double step = 0.0;       // numbers: the inspector's step, and how far inside an open bound a clamp lands
  std::string_view choices;  // choice: the words separated by '|'
  std::string_view meaning;  // one line, for the inspector's help and the docs
  NumberField field;         // numbers: the model's member
};

// Every attribute, owners in the order canvas, interaction, dot, line, surface, group, and within an
// owner in the canonical writer's order.
std::span<const ParameterSpec> parameter_table();

// The attribute `name` of `owner`, or nullptr.
const ParameterSpec* find_parameter(ParameterOwner owner, std::string_view name);

// The XML element name: "vibroimage", "interaction", "dot", "line", "surface", "group".
std::string_view owner_tag(ParameterOwner owner);

// Whether a surface attribute applies to the shape (`shape` is "" for every shape).
bool applies_to_shape(const ParameterSpec& spec, SurfaceShape shape);
std::string_view shape_name(SurfaceShape shape);
std::string_view pattern_name(SurfacePattern pattern);

// Numbers: the range (storage/number_range.hpp, the words every reader uses), and whether `value`
// is finite and inside it.
NumberRange number_range(const ParameterSpec& spec);
bool in_range(const ParameterSpec& spec, double value);
// The nearest value inside the range; `step` inside an open bound. Not finite values become the
// default (or the bound nearest zero when the attribute is required).
double clamp_to_range(const ParameterSpec& spec, double value);
// The range as in the reader's messages: "finite", "> 0", "in [0, 1]", "in (0, 1000]".
std::string range_text(const ParameterSpec& spec);
// The range as an interval: "any", "> 0", "[0, 1]", "(0, 1000]".
std::string interval_text(const ParameterSpec& spec);
// The reader's message for an out-of-range number: "<dot> attribute 'gain' must be in [0, 1], got 3".
std::string out_of_range_message(const ParameterSpec& spec, std::string_view value_text);

// The number `spec` names in the model, or nullptr when it lives elsewhere (another owner, another
// element kind, an absent <interaction>, or not a number).
double* number_in(Image& image, const ParameterSpec& spec);
const double* number_in(const Image& image, const ParameterSpec& spec);
double* number_in(Element& element, const ParameterSpec& spec);
const double* number_in(const Element& element, const ParameterSpec& spec);

// The parameter table of docs/format.md, in Markdown, one row per attribute (header included).
std::string parameter_table_markdown();

}  // namespace vimg
