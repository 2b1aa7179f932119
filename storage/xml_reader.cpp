// parse_image_xml: the XML image format v1 (spec section 1) read into the document model.
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <array>
#include <functional>
#include <span>
#include <vector>
#include <utility>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/parameter_table.hpp"
#include "storage/xml_limits.hpp"

namespace vimg {

namespace {

using tinyxml2::XMLAttribute;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

bool is_valid_id(std::string_view id) {
  if (id.empty()) return false;
  const auto alpha = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (!alpha(id.front())) return false;
  return std::all_of(id.begin() + 1, id.end(),
                     [&](char c) { return alpha(c) || digit(c) || c == '.' || c == '-'; });
}

std::string print_verbatim(const XMLElement& element) {
  tinyxml2::XMLPrinter printer(nullptr, /*compact=*/true);
  element.Accept(&printer);
  return std::string(printer.CStr());
}

// Axis-aligned bounds of a primitive, for the "wholly outside the canvas" warning.
struct Bounds {
  double min_x, min_y, max_x, max_y;
};

// The attributes each element knows, in the order of its slots.
using AttributeNames = std::span<const std::string_view>;
constexpr std::string_view kRootAttributes[] = {"version", "width", "height"};
constexpr std::string_view kInteractionAttributes[] = {"mass", "fullSpeed", "maxDeformation"};
constexpr std::string_view kToolAttributes[] = {"name", "version"};
constexpr std::string_view kDotAttributes[] = {"id", "x", "y", "radius", "gain"};
constexpr std::string_view kLineAttributes[] = {"id", "x1", "y1", "x2", "y2", "width", "frequency", "damping", "gain"};
constexpr std::string_view kRectAttributes[] = {"id", "shape", "x", "y", "width", "height", "period", "relief", "pattern", "gain"};
constexpr std::string_view kEllipseAttributes[] = {"id", "shape", "cx", "cy", "rx", "ry", "period", "relief", "pattern", "gain"};
constexpr std::string_view kPolygonAttributes[] = {"id", "shape", "points", "period", "relief", "pattern", "gain"};
// A surface whose shape is missing or unknown: every geometry attribute is known.
constexpr std::string_view kAnySurfaceAttributes[] = {"id", "shape", "x", "y", "width", "height", "cx", "cy", "rx", "ry",
                                                      "points", "period", "relief", "pattern", "gain"};
constexpr std::string_view kGroupAttributes[] = {"id", "name"};
constexpr std::size_t kMaxSlots = 16;

class Reader {
 public:
  explicit Reader(const std::string& file_name) : list_(file_name, DiagnosticList::Order::by_line) {}

  LoadResult run(std::string_view xml) {
    LoadResult result;
    if (xml.size() > kMaxImageFileBytes) {
      error(0, "file is larger than " + std::to_string(kMaxImageFileBytes / kMiB) + " MiB (limit " +
                   std::to_string(kMaxImageFileBytes) + ")");
      result.diagnostics = list_.take();
      return result;
    }
    if (const auto over = check_xml_limits(xml)) {
      error(over->line, over->message);
      result.diagnostics = list_.take();
      return result;
    }
    tinyxml2::XMLDocument doc(true, tinyxml2::PRESERVE_WHITESPACE);
    doc.Parse(xml.data(), xml.size());
    if (doc.ErrorID() == tinyxml2::XML_ERROR_EMPTY_DOCUMENT) {
      error(0, "the file is empty, expected a <vibroimage> document");
    } else if (doc.Error()) {
      error(doc.ErrorLineNum(), std::string("not well-formed XML (") +
                                    tinyxml2::XMLDocument::ErrorIDToName(doc.ErrorID()) + ")");
    } else {
      const XMLElement* root = doc.RootElement();
      if (root == nullptr) {
        error(1, "no root element, expected <vibroimage>");
      } else if (std::string_view(root->Name()) != "vibroimage") {
        error(root->GetLineNum(), "root element is " + tag(*root) + ", expected <vibroimage>");
      } else if (const XMLElement* extra = root->NextSiblingElement()) {
        error(extra->GetLineNum(), "second root element " + tag(*extra) + " after <vibroimage>");
      } else {
        Image image;
        read_root(*root, image);
        check_duplicate_ids();
        if (!failed()) {
          result.image = std::move(image);
        } else if (root_readable_) {
          result.readable = std::move(image);
          result.value_problems = std::move(value_problems_);
        }
      }
    }
    result.diagnostics = list_.take();
    return result;
  }

