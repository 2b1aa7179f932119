#include "apps/vimg-player/status_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <string>

namespace vimg::player_app {
namespace {

bool has_line(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

TEST(StatusText, ShowsTheRenderThreadPriorityOutcomeInWords) {
  StatusText text("drv2605l /dev/i2c-1", "display dpi", 4.0);
  LoopStats stats;
  stats.priority = RealtimePriority{80, false, EPERM};
  EXPECT_TRUE(has_line(text.lines(stats, 0, false), "Render thread " + describe(stats.priority)));
  stats.priority = RealtimePriority{80, true, 0};
  EXPECT_TRUE(has_line(text.lines(stats, 0, false), "Render thread SCHED_FIFO 80"));
}

TEST(StatusText, SaysWhileTheDeviceIsGone) {
  StatusText text("hid /dev/hidraw3", "--px-per-mm", 5.0);
  const LoopStats stats;
  const std::string gone = "Device gone: output paused, reconnecting";
  EXPECT_FALSE(has_line(text.lines(stats, 0, false), gone));
  EXPECT_TRUE(has_line(text.lines(stats, 0, true), gone));
}

TEST(StatusText, KeepsTheNewestMessagesLast) {
  StatusText text("bos1901 /dev/spidev0.0", "96 dpi assumed", 3.78);
  for (std::size_t i = 1; i <= StatusText::kMessages + 2; ++i) text.note("message " + std::to_string(i));
  const auto lines = text.lines(LoopStats{}, 0, false);
  ASSERT_GE(lines.size(), StatusText::kMessages);
  for (std::size_t i = 0; i < StatusText::kMessages; ++i) {
    EXPECT_EQ(lines[lines.size() - StatusText::kMessages + i], "message " + std::to_string(i + 3));
  }
  EXPECT_FALSE(has_line(lines, "message 2"));
}

}  // namespace
}  // namespace vimg::player_app
