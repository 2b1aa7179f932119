// Data files named inside a volume scene (`file=`): resolved relative to the scene's folder and
// confined to it unless the loader is told otherwise, never a symbolic link, a FIFO or a device,
// never over the size limit; each refusal is `FILE:LINE: error:` naming the attribute.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "storage/limits.hpp"
#include "storage/volume/volume_scene_io.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kNrrd = "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n\n\x07";

// A scene in dir/scene/ whose one scalar data names `file`; returns the scene's path.
fs::path scene_naming(const test::TempDir& dir, const std::string& file) {
  fs::create_directories(dir / "scene");
  const fs::path scene = dir / "scene" / "s.vscene.xml";
  test::write_text_file(scene, "<volumeScene version=\"1.0\">\n<scalarData id=\"s\" file=\"" + file + "\"/>\n</volumeScene>\n");
  return scene;
}

std::string messages(const VolumeSceneLoadResult& r) {
  std::string all;
  for (const auto& d : r.diagnostics) all += d.to_string() + "\n";
  return all;
}

// The scene's message about its line 2 (the data element), which must come first.
void expect_refused(const VolumeSceneLoadResult& r, const fs::path& scene, const std::string& file, const std::string& why) {
  EXPECT_FALSE(r.ok());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].to_string(),
            scene.string() + ":2: error: <scalarData> attribute 'file' = \"" + file + "\": " + why)
      << messages(r);
}

const std::string kOutside =
    "leads outside the scene's folder (data files must be in it or below it unless loading is allowed to leave it)";

TEST(VolumePaths, FilesInTheScenesFolderOrBelowLoad) {
  test::TempDir dir("vp_ok");
  const fs::path scene = scene_naming(dir, "sub/./v.nrrd");
  fs::create_directories(dir / "scene" / "sub");
  test::write_text_file(dir / "scene" / "sub" / "v.nrrd", kNrrd);
  const VolumeSceneLoadResult r = load_volume_scene_file(scene);
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.loaded->scalars.at("s")->values(), std::vector<float>{7.0f});
}

TEST(VolumePaths, LeavingTheFolderIsRefused) {
  test::TempDir dir("vp_up");
  test::write_text_file(dir / "outside.nrrd", kNrrd);
  const fs::path up = scene_naming(dir, "../outside.nrrd");
  expect_refused(load_volume_scene_file(up), up, "../outside.nrrd", kOutside);
  const fs::path sneaky = scene_naming(dir, "sub/../../outside.nrrd");
  expect_refused(load_volume_scene_file(sneaky), sneaky, "sub/../../outside.nrrd", kOutside);
  const std::string absolute = (dir / "outside.nrrd").string();
  const fs::path abs = scene_naming(dir, absolute);
  expect_refused(load_volume_scene_file(abs), abs, absolute, kOutside);
}

TEST(VolumePaths, ADirectorySymlinkLeavingTheFolderIsRefused) {
  test::TempDir dir("vp_dirlink");
  fs::create_directories(dir / "elsewhere");
  test::write_text_file(dir / "elsewhere" / "v.nrrd", kNrrd);
  const fs::path scene = scene_naming(dir, "link/v.nrrd");
  fs::create_directory_symlink(dir / "elsewhere", dir / "scene" / "link");
  expect_refused(load_volume_scene_file(scene), scene, "link/v.nrrd", kOutside);
}

TEST(VolumePaths, TheFileItselfMustNotBeASymlink) {
  test::TempDir dir("vp_link");
  const fs::path scene = scene_naming(dir, "v.nrrd");
  test::write_text_file(dir / "scene" / "real.nrrd", kNrrd);
  fs::create_symlink("real.nrrd", dir / "scene" / "v.nrrd");
  expect_refused(load_volume_scene_file(scene), scene, "v.nrrd", "is a symbolic link (name the file itself)");
}

TEST(VolumePaths, AFifoIsRefusedWithoutBlocking) {
  test::TempDir dir("vp_fifo");
  const fs::path scene = scene_naming(dir, "pipe.nrrd");
  const fs::path fifo = dir / "scene" / "pipe.nrrd";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  VolumeSceneLoadResult r;
  {
    const test::FifoReleaser release(fifo);
    r = load_volume_scene_file(scene);
  }
  expect_refused(r, scene, "pipe.nrrd", "is not a regular file (a FIFO)");
}

TEST(VolumePaths, AFileOverTheSizeLimitIsNotRead) {
  test::TempDir dir("vp_big");
  const fs::path scene = scene_naming(dir, "big.nrrd");
  { std::ofstream(dir / "scene" / "big.nrrd").put('N'); }
  fs::resize_file(dir / "scene" / "big.nrrd", kMaxVolumeFileBytes + 1);  // sparse
  expect_refused(load_volume_scene_file(scene), scene, "big.nrrd", "is larger than 1024 MiB (limit 1073741824 bytes)");
}

TEST(VolumePaths, TheCallerMayAllowFilesElsewhereButNeverDevices) {
  test::TempDir dir("vp_allow");
  test::write_text_file(dir / "outside.nrrd", kNrrd);
  VolumeSceneLoadOptions options;
  options.allow_files_outside_scene_folder = true;
  const VolumeSceneLoadResult up = load_volume_scene_file(scene_naming(dir, "../outside.nrrd"), options);
  EXPECT_TRUE(up.ok()) << messages(up);
  const fs::path zero = scene_naming(dir, "/dev/zero");
  expect_refused(load_volume_scene_file(zero, options), zero, "/dev/zero", "is not a regular file (a character device)");
}

TEST(VolumePaths, TheSceneFileItselfIsReadBounded) {
  test::TempDir dir("vp_scene");
  const fs::path fifo = dir / "s.vscene.xml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const VolumeSceneLoadResult r = load_volume_scene_file(fifo);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].to_string(), fifo.string() + ": error: is not a regular file (a FIFO)");
}

}  // namespace
}  // namespace vimg
