// `vimg import`: the written files pass `vimg validate`, and the command follows the project's
// conventions (--help 0, usage errors 2, bad input 1 with FILE: error).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "png_fixture.hpp"
#include "tests/cli/run_command.hpp"

namespace vimg {
namespace {

using test::CommandRun;

CommandRun vimg(const std::string& args) { return test::run_command("'" VIMG_BINARY_DIR "/cli/vimg' " + args); }

class ImportCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("vimg_import_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return "'" + (dir_ / name).string() + "'"; }
  void write(const std::string& name, const std::string& bytes) const {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
  }
  std::filesystem::path dir_;
};

TEST_F(ImportCommand, ImportedDrawingsAndPicturesPassValidate) {
  const std::string svg = "'" VIMG_SOURCE_DIR "/tests/import/data/adwaita-parental-controls.svg'";
  CommandRun r = vimg("import " + svg + " --out " + path("icon.vimg"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = vimg("validate " + path("icon.vimg"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find(": ok"), std::string::npos);

  std::vector<std::uint8_t> px(20 * 10, 255);
  for (int y = 2; y < 8; ++y) for (int x = 5; x < 15; ++x) px[static_cast<std::size_t>(y * 20 + x)] = 0;
  write("square.png", test::make_png(20, 10, 1, px));
  r = vimg("import " + path("square.png") + " --out " + path("square.png.vimg") + " --width-mm 40 --levels 2");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = vimg("validate " + path("square.png.vimg"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  // Written as a PNG vibroimage too.
  r = vimg("import " + path("square.png") + " --out " + path("square_vimg.png") + " --width-mm 40");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(vimg("validate " + path("square_vimg.png")).exit_code, 0);
  // Importing that PNG again opens it: it already is a vibroimage.
  r = vimg("import " + path("square_vimg.png") + " --out " + path("again.vimg") + " --width-mm 40");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("opened as one, not imported"), std::string::npos) << r.out;
}

TEST_F(ImportCommand, FollowsTheCommandLineConventions) {
  EXPECT_EQ(vimg("import --help").exit_code, 0);
  EXPECT_EQ(vimg("import x.svg").exit_code, 2);  // --out missing
  EXPECT_EQ(vimg("import x.png --out y.vimg --levels 0").exit_code, 2);
  EXPECT_EQ(vimg("import x.png --out y.vimg --width-mm nan").exit_code, 2);
  write("bad.svg", "<svg width='10mm' height='10mm'>\n<rect");
  CommandRun r = vimg("import " + path("bad.svg") + " --out " + path("bad.vimg"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("bad.svg:2: error:"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.vimg"));
  write("p.png", test::make_png(2, 2, 1, {0, 0, 0, 0}));
  r = vimg("import " + path("p.png") + " --out " + path("p.vimg"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("p.png: error: a picture needs the width"), std::string::npos) << r.out;
  write("n.txt", "x");
  EXPECT_EQ(vimg("import " + path("n.txt") + " --out " + path("n.vimg")).exit_code, 1);
}

TEST_F(ImportCommand, SigintAndSigtermWriteNothingAndExit130And143) {
  // A picture large enough that the import is still running when the signal comes.
  const int w = 300, h = 250;
  std::vector<std::uint8_t> px(static_cast<std::size_t>(w * h));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) px[static_cast<std::size_t>(y * w + x)] = static_cast<std::uint8_t>((x * 7 + y * 13) % 256);
  }
  write("big.png", test::make_png(w, h, 1, px));
  for (const auto& [signal, code] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    const CommandRun r = test::run_command("{ '" VIMG_BINARY_DIR "/cli/vimg' import " + path("big.png") + " --out " + path("big.vimg") +
                                           " --width-mm 100 --levels 16 & sleep 0.2; kill -" + signal + " $!; wait $!; echo exit=$?; }");
    EXPECT_NE(r.out.find("exit=" + std::to_string(code)), std::string::npos) << r.out;
    // The message comes from the import's own handler; a signal that arrives before it is installed
    // (a slow start, e.g. under the sanitizers) meets vimg's handler, which exits as quietly.
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename(), "big.png") << "left behind: " << entry.path();
  }
}

}  // namespace
}  // namespace vimg
