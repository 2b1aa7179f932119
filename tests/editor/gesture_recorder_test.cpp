#include "editor/core/gesture_recorder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "editor/core/recent_files.hpp"

namespace vimg::editor {
namespace {

TEST(GestureRecorder, WritesTheSpecHeaderAndRows) {
  GestureRecorder r;
  r.add({0.0, 0, 5.0, 20.0, 1.0, GesturePhase::down});
  r.add({0.01, 0, 6.0, 20.0, 1.0, GesturePhase::move});
  r.add({0.4, 0, 45.0, 20.0, std::nullopt, GesturePhase::up});
  std::istringstream csv(r.to_csv());
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(csv, line)) {
    if (!line.empty() && line[0] != '#') rows.push_back(line);
  }
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0], "time_s,finger,x_mm,y_mm,pressure,phase");
  EXPECT_EQ(rows[1], "0,0,5,20,1,down");
  EXPECT_EQ(rows[3], "0.4,0,45,20,,up");  // no pressure reported: the cell stays empty
  // What the recorder writes, the gesture reader reads back: one stroke, the same points.
  const GestureParseResult back = parse_gesture_csv(r.to_csv(), "take.csv");
  ASSERT_TRUE(back.ok()) << (back.errors.empty() ? "" : back.errors.front());
  ASSERT_EQ(back.gesture->strokes.size(), 1u);
  const auto& points = back.gesture->strokes[0].points;
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[1].time_s, 0.01);
  EXPECT_EQ(points[2].x_mm, 45.0);
  EXPECT_EQ(points[2].pressure, 1.0);  // an empty cell reads as 1
}

TEST(GestureRecorder, TimeNeverDecreasesWithinAFinger) {
  GestureRecorder r;
  r.add({0.5, 0, 0, 0, 1.0, GesturePhase::down});
  r.add({0.2, 1, 0, 0, 1.0, GesturePhase::down});
  r.add({0.4, 0, 1, 0, 1.0, GesturePhase::move});
  EXPECT_DOUBLE_EQ(r.samples()[1].time_s, 0.2) << "another finger keeps its own time";
  EXPECT_DOUBLE_EQ(r.samples()[2].time_s, 0.5);
}

TEST(RecentFiles, MostRecentFirstWithoutDuplicatesAndPersistent) {
  const auto store = std::filesystem::path(VIMG_BINARY_DIR) / "editor_test_recent.txt";
  std::filesystem::remove(store);
  {
    RecentFiles recent(store, 3);
    recent.add("/a.vimg");
    recent.add("/b.vimg");
    recent.add("/a.vimg");
    recent.add("/c.vimg");
    recent.add("/d.vimg");
    EXPECT_EQ(recent.paths(), (std::vector<std::string>{"/d.vimg", "/c.vimg", "/a.vimg"}));
  }
  RecentFiles reloaded(store, 3);
  EXPECT_EQ(reloaded.paths(), (std::vector<std::string>{"/d.vimg", "/c.vimg", "/a.vimg"}));
  std::filesystem::remove(store);
}

TEST(RecentFiles, ADamagedOrHostileStoreGivesOnlyPlausiblePaths) {
  const std::string text = std::string("/ok/a.vimg\nrelative.vimg\n/esc\x1b[31m.vimg\n\n/ok/a.vimg\n/") +
                           std::string(5000, 'x') + "\n/ok/b.png";
  EXPECT_EQ(parse_recent_files(text, 10), (std::vector<std::string>{"/ok/a.vimg", "/ok/b.png"}));
  EXPECT_EQ(parse_recent_files(text, 1), (std::vector<std::string>{"/ok/a.vimg"}));
  // A store far over the read limit costs no more than the limit: it is not read at all (a valid
  // entry after the limit, past empty lines, which are skipped, not refused, included).
  const auto store = std::filesystem::path(VIMG_BINARY_DIR) / "editor_test_recent_huge.txt";
  { std::ofstream(store) << "/first.vimg\n" << std::string(4 * kMaxRecentFilesBytes, '\n') << "/after-the-limit.vimg\n"; }
  EXPECT_EQ(parse_recent_files("/first.vimg\n" + std::string(4 * kMaxRecentFilesBytes, '\n') + "/after-the-limit.vimg\n", 10),
            (std::vector<std::string>{"/first.vimg", "/after-the-limit.vimg"}));  // the parser alone takes it
  RecentFiles recent(store, 10);
  EXPECT_EQ(recent.paths(), (std::vector<std::string>{}));
  std::filesystem::remove(store);
  // Nor is a store that is not a regular file, which would block (a FIFO) or never end (a device).
  EXPECT_EQ(RecentFiles("/dev/zero", 10).paths(), (std::vector<std::string>{}));
}

TEST(GestureRecorder, SavesAtomicallyAndReportsAFailureWithoutLeavingATemporary) {
  GestureRecorder recorder;
  recorder.add(GestureSample{0.0, 0, 1.0, 2.0, std::nullopt, GesturePhase::down});
  recorder.add(GestureSample{0.1, 0, 3.0, 2.0, std::nullopt, GesturePhase::up});
  const auto dir = std::filesystem::path(VIMG_BINARY_DIR) / "editor_test_recorder";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "blocked.csv" / "inside");
  EXPECT_EQ(recorder.save(dir / "take.csv"), std::nullopt);
  EXPECT_EQ(recorder.to_csv().size(), std::filesystem::file_size(dir / "take.csv"));
  EXPECT_NE(recorder.save(dir / "blocked.csv"), std::nullopt);
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) entries += e.path().filename().string()[0] == '.' ? 1 : 0;
  EXPECT_EQ(entries, 0) << "no temporary file is left behind";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vimg::editor
