// The XML reader's elements: dot, line, surface (rect, ellipse, polygon points, pattern), group, and
// unknown elements kept verbatim; the "wholly outside the canvas" warning.
#include <tinyxml2.h>

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/parameter_table.hpp"
#include "storage/xml_reader_detail.hpp"

namespace vimg::xml_reader_detail {

namespace {

constexpr std::string_view kDotAttributes[] = {"id", "x", "y", "radius", "gain"};
constexpr std::string_view kLineAttributes[] = {"id", "x1", "y1", "x2", "y2", "width", "frequency", "damping", "gain"};
constexpr std::string_view kRectAttributes[] = {"id", "shape", "x", "y", "width", "height", "period", "relief", "pattern", "gain"};
constexpr std::string_view kEllipseAttributes[] = {"id", "shape", "cx", "cy", "rx", "ry", "period", "relief", "pattern", "gain"};
constexpr std::string_view kPolygonAttributes[] = {"id", "shape", "points", "period", "relief", "pattern", "gain"};
// A surface whose shape is missing or unknown: every geometry attribute is known.
constexpr std::string_view kAnySurfaceAttributes[] = {"id", "shape", "x", "y", "width", "height", "cx", "cy", "rx", "ry",
                                                      "points", "period", "relief", "pattern", "gain"};
constexpr std::string_view kGroupAttributes[] = {"id", "name"};

}  // namespace

std::string print_verbatim(const XMLElement& element) {
  tinyxml2::XMLPrinter printer(nullptr, /*compact=*/true);
  element.Accept(&printer);
  return std::string(printer.CStr());
}

// A child of <vibroimage> or <group>: a primitive, a group, or an unknown element kept verbatim;
// nothing when it cannot be read (see LoadResult::readable). `depth` is the number of groups
// around it, `index` its place among the children read so far.
std::optional<Element> Reader::read_element(const XMLElement& e, int depth, std::size_t index) {
  path_.push_back(index);
  const std::size_t hard_before = hard_errors_;
  const std::size_t problems_before = value_problems_.size();
  std::optional<Element> element = read_element_body(e, depth);
  if (hard_errors_ != hard_before && (!element || !std::holds_alternative<Group>(element->body))) {
    element.reset();
    value_problems_.resize(problems_before);
  }
  path_.pop_back();
  return element;
}

std::optional<Element> Reader::read_element_body(const XMLElement& e, int depth) {
  Element element;
  element.source_line = e.GetLineNum();
  const std::string_view name = e.Name();
  if (name == "dot") {
    element.extra_attributes = gather(e, kDotAttributes);
    read_id(e, element);
    element.body = read_dot(e);
  } else if (name == "line") {
    element.extra_attributes = gather(e, kLineAttributes);
    read_id(e, element);
    element.body = read_line(e);
  } else if (name == "surface") {
    element.extra_attributes = gather(e, surface_attributes(e));
    read_id(e, element);
    element.body = read_surface(e);
  } else if (name == "group") {
    element.extra_attributes = gather(e, kGroupAttributes);
    read_id(e, element);
    if (depth + 1 > kMaxGroupDepth) {
      error(e.GetLineNum(), "groups nested deeper than " + std::to_string(kMaxGroupDepth) + " levels");
      return std::nullopt;
    }
    element.body = read_group(e, depth + 1);
    return element;
  } else {
    warning(e.GetLineNum(), "unknown element " + tag(e) + " kept as is");
    element.body = UnknownElement{print_verbatim(e)};
    return element;
  }
  read_primitive_children(e, element);
  return element;
}

void Reader::read_primitive_children(const XMLElement& e, Element& element) {
  for (const XMLNode* node = e.FirstChild(); node != nullptr; node = node->NextSibling()) {
    if (const XMLElement* c = node->ToElement()) {
      warning(c->GetLineNum(), "unknown element " + tag(*c) + " in " + tag(e) + " kept as is");
      element.unknown_children.push_back(UnknownElement{print_verbatim(*c)});
    } else {
      note_text(*node, e);
    }
  }
}

void Reader::warn_if_outside(const XMLElement& e, const Bounds& b) {
  if (failed()) return;
  if (b.max_x < 0.0 || b.max_y < 0.0 || b.min_x > canvas_w_ || b.min_y > canvas_h_) {
    const char* id = e.Attribute("id");
    const std::string what = id != nullptr ? "<" + q(e.Name()) + " id=\"" + q(id) + "\">" : tag(e);
    warning(e.GetLineNum(), what + " lies wholly outside the " + format_decimal(canvas_w_) + " x " +
                                format_decimal(canvas_h_) + " mm canvas");
  }
}

Dot Reader::read_dot(const XMLElement& e) {
  Dot d;
  d.x_mm = number(e, ParameterOwner::dot, "x");
  d.y_mm = number(e, ParameterOwner::dot, "y");
  d.radius_mm = number(e, ParameterOwner::dot, "radius");
  d.gain = number(e, ParameterOwner::dot, "gain");
  warn_if_outside(e, {d.x_mm - d.radius_mm, d.y_mm - d.radius_mm, d.x_mm + d.radius_mm, d.y_mm + d.radius_mm});
  return d;
}

Line Reader::read_line(const XMLElement& e) {
  Line l;
  l.x1_mm = number(e, ParameterOwner::line, "x1");
  l.y1_mm = number(e, ParameterOwner::line, "y1");
  l.x2_mm = number(e, ParameterOwner::line, "x2");
  l.y2_mm = number(e, ParameterOwner::line, "y2");
  l.width_mm = number(e, ParameterOwner::line, "width");
  l.frequency_hz = number(e, ParameterOwner::line, "frequency");
  l.damping = number(e, ParameterOwner::line, "damping");
  l.gain = number(e, ParameterOwner::line, "gain");
  const double half = l.width_mm / 2.0;
  warn_if_outside(e, {std::min(l.x1_mm, l.x2_mm) - half, std::min(l.y1_mm, l.y2_mm) - half,
                      std::max(l.x1_mm, l.x2_mm) + half, std::max(l.y1_mm, l.y2_mm) + half});
  return l;
}

std::vector<Point2Mm> Reader::read_points(const XMLElement& e) {
  std::vector<Point2Mm> points;
  const XMLAttribute* a = attribute(e, "points");
  if (a == nullptr) {
    error(e.GetLineNum(), "<surface> is missing required attribute 'points'");
    return points;
  }
  const std::string_view text = a->Value();
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_space(text[i])) ++i;
    if (i == text.size()) break;
    size_t end = i;
    while (end < text.size() && !is_space(text[end])) ++end;
    if (points.size() == kMaxPolygonPoints) {
      error(a->GetLineNum(), "<surface> polygon has more than " + std::to_string(kMaxPolygonPoints) + " points (limit " +
                                 std::to_string(kMaxPolygonPoints) + ")");
      return {};
    }
    const std::string_view pair = text.substr(i, end - i);
    const auto comma = pair.find(',');
    const auto where = [&] {
      return "<surface> attribute 'points': point " + std::to_string(points.size() + 1) + " \"" + q(pair) + "\"";
    };
    if (comma == std::string_view::npos) {
      error(a->GetLineNum(), where() + " is not x,y");
      return {};
    }
    const ParsedNumber x = parse_decimal(pair.substr(0, comma));
    const ParsedNumber y = parse_decimal(pair.substr(comma + 1));
    for (const ParsedNumber* p : {&x, &y}) {
      if (const auto* reason = std::get_if<std::string>(p)) {
        error(a->GetLineNum(), where() + ": " + (p == &x ? "x " : "y ") + *reason);
        return {};
      }
    }
    points.push_back({std::get<double>(x), std::get<double>(y)});
    i = end;
  }
  if (points.size() < 3) {
    error(a->GetLineNum(), "<surface> polygon has " + std::to_string(points.size()) + " points, at least 3 are needed");
  }
  return points;
}

