#include "editor/core/gesture_recorder.hpp"

#include <gtest/gtest.h>

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
  EXPECT_EQ(rows[1], "0.000,0,5.000,20.000,1.000,down");
  EXPECT_EQ(rows[3], "0.400,0,45.000,20.000,,up");
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

}  // namespace
}  // namespace vimg::editor
