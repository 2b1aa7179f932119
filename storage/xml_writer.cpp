// write_image_xml: the canonical XML text of an image (spec section 1 "Round trip", docs/format.md).
#include <string>
#include <string_view>
#include <unordered_set>

#include "storage/image_io.hpp"
#include "storage/number_text.hpp"

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

class Writer {
 public:
  explicit Writer(const Image& image) : image_(image) { collect_ids(image.children); }

  std::string run() {
    out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<vibroimage";
    attr("version", std::to_string(image_.version_major) + "." + std::to_string(image_.version_minor));
    num("width", image_.width_mm);
    num("height", image_.height_mm);
    extras(image_.extra_attributes);
    out_ += ">\n";
    if (image_.meta) write_meta(*image_.meta);
    if (image_.interaction) {
      const InteractionParams& p = *image_.interaction;
      indent(1);
      out_ += "<interaction";
      num("mass", p.mass_kg);
      num("fullSpeed", p.full_speed_mm_per_s);
      num("maxDeformation", p.max_deformation_mm);
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
  void collect_ids(const std::vector<Element>& elements) {
    for (const Element& e : elements) {
      if (!e.id.empty()) used_ids_.insert(e.id);
      if (const auto* g = std::get_if<Group>(&e.body)) collect_ids(g->children);
    }
  }

  // A fresh id "<kind><n>" that no element of the document uses.
  std::string fresh_id(std::string_view kind) {
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
  void num(std::string_view name, double value) { attr(name, format_decimal(value)); }
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
    if (const auto* d = std::get_if<Dot>(&e.body)) {
      open(depth, "dot", e, "dot");
      num("x", d->x_mm);
      num("y", d->y_mm);
      num("radius", d->radius_mm);
      num("gain", d->gain);
      close(depth, "dot", e);
    } else if (const auto* l = std::get_if<Line>(&e.body)) {
      open(depth, "line", e, "line");
      num("x1", l->x1_mm);
      num("y1", l->y1_mm);
      num("x2", l->x2_mm);
      num("y2", l->y2_mm);
      num("width", l->width_mm);
      num("frequency", l->frequency_hz);
      num("damping", l->damping);
      num("gain", l->gain);
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
    switch (s.shape) {
      case SurfaceShape::rect:
        attr("shape", "rect");
        num("x", s.x_mm);
        num("y", s.y_mm);
        num("width", s.width_mm);
        num("height", s.height_mm);
        break;
      case SurfaceShape::ellipse:
        attr("shape", "ellipse");
        num("cx", s.cx_mm);
        num("cy", s.cy_mm);
        num("rx", s.rx_mm);
        num("ry", s.ry_mm);
        break;
      case SurfaceShape::polygon: {
        attr("shape", "polygon");
        std::string points;
        for (const auto& p : s.points) {
          if (!points.empty()) points += ' ';
          points += format_decimal(p.x_mm) + "," + format_decimal(p.y_mm);
        }
        attr("points", points);
        break;
      }
    }
    num("period", s.period_mm);
    num("relief", s.relief_mm);
    switch (s.pattern) {
      case SurfacePattern::sine: attr("pattern", "sine"); break;
      case SurfacePattern::square: attr("pattern", "square"); break;
      case SurfacePattern::triangle: attr("pattern", "triangle"); break;
    }
    num("gain", s.gain);
    close(depth, "surface", e);
  }

  const Image& image_;
  std::string out_;
  std::unordered_set<std::string> used_ids_;
  int next_id_number_ = 0;
};

}  // namespace

std::string write_image_xml(const Image& image) { return Writer(image).run(); }

}  // namespace vimg
