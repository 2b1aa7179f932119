// The metadata of an exported clip (docs/export.md): the image's author in `.haptic`'s
// metadata.author, the image and the gesture by their file names only (a clip is shared; a path
// would name the user's folders), through clip_metadata() and through `vimg render`.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "json_reader.hpp"
#include "storage/export/clip_metadata.hpp"
#include "storage/export/haptic_clip.hpp"

namespace vimg {
namespace {

using test::Json;
using test::JsonReader;

Image image_by(std::optional<std::string> author) {
  Image image;
  Meta meta;
  meta.author = std::move(author);
  image.meta = meta;
  return image;
}

TEST(ClipMetadata, AuthorFromTheImageAndFileNamesOnly) {
  const ClipMetadata m = clip_metadata(image_by("A. Designer"), "/home/someone/private designs/smiley.vimg",
                                       "/home/someone/takes/eyes.csv", "vimg 1.2.3");
  EXPECT_EQ(m.editor, "vimg 1.2.3");
  EXPECT_EQ(m.author, "A. Designer");
  EXPECT_EQ(m.source, "smiley.vimg");
  EXPECT_EQ(m.description, "the gesture eyes.csv over smiley.vimg");
  EXPECT_EQ(m.project, "");
  EXPECT_EQ(m.tags, std::vector<std::string>{"vibroimage"});
  EXPECT_EQ(clip_metadata(image_by(std::nullopt), "a.vimg", "g.csv", "vimg").author, "");
  EXPECT_EQ(clip_metadata(Image{}, "a.vimg", "g.csv", "vimg").author, "");  // no <meta> at all
}

// The keys of the Lofelt/Meta data model v1: metadata {editor, author, source, project, tags, description}.
TEST(ClipMetadata, HapticMetadataHasEveryKeyOfTheDataModel) {
  HapticClip clip;
  clip.duration_s = 0.1;
  clip.amplitude = {{0.0, 0.5}, {0.1, 0.5}};
  clip.frequency = {{0.0, 0.5}, {0.1, 0.5}};
  clip.metadata = clip_metadata(image_by("A. \"Quoted\" Designer"), "/x/y.vimg", "/x/g.csv", "vimg");
  const Json haptic = JsonReader::parse(write_meta_haptic(clip));
  std::set<std::string> keys;
  for (const auto& [key, value] : haptic["metadata"].object()) keys.insert(key);
  EXPECT_EQ(keys, (std::set<std::string>{"editor", "author", "source", "project", "tags", "description"}));
  EXPECT_EQ(haptic["metadata"]["author"].string(), "A. \"Quoted\" Designer");
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// smiley.vimg's <meta> names "A. Designer"; it and the gesture are given by absolute paths.
TEST(ClipMetadata, VimgRenderWritesTheAuthorAndNoFolders) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("vimg_clip_metadata_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string vimg = VIMG_BINARY_DIR "/cli/vimg";
  const std::filesystem::path image = VIMG_SOURCE_DIR "/assets/examples/smiley.vimg";
  const std::filesystem::path gesture = VIMG_SOURCE_DIR "/assets/gestures/smiley_eyes.csv";
  for (const char* name : {"eyes.haptic", "eyes.ahap"}) {
    const std::string command = "'" + vimg + "' render '" + image.string() + "' --gesture '" + gesture.string() +
                                "' --out '" + (dir / name).string() + "'";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const std::string text = read_file(dir / name);
    EXPECT_EQ(text.find(image.parent_path().string()), std::string::npos) << name << " names a folder:\n" << text;
    EXPECT_EQ(text.find(gesture.parent_path().string()), std::string::npos) << name << " names a folder:\n" << text;
    const Json json = JsonReader::parse(text);
    if (std::string(name) == "eyes.haptic") {
      EXPECT_EQ(json["metadata"]["author"].string(), "A. Designer");
      EXPECT_EQ(json["metadata"]["source"].string(), "smiley.vimg");
      EXPECT_EQ(json["metadata"]["description"].string(), "the gesture smiley_eyes.csv over smiley.vimg");
    } else {
      EXPECT_EQ(json["Metadata"]["Description"].string(), "the gesture smiley_eyes.csv over smiley.vimg");
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vimg