 private:
  // An error that leaves the element unreadable (it is not in LoadResult::readable).
  void error(int line, std::string_view message) {
    ++hard_errors_;
    list_.error(line, message);
  }
  // An error that leaves the element readable: a value out of range, an id.
  void readable_error(int line, std::string_view message) { list_.error(line, message); }
  void warning(int line, std::string_view message) { list_.warning(line, message); }
  bool failed() const { return list_.has_errors(); }

  // Input in a message: escaped and cut (docs/limits.md, "Messages").
  static std::string q(std::string_view input) { return escape_input(input); }
  static std::string tag(const XMLElement& e) { return "<" + q(e.Name()) + ">"; }

  // Indexes the attributes of `e` by their place in `known` (one pass, read by attribute()).
  // Unknown attributes become warnings and are returned verbatim in order.
  ExtraAttributes gather(const XMLElement& e, AttributeNames known) {
    known_ = known;
    slots_.fill(nullptr);
    std::size_t unknown = 0;
    for (const XMLAttribute* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
      const std::size_t slot = slot_of(known, a->Name());
      if (slot < known.size()) {
        slots_[slot] = a;
      } else {
        ++unknown;
      }
    }
    // One error instead of a warning per attribute, so that the cap on messages never hides it.
    if (unknown > kMaxUnknownAttributesPerElement) {
      error(e.GetLineNum(), tag(e) + " has " + std::to_string(unknown) + " unknown attributes; at most " +
                                std::to_string(kMaxUnknownAttributesPerElement) +
                                " are kept, so that the file written back stays within " +
                                std::to_string(kMaxAttributesPerElement) + " attributes per element (limit " +
                                std::to_string(kMaxUnknownAttributesPerElement) + ")");
      return {};
    }
    ExtraAttributes extras;
    for (const XMLAttribute* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
      const std::string_view name = a->Name();
      if (slot_of(known, name) < known.size()) continue;
      if (list_.keeps(a->GetLineNum())) {
        warning(a->GetLineNum(), "unknown attribute '" + q(name) + "' on " + tag(e) + " kept as is");
      } else {
        list_.count(Diagnostic::Severity::warning);
      }
      extras.emplace_back(a->Name(), a->Value());
    }
    return extras;
  }

  // The place of `name` in `names`, or names.size(). Attribute names are short and mostly differ in
  // length or first letter, which are compared first.
  static std::size_t slot_of(AttributeNames names, std::string_view name) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::string_view k = names[i];
      if (k.size() == name.size() && !name.empty() && k[0] == name[0] && k == name) return i;
    }
    return names.size();
  }

  // An attribute of the element last gathered.
  const XMLAttribute* attribute(const XMLElement& e, std::string_view name) const {
    const std::size_t slot = slot_of(known_, name);
    if (slot == known_.size()) return e.FindAttribute(std::string(name).c_str());
    return slots_[slot];
  }

  // Reads the number attribute `name` of `owner` (storage/parameter_table.hpp): its default when
  // it is absent (absent and required is an error), the value as read when it is out of range.
  double number(const XMLElement& e, ParameterOwner owner, std::string_view name) {
    const ParameterSpec& spec = *find_parameter(owner, name);
    const double fallback = spec.required ? 0.0 : spec.default_value;
    const XMLAttribute* a = attribute(e, name);
    if (a == nullptr) {
      if (spec.required) error(e.GetLineNum(), tag(e) + " is missing required attribute '" + std::string(name) + "'");
      return fallback;
    }
    const ParsedNumber parsed = parse_decimal(a->Value());
    if (const auto* reason = std::get_if<std::string>(&parsed)) {
      error(a->GetLineNum(), tag(e) + " attribute '" + std::string(name) + "' = \"" + q(a->Value()) + "\" " + *reason);
      return fallback;
    }
    const double value = std::get<double>(parsed);
    if (!in_range(spec, value)) {
      readable_error(a->GetLineNum(), out_of_range_message(spec, q(a->Value())));
      value_problems_.push_back({a->GetLineNum(), path_, &spec, value});
    }
    return value;
  }

