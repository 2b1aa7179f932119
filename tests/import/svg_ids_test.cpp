// The ids of imported SVG elements (storage/import/svg_ids.hpp): valid, unique, the first element
// in document order keeps a shared id (as SVG resolves it), and the work is linear in the elements
// sharing an id (counted, not timed).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "storage/import/import.hpp"
#include "storage/import/svg_ids.hpp"

namespace vimg {
namespace {

TEST(SvgIds, SharedIdsAreNumberedInOrderWithWorkLinearInTheirCount) {
  svg::UniqueIds ids;
  const std::size_t count = 50'000;
  std::set<std::string> given;
  for (std::size_t i = 0; i < count; ++i) given.insert(ids.take("dup"));
  EXPECT_EQ(given.size(), count);
  EXPECT_TRUE(given.contains("dup"));
  EXPECT_TRUE(given.contains("dup-" + std::to_string(count)));
  // One try for the first and two for each later copy (its own id, then the next free suffix);
  // restarting the suffixes at -2 for every copy costs count^2 / 2.
  EXPECT_LE(ids.attempts(), 2 * count);
}

TEST(SvgIds, SuffixesTakenByOtherElementsAreSkippedOnce) {
  svg::UniqueIds ids;
  EXPECT_EQ(ids.take("a-2"), "a-2");
  EXPECT_EQ(ids.take("a"), "a");
  EXPECT_EQ(ids.take("a"), "a-3");
  EXPECT_EQ(ids.take("a"), "a-4");
  EXPECT_EQ(ids.take("9 lives"), "_9_lives");
  EXPECT_EQ(ids.take(""), "");
  EXPECT_EQ(ids.take(nullptr), "");
}

TEST(SvgIds, AGroupKeepsItsIdBeforeTheElementsInsideItAndAnEmptyOneGivesItBack) {
  const std::string svg =
      "<svg xmlns='http://www.w3.org/2000/svg' width='10mm' height='10mm' viewBox='0 0 10 10'>"
      "<g id='x'/><g id='x'><rect id='x' width='1' height='1'/><rect width='2' height='2'/></g></svg>";
  const ImportResult r = import_svg(svg, "g.svg", {});
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.image->children.size(), 1u);
  EXPECT_EQ(r.image->children[0].id, "x");  // the empty first group is left out and so is its claim
  EXPECT_EQ(std::get<Group>(r.image->children[0].body).children[0].id, "x-2");
}

}  // namespace
}  // namespace vimg
