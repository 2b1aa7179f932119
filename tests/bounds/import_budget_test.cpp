// An import gives an image that can be saved and opened again, or an error saying why not
// (storage/import/import.hpp, check_imported_image): the primitive budget counts the elements
// the image will hold, and a drawing within it whose written image still exceeds a reader's
// attribute limit is refused with that limit. Large drawings: slow tests.
#include <gtest/gtest.h>

#include <string>

#include "storage/image_io.hpp"
#include "storage/import/import.hpp"
#include "storage/limits.hpp"
#include "tests/bounds/svg_drawing.hpp"

namespace vimg {
namespace {

using test::errors_of;
using test::svg_of;

TEST(ImportBudget, AShapeThatGivesOnePrimitiveCostsOneElement) {
  // 200 000 small circles are 200 000 dots: within the 249 998 primitives an import may make (each
  // once counted twice, as if wrapped in a group, the drawing was refused at its 125 000th circle).
  const std::size_t count = 200'000;
  const ImportResult r = import_svg(svg_of(count, "<circle cx='5' cy='5' r='0.5'/>"), "dots.svg", {});
  ASSERT_TRUE(r.ok()) << errors_of(r);
  EXPECT_EQ(r.image->children.size(), count);
  EXPECT_TRUE(std::holds_alternative<Dot>(r.image->children.back().body));
}

TEST(ImportBudget, ADrawingWhoseImageExceedsTheAttributeLimitIsRefusedWithIt) {
  // 180 000 stroked lines are within the primitive budget, but their image holds 9 attributes a
  // line: 1.62 million, more than a reader accepts. The import says so instead of giving an image
  // that no save could write and no reader could open.
  const std::size_t count = 180'000;
  const ImportResult r = import_svg(svg_of(count, "<line x1='1' y1='1' x2='5' y2='9' stroke='black'/>"), "lines.svg", {});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(errors_of(r), "lines.svg: error: the imported image could not be opened again: more than " +
                              std::to_string(kMaxXmlAttributes) + " attributes in the file (limit " +
                              std::to_string(kMaxXmlAttributes) + ")\n");
}

}  // namespace
}  // namespace vimg
