// import_picture: a grey or colour picture to SURFACE polygons by grey level (docs/import.md,
// "Pictures"). Each pixel gets a level from its darkness (alpha over white); the pixels of each
// level are outlined by marching squares, the outlines simplified, and each outer outline with its
// holes becomes one polygon (holes bridged, even-odd). Darker levels have a higher gain.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "primitives/geometry/box2.hpp"
#include "primitives/geometry/hit_test.hpp"
#include "storage/import/contours.hpp"
#include "storage/import/import.hpp"
#include "storage/import/rings.hpp"
#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/png_codec.hpp"

namespace vimg {

namespace {

using import::Ring;

struct Outline {
  Ring ring;
  Box2 box;
  double area = 0.0;  // absolute
};

Box2 box_of(const Ring& ring) {
  Box2 b{ring.front(), ring.front()};
  for (const Vec2& p : ring) {
    b.min.x = std::min(b.min.x, p.x);
    b.min.y = std::min(b.min.y, p.y);
    b.max.x = std::max(b.max.x, p.x);
    b.max.y = std::max(b.max.y, p.y);
  }
  return b;
}

bool box_inside(const Box2& inner, const Box2& outer) {
  return inner.min.x >= outer.min.x && inner.min.y >= outer.min.y && inner.max.x <= outer.max.x &&
         inner.max.y <= outer.max.y;
}

// Pixel levels 0 (white or transparent) .. levels (black).
std::vector<std::uint8_t> pixel_levels(const DecodedPng& png, int levels) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(png.width) * static_cast<std::size_t>(png.height));
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::uint8_t* p = png.rgba.data() + i * 4;
    const double luminance = (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
    const double darkness = (1.0 - luminance) * (p[3] / 255.0);
    out[i] = static_cast<std::uint8_t>(std::clamp(std::lround(darkness * levels), 0L, static_cast<long>(levels)));
  }
  return out;
}

class PictureImporter {
 public:
  PictureImporter(const std::string& file, const ImportOptions& options) : file_(file), options_(options) {}

  ImportResult run(std::string_view bytes) {
    if (!options_.width_mm || !(*options_.width_mm > 0.0) || *options_.width_mm > kMaxCanvasMm) {
      return fail("a picture needs the width of its canvas in mm, in (0, " + format_decimal(kMaxCanvasMm) + "] (--width-mm)");
    }
    if (options_.levels < 1 || options_.levels > kMaxPictureLevels) {
      return fail("levels must be 1 .. " + std::to_string(kMaxPictureLevels));
    }
    const DecodedPng png = decode_png_rgba(bytes, std::min(options_.max_pixels, kMaxPngPixels));
    if (!png.error.empty()) return fail("cannot import the picture: " + png.error);
    if (png.width <= 0 || png.height <= 0) return fail("the picture has no pixels");
    const double mm_per_px = *options_.width_mm / png.width;
    image_.width_mm = *options_.width_mm;
    image_.height_mm = png.height * mm_per_px;
    if (image_.height_mm > kMaxCanvasMm) {
      return fail("the canvas would be " + format_decimal(image_.height_mm) + " mm high (limit " +
                  format_decimal(kMaxCanvasMm) + " mm); give a smaller --width-mm");
    }
    const std::vector<std::uint8_t> levels = pixel_levels(png, options_.levels);
    std::vector<std::uint8_t> mask(levels.size());
    for (int level = 1; level <= options_.levels; ++level) {
      for (std::size_t i = 0; i < levels.size(); ++i) mask[i] = levels[i] == level ? 1 : 0;
      Group group;
      const double gain = static_cast<double>(level) / options_.levels;
      if (!outline_level(mask, png.width, png.height, mm_per_px, gain, group.children)) return finish();
      if (group.children.empty()) continue;
      group.name = "grey level " + std::to_string(level) + "/" + std::to_string(options_.levels);
      Element e;
      e.id = "level" + std::to_string(level);
      e.body = std::move(group);
      image_.children.push_back(std::move(e));
    }
    if (dropped_ > 0) {
      warnings_.push_back(std::to_string(dropped_) + " outlines smaller than " + format_decimal(options_.simplify_mm) +
                          " mm were too small to keep as surfaces");
    }
    return finish();
  }

