// The parameter table's ranges, texts and places in the model (storage/parameter_table.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "storage/number_text.hpp"
#include "storage/parameter_table.hpp"

namespace vimg {

namespace {

template <typename T>
double* member(T& object, const NumberField& field) {
  const auto* p = std::get_if<double T::*>(&field);
  return p != nullptr ? &(object.**p) : nullptr;
}

// The inspector's and the docs' column: the interval, or the words of a choice.
std::string docs_range(const ParameterSpec& s) {
  switch (s.kind) {
    case ParameterKind::number: return interval_text(s);
    case ParameterKind::choice: {
      std::string out;
      for (const char c : s.choices) out += c == '|' ? std::string(", ") : std::string(1, c);
      return out;
    }
    case ParameterKind::points: return "at least 3 points, each coordinate finite";
    case ParameterKind::id: return "`[A-Za-z_][A-Za-z0-9_.-]*`, unique";
    case ParameterKind::text: return "any text";
    case ParameterKind::version: return "`1.MINOR`";
  }
  return "";
}

std::string_view kind_word(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::number: return "number";
    case ParameterKind::choice: return "choice";
    case ParameterKind::points: return "points";
    case ParameterKind::id: return "id";
    case ParameterKind::text: return "text";
    case ParameterKind::version: return "version";
  }
  return "";
}

}  // namespace

NumberRange number_range(const ParameterSpec& spec) { return {spec.min, spec.max, spec.min_open, spec.max_open}; }

bool in_range(const ParameterSpec& spec, double value) { return in_range(number_range(spec), value); }

double clamp_to_range(const ParameterSpec& spec, double value) {
  const double low = spec.min_open ? spec.min + spec.step : spec.min;
  const double high = spec.max_open ? spec.max - spec.step : spec.max;
  if (!std::isfinite(value)) {
    if (!spec.required) return spec.default_value;
    return std::clamp(0.0, low, high);
  }
  if (in_range(spec, value)) return value;
  return std::clamp(value, low, high);
}

std::string range_text(const ParameterSpec& spec) { return range_text(number_range(spec)); }

std::string interval_text(const ParameterSpec& spec) { return interval_text(number_range(spec)); }

std::string out_of_range_message(const ParameterSpec& spec, std::string_view value_text) {
  return "<" + std::string(owner_tag(spec.owner)) + "> attribute '" + std::string(spec.name) + "' must be " +
         range_text(spec) + ", got " + std::string(value_text);
}

double* number_in(Image& image, const ParameterSpec& spec) {
  if (spec.owner == ParameterOwner::canvas) return member(image, spec.field);
  if (spec.owner == ParameterOwner::interaction && image.interaction) return member(*image.interaction, spec.field);
  return nullptr;
}

double* number_in(Element& element, const ParameterSpec& spec) {
  if (auto* d = std::get_if<Dot>(&element.body); d && spec.owner == ParameterOwner::dot) return member(*d, spec.field);
  if (auto* l = std::get_if<Line>(&element.body); l && spec.owner == ParameterOwner::line) return member(*l, spec.field);
  if (auto* s = std::get_if<Surface>(&element.body); s && spec.owner == ParameterOwner::surface) {
    return applies_to_shape(spec, s->shape) ? member(*s, spec.field) : nullptr;
  }
  return nullptr;
}

const double* number_in(const Image& image, const ParameterSpec& spec) {
  return number_in(const_cast<Image&>(image), spec);
}

const double* number_in(const Element& element, const ParameterSpec& spec) {
  return number_in(const_cast<Element&>(element), spec);
}

std::string parameter_table_markdown() {
  std::string out = "| element | attribute | kind | unit | default | range | meaning |\n|---|---|---|---|---|---|---|\n";
  for (const ParameterSpec& s : parameter_table()) {
    std::string element = "`<" + std::string(owner_tag(s.owner)) + ">`";
    if (!s.shape.empty()) element += " " + std::string(s.shape);
    std::string default_text = "none";
    if (s.required) {
      default_text = "required";
    } else if (s.kind == ParameterKind::number) {
      default_text = format_decimal(s.default_value);
    } else if (!s.default_text.empty()) {
      default_text = std::string(s.default_text);
    }
    out += "| " + element + " | `" + std::string(s.name) + "` | " + std::string(kind_word(s.kind)) + " | " +
           std::string(s.unit.empty() ? "" : s.unit) + " | " + default_text + " | " + docs_range(s) + " | " +
           std::string(s.meaning) + " |\n";
  }
  return out;
}

}  // namespace vimg
