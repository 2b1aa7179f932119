// import_svg: an SVG document to a vibroimage (docs/import.md, "SVG"). The document walk: the root's
// size and units, groups, transforms, inherited styles, and a warning for everything not imported.
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "storage/import/import.hpp"
#include "storage/import/svg_attributes.hpp"
#include "storage/import/svg_ids.hpp"
#include "storage/import/svg_path.hpp"
#include "storage/import/svg_shapes.hpp"
#include "storage/import/svg_transform.hpp"
#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/xml_limits.hpp"
#include "storage/xml_parse_problem.hpp"

namespace vimg {

namespace {

using svg::Affine;
using svg::Style;
using tinyxml2::XMLElement;

// Elements a renderer draws that have no vibroimage counterpart, and what is lost with them.
constexpr std::pair<std::string_view, std::string_view> kUnsupported[] = {
    {"text", "is not imported: convert text to paths first"},
    {"image", "is not imported: import the picture itself with vimg import"},
    {"use", "is not imported: unlink clones first"},
    {"switch", "is not imported"},
    {"foreignObject", "is not imported"},
    {"style", "is not applied: CSS style sheets are not supported (style attributes are)"},
    {"svg", "is not imported: nested viewports are not supported"},
    {"linearGradient", "is not imported: gradients are not supported"},
    {"radialGradient", "is not imported: gradients are not supported"},
    {"pattern", "is not imported: patterns are not supported"},
    {"filter", "is not imported: filters are not supported"},
    {"clipPath", "is not imported: clip paths are not supported"},
    {"mask", "is not imported: masks are not supported"},
    {"marker", "is not imported: markers are not supported"},
    {"symbol", "is not imported: symbols are drawn only through <use>, which is not supported"},
};

// Not drawn by SVG renderers and without tactile meaning: skipped without a message.
constexpr std::string_view kNotDrawn[] = {"metadata", "title", "desc"};

std::string_view local_name(std::string_view name) {
  if (name.substr(0, 4) == "svg:") name.remove_prefix(4);
  return name;
}

double attr_number(const XMLElement& e, const char* name, double fallback, bool& bad) {
  const char* text = e.Attribute(name);
  if (text == nullptr) return fallback;
  const std::optional<svg::Length> l = svg::parse_length(text);
  const std::optional<double> v = l ? svg::length_user(*l) : std::nullopt;
  if (!v) {
    bad = true;
    return fallback;
  }
  return *v;
}

class SvgImporter {
 public:
  SvgImporter(const std::string& file, const ImportOptions& options)
      : diagnostics_(file, DiagnosticList::Order::by_line), options_(options) {}

  ImportResult run(std::string_view text) {
    if (const auto over = check_xml_limits(text)) {
      diagnostics_.error(over->line, over->message);
      return finish();
    }
    tinyxml2::XMLDocument doc(true, tinyxml2::COLLAPSE_WHITESPACE);
    doc.Parse(text.data(), text.size());
    if (doc.Error()) {
      diagnostics_.error(doc.ErrorLineNum(), xml_parse_problem(doc.ErrorID()));
      return finish();
    }
    const XMLElement* root = doc.RootElement();
    if (root == nullptr || local_name(root->Name()) != "svg") {
      diagnostics_.error(root ? root->GetLineNum() : 1, "the root element is not <svg>, so this is not an SVG drawing");
      return finish();
    }
    Affine root_map;
    if (!canvas(*root, root_map)) return finish();
    for (const XMLElement* e = root->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      if (local_name(e->Name()) == "title" && e->GetText() != nullptr) title_elements_ = 2;
    }
    Style style;
    walk(*root, root_map, cascade(*root, style), 0, image_.children);
    return finish();
  }

 private:
  void warn(const XMLElement& e, const std::string& message) {
    diagnostics_.warning(e.GetLineNum(), "<" + std::string(local_name(e.Name())) + "> " + message);
  }

