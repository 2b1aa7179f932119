// `vimg validate | convert | info` run as a user would (spec section 4): output and exit codes.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "storage/image_io.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class VimgCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  struct Run {
    int exit_code = -1;
    std::string out;
    std::string err;
  };

  // Runs `vimg ARGS` in `cwd` (the temp dir by default).
  Run vimg(const std::string& args, const fs::path& cwd = {}) {
    const fs::path where = cwd.empty() ? dir_ : cwd;
    const std::string cmd = "cd '" + where.string() + "' && '" VIMG_BINARY_DIR "/cli/vimg' " + args + " >'" +
                            (dir_ / "stdout.txt").string() + "' 2>'" + (dir_ / "stderr.txt").string() + "'";
    const int status = std::system(cmd.c_str());
    Run run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = slurp(dir_ / "stdout.txt");
    run.err = slurp(dir_ / "stderr.txt");
    return run;
  }

  fs::path copy_in(const std::string& source, const std::string& name) {
    fs::copy_file(source, dir_ / name, fs::copy_options::overwrite_existing);
    return dir_ / name;
  }

  fs::path dir_;
  const std::string data_ = VIMG_TEST_DATA_DIR;
  const std::string smiley_ = VIMG_SOURCE_DIR "/assets/examples/smiley.vimg";
};

TEST_F(VimgCommand, ValidateAcceptsValidFiles) {
  copy_in(smiley_, "smiley.vimg");
  const Run r = vimg("validate smiley.vimg");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "smiley.vimg: ok\n");
}

TEST_F(VimgCommand, ValidatePrintsFileLineAndProblem) {
  copy_in(data_ + "/invalid/dot_radius_negative.vimg", "bad.vimg");
  const Run r = vimg("validate bad.vimg");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out, "bad.vimg:3: error: <dot> attribute 'radius' must be > 0, got -1\n");
}

TEST_F(VimgCommand, ValidateWithWarningsIsStillValid) {
  copy_in(data_ + "/valid/outside_canvas.vimg", "w.vimg");
  const Run r = vimg("validate w.vimg");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("w.vimg:4: warning: <dot id=\"beyond\"> lies wholly outside"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("w.vimg: ok"), std::string::npos);
}

TEST_F(VimgCommand, ValidateOneInvalidAmongManyFails) {
  copy_in(smiley_, "a.vimg");
  copy_in(data_ + "/invalid/duplicate_id.vimg", "b.vimg");
  const Run r = vimg("validate a.vimg b.vimg missing.vimg");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("a.vimg: ok"), std::string::npos);
  EXPECT_NE(r.out.find("b.vimg:5: error: duplicate id 'a' (first used on line 3)"), std::string::npos);
  EXPECT_NE(r.out.find("missing.vimg: error: cannot open"), std::string::npos);
}

TEST_F(VimgCommand, ValidateUsageErrorsExitTwo) {
  EXPECT_EQ(vimg("validate").exit_code, 2);
  EXPECT_EQ(vimg("validate --strict x.vimg").exit_code, 2);
}

TEST_F(VimgCommand, ConvertToPngAndBackKeepsTheImage) {
  copy_in(smiley_, "smiley.vimg");
  const Run to_png = vimg("convert smiley.vimg smiley.png --scale 4");
  ASSERT_EQ(to_png.exit_code, 0) << to_png.err;
  const Run validate = vimg("validate smiley.png");
  EXPECT_EQ(validate.exit_code, 0);
  const Run back = vimg("convert smiley.png again.vimg");
  ASSERT_EQ(back.exit_code, 0) << back.err;
  EXPECT_EQ(slurp(dir_ / "again.vimg"), slurp(dir_ / "smiley.vimg")) << "smiley.vimg is canonical";
  const LoadResult png = load_image_file(dir_ / "smiley.png");
  ASSERT_TRUE(png.ok());
}

TEST_F(VimgCommand, ConvertNeverOverwritesItsInput) {
  copy_in(smiley_, "smiley.vimg");
  const std::string before = slurp(dir_ / "smiley.vimg");
  const Run same = vimg("convert smiley.vimg ./smiley.vimg");
  EXPECT_EQ(same.exit_code, 1);
  EXPECT_NE(same.err.find("refusing to overwrite the input"), std::string::npos) << same.err;
  EXPECT_EQ(slurp(dir_ / "smiley.vimg"), before);
}

TEST_F(VimgCommand, ConvertOfAnInvalidFileWritesNothing) {
  copy_in(data_ + "/invalid/polygon_two_points.vimg", "bad.vimg");
  const Run r = vimg("convert bad.vimg out.png");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.vimg:3: error: <surface> polygon has 2 points"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

TEST_F(VimgCommand, ConvertRejectsBadArguments) {
  copy_in(smiley_, "smiley.vimg");
  EXPECT_EQ(vimg("convert smiley.vimg").exit_code, 2);
  EXPECT_EQ(vimg("convert smiley.vimg out.png --scale").exit_code, 2);
  EXPECT_EQ(vimg("convert smiley.vimg out.png --scale 0").exit_code, 2);
  EXPECT_EQ(vimg("convert smiley.vimg out.png --scale 1,5").exit_code, 2);
  const Run ext = vimg("convert smiley.vimg out.svg");
  EXPECT_EQ(ext.exit_code, 1);
  EXPECT_NE(ext.err.find("must end in .vimg or .png"), std::string::npos);
  const Run huge = vimg("convert smiley.vimg out.png --scale 1000");
  EXPECT_EQ(huge.exit_code, 1);
  EXPECT_NE(huge.err.find("exceeds the limit"), std::string::npos) << huge.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

TEST_F(VimgCommand, InfoSummarisesTheImage) {
  copy_in(smiley_, "smiley.vimg");
  const Run r = vimg("info smiley.vimg");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("70 x 140 mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("primitives:   4 (dots 2, lines 1, surfaces 1)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("groups:       1"), std::string::npos);
  EXPECT_NE(r.out.find("title:        Smiley"), std::string::npos);
  EXPECT_NE(r.out.find("author:       A. Designer"), std::string::npos);
}

TEST_F(VimgCommand, InfoOnABrokenFileFails) {
  copy_in(data_ + "/invalid/wrong_root.vimg", "x.vimg");
  const Run r = vimg("info x.vimg");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("x.vimg:2: error: root element is <svg>"), std::string::npos) << r.err;
  EXPECT_EQ(vimg("info").exit_code, 2);
}

}  // namespace
}  // namespace vimg
