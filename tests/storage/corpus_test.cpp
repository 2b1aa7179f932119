// The file corpus in tests/data: every invalid image gives exactly the messages in its .expected
// file; every valid image loads, gives exactly its expected warnings (none without a .expected)
// and survives a canonical round trip.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "storage/image_io.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> images_in(const std::string& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(VIMG_TEST_DATA_DIR) / folder)) {
    if (entry.path().extension() == ".vimg") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The diagnostics of a file, one per line, as `vimg validate` prints them with the bare file name.
std::string messages_for(const fs::path& file, LoadResult& result) {
  result = parse_image_xml(test::read_text_file(file), file.filename().string());
  std::string text;
  for (const auto& d : result.diagnostics) text += d.to_string() + "\n";
  return text;
}

std::string expected_for(const fs::path& file) {
  fs::path expected = file;
  expected.replace_extension(".expected");
  return fs::exists(expected) ? test::read_text_file(expected) : std::string();
}

TEST(Corpus, HasAtLeastThirtyInvalidImages) { EXPECT_GE(images_in("invalid").size(), 30u); }

TEST(Corpus, EveryInvalidImageGivesItsExactMessagesAndNoImage) {
  for (const auto& file : images_in("invalid")) {
    SCOPED_TRACE(file.string());
    fs::path expected_path = file;
    expected_path.replace_extension(".expected");
    ASSERT_TRUE(fs::exists(expected_path)) << "every invalid image needs a .expected file";
    LoadResult result;
    EXPECT_EQ(messages_for(file, result), expected_for(file));
    EXPECT_FALSE(result.ok()) << "an invalid file must never yield an image";
    EXPECT_TRUE(has_errors(result.diagnostics));
    EXPECT_NE(expected_for(file).find(": error: "), std::string::npos);
  }
}

TEST(Corpus, EveryValidImageLoadsWithExactlyItsWarnings) {
  const auto files = images_in("valid");
  ASSERT_GE(files.size(), 5u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    LoadResult result;
    EXPECT_EQ(messages_for(file, result), expected_for(file));
    ASSERT_TRUE(result.ok());
    EXPECT_FALSE(has_errors(result.diagnostics));
  }
}

TEST(Corpus, ValidImagesRoundTripThroughTheCanonicalWriter) {
  for (const auto& file : images_in("valid")) {
    SCOPED_TRACE(file.string());
    const LoadResult first = parse_image_xml(test::read_text_file(file), "first");
    ASSERT_TRUE(first.ok());
    const std::string canonical = write_image_xml(*first.image);
    const LoadResult second = parse_image_xml(canonical, "second");
    ASSERT_TRUE(second.ok()) << canonical;
    // Ids assigned by the writer are the only difference allowed; a second save changes nothing.
    EXPECT_EQ(write_image_xml(*second.image), canonical);
    const LoadResult third = parse_image_xml(write_image_xml(*second.image), "third");
    ASSERT_TRUE(third.ok());
    EXPECT_EQ(*third.image, *second.image);
  }
}

TEST(Corpus, CanonicalFilesSaveToIdenticalBytes) {
  // smiley.vimg and every_kind.vimg are written canonically by hand.
  for (const char* name : {"valid/smiley.vimg", "valid/every_kind.vimg"}) {
    SCOPED_TRACE(name);
    const std::string text = test::read_text_file(fs::path(VIMG_TEST_DATA_DIR) / name);
    const LoadResult loaded = parse_image_xml(text, name);
    ASSERT_TRUE(loaded.ok());
    EXPECT_EQ(write_image_xml(*loaded.image), text);
  }
}

}  // namespace
}  // namespace vimg
