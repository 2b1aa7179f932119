// The .vsc writer (layout in vsc_format.hpp).
#include <bit>
#include <cstdint>
#include <cstring>
#include <variant>

#include "storage/vsc/vsc_format.hpp"
#include "storage/vsc/vsc_image.hpp"

namespace vimg {

static_assert(std::endian::native == std::endian::little, "the .vsc writer stores numbers as the host does");

namespace {

class ByteWriter {
 public:
  void u8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void u32(std::uint32_t v) { raw(&v, sizeof v); }
  void i32(std::int32_t v) { raw(&v, sizeof v); }
  void f64(double v) { raw(&v, sizeof v); }
  void str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    out_ += s;
  }
  std::string& bytes() { return out_; }

 private:
  void raw(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  std::string out_;
};

void write_elements(ByteWriter& w, const std::vector<Element>& elements);

void write_element(ByteWriter& w, const Element& e) {
  w.str(e.id);
  if (const auto* d = std::get_if<Dot>(&e.body)) {
    w.u8(static_cast<std::uint8_t>(vsc::ElementKind::dot));
    for (double v : {d->x_mm, d->y_mm, d->radius_mm, d->gain}) w.f64(v);
  } else if (const auto* l = std::get_if<Line>(&e.body)) {
    w.u8(static_cast<std::uint8_t>(vsc::ElementKind::line));
    for (double v : {l->x1_mm, l->y1_mm, l->x2_mm, l->y2_mm, l->width_mm, l->frequency_hz, l->damping, l->gain}) w.f64(v);
  } else if (const auto* s = std::get_if<Surface>(&e.body)) {
    w.u8(static_cast<std::uint8_t>(vsc::ElementKind::surface));
    w.u8(static_cast<std::uint8_t>(s->shape));
    w.u8(static_cast<std::uint8_t>(s->pattern));
    for (double v : {s->x_mm, s->y_mm, s->width_mm, s->height_mm, s->cx_mm, s->cy_mm, s->rx_mm, s->ry_mm, s->period_mm,
                     s->relief_mm, s->gain})
      w.f64(v);
    w.u32(static_cast<std::uint32_t>(s->points.size()));
    for (const Point2Mm& p : s->points) {
      w.f64(p.x_mm);
      w.f64(p.y_mm);
    }
  } else if (const auto* g = std::get_if<Group>(&e.body)) {
    w.u8(static_cast<std::uint8_t>(vsc::ElementKind::group));
    w.u8(g->name ? 1 : 0);
    if (g->name) w.str(*g->name);
    write_elements(w, g->children);
  }
}

void write_elements(ByteWriter& w, const std::vector<Element>& elements) {
  w.u32(static_cast<std::uint32_t>(elements.size()));
  for (const Element& e : elements) write_element(w, e);
}

std::vector<Element> renderable_elements(const std::vector<Element>& elements) {
  std::vector<Element> kept;
  for (const Element& e : elements) {
    if (std::holds_alternative<UnknownElement>(e.body)) continue;
    Element copy;
    copy.id = e.id;
    if (const auto* g = std::get_if<Group>(&e.body)) {
      copy.body = Group{g->name, renderable_elements(g->children)};
    } else {
      copy.body = e.body;
    }
    kept.push_back(std::move(copy));
  }
  return kept;
}

}  // namespace

Image renderable_part(const Image& image) {
  Image kept;
  kept.version_major = image.version_major;
  kept.version_minor = image.version_minor;
  kept.width_mm = image.width_mm;
  kept.height_mm = image.height_mm;
  if (image.interaction) {
    InteractionParams p;
    p.mass_kg = image.interaction->mass_kg;
    p.full_speed_mm_per_s = image.interaction->full_speed_mm_per_s;
    p.max_deformation_mm = image.interaction->max_deformation_mm;
    kept.interaction = p;
  }
  kept.children = renderable_elements(image.children);
  return kept;
}

std::string write_vsc(const VscImage& v) {
  const Image image = renderable_part(v.image);
  ByteWriter w;
  w.bytes().append(vsc::kMagic);
  w.u32(vsc::kFormatVersion);
  w.u32(0);  // the byte count of the rest, filled in below
  const ResponseParams& a = v.actuator;
  w.u8(static_cast<std::uint8_t>(a.model));
  for (double x : {a.resonance_hz, a.q, a.low_hz, a.high_hz, a.spin_up_s, a.spin_down_s}) w.f64(x);
  w.i32(image.version_major);
  w.i32(image.version_minor);
  w.f64(image.width_mm);
  w.f64(image.height_mm);
  w.u8(image.interaction ? 1 : 0);
  if (image.interaction) {
    for (double x : {image.interaction->mass_kg, image.interaction->full_speed_mm_per_s, image.interaction->max_deformation_mm})
      w.f64(x);
  }
  write_elements(w, image.children);
  std::string out = std::move(w.bytes());
  const auto rest = static_cast<std::uint32_t>(out.size() - vsc::kHeaderBytes);
  std::memcpy(out.data() + 12, &rest, sizeof rest);
  return out;
}

}  // namespace vimg
