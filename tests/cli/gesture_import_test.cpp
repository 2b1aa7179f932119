// `vimg gesture import`: a real two-finger recording becomes a two-finger gesture of the same
// duration that `vimg render` plays; usage and input errors exit 2 and 1 with their messages.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";
const std::string kTraces = VIMG_TEST_DATA_DIR "/evdev/";

struct Row {
  double time_s = 0.0;
  int finger = 0;
  double x_mm = 0.0, y_mm = 0.0;
  std::string pressure, phase;
};

std::vector<Row> read_rows(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time_s,finger,x_mm,y_mm,pressure,phase");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string f[6];
    for (auto& s : f) std::getline(ss, s, ',');
    rows.push_back({std::stod(f[0]), std::stoi(f[1]), std::stod(f[2]), std::stod(f[3]), f[4], f[5]});
  }
  return rows;
}

class GestureImport : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_gesture_import_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  test::CommandRun vimg(const std::string& args) { return test::run_command("cd '" + dir_.string() + "' && '" + kVimg + "' " + args); }
  fs::path dir_;
};

// Done when: an evdev recording of two fingers becomes a two-finger gesture of the same duration.
TEST_F(GestureImport, TwoFingerRecordingBecomesATwoFingerGestureOfTheSameDurationThatRenders) {
  const auto run = vimg("gesture import '" + kTraces + "atmel-maxtouch.2-fingers-touch-release.evemu' --panel-mm 154x92.4 --out g.csv");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const std::vector<Row> rows = read_rows(dir_ / "g.csv");
  std::set<int> fingers;
  std::map<int, std::vector<Row>> by_finger;
  for (const Row& r : rows) {
    fingers.insert(r.finger);
    by_finger[r.finger].push_back(r);
  }
  EXPECT_EQ(fingers, (std::set<int>{0, 1}));
  EXPECT_DOUBLE_EQ(rows.front().time_s, 0.0);
  EXPECT_DOUBLE_EQ(rows.back().time_s, 0.824235);  // the recording's last event minus its first
  for (const auto& [finger, strokes] : by_finger) {
    EXPECT_EQ(strokes.front().phase, "down");
    EXPECT_EQ(strokes.back().phase, "up");
  }
  // The panel's 800x480 digitizer (0..799, 0..479) spans 154 x 92.4 mm: (539, 167) is at
  // 539 / 799 * 154 mm, 167 / 479 * 92.4 mm.
  EXPECT_NEAR(by_finger[0].front().x_mm, 539.0 / 799.0 * 154.0, 1e-9);
  EXPECT_NEAR(by_finger[0].front().y_mm, 167.0 / 479.0 * 92.4, 1e-9);
  EXPECT_EQ(by_finger[0].front().pressure, "1");  // no pressure axis: full pressure
  const auto render = vimg("render '" VIMG_SOURCE_DIR "/assets/examples/smiley.vimg' --gesture g.csv --out drive.csv");
  ASSERT_EQ(render.exit_code, 0) << render.out;
  std::ifstream drive(dir_ / "drive.csv");
  std::string line, last;
  std::size_t lines = 0;
  while (std::getline(drive, line)) ++lines, last = line;
  EXPECT_GT(lines, 8000u * 8 / 10);  // 0.82 s at 8000 Hz
}

TEST_F(GestureImport, EveryRecordingFormImportsAndPxPerMmScales) {
  for (const char* name : {"protocol-a.two-fingers.evemu", "getevent.two-fingers.txt", "wacom-isdv4-e6.2fg-tap.events"}) {
    const auto run = vimg("gesture import '" + kTraces + name + "' --px-per-mm 10 --out g.csv");
    ASSERT_EQ(run.exit_code, 0) << name << ": " << run.out;
    const std::vector<Row> rows = read_rows(dir_ / "g.csv");
    std::set<int> fingers;
    for (const Row& r : rows) fingers.insert(r.finger);
    EXPECT_EQ(fingers.size(), 2u) << name;
  }
  const std::vector<Row> rows = read_rows(dir_ / "g.csv");  // the Wacom tap: (1488, 692) at 10 units per mm
  EXPECT_DOUBLE_EQ(rows.front().x_mm, 148.8);
  EXPECT_DOUBLE_EQ(rows.front().y_mm, 69.2);
}