  // Canvas size (mm) and the map from root user units to mm.
  bool canvas(const XMLElement& root, Affine& map) {
    const int line = root.GetLineNum();
    std::optional<svg::ViewBox> box;
    if (const char* vb = root.Attribute("viewBox")) {
      box = svg::parse_view_box(vb);
      if (!box || !(box->width > 0.0) || !(box->height > 0.0)) {
        diagnostics_.warning(line, std::string("viewBox '") + escape_input(vb) + "' is not 4 numbers with a positive size; ignored");
        box.reset();
      }
    }
    const auto side = [&](const char* name) -> std::optional<svg::Length> {
      const char* t = root.Attribute(name);
      if (t == nullptr) return std::nullopt;
      std::optional<svg::Length> l = svg::parse_length(t);
      if (!l || l->unit == svg::Length::Unit::percent || l->unit == svg::Length::Unit::em ||
          l->unit == svg::Length::Unit::ex || !(l->value > 0.0)) {
        diagnostics_.warning(line, std::string(name) + " '" + escape_input(t) + "' is not an absolute length; ignored");
        return std::nullopt;
      }
      return l;
    };
    const std::optional<svg::Length> w = side("width"), h = side("height");
    double width_mm = 0.0, height_mm = 0.0;
    if (options_.mm_per_unit) {
      const double k = *options_.mm_per_unit;
      const double wu = box ? box->width : (w ? w->value : 0.0), hu = box ? box->height : (h ? h->value : 0.0);
      width_mm = wu * k;
      height_mm = hu * k;
      map = Affine{k, 0, 0, k, box ? -box->x * k : 0.0, box ? -box->y * k : 0.0};
    } else {
      const double px_mm = svg::kMmPerInch / svg::kPxPerInch;
      width_mm = w ? *svg::length_mm(*w) : (box ? box->width * px_mm : 0.0);
      height_mm = h ? *svg::length_mm(*h) : (box ? box->height * px_mm : 0.0);
      if (box) {
        const char* par = root.Attribute("preserveAspectRatio");
        std::optional<Affine> fit = svg::view_box_transform(*box, width_mm, height_mm, par ? par : "");
        if (!fit) {
          diagnostics_.warning(line, std::string("preserveAspectRatio '") + escape_input(par) + "' does not parse; xMidYMid meet is used");
          fit = svg::view_box_transform(*box, width_mm, height_mm, "");
        }
        map = *fit;
      } else {
        map = Affine{px_mm, 0, 0, px_mm, 0, 0};
      }
    }
    if (!(width_mm > 0.0) || !(height_mm > 0.0)) {
      diagnostics_.error(line, "the drawing has no size: give <svg> width and height or a viewBox, or use --mm-per-unit with a viewBox");
      return false;
    }
    if (width_mm > kMaxCanvasMm || height_mm > kMaxCanvasMm || !std::isfinite(width_mm) || !std::isfinite(height_mm)) {
      const auto mm = [](double v) { return std::isfinite(v) ? format_decimal(v) : std::string("infinite"); };
      diagnostics_.error(line, "the drawing is " + mm(width_mm) + " x " + mm(height_mm) +
                                   " mm, larger than a canvas may be (limit " + mm(kMaxCanvasMm) + " mm)");
      return false;
    }
    image_.width_mm = width_mm;
    image_.height_mm = height_mm;
    return true;
  }

  Style cascade(const XMLElement& e, const Style& parent) {
    static constexpr const char* kProperties[] = {"fill",         "stroke",           "stroke-width", "fill-rule",
                                                  "display",      "visibility",       "fill-opacity", "stroke-opacity",
                                                  "opacity",      "stroke-dasharray", "clip-path",    "mask",
                                                  "filter",       "marker-start",     "marker-mid",   "marker-end"};
    std::vector<std::pair<std::string, std::string>> presentation;
    for (const char* name : kProperties) {
      if (const char* v = e.Attribute(name)) presentation.emplace_back(name, v);
    }
    const char* style_attribute = e.Attribute("style");
    const svg::DeclaredProperties declared = svg::declared_properties(presentation, style_attribute ? style_attribute : "");
    std::vector<std::string> problems;
    Style s = svg::cascade(parent, declared, problems);
    for (const std::string& p : problems) warn(e, escape_input(p, kMaxMessageBytes / 2));
    for (const char* name : {"clip-path", "mask", "filter", "marker-start", "marker-mid", "marker-end"}) {
      const std::optional<std::string> v = declared.get(name);
      if (v && *v != "none") warn(e, std::string(name) + " is not applied (the shape is imported without it)");
    }
    return s;
  }

  // Elements the image will hold, counted as each shape gives them: primitives and groups, and the
  // <meta> and <title> a drawing's title becomes, within kMaxImportPrimitives (storage/limits.hpp).
  std::size_t primitive_budget() const { return kMaxImportPrimitives - title_elements_; }
  bool take_budget(const XMLElement& e, std::size_t count) {
    primitives_ += count;
    if (primitives_ > primitive_budget()) {
      const std::string limit = std::to_string(primitive_budget());
      diagnostics_.error(e.GetLineNum(), "the drawing gives more than " + limit + " primitives and groups (limit " + limit + ")");
      return false;
    }
    return true;
  }

  void walk(const XMLElement& parent, const Affine& ctm, const Style& style, int depth, std::vector<Element>& out) {
    for (const XMLElement* e = parent.FirstChildElement(); e != nullptr && !diagnostics_.has_errors();
         e = e->NextSiblingElement()) {
      const std::string_view name = local_name(e->Name());
      if (name.find(':') != std::string_view::npos) continue;  // another namespace: editor data (inkscape, sodipodi)
      if (depth == 0 && name == "title" && e->GetText() != nullptr) {
        if (!image_.meta) image_.meta.emplace();
        image_.meta->title = e->GetText();
      }
      if (std::find(std::begin(kNotDrawn), std::end(kNotDrawn), name) != std::end(kNotDrawn)) continue;
      element(*e, name, ctm, style, depth, out);
    }
  }

