// `vimg render` with hostile gestures: bounded time, bounded output, clear messages, no output.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "run_command.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

using RenderRun = test::CommandRun;

class RenderCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_render_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  RenderRun render(const std::string& gesture, const std::string& out = "out.wav") {
    const std::string cmd = "cd '" + dir_.string() + "' && timeout 20 '" VIMG_BINARY_DIR "/cli/vimg' render '" VIMG_SOURCE_DIR
                            "/assets/examples/smiley.vimg' --gesture '" + gesture + "' --out " + out + " 2>&1";
    return test::run_command(cmd);
  }

  std::string write_gesture(const std::string& rows) {
    const fs::path path = dir_ / "g.csv";
    std::ofstream(path) << "time_s,finger,x_mm,y_mm,pressure,phase\n" << rows;
    return path.string();
  }

  fs::path dir_;
};

TEST_F(RenderCommand, AGestureFarFromTimeZeroIsRefusedBeforeRendering) {
  const RenderRun r = render(write_gesture("500,0,10,10,,down\n700,0,60,60,,up\n"));
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("g.csv: error: the render would last 700 s from time 0 (limit 600 s)"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "out.wav"));
}

TEST_F(RenderCommand, HugeTimesAreRefusedWithTheirLineAndLimit) {
  const RenderRun r = render(write_gesture("0,0,10,10,,down\n1e300,0,60,60,,up\n"));
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("g.csv:3: error: time_s '1e300' is beyond 86400 s (limit 86400)"), std::string::npos) << r.out;
}

TEST_F(RenderCommand, ADeviceAsTheGestureIsRefusedWithoutReadingIt) {
  const RenderRun r = render("/dev/zero");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("/dev/zero: error: is not a regular file (a character device)"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "out.wav"));
}

TEST_F(RenderCommand, AnOrdinaryGestureStillRenders) {
  const RenderRun r = render(write_gesture("0,0,10,10,,down\n0.5,0,60,60,,up\n"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_GT(fs::file_size(dir_ / "out.wav"), 44u);
}

// A long render (a 9-minute gesture at 48 kHz) interrupted by a signal: exit 128 + signal, no
// output and no temporary left in the folder.
TEST_F(RenderCommand, AnInterruptedRenderLeavesNothingAndSaysWhichSignal) {
  std::string rows = "0,0,5,5,,down\n";
  for (int i = 1; i <= 540; ++i) rows += std::to_string(i) + ",0," + std::to_string(5 + (i % 50)) + ",60,,move\n";
  rows += "541,0,5,5,,up\n";
  const std::string gesture = write_gesture(rows);
  for (const auto& [signal_name, expected] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    const std::string cmd = "cd '" + dir_.string() + "' && ('" VIMG_BINARY_DIR "/cli/vimg' render '" VIMG_SOURCE_DIR
                            "/assets/examples/smiley.vimg' --gesture '" + gesture +
                            "' --out long.wav --rate 48000 & pid=$!; "
                            // Signal once it renders (its temporary exists): a background job of a
                            // script starts with SIGINT ignored until vimg installs its handler.
                            "for i in $(seq 400); do ls .long.wav.tmp-* >/dev/null 2>&1 && break; sleep 0.05; done; kill -" + signal_name +
                            " $pid; wait $pid; echo \"exit=$?\")";
    const test::CommandRun r = test::run_command(cmd);
    EXPECT_NE(r.out.find("exit=" + std::to_string(expected)), std::string::npos) << signal_name << "\n" << r.out;
    EXPECT_NE(r.out.find("interrupted; long.wav not written"), std::string::npos) << r.out;
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(dir_)) {
      if (e.path().filename() != "g.csv") left.push_back(e.path().filename().string());
    }
    EXPECT_TRUE(left.empty()) << signal_name << ": left " << (left.empty() ? "" : left.front());
  }
}

// A scene's data file outside the scene's folder is refused unless the user asks for it explicitly.
TEST_F(RenderCommand, VolumeDataOutsideTheSceneFolderNeedsTheExplicitFlag) {
  const std::string vimg = "'" VIMG_BINARY_DIR "/cli/vimg'";
  const std::string in_dir = "cd '" + dir_.string() + "' && ";
  ASSERT_EQ(test::run_command(in_dir + vimg + " volume make-study --seed 3 --out s").exit_code, 0);
  fs::create_directories(dir_ / "elsewhere");
  fs::rename(dir_ / "s" / "feature.nrrd", dir_ / "elsewhere" / "feature.nrrd");
  std::string scene;
  {
    std::ifstream in(dir_ / "s" / "study.vscene.xml");
    scene.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto at = scene.find("file=\"feature.nrrd\"");
  ASSERT_NE(at, std::string::npos);
  scene.replace(at, std::string("file=\"feature.nrrd\"").size(), "file=\"../elsewhere/feature.nrrd\"");
  std::ofstream(dir_ / "s" / "study.vscene.xml") << scene;
  write_gesture("");  // not used; keeps the folder layout of the other tests
  std::ofstream(dir_ / "p.csv") << "time_s,x_mm,y_mm,z_mm\n0,-20,0,0\n0.5,20,0,0\n";
  const std::string probe = in_dir + vimg + " volume probe s/study.vscene.xml --path p.csv --out f.csv";
  const test::CommandRun refused = test::run_command(probe);
  EXPECT_EQ(refused.exit_code, 1) << refused.out;
  EXPECT_NE(refused.out.find("study.vscene.xml:3: error:"), std::string::npos) << refused.out;
  EXPECT_FALSE(fs::exists(dir_ / "f.csv"));
  const test::CommandRun allowed = test::run_command(probe + " --allow-outside-files");
  EXPECT_EQ(allowed.exit_code, 0) << allowed.out;
  EXPECT_TRUE(fs::exists(dir_ / "f.csv"));
}

}  // namespace
}  // namespace vimg