TEST_F(GestureImport, WithoutAMappingOrRangesItIsAUsageError) {
  const auto none = vimg("gesture import '" + kTraces + "atmel-maxtouch.2-fingers-touch-release.evemu' --out g.csv");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.out.find("pass --panel-mm WxH"), std::string::npos) << none.out;
  const auto no_ranges = vimg("gesture import '" + kTraces + "wacom-isdv4-e6.2fg-tap.events' --panel-mm 100x50 --out g.csv");
  EXPECT_EQ(no_ranges.exit_code, 2);
  EXPECT_NE(no_ranges.out.find("has none"), std::string::npos) << no_ranges.out;
  std::ofstream(dir_ / "empty.evemu") << "A: 35 0 0 0 0 0\nA: 36 0 479 0 0 0\nE: 0.0 0003 0039 5\nE: 0.0 0003 0035 1\n"
                                          "E: 0.0 0003 0036 1\nE: 0.0 0000 0000 0\n";
  const auto empty_range = vimg("gesture import empty.evemu --panel-mm 100x50 --out g.csv");
  EXPECT_EQ(empty_range.exit_code, 2);
  EXPECT_NE(empty_range.out.find("--panel-mm needs the digitizer's axis ranges, and empty.evemu gives an empty x range "
                                 "(min 0 = max 0, line 1); pass --px-per-mm K instead"),
            std::string::npos)
      << empty_range.out;
  const auto both = vimg("gesture import '" + kTraces + "getevent.two-fingers.txt' --panel-mm 100x50 --px-per-mm 3 --out g.csv");
  EXPECT_EQ(both.exit_code, 2);
  const auto bad_panel = vimg("gesture import '" + kTraces + "getevent.two-fingers.txt' --panel-mm 100 --out g.csv");
  EXPECT_EQ(bad_panel.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "g.csv"));
}

TEST_F(GestureImport, BadRecordingsExitOneWithFileAndLine) {
  std::ofstream(dir_ / "bad.evemu") << "E: 0.0 0003 0039 5\nE: 0.0 0003 0035 1\nE: 0.0 0003 0036 1\nE: 0.0 0000 0000 0\nnonsense here\n";
  const auto run = vimg("gesture import bad.evemu --px-per-mm 1 --out g.csv");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.out.find("bad.evemu:5: error: expected an evemu event"), std::string::npos) << run.out;
  std::ofstream(dir_ / "far.evemu") << "E: 0.0 0003 0039 5\nE: 0.0 0003 0035 20000000\nE: 0.0 0003 0036 1\nE: 0.0 0000 0000 0\n";
  const auto far = vimg("gesture import far.evemu --px-per-mm 1 --out g.csv");
  EXPECT_EQ(far.exit_code, 1);
  EXPECT_NE(far.out.find("far.evemu:4: error: finger 0 at (20000000, 1) mm is beyond 10000 mm (limit 10000)"), std::string::npos) << far.out;
  const auto fifo = vimg("gesture import /dev/zero --px-per-mm 1 --out g.csv");
  EXPECT_EQ(fifo.exit_code, 1);
  EXPECT_NE(fifo.out.find("/dev/zero: error: is not a regular file"), std::string::npos) << fifo.out;
  EXPECT_FALSE(fs::exists(dir_ / "g.csv"));
}

// A file that is not text (storage/text_bytes.hpp) gets one message naming the first byte that is
// not, counted from 0, and reading stops: no line of its bytes is shown.
TEST_F(GestureImport, ABinaryFileIsNamedOnceAsNotATextRecording) {
  std::string bytes = "# EVEMU 1.3\n";  // 12 bytes of text, then every byte value four times over
  for (int round = 0; round < 4; ++round) {
    for (int b = 0; b < 256; ++b) bytes.push_back(static_cast<char>(b));
  }
  std::ofstream(dir_ / "data.bin", std::ios::binary) << bytes;
  const auto run = vimg("gesture import data.bin --px-per-mm 1 --out g.csv");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out, "data.bin: error: this is not a text touch recording (binary data at byte 12)\n");
  // A picture: the PNG signature's first byte, 0x89, starts no UTF-8 sequence.
  std::ofstream(dir_ / "picture.png", std::ios::binary) << "\x89PNG\r\n\x1a\n" << bytes;
  const auto picture = vimg("gesture import picture.png --px-per-mm 1 --out g.csv");
  EXPECT_EQ(picture.exit_code, 1);
  EXPECT_EQ(picture.out, "picture.png: error: this is not a text touch recording (binary data at byte 0)\n");
  EXPECT_FALSE(fs::exists(dir_ / "g.csv"));
}

// A text recording with a damaged line is still read as text: that line is an error at its line,
// without its bytes.
TEST_F(GestureImport, OneLineThatIsNotTextIsAnErrorAtItsLine) {
  const std::string head = "E: 0.0 0003 0039 5\nE: 0.0 0003 0035 1\n";
  std::ofstream(dir_ / "nul.evemu", std::ios::binary)
      << head << std::string("E: 0.0 0003 \0\xff 1\n", 17) << "E: 0.0 0000 0000 0\n";
  const auto run = vimg("gesture import nul.evemu --px-per-mm 1 --out g.csv");
  EXPECT_EQ(run.exit_code, 1);
  const std::string at = std::to_string(head.size() + 12);
  EXPECT_NE(run.out.find("nul.evemu:3: error: the line is not text (binary data at byte " + at + ")\n"), std::string::npos)
      << run.out;
  EXPECT_EQ(run.out.find("\\x"), std::string::npos) << "the line's bytes are not shown: " << run.out;
  EXPECT_EQ(run.out.find("not a text touch recording"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(dir_ / "g.csv"));
}

}  // namespace
}  // namespace vimg
