// SVG import: primitives at the places the drawing puts them (±0.1 mm), the mapping of each
// element kind, warnings for what is not imported, limits, and a file written by Inkscape.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "primitives/geometry/hit_test.hpp"
#include "storage/image_io.hpp"
#include "storage/import/import.hpp"
#include "storage/limits.hpp"

namespace vimg {
namespace {

ImportResult import_text(const std::string& svg, ImportOptions options = {}) { return import_svg(svg, "t.svg", options); }

std::string svg_mm(const std::string& body, const std::string& size = "100") {
  return "<svg xmlns='http://www.w3.org/2000/svg' width='" + size + "mm' height='" + size + "mm' viewBox='0 0 " + size +
         " " + size + "'>\n" + body + "\n</svg>";
}

const Element* find(const std::vector<Element>& elements, const std::string& id) {
  for (const Element& e : elements) {
    if (e.id == id) return &e;
    if (const auto* g = std::get_if<Group>(&e.body)) {
      if (const Element* found = find(g->children, id)) return found;
    }
  }
  return nullptr;
}

std::string warnings_of(const ImportResult& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics) out += d.to_string() + "\n";
  return out;
}

constexpr double kPlace = 0.1;  // mm: the issue's tolerance for places

TEST(SvgImport, RectCircleLineCubicAndTransformedGroupLandWhereTheDrawingPutsThem) {
  const ImportResult r = import_text(svg_mm(R"svg(
  <rect id="box" x="10" y="12" width="20" height="15"/>
  <circle id="disc" cx="60" cy="20" r="8"/>
  <line id="rail" x1="10" y1="40" x2="50" y2="45" stroke="black" stroke-width="2"/>
  <path id="wave" d="M10,60 C20,50 40,70 50,60" fill="none" stroke="black" stroke-width="0.5"/>
  <g id="turned" transform="translate(70,50) rotate(30)">
    <rect id="inner" x="0" y="0" width="10" height="4"/>
  </g>)svg"));
  ASSERT_TRUE(r.ok()) << warnings_of(r);
  const Image& img = *r.image;
  EXPECT_DOUBLE_EQ(img.width_mm, 100.0);

  const auto& box = std::get<Surface>(find(img.children, "box")->body);
  EXPECT_EQ(box.shape, SurfaceShape::rect);
  EXPECT_NEAR(box.x_mm, 10, kPlace);
  EXPECT_NEAR(box.y_mm, 12, kPlace);
  EXPECT_NEAR(box.width_mm, 20, kPlace);
  EXPECT_NEAR(box.height_mm, 15, kPlace);

  const auto& disc = std::get<Surface>(find(img.children, "disc")->body);
  EXPECT_EQ(disc.shape, SurfaceShape::ellipse);
  EXPECT_NEAR(disc.cx_mm, 60, kPlace);
  EXPECT_NEAR(disc.cy_mm, 20, kPlace);
  EXPECT_NEAR(disc.rx_mm, 8, kPlace);

  const auto& rail = std::get<Line>(find(img.children, "rail")->body);
  EXPECT_NEAR(rail.x1_mm, 10, kPlace);
  EXPECT_NEAR(rail.y2_mm, 45, kPlace);
  EXPECT_NEAR(rail.width_mm, 2, kPlace);

  // The cubic: a chain of LINEs from (10,60) to (50,60) through B(0.5) = (30, 60).
  const auto& wave = std::get<Group>(find(img.children, "wave")->body);
  ASSERT_GT(wave.children.size(), 4u);
  const auto& first = std::get<Line>(wave.children.front().body);
  const auto& last = std::get<Line>(wave.children.back().body);
  EXPECT_NEAR(first.x1_mm, 10, kPlace);
  EXPECT_NEAR(first.y1_mm, 60, kPlace);
  EXPECT_NEAR(last.x2_mm, 50, kPlace);
  EXPECT_NEAR(last.y2_mm, 60, kPlace);
  for (int i = 0; i <= 20; ++i) {  // every point of the curve is within 0.05 mm of the chain
    const double t = i / 20.0, u = 1 - t;
    const Vec2 q = Vec2{10, 60} * (u * u * u) + Vec2{20, 50} * (3 * u * u * t) + Vec2{40, 70} * (3 * u * t * t) +
                   Vec2{50, 60} * (t * t * t);
    double best = 1e9;
    for (const Element& e : wave.children) {
      const auto& l = std::get<Line>(e.body);
      best = std::min(best, distance_to_segment(q, {l.x1_mm, l.y1_mm}, {l.x2_mm, l.y2_mm}));
      EXPECT_NEAR(l.width_mm, 0.5, 1e-12);
    }
    EXPECT_LE(best, 0.05 + 1e-9) << t;
  }

  // The rotated rect: a polygon whose corners are the transformed corners.
  const Element* turned = find(img.children, "turned");
  ASSERT_NE(turned, nullptr);
  EXPECT_EQ(std::get<Group>(turned->body).name, "turned");
  const auto& inner = std::get<Surface>(find(img.children, "inner")->body);
  ASSERT_EQ(inner.shape, SurfaceShape::polygon);
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const Vec2 corners[4] = {{70, 50}, {70 + 10 * c, 50 + 10 * s}, {70 + 10 * c - 4 * s, 50 + 10 * s + 4 * c}, {70 - 4 * s, 50 + 4 * c}};
  ASSERT_EQ(inner.points.size(), 4u);
  for (const Vec2& corner : corners) {
    const bool present = std::any_of(inner.points.begin(), inner.points.end(), [&](const Point2Mm& p) {
      return std::hypot(p.x_mm - corner.x, p.y_mm - corner.y) <= kPlace;
    });
    EXPECT_TRUE(present) << corner.x << "," << corner.y;
  }
  // What `vimg validate` reads: the written image parses back without errors or warnings.
  const LoadResult back = parse_image_xml(write_image_xml(img), "t.vimg");
  EXPECT_TRUE(back.ok());
  EXPECT_TRUE(back.diagnostics.empty());
}

TEST(SvgImport, SmallCirclesAreDotsAndStrokedShapesAreOutlines) {
  const ImportResult r = import_text(svg_mm(R"svg(
  <circle id="tiny" cx="5" cy="5" r="2"/>
  <circle id="ring" cx="50" cy="50" r="10" fill="none" stroke="black" stroke-width="1"/>
  <ellipse id="oval" cx="20" cy="80" rx="6" ry="3" fill="none" stroke="#000"/>
  <polygon id="tri" points="10,10 30,10 20,30" fill="none" stroke="black"/>
  <polyline id="zig" points="60,10 70,20 80,10 90,20" fill="red"/>)svg"));
  ASSERT_TRUE(r.ok()) << warnings_of(r);
  const auto& tiny = std::get<Dot>(find(r.image->children, "tiny")->body);
  EXPECT_NEAR(tiny.radius_mm, 2, 1e-12);
  const auto& ring = std::get<Group>(find(r.image->children, "ring")->body);
  for (const Element& e : ring.children) {
    const auto& l = std::get<Line>(e.body);
    EXPECT_NEAR(std::hypot(l.x1_mm - 50, l.y1_mm - 50), 10, 0.05);
  }
  EXPECT_EQ(std::get<Group>(find(r.image->children, "tri")->body).children.size(), 3u);  // closed outline
  EXPECT_EQ(std::get<Group>(find(r.image->children, "zig")->body).children.size(), 3u);  // polyline: a chain, never a surface
}

TEST(SvgImport, FilledAndStrokedGivesTheSurfaceAndItsOutline) {
  const ImportResult r = import_text(svg_mm(R"svg(<rect id="both" x="10" y="10" width="10" height="10" stroke="black"/>)svg"));
  ASSERT_TRUE(r.ok());
  const auto& g = std::get<Group>(find(r.image->children, "both")->body);
  ASSERT_EQ(g.children.size(), 5u);
  EXPECT_TRUE(std::holds_alternative<Surface>(g.children[0].body));
}

TEST(SvgImport, ClosedPathWithAHoleIsOnePolygonFilledEvenOdd) {
  const ImportResult r = import_text(
      svg_mm(R"svg(<path id="frame" fill-rule="evenodd" d="M10 10 H50 V50 H10 Z M20 20 H40 V40 H20 Z"/>)svg"));
  ASSERT_TRUE(r.ok()) << warnings_of(r);
  const auto& s = std::get<Surface>(find(r.image->children, "frame")->body);
  Polygon p;
  for (const Point2Mm& q : s.points) p.vertices.push_back({q.x_mm, q.y_mm});
  EXPECT_TRUE(contains(p, {15, 15}));
  EXPECT_FALSE(contains(p, {30, 30}));
  EXPECT_FALSE(contains(p, {60, 30}));
}

TEST(SvgImport, NonzeroFillKeepsSameDirectionNestingFilledAndOppositeDirectionAHole) {
  const auto polygon_of = [](const ImportResult& r) {
    Polygon p;
    for (const Point2Mm& q : std::get<Surface>(find(r.image->children, "p")->body).points) p.vertices.push_back({q.x_mm, q.y_mm});
    return p;
  };
  // Both squares clockwise: nonzero fills the inner one too.
  const ImportResult same = import_text(svg_mm("<path id='p' d='M10 10 H50 V50 H10 Z M20 20 H40 V40 H20 Z'/>"));
  ASSERT_TRUE(same.ok());
  EXPECT_TRUE(contains(polygon_of(same), {30, 30}));
  EXPECT_TRUE(contains(polygon_of(same), {15, 15}));
  // The inner one counter-clockwise: a hole under nonzero as under even-odd.
  const ImportResult opposite = import_text(svg_mm("<path id='p' d='M10 10 H50 V50 H10 Z M20 20 V40 H40 V20 Z'/>"));
  ASSERT_TRUE(opposite.ok());
  EXPECT_FALSE(contains(polygon_of(opposite), {30, 30}));
  EXPECT_TRUE(contains(polygon_of(opposite), {15, 15}));
  // Even-odd: a hole whatever the direction.
  const ImportResult even_odd = import_text(svg_mm("<path id='p' fill-rule='evenodd' d='M10 10 H50 V50 H10 Z M20 20 H40 V40 H20 Z'/>"));
  EXPECT_FALSE(contains(polygon_of(even_odd), {30, 30}));
}

TEST(SvgImport, NonzeroBeyondAThousandSubpathsIsFilledEvenOddWithAWarning) {
  // Nested squares all turning the same way: nonzero fills everything inside the outermost, even-odd
  // every other band. docs/import.md: beyond 1000 subpaths the path is filled even-odd, with a warning.
  const auto nested = [](int count) {
    std::string d;
    for (int k = 0; k < count; ++k) {
      const std::string a = std::to_string(0.01 + 0.04 * k), b = std::to_string(99.99 - 0.04 * k);
      d += "M" + a + " " + a + " H" + b + " V" + b + " H" + a + " Z ";
    }
    return svg_mm("<path id='p' d='" + d + "'/>");
  };
  const auto polygon_of = [](const ImportResult& r) {
    Polygon p;
    for (const Point2Mm& q : std::get<Surface>(find(r.image->children, "p")->body).points) p.vertices.push_back({q.x_mm, q.y_mm});
    return p;
  };
  const Vec2 in_two_squares{0.07, 50.0};
  const ImportResult at_limit = import_text(nested(1000));
  ASSERT_TRUE(at_limit.ok()) << warnings_of(at_limit);
  EXPECT_EQ(warnings_of(at_limit).find("even-odd"), std::string::npos) << warnings_of(at_limit);
  EXPECT_TRUE(contains(polygon_of(at_limit), in_two_squares));
  const ImportResult over = import_text(nested(1001));
  ASSERT_TRUE(over.ok()) << warnings_of(over);
  EXPECT_NE(warnings_of(over).find("t.svg:2: warning: <path> fill-rule nonzero with more than 1000 subpaths: filled by the "
                                   "even-odd rule"),
            std::string::npos)
      << warnings_of(over);
  EXPECT_FALSE(contains(polygon_of(over), in_two_squares));
}

TEST(SvgImport, AShapeBeyondABillionMillimetresIsAWarningAndNotImported) {
  // docs/import.md, docs/limits.md kMaxImportCoordinateMm: 1e9 mm after the transforms.
  const ImportResult r = import_text(svg_mm(R"svg(<rect id="within" width="10" height="10" transform="scale(9e7)"/>
<rect id="beyond" width="10" height="10" transform="scale(2e8)"/>
<path id="far" d="M0 0 L1 1 L2e9 0 Z"/>)svg"));
  ASSERT_TRUE(r.ok()) << warnings_of(r);
  EXPECT_NE(find(r.image->children, "within"), nullptr);
  EXPECT_EQ(find(r.image->children, "beyond"), nullptr);
  EXPECT_EQ(find(r.image->children, "far"), nullptr);
  for (const char* line : {"t.svg:3: warning: <rect>", "t.svg:4: warning: <path>"}) {
    EXPECT_NE(warnings_of(r).find(std::string(line) + " has coordinates beyond 1e9 mm (or not finite) after its transforms: "
                                  "not imported"),
              std::string::npos)
        << line << "\n" << warnings_of(r);
  }
}

TEST(SvgImport, PhysicalUnitsComeFromWidthHeightAndViewBox) {
  const std::string rect = "<rect id='r' x='10' y='10' width='10' height='10'/>";
  // 2 in wide, viewBox 0..100: a user unit is 0.508 mm.
  ImportResult r = import_text("<svg xmlns='http://www.w3.org/2000/svg' width='2in' height='2in' viewBox='0 0 100 100'>" + rect + "</svg>");
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.image->width_mm, 50.8, 1e-9);
  EXPECT_NEAR(std::get<Surface>(find(r.image->children, "r")->body).x_mm, 5.08, 1e-9);
  // No viewBox, px: 96 per inch.
  r = import_text("<svg xmlns='http://www.w3.org/2000/svg' width='96' height='192'>" + rect + "</svg>");
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.image->height_mm, 50.8, 1e-9);
  EXPECT_NEAR(std::get<Surface>(find(r.image->children, "r")->body).width_mm, 10 * 25.4 / 96, 1e-9);
  // --mm-per-unit overrides.
  ImportOptions options;
  options.mm_per_unit = 2.0;
  r = import_text("<svg xmlns='http://www.w3.org/2000/svg' width='3in' height='3in' viewBox='5 5 40 30'>" + rect + "</svg>", options);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.image->width_mm, 80, 1e-9);
  EXPECT_NEAR(std::get<Surface>(find(r.image->children, "r")->body).x_mm, 10, 1e-9);
  // A wider viewBox than the viewport: centred (xMidYMid meet).
  r = import_text("<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='100mm' viewBox='0 0 200 100'>" + rect + "</svg>");
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(std::get<Surface>(find(r.image->children, "r")->body).y_mm, 25 + 5, 1e-9);
}

TEST(SvgImport, UnsupportedContentIsListedWithItsLine) {
  const ImportResult r = import_text(svg_mm(R"svg(<defs><linearGradient id="g"/></defs>
<text x="1" y="1">hello</text>
<image href="x.png" width="1" height="1"/>
<use href="#a"/>
<rect x="1" y="1" width="5" height="5" fill="url(#g)"/>
<rect x="1" y="1" width="5" height="5" clip-path="url(#c)"/>
<circle cx="5" cy="5" r="3" fill="none"/>
<wobble/>)svg"));
  ASSERT_TRUE(r.ok());
  const std::string w = warnings_of(r);
  for (const char* expected : {"t.svg:2: warning: <linearGradient>", "t.svg:3: warning: <text>", "t.svg:4: warning: <image>",
                               "t.svg:5: warning: <use>", "t.svg:6: warning: <rect> fill is a gradient",
                               "t.svg:7: warning: <rect> clip-path", "t.svg:8: warning: <circle> has neither fill nor stroke",
                               "t.svg:9: warning: <wobble>"}) {
    EXPECT_NE(w.find(expected), std::string::npos) << expected << "\n" << w;
  }
}

TEST(SvgImport, BadInputIsAnErrorWithItsLine) {
  EXPECT_FALSE(import_text("<svg").ok());
  const ImportResult not_svg = import_text("<html/>");
  ASSERT_FALSE(not_svg.ok());
  EXPECT_NE(warnings_of(not_svg).find("t.svg:1: error:"), std::string::npos);
  const ImportResult no_size = import_text("<svg xmlns='http://www.w3.org/2000/svg'><rect width='1' height='1'/></svg>");
  ASSERT_FALSE(no_size.ok());
  EXPECT_NE(warnings_of(no_size).find("has no size"), std::string::npos);
  EXPECT_FALSE(import_text("<svg width='20000mm' height='1mm'/>").ok());
  const ImportResult path_error = import_text(svg_mm("\n<path d='M0 0 L10 10 L20 q'/>"));
  ASSERT_TRUE(path_error.ok());
  EXPECT_NE(warnings_of(path_error).find("t.svg:3: warning: <path> path data: a number was expected at byte 17"), std::string::npos)
      << warnings_of(path_error);
}

TEST(SvgImport, LimitsAreRefusedWithTheirValue) {
  std::string points;
  for (std::size_t i = 0; i <= kMaxPolygonPoints; ++i) points += std::to_string(i % 90) + "," + std::to_string(i % 7) + " ";
  const ImportResult r = import_text(svg_mm("<polygon points='" + points + "'/>"));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(warnings_of(r).find("(limit " + std::to_string(kMaxPolygonPoints) + ")"), std::string::npos);
  std::string deep;
  for (int i = 0; i <= kMaxGroupDepth; ++i) deep += "<g>";
  deep += "<rect width='1' height='1'/>";
  for (int i = 0; i <= kMaxGroupDepth; ++i) deep += "</g>";
  const ImportResult too_deep = import_text(svg_mm(deep));
  ASSERT_FALSE(too_deep.ok());
  EXPECT_NE(warnings_of(too_deep).find("(limit 32)"), std::string::npos);
}

TEST(SvgImport, IdsAreMadeValidAndUnique) {
  const ImportResult r = import_text(svg_mm(R"svg(<rect id="1st box" width="5" height="5"/><rect id="1st box" x="10" width="5" height="5"/>)svg"));
  ASSERT_TRUE(r.ok());
  EXPECT_NE(find(r.image->children, "_1st_box"), nullptr);
  EXPECT_NE(find(r.image->children, "_1st_box-2"), nullptr);
  EXPECT_TRUE(parse_image_xml(write_image_xml(*r.image), "t.vimg").ok());
}

TEST(SvgImport, InkscapeFileFromAdwaitaImportsAndValidates) {
  const std::filesystem::path file = VIMG_SOURCE_DIR "/tests/import/data/adwaita-parental-controls.svg";
  const ImportResult r = import_file(file, {});
  ASSERT_TRUE(r.ok()) << warnings_of(r);
  EXPECT_EQ(warnings_of(r), "");  // editor data (sodipodi, inkscape, RDF) is not drawing content
  const Image& img = *r.image;
  EXPECT_NEAR(img.width_mm, 16.009901 * 25.4 / 96, 1e-9);
  ASSERT_EQ(img.children.size(), 1u);  // the one non-empty layer
  const auto& layer = std::get<Group>(img.children[0].body);
  EXPECT_EQ(img.children[0].id, "layer3");
  EXPECT_EQ(layer.children.size(), 7u);  // seven filled paths
  // path4042 is a circle of radius 2.5 px about (197.5, 490.5) in the layer, translated by (-191.9899, -488).
  const auto& head = std::get<Surface>(find(img.children, "path4042")->body);
  const double px = 25.4 / 96;
  for (const Point2Mm& p : head.points) {
    EXPECT_NEAR(std::hypot(p.x_mm - (197.5 - 191.9899) * px, p.y_mm - 2.5 * px), 2.5 * px, 0.05);
  }
  EXPECT_TRUE(parse_image_xml(write_image_xml(img), "adwaita.vimg").ok());
}

}  // namespace
}  // namespace vimg