AttributeNames Reader::surface_attributes(const XMLElement& e) {
  const char* shape = e.Attribute("shape");
  const std::string_view v = shape != nullptr ? shape : "";
  if (v == "rect") return kRectAttributes;
  if (v == "ellipse") return kEllipseAttributes;
  if (v == "polygon") return kPolygonAttributes;
  return kAnySurfaceAttributes;
}

Surface Reader::read_surface(const XMLElement& e) {
  Surface s;
  const XMLAttribute* shape = attribute(e, "shape");
  Bounds bounds{0, 0, 0, 0};
  if (shape == nullptr) {
    error(e.GetLineNum(), "<surface> is missing required attribute 'shape'");
  } else if (std::string_view(shape->Value()) == "rect") {
    s.shape = SurfaceShape::rect;
    s.x_mm = number(e, ParameterOwner::surface, "x");
    s.y_mm = number(e, ParameterOwner::surface, "y");
    s.width_mm = number(e, ParameterOwner::surface, "width");
    s.height_mm = number(e, ParameterOwner::surface, "height");
    bounds = {s.x_mm, s.y_mm, s.x_mm + s.width_mm, s.y_mm + s.height_mm};
  } else if (std::string_view(shape->Value()) == "ellipse") {
    s.shape = SurfaceShape::ellipse;
    s.cx_mm = number(e, ParameterOwner::surface, "cx");
    s.cy_mm = number(e, ParameterOwner::surface, "cy");
    s.rx_mm = number(e, ParameterOwner::surface, "rx");
    s.ry_mm = number(e, ParameterOwner::surface, "ry");
    bounds = {s.cx_mm - s.rx_mm, s.cy_mm - s.ry_mm, s.cx_mm + s.rx_mm, s.cy_mm + s.ry_mm};
  } else if (std::string_view(shape->Value()) == "polygon") {
    s.shape = SurfaceShape::polygon;
    s.points = read_points(e);
    if (!s.points.empty()) {
      bounds = {s.points[0].x_mm, s.points[0].y_mm, s.points[0].x_mm, s.points[0].y_mm};
      for (const auto& p : s.points) {
        bounds = {std::min(bounds.min_x, p.x_mm), std::min(bounds.min_y, p.y_mm), std::max(bounds.max_x, p.x_mm),
                  std::max(bounds.max_y, p.y_mm)};
      }
    }
  } else {
    error(shape->GetLineNum(), "<surface> attribute 'shape' = \"" + q(shape->Value()) + "\" must be rect, ellipse or polygon");
  }
  s.period_mm = number(e, ParameterOwner::surface, "period");
  s.relief_mm = number(e, ParameterOwner::surface, "relief");
  s.pattern = read_pattern(e);
  s.gain = number(e, ParameterOwner::surface, "gain");
  if (shape != nullptr) warn_if_outside(e, bounds);
  return s;
}

SurfacePattern Reader::read_pattern(const XMLElement& e) {
  const XMLAttribute* a = attribute(e, "pattern");
  if (a == nullptr) return Surface{}.pattern;
  const std::string_view v = a->Value();
  if (v == "sine") return SurfacePattern::sine;
  if (v == "square") return SurfacePattern::square;
  if (v == "triangle") return SurfacePattern::triangle;
  readable_error(a->GetLineNum(), "<surface> attribute 'pattern' = \"" + q(v) + "\" must be sine, square or triangle");
  return Surface{}.pattern;
}

Group Reader::read_group(const XMLElement& e, int depth) {
  Group g;
  if (const XMLAttribute* name = attribute(e, "name")) g.name = std::string(name->Value());
  for (const XMLNode* node = e.FirstChild(); node != nullptr; node = node->NextSibling()) {
    if (const XMLElement* c = node->ToElement()) {
      if (auto child = read_element(*c, depth, g.children.size())) g.children.push_back(std::move(*child));
    } else {
      note_text(*node, e);
    }
  }
  return g;
}

}  // namespace vimg::xml_reader_detail
