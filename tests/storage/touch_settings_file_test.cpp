// The touch-latency settings file (storage/touch_settings_file.hpp): what is written reads back
// exactly, each bad line is an error naming its line and is ignored, and reading never hangs.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "primitives/touch_prediction/touch_latency_defaults.hpp"
#include "storage/touch_settings_file.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

TEST(TouchSettingsFile, WhatIsWrittenReadsBackExactly) {
  std::mt19937_64 random(20261127);
  std::uniform_real_distribution<double> ms(0.0, kMaxTouchPanelLatency_s * 1e3);
  for (int i = 0; i < 500; ++i) {
    const double latency_ms = i == 0 ? 0.0 : i == 1 ? kMaxTouchPanelLatency_s * 1e3 : ms(random);
    const bool prediction = i % 2 == 0;
    const TouchSettingsRead read = parse_touch_settings(touch_settings_text(latency_ms, prediction, "vimg-editor"), "t.txt");
    ASSERT_TRUE(read.diagnostics.empty()) << read.diagnostics.front().to_string();
    ASSERT_TRUE(read.settings.latency_ms && read.settings.prediction);
    EXPECT_EQ(*read.settings.latency_ms, latency_ms);
    EXPECT_EQ(*read.settings.prediction, prediction);
  }
}

TEST(TouchSettingsFile, CommentsBlanksAndWindowsLineEndsAreFine) {
  const TouchSettingsRead read = parse_touch_settings("# a comment\r\n\r\n  touch_latency_ms=12.5 \r\n\ttouch_prediction = off\r\n", "t.txt");
  EXPECT_TRUE(read.diagnostics.empty());
  EXPECT_EQ(read.settings.latency_ms, 12.5);
  EXPECT_EQ(read.settings.prediction, false);
}

TEST(TouchSettingsFile, EachBadLineIsAnErrorOnItsLineAndIsIgnored) {
  const TouchSettingsRead read = parse_touch_settings(
      "touch_latency_ms = 500.5\n"   // 1: above the bound
      "touch_latency_ms = -1\n"      // 2: below
      "touch_latency_ms = nan\n"     // 3
      "touch_prediction = yes\n"     // 4
      "touch_latency\n"              // 5: no '='
      "colour = red\n"               // 6: unknown
      "touch_latency_ms = 30\n"      // 7: fine
      "touch_latency_ms = 31\n"      // 8: twice
      "touch_prediction = off\n",    // 9: fine
      "t.txt");
  ASSERT_EQ(read.diagnostics.size(), 7u);
  const int lines[] = {1, 2, 3, 4, 5, 6, 8};
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(read.diagnostics[i].line, lines[i]) << read.diagnostics[i].to_string();
    EXPECT_EQ(read.diagnostics[i].to_string().rfind("t.txt:" + std::to_string(lines[i]) + ": error: ", 0), 0u);
  }
  EXPECT_NE(read.diagnostics[0].message.find("from 0 to 500"), std::string::npos);
  EXPECT_NE(read.diagnostics[6].message.find("twice"), std::string::npos);
  EXPECT_EQ(read.settings.latency_ms, 30.0);
  EXPECT_EQ(read.settings.prediction, false);
}

class TouchSettingsFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_touch_settings_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(TouchSettingsFiles, AMissingFileIsNoErrorAndAWrittenOneReadsBack) {
  const fs::path file = dir_ / "config" / "touch-latency.txt";
  const TouchSettingsRead none = read_touch_settings(file);
  EXPECT_TRUE(none.diagnostics.empty());
  EXPECT_FALSE(none.settings.latency_ms || none.settings.prediction);
  ASSERT_FALSE(write_touch_settings(file, 42.25, false, "vimg-editor"));  // makes the folder too
  const TouchSettingsRead back = read_touch_settings(file);
  EXPECT_TRUE(back.diagnostics.empty());
  EXPECT_EQ(back.settings.latency_ms, 42.25);
  EXPECT_EQ(back.settings.prediction, false);
}

TEST_F(TouchSettingsFiles, AFifoIsRefusedWithoutBlocking) {
  fs::create_directories(dir_);
  const fs::path fifo = dir_ / "touch-latency.txt";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const TouchSettingsRead read = read_touch_settings(fifo);
  ASSERT_EQ(read.diagnostics.size(), 1u);
  EXPECT_NE(read.diagnostics[0].message.find("FIFO"), std::string::npos) << read.diagnostics[0].to_string();
}

}  // namespace
}  // namespace vimg