  void element(const XMLElement& e, std::string_view name, const Affine& parent_ctm, const Style& parent_style,
               int depth, std::vector<Element>& out) {
    if (name == "defs") {
      for (const XMLElement* d = e.FirstChildElement(); d != nullptr; d = d->NextSiblingElement()) {
        if (std::string_view(d->Name()).find(':') == std::string_view::npos) {
          warn(*d, "in <defs> is not imported (only shapes drawn in the document are)");
        }
      }
      return;
    }
    for (const auto& [unsupported, why] : kUnsupported) {
      if (name == unsupported) return warn(e, std::string(why));
    }
    const Style style = cascade(e, parent_style);
    if (!style.displayed) return;  // display:none draws nothing, in SVG as here
    Affine ctm = parent_ctm;
    if (const char* t = e.Attribute("transform")) {
      const svg::TransformParse parsed = svg::parse_transform(t);
      if (!parsed.error.empty()) return warn(e, "transform '" + escape_input(t) + "': " + parsed.error + "; not imported");
      ctm = parent_ctm * parsed.transform;
    }
    if (name == "g" || name == "a") return group(e, ctm, style, depth, out);
    svg::ShapeGeometry g;
    if (!geometry(e, name, g)) return;
    if (!style.visible) return;  // visibility:hidden draws nothing
    if (style.fill && style.fill_is_server && !g.lines_only) warn(e, "fill is a gradient or pattern: imported as a plain surface");
    if (style.stroke && style.dashed) warn(e, "stroke-dasharray is not imported: the stroke becomes a solid line");
    svg::ShapeSettings settings{ctm, style, options_.tolerance_mm, options_.dot_max_radius_mm, kMaxPolygonPoints};
    settings.points_left = kMaxImportPoints - points_;
    settings.outline_tests_left = kMaxImportOutlineTests - outline_tests_;
    settings.primitives_left = primitive_budget() - std::min(primitive_budget(), primitives_);
    svg::ShapeOutput shape = svg::convert_shape(g, settings);
    points_ += shape.points;
    outline_tests_ += shape.outline_tests;
    for (const std::string& w : shape.warnings) warn(e, w);
    if (!shape.error.empty()) return diagnostics_.error(e.GetLineNum(), shape.error);
    // One primitive stands alone; several go into a group, which is an element too.
    const std::size_t elements = shape.over_primitives ? settings.primitives_left + 1
                                                       : shape.primitives.size() + (shape.primitives.size() > 1 ? 1 : 0);
    if (elements == 0 || !take_budget(e, elements)) return;
    for (Element& p : shape.primitives) p.source_line = e.GetLineNum();
    if (shape.primitives.size() == 1) {
      shape.primitives.front().id = ids_.take(e.Attribute("id"));
      out.push_back(std::move(shape.primitives.front()));
      return;
    }
    Element wrapper;
    wrapper.id = ids_.take(e.Attribute("id"));
    wrapper.source_line = e.GetLineNum();
    Group chain;
    if (const char* id = e.Attribute("id")) chain.name = id;
    chain.children = std::move(shape.primitives);
    wrapper.body = std::move(chain);
    if (depth + 1 > kMaxGroupDepth) return group_too_deep(e);
    out.push_back(std::move(wrapper));
  }

  void group_too_deep(const XMLElement& e) {
    diagnostics_.error(e.GetLineNum(), "groups nest deeper than " + std::to_string(kMaxGroupDepth) + " levels (limit " +
                                           std::to_string(kMaxGroupDepth) + ")");
  }

  void group(const XMLElement& e, const Affine& ctm, const Style& style, int depth, std::vector<Element>& out) {
    if (depth + 1 > kMaxGroupDepth) return group_too_deep(e);
    const char* id = e.Attribute("id");
    std::string unique = ids_.take(id);  // before the children's: the first in document order keeps an id
    Group g;
    walk(e, ctm, style, depth + 1, g.children);
    if (g.children.empty()) return ids_.release(unique);  // an empty group (e.g. an unused layer) has nothing to feel
    if (!take_budget(e, 1)) return;
    const char* label = e.Attribute("inkscape:label");
    if (label != nullptr) {
      g.name = label;
    } else if (id != nullptr) {
      g.name = id;
    }
    Element element;
    element.id = std::move(unique);
    element.source_line = e.GetLineNum();
    element.body = std::move(g);
    out.push_back(std::move(element));
  }

