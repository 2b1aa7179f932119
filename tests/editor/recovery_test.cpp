#include "editor/core/recovery.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "storage/image_io.hpp"

namespace vimg::editor {
namespace {

TEST(RecoveryStore, KeepsTheDocumentAndItsOriginUntilDiscarded) {
  const auto dir = std::filesystem::path(VIMG_BINARY_DIR) / "editor_test_recovery";
  std::filesystem::remove_all(dir);
  RecoveryStore store(dir);
  EXPECT_FALSE(store.exists());

  Image image;
  image.width_mm = 70;
  image.height_mm = 140;
  Element dot;
  dot.id = "eye";
  dot.body = Dot{25, 55, 1.5, 1.0};
  image.children.push_back(dot);
  ASSERT_EQ(store.save(image, "/home/designer/smiley.vimg"), std::nullopt);
  EXPECT_TRUE(store.exists());
  EXPECT_EQ(store.recorded_origin(), "/home/designer/smiley.vimg");

  LoadResult loaded = load_image_file(store.file());
  ASSERT_TRUE(loaded.ok());
  EXPECT_EQ(*loaded.image, image);

  store.discard();
  EXPECT_FALSE(store.exists());
  std::filesystem::remove_all(dir);
}

TEST(RecoveryStore, AnUnwritableFolderIsAMessageNotACrash) {
  const auto blocker = std::filesystem::path(VIMG_BINARY_DIR) / "editor_test_recovery_blocker";
  std::filesystem::remove_all(blocker);
  { std::ofstream(blocker) << "a file where the folder should be"; }
  RecoveryStore store(blocker / "sub");
  const auto error = store.save(Image{}, "");
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("editor_test_recovery_blocker"), std::string::npos) << *error;
  std::filesystem::remove_all(blocker);
}

}  // namespace
}  // namespace vimg::editor
