// The import examples (examples/import) are what the importer makes of their sources, so that the
// files docs/import.md shows stay current.
#include <gtest/gtest.h>

#include <filesystem>

#include "storage/image_io.hpp"
#include "storage/import/import.hpp"

namespace vimg {
namespace {

const std::filesystem::path kExamples = std::filesystem::path(VIMG_SOURCE_DIR) / "examples" / "import";

TEST(ImportExamples, DrawingAndPictureMatchTheirImports) {
  ImportOptions picture;
  picture.width_mm = 60.0;
  picture.levels = 4;
  const std::pair<const char*, ImportOptions> cases[] = {{"drawing", ImportOptions{}}, {"picture", picture}};
  for (const auto& [name, options] : cases) {
    const std::filesystem::path source = kExamples / (std::string(name) + (std::string(name) == "drawing" ? ".svg" : ".png"));
    const ImportResult imported = import_file(source, options);
    ASSERT_TRUE(imported.ok()) << name;
    const LoadResult stored = load_image_file(kExamples / (std::string(name) + ".vimg"));
    ASSERT_TRUE(stored.ok()) << name;
    EXPECT_EQ(write_image_xml(*imported.image), write_image_xml(*stored.image)) << name << ": regenerate with vimg import";
  }
}

}  // namespace
}  // namespace vimg
