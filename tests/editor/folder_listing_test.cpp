#include "editor/core/folder_listing.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "editor/core/recent_files.hpp"

namespace vimg::editor {
namespace {

namespace fs = std::filesystem;

struct Folder {
  fs::path root;
  explicit Folder(const std::string& name) : root(fs::path(VIMG_BINARY_DIR) / name) {
    fs::remove_all(root);
    fs::create_directories(root);
  }
  ~Folder() { fs::remove_all(root); }
  void file(const std::string& name, std::size_t bytes = 3) {
    fs::create_directories((root / name).parent_path());
    std::ofstream(root / name) << std::string(bytes, 'x');
  }
};

std::vector<std::string> names(const FolderListing& listing) {
  std::vector<std::string> out;
  for (const auto& e : listing.entries) out.push_back(e.folder ? e.name + "/" : e.name);
  return out;
}

TEST(FolderListing, FoldersFirstThenAcceptedFilesEachByNameIgnoringCase) {
  Folder f("editor_test_listing_sort");
  for (const char* n : {"b.vimg", "A.PNG", "c.txt", "notes.xml", "z.png", ".hidden.vimg", "d.csv"}) f.file(n);
  fs::create_directories(f.root / "Zeta");
  fs::create_directories(f.root / "alpha");
  fs::create_directories(f.root / ".git");
  const FolderListing images = list_folder(f.root, image_filters()[0]);
  EXPECT_FALSE(images.error);
  EXPECT_EQ(names(images), (std::vector<std::string>{"alpha/", "Zeta/", "A.PNG", "b.vimg", "notes.xml", "z.png"}));
  EXPECT_EQ(names(list_folder(f.root, image_filters()[2])), (std::vector<std::string>{"alpha/", "Zeta/", "A.PNG", "z.png"}));
  EXPECT_EQ(names(list_folder(f.root, image_filters()[1])), (std::vector<std::string>{"alpha/", "Zeta/", "b.vimg", "notes.xml"}));
  EXPECT_EQ(names(list_folder(f.root, gesture_filters()[0])), (std::vector<std::string>{"alpha/", "Zeta/", "d.csv"}));
  EXPECT_EQ(list_folder(f.root, image_filters()[3]).entries.size(), 8u);  // all files
  EXPECT_EQ(list_folder(f.root, image_filters()[3], true).entries.size(), 10u);  // and the hidden ones
}

// Property: every listed file is accepted by the filter, and every accepted file is listed.
TEST(FolderListing, ListsExactlyTheFilesTheFilterAccepts) {
  Folder f("editor_test_listing_filter");
  const std::vector<std::string> all = {"a.vimg", "b.VIMG", "c.xml", "d.png", "e.Png", "f.pngx", "g", "png", ".png.txt", "h.csv"};
  for (const auto& n : all) f.file(n);
  for (const FileFilter& filter : image_filters()) {
    const FolderListing listing = list_folder(f.root, filter, true);
    std::vector<std::string> want;
    for (const auto& n : all) {
      if (accepts(filter, n)) want.push_back(n);
    }
    std::vector<std::string> got;
    for (const auto& e : listing.entries) got.push_back(e.name);
    std::sort(want.begin(), want.end());
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want) << filter.label;
  }
  EXPECT_FALSE(accepts(image_filters()[0], "png"));   // a bare extension is not a name
  EXPECT_FALSE(accepts(image_filters()[0], "f.pngx"));
}

TEST(FolderListing, GivesFileSizesAndTheFolderInNormalForm) {
  Folder f("editor_test_listing_size");
  f.file("sub/a.vimg", 1234);
  const FolderListing listing = list_folder(f.root / "sub" / ".." / "sub" / "", image_filters()[0]);
  EXPECT_EQ(listing.folder, fs::absolute(f.root / "sub").lexically_normal());
  ASSERT_EQ(listing.entries.size(), 1u);
  EXPECT_EQ(listing.entries[0].size_bytes, 1234u);
}

TEST(FolderListing, AFolderThatCannotBeReadIsAMessage) {
  const FolderListing listing = list_folder(fs::path(VIMG_BINARY_DIR) / "no-such-folder-here", image_filters()[0]);
  ASSERT_TRUE(listing.error);
  EXPECT_NE(listing.error->find("no-such-folder-here"), std::string::npos);
  EXPECT_TRUE(listing.entries.empty());
}

TEST(FolderListing, AHugeFolderIsCut) {
  Folder f("editor_test_listing_huge");
  for (std::size_t i = 0; i < kMaxFolderEntries + 5; ++i) f.file("f" + std::to_string(i) + ".vimg", 0);
  const FolderListing listing = list_folder(f.root, image_filters()[0]);
  EXPECT_TRUE(listing.truncated);
  EXPECT_EQ(listing.entries.size(), kMaxFolderEntries);
}

TEST(FolderListing, UpStopsAtTheRoot) {
  EXPECT_EQ(parent_folder("/a/b"), fs::path("/a"));
  EXPECT_EQ(parent_folder("/a/b/"), fs::path("/a"));
  EXPECT_EQ(parent_folder("/a"), fs::path("/"));
  EXPECT_EQ(parent_folder("/"), fs::path("/"));
}

TEST(FolderListing, ATypedPathIsResolvedAgainstTheFolderShownOrHome) {
  const fs::path folder = "/data/images", home = "/home/d";
  EXPECT_EQ(resolve_typed_path("smiley.vimg", folder, home), fs::path("/data/images/smiley.vimg"));
  EXPECT_EQ(resolve_typed_path("../x/a.png", folder, home), fs::path("/data/x/a.png"));
  EXPECT_EQ(resolve_typed_path("/tmp/a.vimg", folder, home), fs::path("/tmp/a.vimg"));
  EXPECT_EQ(resolve_typed_path("~", folder, home), fs::path("/home/d"));
  EXPECT_EQ(resolve_typed_path("~/v/a.vimg", folder, home), fs::path("/home/d/v/a.vimg"));
  EXPECT_EQ(resolve_typed_path("", folder, home), std::nullopt);
}

TEST(FolderListing, ASavedNameWithoutExtensionGetsTheFiltersFirst) {
  EXPECT_EQ(with_extension("picture", save_filters()[1]), "picture.png");
  EXPECT_EQ(with_extension("picture", save_filters()[0]), "picture.vimg");
  EXPECT_EQ(with_extension("a.png", save_filters()[0]), "a.png");  // the format follows the extension
  EXPECT_EQ(with_extension("take", gesture_filters()[0]), "take.csv");
}

// The recent folders are a RecentFiles list: most recent first, no duplicates, kept across runs.
TEST(FolderListing, RecentFoldersAreKeptMostRecentFirst) {
  Folder f("editor_test_recent_folders");
  const fs::path store = f.root / "config" / "recent-folders.txt";
  {
    RecentFiles recent(store, 3);
    for (const char* d : {"/a", "/b", "/c", "/b", "/d"}) recent.add(d);
    EXPECT_EQ(recent.paths(), (std::vector<std::string>{"/d", "/b", "/c"}));
  }
  RecentFiles again(store, 3);
  EXPECT_EQ(again.paths(), (std::vector<std::string>{"/d", "/b", "/c"}));
}

TEST(FolderListing, ImportOffersDrawingsAndPicturesOnly) {
  const FileFilter both = import_filters().front();
  for (const char* name : {"a.svg", "B.SVG", "c.png", "d.Png"}) EXPECT_TRUE(accepts(both, name)) << name;
  for (const char* name : {"a.vimg", "b.xml", "svg", "c.svgz", "d.png.txt"}) EXPECT_FALSE(accepts(both, name)) << name;
}

}  // namespace
}  // namespace vimg::editor
