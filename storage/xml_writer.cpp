// write_image_xml: the canonical XML text of an image (spec section 1 "Round trip", docs/format-xml.md).
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/parameter_table.hpp"
#include "storage/xml_limits.hpp"

namespace vimg {

namespace {

void append_escaped(std::string& out, std::string_view text, bool attribute) {
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += attribute ? "&quot;" : "\""; break;
      case '\n': out += attribute ? "&#10;" : "\n"; break;
      case '\t': out += attribute ? "&#9;" : "\t"; break;
      case '\r': out += "&#13;"; break;
      default: out += c;
    }
  }
}

// The number parameters of one owner, in the table's (canonical) order.
std::vector<const ParameterSpec*> number_specs_of(ParameterOwner owner) {
  std::vector<const ParameterSpec*> specs;
  for (const ParameterSpec& spec : parameter_table()) {
    if (spec.owner == owner && spec.kind == ParameterKind::number) specs.push_back(&spec);
  }
  return specs;
}

std::span<const ParameterSpec* const> number_specs(ParameterOwner owner) {
  static const std::array<std::vector<const ParameterSpec*>, 5> by_owner = {
      number_specs_of(ParameterOwner::canvas), number_specs_of(ParameterOwner::interaction),
      number_specs_of(ParameterOwner::dot), number_specs_of(ParameterOwner::line),
      number_specs_of(ParameterOwner::surface)};
  switch (owner) {
    case ParameterOwner::canvas: return by_owner[0];
    case ParameterOwner::interaction: return by_owner[1];
    case ParameterOwner::dot: return by_owner[2];
    case ParameterOwner::line: return by_owner[3];
    case ParameterOwner::surface: return by_owner[4];
    default: break;
  }
  return {};
}

class Writer {
 public:
  explicit Writer(const Image& image) : image_(image) {}

  std::string run() {
    // Room for the whole text at once: growing an 18 MB string by doubling copies it and touches
    // twice its pages, which cost more than writing it (docs/benchmarks/storage.md). Untouched room costs
    // nothing (the allocator maps large blocks lazily).
    out_.reserve(4096 + size_estimate(image_.children));
    out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<vibroimage";
    attr("version", std::to_string(image_.version_major) + "." + std::to_string(image_.version_minor));
    numbers(ParameterOwner::canvas, [&](const ParameterSpec& spec) { return number_in(image_, spec); });
    extras(image_.extra_attributes);
    out_ += ">\n";
    if (image_.meta) write_meta(*image_.meta);
    if (image_.interaction) {
      const InteractionParams& p = *image_.interaction;
      indent(1);
      out_ += "<interaction";
      numbers(ParameterOwner::interaction, [&](const ParameterSpec& spec) { return number_in(image_, spec); });
      extras(p.extra_attributes);
      if (p.unknown_children.empty()) {
        out_ += "/>\n";
      } else {
        out_ += ">\n";
        for (const auto& u : p.unknown_children) unknown(2, u);
        indent(1);
        out_ += "</interaction>\n";
      }
    }
    for (const Element& e : image_.children) write_element(e, 1);
    out_ += "</vibroimage>\n";
    return std::move(out_);
  }

 private:
  // An upper estimate of the text of `elements` (numbers at most 24 characters each).
  static std::size_t size_estimate(const std::vector<Element>& elements) {
    std::size_t bytes = 0;
    for (const Element& e : elements) {
      bytes += 768 + e.id.size();
      for (const auto& [name, value] : e.extra_attributes) bytes += name.size() + 6 * value.size() + 4;
      for (const UnknownElement& u : e.unknown_children) bytes += u.xml.size() + 64;
      if (const auto* s = std::get_if<Surface>(&e.body)) bytes += 50 * s->points.size();
      if (const auto* g = std::get_if<Group>(&e.body)) bytes += size_estimate(g->children) + (g->name ? 6 * g->name->size() : 0);
      if (const auto* u = std::get_if<UnknownElement>(&e.body)) bytes += u->xml.size();
    }
    return bytes;
  }

  void collect_ids(const std::vector<Element>& elements) {
    for (const Element& e : elements) {
      if (!e.id.empty()) used_ids_.insert(e.id);
      if (const auto* g = std::get_if<Group>(&e.body)) collect_ids(g->children);
    }
  }

  // A fresh id "<kind><n>" that no element of the document uses. The ids in use are collected
  // the first time one is needed (a document read from a file has all its ids).
  std::string fresh_id(std::string_view kind) {
    if (!ids_collected_) {
      collect_ids(image_.children);
      ids_collected_ = true;
    }
    for (;;) {
      std::string id = std::string(kind) + std::to_string(++next_id_number_);
      if (used_ids_.insert(id).second) return id;
    }
  }

  void indent(int depth) { out_.append(static_cast<size_t>(depth) * 2, ' '); }
  void attr(std::string_view name, std::string_view value) {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    append_escaped(out_, value, true);
    out_ += '"';
  }
  // A number needs no escaping.
  void num(std::string_view name, double value) {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    append_decimal(out_, value);
    out_ += '"';
  }

