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
    DecodedPng png = decode_png_rgba(bytes, std::min(options_.max_pixels, kMaxPngPixels));
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
    png.rgba = {};  // 4 bytes a pixel, no longer needed while tracing
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

  // Work of placing and bridging holes, against kMaxPictureContainmentTests; false past it.
  bool count_work(double work) {
    work_ += work;
    if (work_ <= kMaxPictureContainmentTests) return true;
    error_ = "the picture has too many holes in large outlines to import (limit " +
             std::to_string(static_cast<long long>(kMaxPictureContainmentTests)) +
             " point tests); use fewer --levels or a smaller picture";
    return false;
  }

  std::string too_many_points(double gain) const {
    return "an outline of gain " + format_decimal(gain) + " has more than " + std::to_string(kMaxPolygonPoints) +
           " points (limit " + std::to_string(kMaxPolygonPoints) + "); use a smaller picture";
  }

  // Traces and simplifies one level's outlines, refusing as soon as a limit is passed: the points
  // kept (of one outline and in all) and the surfaces with this level's group are counted while
  // tracing, so that nothing past a limit is ever traced or held.
  bool trace_level(const std::vector<std::uint8_t>& mask, int width, int height, double tolerance_px, double gain,
                   std::vector<Outline>& outers, std::vector<Outline>& holes) {
    import::RingSimplifier simplifier(tolerance_px);
    const auto on_point = [&](Vec2 p) {
      simplifier.add(p);
      if (simplifier.kept() > kMaxPolygonPoints) {
        error_ = too_many_points(gain);
        return false;
      }
      if (points_ + simplifier.kept() > kMaxImportPoints) {
        error_ = "the outlines of the picture hold more than " + std::to_string(kMaxImportPoints) + " points (limit " +
                 std::to_string(kMaxImportPoints) + "); use fewer --levels or a smaller picture";
        return false;
      }
      return true;
    };
    const auto on_end = [&] {
      Ring simple = simplifier.finish();
      if (simple.size() < 3) {
        ++dropped_;
        return true;
      }
      if (simple.size() > kMaxPolygonPoints) {
        error_ = too_many_points(gain);
        return false;
      }
      points_ += simple.size();
      const double area = import::twice_signed_area(simple) / 2.0;
      const bool outer = area < 0.0;
      // This level's group and its surfaces so far, after the levels before.
      if (outer && primitives_ + 1 + outers.size() + 1 > kMaxImportPrimitives) {
        error_ = "the picture gives more than " + std::to_string(kMaxImportPrimitives) + " surfaces and groups (limit " +
                 std::to_string(kMaxImportPrimitives) + "); use fewer --levels or a smaller picture";
        return false;
      }
      Outline o{std::move(simple), {}, std::fabs(area)};
      o.box = box_of(o.ring);
      (outer ? outers : holes).push_back(std::move(o));
      return true;
    };
    import::walk_contours(mask, width, height, on_point, on_end);
    return error_.empty();
  }

  bool outline_level(const std::vector<std::uint8_t>& mask, int width, int height, double mm_per_px, double gain,
                     std::vector<Element>& out) {
    std::vector<Outline> outers, holes;
    if (!trace_level(mask, width, height, options_.simplify_mm / mm_per_px, gain, outers, holes)) return false;
    // Smallest outlines first, so that a hole's parent is the first outline that holds it.
    std::sort(outers.begin(), outers.end(), [](const Outline& a, const Outline& b) { return a.area < b.area; });
    std::vector<std::vector<Ring>> polygons(outers.size());
    std::vector<std::size_t> polygon_points(outers.size());
    for (std::size_t i = 0; i < outers.size(); ++i) {
      polygon_points[i] = outers[i].ring.size();
      polygons[i].push_back(std::move(outers[i].ring));
    }
    for (Outline& hole : holes) {
      bool placed = false;
      for (std::size_t i = 0; i < outers.size() && !placed; ++i) {
        if (!count_work(1.0)) return false;  // the box test
        if (!box_inside(hole.box, outers[i].box)) continue;
        if (!count_work(static_cast<double>(polygons[i].front().size()))) return false;
        if (contains(Polygon{polygons[i].front()}, hole.ring.front())) {
          // A bridged hole adds its points and the two ends of its bridge.
          polygon_points[i] += hole.ring.size() + 2;
          if (polygon_points[i] > kMaxPolygonPoints) {
            error_ = too_many_points(gain);
            return false;
          }
          polygons[i].push_back(std::move(hole.ring));
          placed = true;
        }
      }
      if (!placed) ++dropped_;  // cannot happen for rings of one mask; counted rather than lost
    }
    for (const std::vector<Ring>& rings : polygons) {
      // Bridging looks for each hole's nearest outline point.
      if (!count_work(static_cast<double>(rings.front().size()) * static_cast<double>(rings.size() - 1))) return false;
      const Ring joined = import::bridge_rings(rings);
      ++primitives_;
      Surface s;
      s.shape = SurfaceShape::polygon;
      s.gain = gain;
      s.points.reserve(joined.size());
      for (const Vec2& p : joined) s.points.push_back({p.x * mm_per_px, p.y * mm_per_px});
      Element e;
      e.body = std::move(s);
      out.push_back(std::move(e));
    }
    if (!out.empty()) ++primitives_;  // the level's group
    return true;
  }

  std::string file_;
  const ImportOptions& options_;
  Image image_;
  std::vector<std::string> warnings_;
  std::string error_;
  std::size_t dropped_ = 0;
  std::size_t primitives_ = 0;  // surfaces and groups given so far, within kMaxImportPrimitives
  std::size_t points_ = 0;      // outline points kept so far, within kMaxImportPoints
  double work_ = 0.0;           // within kMaxPictureContainmentTests
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
