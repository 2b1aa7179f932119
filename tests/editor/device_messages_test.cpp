// The device's messages reach the editor while it plays (editor/core/play_output.hpp,
// device_messages.hpp): a hal output's faults, as its device service formats them, come out of the
// editor's output, go to stderr as "vimg-editor: MESSAGE" and the newest to the status bar; a CSV
// file or no output says nothing.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "editor/core/device_messages.hpp"
#include "editor/core/play_output.hpp"
#include "hal/fault_log.hpp"

namespace vimg::editor {
namespace {

// A hal output whose device service has formatted `pending` (as Drv2605lOut's and HidOut's do).
class FaultyOutput final : public Output {
 public:
  explicit FaultyOutput(std::vector<std::string> pending) : pending_(std::move(pending)) {}
  DriveSink& sink() override { return sink_; }
  std::string description() const override { return "drv2605l /dev/i2c-1"; }
  std::vector<std::string> take_messages() override { return std::exchange(pending_, {}); }

 private:
  class Nothing final : public DriveSink {
    void open(double) override {}
    void write(std::span<const float>, double) override {}
    void close() override {}
  } sink_;
  std::vector<std::string> pending_;
};

// What was written to a temporary file standing for stderr.
class Log {
 public:
  Log() : file_(std::tmpfile()) {}
  ~Log() { std::fclose(file_); }
  std::FILE* file() { return file_; }
  std::string text() {
    std::fflush(file_);
    std::rewind(file_);
    std::string out;
    for (int c; (c = std::fgetc(file_)) != EOF;) out += static_cast<char>(c);
    return out;
  }

 private:
  std::FILE* file_;
};

TEST(DeviceMessages, AFaultWhilePlayingReachesStderrAndTheStatusBar) {
  const std::string over_current = describe({FaultKind::over_current, 0, 0}, "/dev/i2c-1");
  const std::string gone = describe({FaultKind::device_gone, ENODEV, 0}, "/dev/i2c-1");
  std::unique_ptr<PlayOutput> output = play_output(std::make_unique<FaultyOutput>(std::vector{over_current, gone}));
  Notices notices;
  notices.status = "playing to drv2605l:/dev/i2c-1";
  Log log;
  EXPECT_EQ(show_device_messages(output->take_messages(), "playing to drv2605l:/dev/i2c-1", notices, log.file()), 2u);
  EXPECT_EQ(log.text(), "vimg-editor: " + over_current + "\nvimg-editor: " + gone + "\n");
  EXPECT_EQ(notices.status, "playing to drv2605l:/dev/i2c-1: " + gone);
  EXPECT_FALSE(notices.error_opening);  // playing goes on: no dialog in the designer's way
  // Taken once: the next frame shows nothing new and leaves the status bar alone.
  notices.status = "autosaved";
  EXPECT_EQ(show_device_messages(output->take_messages(), "playing to drv2605l:/dev/i2c-1", notices, log.file()), 0u);
  EXPECT_EQ(notices.status, "autosaved");
}

TEST(DeviceMessages, TheHalOutputIsStillTheSinkTheRendererDrives) {
  class Counting final : public Output {
   public:
    class Sink final : public DriveSink {
     public:
      void open(double rate) override { opened_hz = rate; }
      void write(std::span<const float> drive, double) override { written += drive.size(); }
      void close() override { ++closed; }
      bool paces_stream() const override { return true; }
      std::size_t min_block_samples() const override { return 32; }
      double opened_hz = 0.0;
      std::size_t written = 0;
      int closed = 0;
    } sink_;
    DriveSink& sink() override { return sink_; }
    std::string description() const override { return "counting"; }
  };
  auto hal = std::make_unique<Counting>();
  Counting::Sink& sink = hal->sink_;
  std::unique_ptr<PlayOutput> output = play_output(std::move(hal));
  output->open(8000.0);
  const std::vector<float> block(64, 0.5f);
  output->write(block, 0.0);
  output->close();
  EXPECT_EQ(sink.opened_hz, 8000.0);
  EXPECT_EQ(sink.written, 64u);
  EXPECT_EQ(sink.closed, 1);
  EXPECT_TRUE(output->paces_stream());
  EXPECT_EQ(output->min_block_samples(), 32u);
  EXPECT_TRUE(output->take_messages().empty());
}

TEST(DeviceMessages, ACsvFileOrNoOutputSaysNothing) {
  class Nothing final : public DriveSink {
    void open(double) override {}
    void write(std::span<const float>, double) override {}
    void close() override {}
  };
  std::unique_ptr<PlayOutput> output = play_output(std::make_unique<Nothing>());
  EXPECT_TRUE(output->take_messages().empty());
}

}  // namespace
}  // namespace vimg::editor
