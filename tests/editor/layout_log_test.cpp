#include "editor/core/layout_log.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

namespace vimg::editor {
namespace {

// What a LayoutLog writes while `use` prints through it.
std::string printed(bool enabled, const std::function<void(LayoutLog&)>& use) {
  std::FILE* f = std::tmpfile();
  if (!f) return "(no temporary file)";
  LayoutLog log(enabled, f);
  use(log);
  std::rewind(f);
  std::string out;
  char buf[256];
  while (std::fgets(buf, sizeof buf, f)) out += buf;
  std::fclose(f);
  return out;
}

TEST(LayoutLog, PrintsANameWhenItAppearsAndWhenItMovesNeverTwiceTheSame) {
  EXPECT_EQ(printed(true,
                    [](LayoutLog& log) {
                      log.print("canvas", 10, 20, 300, 200);
                      log.print("canvas", 10, 20, 300, 200);
                      log.print("radius", 1, 2, 3, 4);
                      log.print("canvas", 11, 20, 300, 200);
                      log.print("radius", 1, 2, 3, 4);
                    }),
            "layout canvas 10 20 300 200\nlayout radius 1 2 3 4\nlayout canvas 11 20 300 200\n");
}

TEST(LayoutLog, ANameThatPrefixesAnotherIsItsOwnEntry) {
  EXPECT_EQ(printed(true,
                    [](LayoutLog& log) {
                      log.print("x", 1, 1, 1, 1);
                      log.print("x##dot", 2, 2, 2, 2);
                      log.print("x", 1, 1, 1, 1);
                    }),
            "layout x 1 1 1 1\nlayout x##dot 2 2 2 2\n");
}

TEST(LayoutLog, DisabledPrintsNothing) {
  EXPECT_EQ(printed(false, [](LayoutLog& log) { log.print("canvas", 10, 20, 300, 200); }), "");
}

}  // namespace
}  // namespace vimg::editor
