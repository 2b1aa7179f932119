#include "storage/csv_lines.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace vimg {
namespace {

std::vector<std::string> rows_of(CsvLines& lines) {
  std::vector<std::string> rows;
  while (const auto row = lines.row()) rows.push_back(std::to_string(lines.line()) + ":" + std::string(*row));
  return rows;
}

TEST(CsvLines, HeaderThenRowsWithTheirLineNumbersPastBlankAndCommentLines) {
  CsvLines lines("\n# note\na,b\r\n\n1,2\r\n# more\n3,4");
  ASSERT_EQ(lines.header(), "a,b");
  EXPECT_EQ(lines.line(), 3);
  EXPECT_EQ(rows_of(lines), (std::vector<std::string>{"5:1,2", "7:3,4"}));
  EXPECT_EQ(lines.line(), 7);
  EXPECT_FALSE(lines.past_row_limit());
}

TEST(CsvLines, TheLastLineCountsBlankLinesAtTheEnd) {
  CsvLines lines("a\n1\n\n\n");
  ASSERT_EQ(lines.header(), "a");
  EXPECT_EQ(rows_of(lines), (std::vector<std::string>{"2:1"}));
  EXPECT_EQ(lines.line(), 4);
}

TEST(CsvLines, NoHeaderInAnEmptyOrBlankText) {
  CsvLines empty("");
  EXPECT_FALSE(empty.header());
  EXPECT_EQ(empty.line(), 0);
  CsvLines blank("\n\r\n# only a comment\n");
  EXPECT_FALSE(blank.header());
  EXPECT_EQ(blank.line(), 3);
}

TEST(CsvLines, OnlyOneCarriageReturnGoesUnlessBlanksAreTrimmed) {
  CsvLines exact(" a ,b\r\r\n  # not a comment here\n");
  EXPECT_EQ(exact.header(), " a ,b\r");
  EXPECT_EQ(exact.row(), "  # not a comment here");
  CsvLines trimmed(" a ,b\r\r\n  # a comment\n\t1,2 \n", {.trim_blanks = true});
  EXPECT_EQ(trimmed.header(), "a ,b");
  EXPECT_EQ(rows_of(trimmed), (std::vector<std::string>{"3:1,2"}));
}

TEST(CsvLines, CommentsCanBeRows) {
  CsvLines lines("a\n# 1\n", {.comments = false});
  EXPECT_EQ(lines.header(), "a");
  EXPECT_EQ(lines.row(), "# 1");
}

TEST(CsvLines, TheRowPastTheLimitEndsTheRowsAtItsLine) {
  CsvLines lines("h\n1\n\n2\n3\n4\n", {.max_rows = 2});
  ASSERT_EQ(lines.header(), "h");
  EXPECT_EQ(rows_of(lines), (std::vector<std::string>{"2:1", "4:2"}));
  EXPECT_TRUE(lines.past_row_limit());
  EXPECT_EQ(lines.line(), 5);
  EXPECT_EQ(lines.row_limit_problem(), "more than 2 rows (limit 2)");
  EXPECT_FALSE(lines.row());
  EXPECT_EQ(lines.line(), 5);
}

TEST(CsvLines, RowsUpToTheLimitAreAllRead) {
  CsvLines lines("h\n1\n2\n", {.max_rows = 2});
  ASSERT_EQ(lines.header(), "h");
  EXPECT_EQ(rows_of(lines).size(), 2u);
  EXPECT_FALSE(lines.past_row_limit());
}

}  // namespace
}  // namespace vimg