  bool geometry(const XMLElement& e, std::string_view name, svg::ShapeGeometry& g) {
    bool bad = false;
    const auto n = [&](const char* attribute, double fallback = 0.0) { return attr_number(e, attribute, fallback, bad); };
    if (name == "path") {
      const char* d = e.Attribute("d");
      svg::PathParse parsed = svg::parse_path_data(d ? d : "", kMaxPolygonPoints);
      if (!parsed.error.empty()) {
        warn(e, "path data: " + parsed.error + " at byte " + std::to_string(parsed.error_offset + 1) +
                    "; drawn up to there, as SVG renderers do");
      }
      g.subpaths = std::move(parsed.subpaths);
    } else if (name == "rect") {
      g.native = svg::ShapeGeometry::Native::rect;
      g.x = n("x"), g.y = n("y"), g.width = n("width"), g.height = n("height");
      double rx = n("rx", -1.0), ry = n("ry", -1.0);
      if (rx < 0.0) rx = ry;
      if (ry < 0.0) ry = rx;
      rx = std::min(std::max(rx, 0.0), g.width / 2.0);
      ry = std::min(std::max(ry, 0.0), g.height / 2.0);
      if (rx > 0.0 && ry > 0.0) g.native = svg::ShapeGeometry::Native::none;  // rounded: a polygon
      if (!(g.width > 0.0) || !(g.height > 0.0)) return zero_size(e);
      g.subpaths = svg::rect_outline(g.x, g.y, g.width, g.height, rx, ry);
    } else if (name == "circle" || name == "ellipse") {
      g.native = svg::ShapeGeometry::Native::ellipse;
      g.cx = n("cx"), g.cy = n("cy");
      g.rx = name == "circle" ? n("r") : n("rx");
      g.ry = name == "circle" ? g.rx : n("ry");
      if (!(g.rx > 0.0) || !(g.ry > 0.0)) return zero_size(e);
      g.subpaths = svg::ellipse_outline(g.cx, g.cy, g.rx, g.ry);
    } else if (name == "line") {
      g.lines_only = true;
      g.subpaths.push_back({{n("x1"), n("y1")}, {{svg::PathSegment::Kind::line, {}, {}, {n("x2"), n("y2")}}}, false});
    } else if (name == "polyline" || name == "polygon") {
      g.lines_only = name == "polyline";
      const char* points = e.Attribute("points");
      std::string_view text = points ? points : "";
      std::size_t pos = 0;
      svg::Subpath sp;
      double x = 0, y = 0;
      std::size_t count = 0;
      while (svg::scan_number(text, pos, x, count > 0) && svg::scan_number(text, pos, y, true)) {
        if (++count > kMaxPolygonPoints) {
          diagnostics_.error(e.GetLineNum(), "more than " + std::to_string(kMaxPolygonPoints) + " points (limit " +
                                                 std::to_string(kMaxPolygonPoints) + ")");
          return false;
        }
        if (count == 1) {
          sp.start = {x, y};
        } else {
          sp.segments.push_back({svg::PathSegment::Kind::line, {}, {}, {x, y}});
        }
      }
      svg::skip_comma_wsp(text, pos);
      if (pos < text.size()) warn(e, "points: not a list of coordinate pairs from byte " + std::to_string(pos + 1) + "; read up to there");
      sp.closed = name == "polygon";
      if (sp.segments.empty()) return zero_size(e);
      g.subpaths.push_back(std::move(sp));
    } else {
      warn(e, "is not an SVG shape this importer knows: not imported");
      return false;
    }
    if (bad) {
      warn(e, "has a coordinate that is not a length in absolute units: not imported");
      return false;
    }
    return true;
  }

  bool zero_size(const XMLElement& e) {
    warn(e, "has no area or length (it draws nothing): not imported");
    return false;
  }

  ImportResult finish() {
    ImportResult result;
    const bool failed = diagnostics_.has_errors();
    result.diagnostics = diagnostics_.take();
    if (!failed) result.image = std::move(image_);
    return result;
  }

  DiagnosticList diagnostics_;
  const ImportOptions& options_;
  Image image_;
  svg::UniqueIds ids_;
  std::size_t title_elements_ = 0;  // 2 when the drawing has a title: <meta> and its <title>
  // So far: points flattened, outline tests, primitives (kMaxImportPoints, ...OutlineTests, ...Primitives).
  std::size_t points_ = 0, outline_tests_ = 0, primitives_ = 0;
};

}  // namespace

ImportResult import_svg(std::string_view svg_text, const std::string& file_name, const ImportOptions& options) {
  SvgImporter importer(file_name, options);
  try {
    ImportResult result = importer.run(svg_text);
    check_imported_image(result, file_name);
    return result;
  } catch (const std::bad_alloc&) {
    return import_failure(file_name, "out of memory importing the drawing");
  }
}

}  // namespace vimg
