// SVG drawings built to hurt the importer (issue 23, "Imports built to hurt"), each run in a child
// under an address-space and a CPU cap (bounded_child.hpp): the import finishes inside them, or is
// refused with the limit it reached named (`FILE:LINE: error: ... (limit N)`), never "out of memory"
// and never killed. And the documented largest drawing imports and reads back, one more is refused
// naming the drawing and the limit (docs/import.md "Limits", docs/limits.md "Import").
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "storage/image_io.hpp"
#include "storage/import/import.hpp"
#include "storage/limits.hpp"
#include "tests/bounds/svg_drawing.hpp"
#include "tests/bounds/bounded_child.hpp"

namespace vimg {
namespace {

constexpr std::size_t kMemoryCapBytes = std::size_t{512} << 20;
constexpr int kCpuCapSeconds = 30;

using test::errors_of;
using test::svg_of;

void collect_ids(const std::vector<Element>& elements, std::set<std::string>& ids) {
  for (const Element& e : elements) {
    ids.insert(e.id);
    if (const auto* g = std::get_if<Group>(&e.body)) collect_ids(g->children, ids);
  }
}

TEST(SvgBounds, FiftyThousandElementsSharingOneIdImportWithinTheCaps) {
  // Each copy used to try "dup-2", "dup-3", ... from the start: 1.25e9 set look-ups for 50 000.
  const std::size_t count = 50'000;
  const std::string svg = svg_of(count, "<circle id='dup' cx='5' cy='5' r='0.5'/>");
  const test::ChildOutcome outcome = test::run_bounded(
      [&] {
        const ImportResult r = import_svg(svg, "ids.svg", {});
        if (!r.ok()) return "refused: " + errors_of(r);
        std::set<std::string> ids;
        collect_ids(r.image->children, ids);
        const bool first_keeps_it = r.image->children.front().id == "dup";
        const bool last_numbered = r.image->children.back().id == "dup-" + std::to_string(count);
        return std::to_string(ids.size()) + " ids" + (first_keeps_it ? ", the first 'dup'" : "") +
               (last_numbered ? ", the last 'dup-50000'" : "");
      },
      kMemoryCapBytes, kCpuCapSeconds);
  ASSERT_TRUE(outcome.finished()) << outcome.describe();
  EXPECT_EQ(outcome.output, "50000 ids, the first 'dup', the last 'dup-50000'");
}

TEST(SvgBounds, ArcsOfEnormousRadiusAreRefusedAtThePointLimitWithinTheCaps) {
  // Each arc is the large way round a circle of 10 km: some 65 500 points within 0.05 mm, under
  // the limit of one outline, but 20 000 of them are 21 GB of points ("out of memory" under the
  // cap, before). Counted as they are produced, the import stops at kMaxImportPoints, at the line
  // of the element that reached it (the 64th).
  const std::string svg = svg_of(20'000, "<path d='M0,0 A1e7,1e7 0 1 1 1,0 Z'/>");
  const test::ChildOutcome outcome = test::run_bounded(
      [&] {
        const ImportResult r = import_svg(svg, "arcs.svg", {});
        return r.ok() ? std::string("imported") : errors_of(r);
      },
      kMemoryCapBytes, kCpuCapSeconds);
  ASSERT_TRUE(outcome.finished()) << outcome.describe();
  const std::string limit = std::to_string(kMaxImportPoints);
  EXPECT_NE(outcome.output.find("arcs.svg:"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find(": error: the drawing's curves and outlines flatten to more than " + limit +
                                " points in all (limit " + limit + ")"),
            std::string::npos)
      << outcome.output;
  EXPECT_EQ(outcome.output.find("arcs.svg: error:"), std::string::npos) << "the line is named: " << outcome.output;
}

// `count` paths of path data `d`.
std::string paths_of(std::size_t count, const std::string& d, const std::string& fill_rule) {
  return svg_of(count, "<path fill-rule='" + fill_rule + "' d='" + d + "'/>");
}

TEST(SvgBounds, PathsOfManyNestedSubpathsAreRefusedAtTheOutlineTestLimitWithinTheCaps) {
  // Nonzero fill: 1000 nested squares test every square against every other, 10^6 tests a path;
  // 200 paths used to take minutes. The boxes and edges visited are counted for the whole drawing.
  std::string nested;
  for (int k = 0; k < 1000; ++k) {
    const std::string a = std::to_string(0.01 * k), side = std::to_string(100 - 0.02 * k);
    nested += "M" + a + " " + a + " h" + side + " v" + side + " h-" + side + " z ";
  }
  // Even-odd: 10 000 holes at the centre of a 40 000-gon are all equally near every vertex, so the
  // nearest bridge vertex is searched among all of them: 4 * 10^8 distances a path, 20 paths minutes.
  std::string holed = "M95,50";
  for (int k = 1; k < 40'000; ++k) {
    const double t = 2 * 3.14159265358979 * k / 40'000;
    holed += " L" + std::to_string(50 + 45 * std::cos(t)) + "," + std::to_string(50 + 45 * std::sin(t));
  }
  holed += " Z";
  for (int k = 0; k < 10'000; ++k) holed += " M50,50 l0.01,0 l0,0.01 z";
  const std::string limit = std::to_string(kMaxImportOutlineTests);
  for (const auto& [name, svg] : {std::pair{"nested.svg", paths_of(200, nested, "nonzero")},
                                  std::pair{"holed.svg", paths_of(20, holed, "evenodd")}}) {
    const test::ChildOutcome outcome = test::run_bounded(
        [&svg = svg, &name = name] {
          const ImportResult r = import_svg(svg, name, {});
          return r.ok() ? std::string("imported") : errors_of(r);
        },
        kMemoryCapBytes, kCpuCapSeconds);
    ASSERT_TRUE(outcome.finished()) << name << ": " << outcome.describe();
    EXPECT_NE(outcome.output.find(": error: placing the subpaths of this path takes more than " + limit +
                                  " outline tests in the drawing (limit " + limit + ")"),
              std::string::npos)
        << name << ": " << outcome.output;
  }
}

TEST(SvgBounds, TheDocumentedMostPrimitivesImportAndReadBackAndOneMoreIsRefusedNamingTheDrawing) {
  const std::string dot = "<circle cx='5' cy='5' r='0.5'/>";
  const ImportResult at_limit = import_svg(svg_of(kMaxImportPrimitives, dot), "most.svg", {});
  ASSERT_TRUE(at_limit.ok()) << errors_of(at_limit);
  EXPECT_EQ(at_limit.image->children.size(), kMaxImportPrimitives);
  EXPECT_TRUE(parse_image_xml(write_image_xml(*at_limit.image), "most.vimg").ok());

  const ImportResult over = import_svg(svg_of(kMaxImportPrimitives + 1, dot), "over.svg", {});
  ASSERT_FALSE(over.ok());
  const std::string limit = std::to_string(kMaxImportPrimitives);
  // The last circle is on line kMaxImportPrimitives + 2 (the <svg> tag is line 1).
  EXPECT_EQ(errors_of(over), "over.svg:" + std::to_string(kMaxImportPrimitives + 2) +
                                 ": error: the drawing gives more than " + limit + " primitives and groups (limit " +
                                 limit + ")\n");

  // A title becomes <meta><title>: two elements of the same budget.
  const std::string title = "<title>t</title>";
  const ImportResult titled = import_svg(svg_of(kMaxImportPrimitives - 2, dot, title), "titled.svg", {});
  ASSERT_TRUE(titled.ok()) << errors_of(titled);
  EXPECT_TRUE(parse_image_xml(write_image_xml(*titled.image), "titled.vimg").ok());
  const ImportResult titled_over = import_svg(svg_of(kMaxImportPrimitives - 1, dot, title), "titled.svg", {});
  ASSERT_FALSE(titled_over.ok());
  EXPECT_NE(errors_of(titled_over).find("(limit " + std::to_string(kMaxImportPrimitives - 2) + ")"), std::string::npos)
      << errors_of(titled_over);
}

}  // namespace
}  // namespace vimg
