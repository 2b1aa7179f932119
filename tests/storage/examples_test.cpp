// The bundled examples (assets/examples) open without errors or warnings, are canonical, and each
// .png restores its .vimg exactly. The matching-test sets have the complexities they claim.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "storage/image_io.hpp"
#include "storage/image_summary.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;
const fs::path kExamples = fs::path(VIMG_SOURCE_DIR) / "assets" / "examples";

TEST(Examples, OpenCleanlyAreCanonicalAndTheirPngsRestoreThem) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kExamples)) {
    if (entry.path().extension() != ".vimg") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    const LoadResult xml = load_image_file(entry.path());
    ASSERT_TRUE(xml.ok());
    EXPECT_TRUE(xml.diagnostics.empty()) << xml.diagnostics[0].to_string();
    EXPECT_EQ(write_image_xml(*xml.image), test::read_text_file(entry.path()));
    fs::path png = entry.path();
    png.replace_extension(".png");
    ASSERT_TRUE(fs::exists(png)) << "every example has its .png";
    const LoadResult picture = load_image_file(png);
    ASSERT_TRUE(picture.ok());
    EXPECT_EQ(*picture.image, *xml.image);
  }
  EXPECT_GE(count, 5);
  EXPECT_TRUE(fs::exists(kExamples / "smiley.vimg"));
}

int objects_in(const std::string& name) {
  const LoadResult r = load_image_file(kExamples / name);
  EXPECT_TRUE(r.ok()) << name;
  return r.ok() ? summarize(*r.image).groups : -1;
}

TEST(Examples, MatchingTestSetsHaveTheirComplexities) {
  EXPECT_EQ(objects_in("set_a1_one_object.vimg"), 1);
  EXPECT_EQ(objects_in("set_a2_two_objects.vimg"), 2);
  EXPECT_EQ(objects_in("set_a3_three_objects.vimg"), 3);
  EXPECT_EQ(objects_in("set_a4_four_objects.vimg"), 4);
  for (const char* name : {"set_b1_house_and_tree.vimg", "set_b2_car_and_sun.vimg", "set_b3_boat_and_fish.vimg",
                           "set_b4_fence_and_ball.vimg"}) {
    EXPECT_EQ(objects_in(name), 2) << name;
  }
}

}  // namespace
}  // namespace vimg
