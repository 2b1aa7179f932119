#include "editor/core/layout_log.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace vimg::editor {
namespace {

std::string contents(std::FILE* f) {
  std::rewind(f);
  std::string out;
  char buf[256];
  while (std::fgets(buf, sizeof buf, f)) out += buf;
  return out;
}

TEST(LayoutLog, PrintsANameWhenItAppearsAndWhenItMovesNeverTwiceTheSame) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  LayoutLog log(true, f);
  log.print("canvas", 10, 20, 300, 200);
  log.print("canvas", 10, 20, 300, 200);
  log.print("radius", 1, 2, 3, 4);
  log.print("canvas", 11, 20, 300, 200);
  log.print("radius", 1, 2, 3, 4);
  EXPECT_EQ(contents(f), "layout canvas 10 20 300 200\nlayout radius 1 2 3 4\nlayout canvas 11 20 300 200\n");
  std::fclose(f);
}

TEST(LayoutLog, ANameThatPrefixesAnotherIsItsOwnEntry) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  LayoutLog log(true, f);
  log.print("x", 1, 1, 1, 1);
  log.print("x##dot", 2, 2, 2, 2);
  log.print("x", 1, 1, 1, 1);
  EXPECT_EQ(contents(f), "layout x 1 1 1 1\nlayout x##dot 2 2 2 2\n");
  std::fclose(f);
}

TEST(LayoutLog, DisabledPrintsNothing) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  LayoutLog log(false, f);
  log.print("canvas", 10, 20, 300, 200);
  EXPECT_EQ(contents(f), "");
  std::fclose(f);
}

}  // namespace
}  // namespace vimg::editor