  // Every number attribute of `owner` that `value_of` finds, in the parameter table's order (the
  // canonical order); the table has no defaults to leave out: a canonical file states every value.
  template <typename ValueOf>
  void numbers(ParameterOwner owner, ValueOf value_of) {
    for (const ParameterSpec* spec : number_specs(owner)) {
      if (const double* value = value_of(*spec)) num(spec->name, *value);
    }
  }
  void points(std::string_view name, const std::vector<Point2Mm>& list) {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (i > 0) out_ += ' ';
      append_decimal(out_, list[i].x_mm);
      out_ += ',';
      append_decimal(out_, list[i].y_mm);
    }
    out_ += '"';
  }
  void extras(const ExtraAttributes& extra) {
    for (const auto& [name, value] : extra) attr(name, value);
  }

  void text_element(int depth, std::string_view name, std::string_view text) {
    indent(depth);
    out_ += '<';
    out_ += name;
    out_ += '>';
    const bool all_space = !text.empty() && text.find_first_not_of(" \t\n\r") == std::string_view::npos;
    if (all_space) {
      // A parser drops whitespace-only text, so it is written as character references.
      for (const char c : text) out_ += "&#" + std::to_string(static_cast<int>(c)) + ";";
    } else {
      append_escaped(out_, text, false);
    }
    out_ += "</";
    out_ += name;
    out_ += ">\n";
  }

  void unknown(int depth, const UnknownElement& u) {
    indent(depth);
    out_ += u.xml;
    out_ += '\n';
  }

  void write_meta(const Meta& meta) {
    indent(1);
    out_ += "<meta";
    extras(meta.extra_attributes);
    out_ += ">\n";
    if (meta.title) text_element(2, "title", *meta.title);
    if (meta.author) text_element(2, "author", *meta.author);
    if (meta.description) text_element(2, "description", *meta.description);
    if (meta.created) text_element(2, "created", *meta.created);
    for (const auto& tag : meta.tags) text_element(2, "tag", tag);
    if (meta.tool) {
      indent(2);
      out_ += "<tool";
      attr("name", meta.tool->name);
      attr("version", meta.tool->version);
      extras(meta.tool->extra_attributes);
      out_ += "/>\n";
    }
    for (const auto& u : meta.unknown_children) unknown(2, u);
    indent(1);
    out_ += "</meta>\n";
  }

  void open(int depth, std::string_view name, const Element& e, std::string_view id_kind) {
    indent(depth);
    out_ += '<';
    out_ += name;
    attr("id", e.id.empty() ? fresh_id(id_kind) : e.id);
  }

  // Closes a primitive's start tag, writing its extra attributes and unknown children.
  void close(int depth, std::string_view name, const Element& e) {
    extras(e.extra_attributes);
    if (e.unknown_children.empty()) {
      out_ += "/>\n";
      return;
    }
    out_ += ">\n";
    for (const auto& u : e.unknown_children) unknown(depth + 1, u);
    indent(depth);
    out_ += "</";
    out_ += name;
    out_ += ">\n";
  }

  void write_element(const Element& e, int depth) {
    if (std::holds_alternative<Dot>(e.body)) {
      open(depth, "dot", e, "dot");
      numbers(ParameterOwner::dot, [&](const ParameterSpec& spec) { return number_in(e, spec); });
      close(depth, "dot", e);
    } else if (std::holds_alternative<Line>(e.body)) {
      open(depth, "line", e, "line");
      numbers(ParameterOwner::line, [&](const ParameterSpec& spec) { return number_in(e, spec); });
      close(depth, "line", e);
    } else if (const auto* s = std::get_if<Surface>(&e.body)) {
      write_surface(e, *s, depth);
    } else if (const auto* g = std::get_if<Group>(&e.body)) {
      open(depth, "group", e, "group");
      if (g->name) attr("name", *g->name);
      extras(e.extra_attributes);
      if (g->children.empty() && e.unknown_children.empty()) {
        out_ += "/>\n";
        return;
      }
      out_ += ">\n";
      for (const Element& child : g->children) write_element(child, depth + 1);
      for (const auto& u : e.unknown_children) unknown(depth + 1, u);
      indent(depth);
      out_ += "</group>\n";
    } else if (const auto* u = std::get_if<UnknownElement>(&e.body)) {
      unknown(depth, *u);
    }
  }

  void write_surface(const Element& e, const Surface& s, int depth) {
    open(depth, "surface", e, "surface");
    // The table's order: shape, the shape's geometry, period, relief, pattern, gain.
    for (const ParameterSpec& spec : parameter_table()) {
      if (spec.owner != ParameterOwner::surface || !applies_to_shape(spec, s.shape)) continue;
      switch (spec.kind) {
        case ParameterKind::number: num(spec.name, *number_in(e, spec)); break;
        case ParameterKind::choice: attr(spec.name, spec.name == "shape" ? shape_name(s.shape) : pattern_name(s.pattern)); break;
        case ParameterKind::points: points(spec.name, s.points); break;
        case ParameterKind::id:
        case ParameterKind::text:
        case ParameterKind::version: break;  // the id is written by open()
      }
    }
    close(depth, "surface", e);
  }

  const Image& image_;
  std::string out_;
  std::unordered_set<std::string> used_ids_;
  bool ids_collected_ = false;
  int next_id_number_ = 0;
};

}  // namespace

std::string write_image_xml(const Image& image) { return Writer(image).run(); }

std::optional<std::string> saved_text_error(std::string_view xml) {
  if (xml.size() > kMaxImageFileBytes) {
    return "the XML text of this image is " + std::to_string(xml.size()) + " bytes, more than a reader accepts (limit " +
           std::to_string(kMaxImageFileBytes) + ")";
  }
  if (const auto refused = check_xml_limits(xml)) {
    return "the XML text of this image could not be opened again: line " + std::to_string(refused->line) + ": " +
           refused->message;
  }
  return std::nullopt;
}

}  // namespace vimg