  void read_id(const XMLElement& e, Element& element) {
    const XMLAttribute* a = attribute(e, "id");
    if (a == nullptr) return;
    element.id = a->Value();
    if (!is_valid_id(element.id)) {
      readable_error(a->GetLineNum(), tag(e) + " id \"" + q(element.id) + "\" must match [A-Za-z_][A-Za-z0-9_.-]*");
      element.id.clear();
      return;
    }
    ids_.emplace_back(std::string_view(a->Value()), a->GetLineNum());
  }

  // Every id used twice or more is an error at each later use, naming the first. Sorting hashes
  // (with the document position) keeps this fast for 100 000 ids.
  void check_duplicate_ids() {
    std::vector<std::pair<std::size_t, std::size_t>> keys;  // hash, index in ids_
    keys.reserve(ids_.size());
    for (std::size_t i = 0; i < ids_.size(); ++i) keys.emplace_back(std::hash<std::string_view>{}(ids_[i].first), i);
    std::sort(keys.begin(), keys.end());
    for (std::size_t run = 0; run < keys.size();) {
      std::size_t end = run + 1;
      while (end < keys.size() && keys[end].first == keys[run].first) ++end;
      for (std::size_t j = run + 1; j < end; ++j) {
        const auto& later = ids_[keys[j].second];
        for (std::size_t k = run; k < j; ++k) {
          const auto& first = ids_[keys[k].second];
          if (first.first != later.first) continue;  // a hash collision, not a duplicate
          readable_error(later.second, "duplicate id '" + q(later.first) + "' (first used on line " +
                                  std::to_string(first.second) + ")");
          break;
        }
      }
      run = end;
    }
  }

  void read_root(const XMLElement& root, Image& image) {
    image.extra_attributes = gather(root, kRootAttributes);
    read_version(root, image);
    image.width_mm = number(root, ParameterOwner::canvas, "width");
    image.height_mm = number(root, ParameterOwner::canvas, "height");
    root_readable_ = hard_errors_ == 0;
    canvas_w_ = image.width_mm;
    canvas_h_ = image.height_mm;
    int meta_line = 0;
    int interaction_line = 0;
    for (const XMLNode* node = root.FirstChild(); node != nullptr; node = node->NextSibling()) {
      const XMLElement* child = node->ToElement();
      if (child == nullptr) {
        note_text(*node, root);
        continue;
      }
      const std::string_view name = child->Name();
      if (name == "meta") {
        if (meta_line != 0) {
          error(child->GetLineNum(), "second <meta> (the first is on line " + std::to_string(meta_line) + ")");
          continue;
        }
        meta_line = child->GetLineNum();
        image.meta = read_meta(*child);
      } else if (name == "interaction") {
        if (interaction_line != 0) {
          error(child->GetLineNum(),
                "second <interaction> (the first is on line " + std::to_string(interaction_line) + ")");
          continue;
        }
        interaction_line = child->GetLineNum();
        image.interaction = read_interaction(*child);
      } else if (auto element = read_element(*child, 0, image.children.size())) {
        image.children.push_back(std::move(*element));
      }
    }
  }

