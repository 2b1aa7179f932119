// storage/shipped_data.hpp: where a program finds the shipped profiles and examples, from its own
// location (installed, moved, or in the build tree) or from VIBROIMAGE_DATA_DIR.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "storage/shipped_data.hpp"

namespace vimg {
namespace {
namespace fs = std::filesystem;

class ShippedData : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(VIMG_BINARY_DIR) / "test_output" / "shipped_data" /
            ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void make_data(const fs::path& share) { fs::create_directories(share / "vibroimage" / "profiles"); }
  fs::path root_;
};

TEST_F(ShippedData, AnInstalledProgramFindsTheShareFolderNextToItsBinFolder) {
  make_data(root_ / "prefix" / "share");
  const auto found = find_shipped_data_dir(nullptr, root_ / "prefix" / "bin" / "vimg");
  ASSERT_TRUE(found);
  EXPECT_EQ(*found, root_ / "prefix" / "share" / "vibroimage");
}

TEST_F(ShippedData, AProgramInTheBuildTreeFindsTheBuildTreesShareFolderTwoLevelsUp) {
  make_data(root_ / "build" / "share");
  const auto found = find_shipped_data_dir(nullptr, root_ / "build" / "apps" / "vimg-player" / "vimg-player");
  ASSERT_TRUE(found);
  EXPECT_EQ(*found, root_ / "build" / "share" / "vibroimage");
}

TEST_F(ShippedData, TheSearchStopsThreeLevelsUp) {
  make_data(root_ / "share");
  EXPECT_TRUE(find_shipped_data_dir(nullptr, root_ / "a" / "b" / "prog"));
  EXPECT_FALSE(find_shipped_data_dir(nullptr, root_ / "a" / "b" / "c" / "d" / "prog"));
}

TEST_F(ShippedData, AFolderWithoutProfilesDoesNotCount) {
  fs::create_directories(root_ / "prefix" / "share" / "vibroimage" / "examples");
  EXPECT_FALSE(find_shipped_data_dir(nullptr, root_ / "prefix" / "bin" / "vimg"));
}

TEST_F(ShippedData, TheEnvironmentVariableWinsWhenSetAndNotEmpty) {
  make_data(root_ / "prefix" / "share");
  EXPECT_EQ(*find_shipped_data_dir("/elsewhere/data", root_ / "prefix" / "bin" / "vimg"), fs::path("/elsewhere/data"));
  EXPECT_EQ(*find_shipped_data_dir("", root_ / "prefix" / "bin" / "vimg"), root_ / "prefix" / "share" / "vibroimage");
}

TEST_F(ShippedData, ThisTestProgramFindsTheBuildTreesLinkToTheShippedProfiles) {
  // tests/storage_tests sits two levels below the build folder, whose share/vibroimage the build
  // links to the sources' assets (cmake/VimgInstall.cmake).
  const auto found = shipped_data_dir();
  ASSERT_TRUE(found) << shipped_data_help();
  EXPECT_TRUE(fs::exists(*found / "profiles" / "lra-175hz-drv2605l.xml"));
  EXPECT_EQ(resolve_profile_argument("lra-175hz-drv2605l"), *found / "profiles" / "lra-175hz-drv2605l.xml");
  const std::vector<std::string> names = shipped_profile_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "ideal"), names.end());
}

TEST_F(ShippedData, APathOrAFileInTheWorkingFolderIsNeverReplacedByAShippedProfile) {
  EXPECT_EQ(resolve_profile_argument("profiles/lra-175hz-drv2605l"), fs::path("profiles/lra-175hz-drv2605l"));
  EXPECT_EQ(resolve_profile_argument("lra-175hz-drv2605l.xml"), fs::path("lra-175hz-drv2605l.xml"));
  EXPECT_EQ(resolve_profile_argument("no-such-profile"), fs::path("no-such-profile"));
  const fs::path here = fs::current_path();
  fs::current_path(root_);
  std::ofstream(root_ / "lra-175hz-drv2605l") << "<actuator/>";
  EXPECT_EQ(resolve_profile_argument("lra-175hz-drv2605l"), fs::path("lra-175hz-drv2605l"));
  fs::current_path(here);
}

}  // namespace
}  // namespace vimg