 private:
  ImportResult fail(std::string message) {
    error_ = std::move(message);
    return finish();
  }

  ImportResult finish() {
    ImportResult r;
    for (const std::string& w : warnings_) r.diagnostics.push_back({Diagnostic::Severity::warning, file_, 0, w});
    if (!error_.empty()) {
      r.diagnostics.push_back({Diagnostic::Severity::error, file_, 0, error_});
    } else {
      r.image = std::move(image_);
    }
    return r;
  }

  bool outline_level(const std::vector<std::uint8_t>& mask, int width, int height, double mm_per_px, double gain,
                     std::vector<Element>& out) {
    std::vector<Outline> outers, holes;
    const double tolerance_px = options_.simplify_mm / mm_per_px;
    for (Ring& ring : import::trace_contours(mask, width, height)) {
      Ring simple = import::simplify_ring(ring, tolerance_px);
      if (simple.size() < 3) {
        ++dropped_;
        continue;
      }
      const double area = import::twice_signed_area(simple) / 2.0;
      Outline o{std::move(simple), {}, std::fabs(area)};
      o.box = box_of(o.ring);
      (area < 0.0 ? outers : holes).push_back(std::move(o));
    }
    // Smallest outlines first, so that a hole's parent is the first outline that holds it.
    std::sort(outers.begin(), outers.end(), [](const Outline& a, const Outline& b) { return a.area < b.area; });
    std::vector<std::vector<Ring>> polygons(outers.size());
    for (std::size_t i = 0; i < outers.size(); ++i) polygons[i].push_back(std::move(outers[i].ring));
    for (Outline& hole : holes) {
      bool placed = false;
      for (std::size_t i = 0; i < outers.size() && !placed; ++i) {
        if (!box_inside(hole.box, outers[i].box)) continue;
        work_ += static_cast<double>(polygons[i].front().size());
        if (work_ > kMaxPictureContainmentTests) {
          error_ = "the picture has too many holes in large outlines to import (limit " +
                   std::to_string(static_cast<long long>(kMaxPictureContainmentTests)) + " point tests); use fewer --levels or a smaller picture";
          return false;
        }
        if (contains(Polygon{polygons[i].front()}, hole.ring.front())) {
          polygons[i].push_back(std::move(hole.ring));
          placed = true;
        }
      }
      if (!placed) ++dropped_;  // cannot happen for rings of one mask; counted rather than lost
    }
    for (const std::vector<Ring>& rings : polygons) {
      const Ring joined = import::bridge_rings(rings);
      if (joined.size() > kMaxPolygonPoints) {
        error_ = "an outline of gain " + format_decimal(gain) + " has more than " + std::to_string(kMaxPolygonPoints) +
                 " points (limit " + std::to_string(kMaxPolygonPoints) + "); use a smaller picture";
        return false;
      }
      if (++primitives_ + 1 > kMaxXmlElements) {
        error_ = "the picture gives more than " + std::to_string(kMaxXmlElements - 1) + " surfaces (limit " +
                 std::to_string(kMaxXmlElements - 1) + "); use fewer --levels or a smaller picture";
        return false;
      }
      Surface s;
      s.shape = SurfaceShape::polygon;
      s.gain = gain;
      s.points.reserve(joined.size());
      for (const Vec2& p : joined) s.points.push_back({p.x * mm_per_px, p.y * mm_per_px});
      Element e;
      e.body = std::move(s);
      out.push_back(std::move(e));
    }
    return true;
  }

  std::string file_;
  const ImportOptions& options_;
  Image image_;
  std::vector<std::string> warnings_;
  std::string error_;
  std::size_t dropped_ = 0;
  std::size_t primitives_ = 0;
  double work_ = 0.0;
};

}  // namespace

ImportResult import_picture(std::string_view png_bytes, const std::string& file_name, const ImportOptions& options) {
  PictureImporter importer(file_name, options);
  try {
    ImportResult result = importer.run(png_bytes);
    check_imported_image(result, file_name);
    return result;
  } catch (const std::bad_alloc&) {
    return import_failure(file_name, "out of memory importing the picture");
  }
}

}  // namespace vimg
