// An import gives an image that can be saved and opened again, or an error saying why not
// (storage/import/import.hpp, check_imported_image): the primitive budget counts the elements
// the image will hold, and a drawing within it whose written image still exceeds a reader's
// attribute limit is refused with that limit. Large drawings: slow tests.
#include <gtest/gtest.h>

#include <string>

#include "storage/image_io.hpp"
#include "storage/import/import.hpp"
#include "storage/limits.hpp"

namespace vimg {
namespace {

std::string svg_of(std::size_t count, const std::string& shape) {
  std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='100mm' viewBox='0 0 100 100'>\n";
  svg.reserve(count * (shape.size() + 8));
  for (std::size_t i = 0; i < count; ++i) svg += shape + "\n";
  return svg + "</svg>\n";
}

std::string errors_of(const ImportResult& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics) {
    if (d.severity == Diagnostic::Severity::error) out += d.to_string() + "\n";
  }
  return out;
}

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