  void read_version(const XMLElement& root, Image& image) {
    const XMLAttribute* a = attribute(root, "version");
    if (a == nullptr) {
      error(root.GetLineNum(), "<vibroimage> is missing required attribute 'version'");
      return;
    }
    const std::string_view text = a->Value();
    const auto dot = text.find('.');
    const auto digits = [](std::string_view s) {
      return !s.empty() && s.size() <= 6 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (dot == std::string_view::npos || !digits(text.substr(0, dot)) || !digits(text.substr(dot + 1))) {
      error(a->GetLineNum(), "<vibroimage> attribute 'version' = \"" + q(text) + "\" is not MAJOR.MINOR");
      return;
    }
    image.version_major = std::stoi(std::string(text.substr(0, dot)));
    image.version_minor = std::stoi(std::string(text.substr(dot + 1)));
    if (image.version_major != kFormatMajor) {
      error(a->GetLineNum(), "file format version " + std::string(text) + " is not supported: this reader reads version " +
                                 std::to_string(kFormatMajor) + "." + std::to_string(kFormatMinor) +
                                 (image.version_major > kFormatMajor ? " (the file is newer)" : ""));
    }
  }

  void note_text(const XMLNode& node, const XMLElement& parent) {
    if (node.ToText() != nullptr) {
      warning(node.GetLineNum(), "text inside " + tag(parent) + " is ignored");
    }
  }

  static std::string text_of(const XMLElement& e) {
    std::string text;
    for (const XMLNode* n = e.FirstChild(); n != nullptr; n = n->NextSibling()) {
      if (const auto* t = n->ToText()) text += t->Value();
    }
    return text;
  }

  void read_meta_text(const XMLElement& e, std::optional<std::string>& field) {
    if (field) {
      error(e.GetLineNum(), "second " + tag(e) + " in <meta>");
      return;
    }
    collect_ignored_attributes(e);
    for (const XMLElement* c = e.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
      warning(c->GetLineNum(), "element " + tag(*c) + " inside " + tag(e) + " is ignored");
    }
    field = text_of(e);
  }

  void collect_ignored_attributes(const XMLElement& e) {
    for (const XMLAttribute* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
      warning(a->GetLineNum(), "unknown attribute '" + q(a->Name()) + "' on " + tag(e) + " is ignored");
    }
  }

  static bool is_iso8601(std::string_view s) {
    // YYYY-MM-DD, optionally followed by THH:MM[:SS[.fraction]][Z|+HH:MM|-HH:MM].
    size_t i = 0;
    const auto digits = [&](size_t n) {
      for (size_t k = 0; k < n; ++k, ++i) {
        if (i >= s.size() || s[i] < '0' || s[i] > '9') return false;
      }
      return true;
    };
    const auto lit = [&](char c) {
      if (i < s.size() && s[i] == c) {
        ++i;
        return true;
      }
      return false;
    };
    if (!(digits(4) && lit('-') && digits(2) && lit('-') && digits(2))) return false;
    if (i == s.size()) return true;
    if (!(lit('T') && digits(2) && lit(':') && digits(2))) return false;
    if (lit(':')) {
      if (!digits(2)) return false;
      if (lit('.')) {
        if (!digits(1)) return false;
        while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
      }
    }
    if (i == s.size() || lit('Z')) return i == s.size();
    if (lit('+') || lit('-')) return digits(2) && lit(':') && digits(2) && i == s.size();
    return false;
  }

  Meta read_meta(const XMLElement& e) {
    Meta meta;
    meta.extra_attributes = gather(e, {});
    for (const XMLNode* node = e.FirstChild(); node != nullptr; node = node->NextSibling()) {
      const XMLElement* c = node->ToElement();
      if (c == nullptr) {
        note_text(*node, e);
        continue;
      }
      const std::string_view name = c->Name();
      if (name == "title") {
        read_meta_text(*c, meta.title);
      } else if (name == "author") {
        read_meta_text(*c, meta.author);
      } else if (name == "description") {
        read_meta_text(*c, meta.description);
      } else if (name == "created") {
        read_meta_text(*c, meta.created);
        if (meta.created && !is_iso8601(*meta.created)) {
          error(c->GetLineNum(), "<created> \"" + q(*meta.created) + "\" is not an ISO 8601 date (YYYY-MM-DD[THH:MM[:SS]][Z])");
        }
      } else if (name == "tag") {
        std::optional<std::string> tag_text;
        read_meta_text(*c, tag_text);
        meta.tags.push_back(tag_text.value_or(""));
      } else if (name == "tool") {
        if (meta.tool) {
          error(c->GetLineNum(), "second <tool> in <meta>");
          continue;
        }
        ToolInfo tool;
        const char* tool_name = c->Attribute("name");
        const char* tool_version = c->Attribute("version");
        if (tool_name == nullptr) error(c->GetLineNum(), "<tool> is missing required attribute 'name'");
        if (tool_version == nullptr) error(c->GetLineNum(), "<tool> is missing required attribute 'version'");
        tool.name = tool_name ? tool_name : "";
        tool.version = tool_version ? tool_version : "";
        tool.extra_attributes = gather(*c, kToolAttributes);
        meta.tool = tool;
      } else {
        warning(c->GetLineNum(), "unknown element " + tag(*c) + " in <meta> kept as is");
        meta.unknown_children.push_back(UnknownElement{print_verbatim(*c)});
      }
    }
    return meta;
  }

  InteractionParams read_interaction(const XMLElement& e) {
    InteractionParams p;
    p.extra_attributes = gather(e, kInteractionAttributes);
    p.mass_kg = number(e, ParameterOwner::interaction, "mass");
    p.full_speed_mm_per_s = number(e, ParameterOwner::interaction, "fullSpeed");
    p.max_deformation_mm = number(e, ParameterOwner::interaction, "maxDeformation");
    for (const XMLNode* node = e.FirstChild(); node != nullptr; node = node->NextSibling()) {
      if (const XMLElement* c = node->ToElement()) {
        warning(c->GetLineNum(), "unknown element " + tag(*c) + " in <interaction> kept as is");
        p.unknown_children.push_back(UnknownElement{print_verbatim(*c)});
      } else {
        note_text(*node, e);
      }
    }
    return p;
  }

  // A child of <vibroimage> or <group>: a primitive, a group, or an unknown element kept verbatim;
  // nothing when it cannot be read (see LoadResult::readable). `depth` is the number of groups
  // around it, `index` its place among the children read so far.
  std::optional<Element> read_element(const XMLElement& e, int depth, std::size_t index) {
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

  std::optional<Element> read_element_body(const XMLElement& e, int depth) {
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

  void read_primitive_children(const XMLElement& e, Element& element) {
    for (const XMLNode* node = e.FirstChild(); node != nullptr; node = node->NextSibling()) {
      if (const XMLElement* c = node->ToElement()) {
        warning(c->GetLineNum(), "unknown element " + tag(*c) + " in " + tag(e) + " kept as is");
        element.unknown_children.push_back(UnknownElement{print_verbatim(*c)});
      } else {
        note_text(*node, e);
      }
    }
  }

  void warn_if_outside(const XMLElement& e, const Bounds& b) {
    if (failed()) return;
    if (b.max_x < 0.0 || b.max_y < 0.0 || b.min_x > canvas_w_ || b.min_y > canvas_h_) {
      const char* id = e.Attribute("id");
      const std::string what = id != nullptr ? "<" + q(e.Name()) + " id=\"" + q(id) + "\">" : tag(e);
      warning(e.GetLineNum(), what + " lies wholly outside the " + format_decimal(canvas_w_) + " x " +
                                  format_decimal(canvas_h_) + " mm canvas");
    }
  }

  Dot read_dot(const XMLElement& e) {
    Dot d;
    d.x_mm = number(e, ParameterOwner::dot, "x");
    d.y_mm = number(e, ParameterOwner::dot, "y");
    d.radius_mm = number(e, ParameterOwner::dot, "radius");
    d.gain = number(e, ParameterOwner::dot, "gain");
    warn_if_outside(e, {d.x_mm - d.radius_mm, d.y_mm - d.radius_mm, d.x_mm + d.radius_mm, d.y_mm + d.radius_mm});
    return d;
  }

  Line read_line(const XMLElement& e) {
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

  std::vector<Point2Mm> read_points(const XMLElement& e) {
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

  static AttributeNames surface_attributes(const XMLElement& e) {
    const char* shape = e.Attribute("shape");
    const std::string_view v = shape != nullptr ? shape : "";
    if (v == "rect") return kRectAttributes;
    if (v == "ellipse") return kEllipseAttributes;
    if (v == "polygon") return kPolygonAttributes;
    return kAnySurfaceAttributes;
  }

  Surface read_surface(const XMLElement& e) {
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

  SurfacePattern read_pattern(const XMLElement& e) {
    const XMLAttribute* a = attribute(e, "pattern");
    if (a == nullptr) return Surface{}.pattern;
    const std::string_view v = a->Value();
    if (v == "sine") return SurfacePattern::sine;
    if (v == "square") return SurfacePattern::square;
    if (v == "triangle") return SurfacePattern::triangle;
    readable_error(a->GetLineNum(), "<surface> attribute 'pattern' = \"" + q(v) + "\" must be sine, square or triangle");
    return Surface{}.pattern;
  }

  Group read_group(const XMLElement& e, int depth) {
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

  DiagnosticList list_;
  std::size_t hard_errors_ = 0;  // errors that leave an element (or the root) unreadable
  bool root_readable_ = false;   // version and canvas size read
  std::vector<std::size_t> path_;  // of the element being read (ValueProblem::path)
  std::vector<ValueProblem> value_problems_;
  std::vector<std::pair<std::string_view, int>> ids_;  // id text (owned by the document), line
  AttributeNames known_;
  std::array<const XMLAttribute*, kMaxSlots> slots_{};
  double canvas_w_ = 0.0;
  double canvas_h_ = 0.0;
};

}  // namespace

LoadResult parse_image_xml(std::string_view xml, const std::string& file_name) {
  return Reader(file_name).run(xml);
}

}  // namespace vimg
