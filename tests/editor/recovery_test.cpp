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
  EXPECT_EQ(store.file().parent_path().parent_path(), dir);

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

Image image_with_dot(const char* id) {
  Image image;
  image.width_mm = 70;
  image.height_mm = 140;
  Element dot;
  dot.id = id;
  dot.body = Dot{25, 55, 1.5, 1.0};
  image.children.push_back(dot);
  return image;
}

TEST(RecoveryStore, TwoEditorsNeverShareASlot) {
  const auto dir = std::filesystem::path(VIMG_BINARY_DIR) / "editor_test_recovery_two";
  std::filesystem::remove_all(dir);
  {
    RecoveryStore first(dir), second(dir), third(dir);
    ASSERT_EQ(first.save(image_with_dot("a"), "/work/a.vimg"), std::nullopt);
    ASSERT_EQ(second.save(image_with_dot("b"), "/work/b.vimg"), std::nullopt);
    ASSERT_EQ(third.save(image_with_dot("c"), "/work/a.vimg"), std::nullopt);  // the same file, twice open
    EXPECT_NE(first.file(), second.file());
    EXPECT_NE(first.file(), third.file());
    // Each keeps its own document.
    EXPECT_EQ(*load_image_file(first.file()).image, image_with_dot("a"));
    EXPECT_EQ(*load_image_file(second.file()).image, image_with_dot("b"));
    EXPECT_EQ(*load_image_file(third.file()).image, image_with_dot("c"));
    // A clean exit of one leaves the others' recovery data alone.
    second.discard();
    EXPECT_TRUE(first.exists());
    EXPECT_TRUE(third.exists());
    // Nothing is orphaned while its editor runs.
    RecoveryStore newcomer(dir);
    EXPECT_FALSE(newcomer.adopt_orphan());
  }
  std::filesystem::remove_all(dir);
}

TEST(RecoveryStore, AnOrphanedSlotIsOfferedOnTheNextStart) {
  const auto dir = std::filesystem::path(VIMG_BINARY_DIR) / "editor_test_recovery_orphan";
  std::filesystem::remove_all(dir);
  {
    RecoveryStore crashed(dir);  // goes away without discard(): a crash, as far as the slot knows
    ASSERT_EQ(crashed.save(image_with_dot("lost"), "/work/lost.vimg"), std::nullopt);
  }
  RecoveryStore running(dir);
  ASSERT_EQ(running.save(image_with_dot("mine"), ""), std::nullopt);
  RecoveryStore next(dir);
  ASSERT_TRUE(next.adopt_orphan());
  EXPECT_EQ(next.recorded_origin(), "/work/lost.vimg");
  EXPECT_EQ(*load_image_file(next.file()).image, image_with_dot("lost"));
  RecoveryStore another(dir);
  EXPECT_FALSE(another.adopt_orphan()) << "the adopted slot is locked by its new owner";
  next.discard();
  EXPECT_FALSE(std::filesystem::exists(next.file()));
  EXPECT_TRUE(running.exists());
  std::filesystem::remove_all(dir);
}

TEST(RecoveryStore, TheOldSingleSlotIsOfferedToo) {
  const auto dir = std::filesystem::path(VIMG_BINARY_DIR) / "editor_test_recovery_legacy";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ASSERT_EQ(save_image_file(image_with_dot("old"), dir / "recovery.vimg"), std::nullopt);
  { std::ofstream(dir / "recovery.origin") << "/work/old.vimg\n"; }
  RecoveryStore store(dir);
  ASSERT_TRUE(store.adopt_orphan());
  EXPECT_EQ(store.recorded_origin(), "/work/old.vimg");
  EXPECT_EQ(*load_image_file(store.file()).image, image_with_dot("old"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vimg::editor
