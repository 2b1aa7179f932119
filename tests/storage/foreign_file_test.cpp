// foreign_file_kind: files that are plainly not images are named for what they are; anything that
// may be XML (or is a PNG, or is for the XML reader to describe) is left to the readers.
#include <gtest/gtest.h>

#include <string>

#include "storage/foreign_file.hpp"
#include "storage/image_io.hpp"

namespace vimg {
namespace {

std::string what_of(std::string_view bytes) {
  const auto kind = foreign_file_kind(bytes);
  return kind ? kind->what : "";
}

TEST(ForeignFile, KnownSignaturesAreNamed) {
  EXPECT_EQ(what_of("NRRD0004\ntype: uchar\n").rfind("a NRRD volume", 0), 0u);
  EXPECT_EQ(what_of("\xFF\xD8\xFF\xE0rest").rfind("a JPEG picture", 0), 0u);
  EXPECT_EQ(what_of("GIF89a...."), "a GIF picture");
  EXPECT_EQ(what_of("%PDF-1.7\n"), "a PDF document");
  EXPECT_EQ(what_of(std::string("PK\x03\x04", 4) + "zip").rfind("a ZIP archive", 0), 0u);
  EXPECT_EQ(what_of("\x1F\x8B\x08"), "gzip-compressed data");
  EXPECT_EQ(what_of(std::string("RIFF\x24\0\0\0WAVEfmt ", 16)), "a WAV sound");
  EXPECT_EQ(what_of(std::string("II*\0", 4)), "a TIFF picture");
}

TEST(ForeignFile, TextThatCannotBeXmlIsQuotedEscapedAndShortAtItsLine) {
  const auto csv = foreign_file_kind("\n\n  time_s,x_mm\n0,1\n");
  ASSERT_TRUE(csv);
  EXPECT_EQ(csv->line, 3);
  EXPECT_EQ(csv->what, "text that is not XML, starting with 'time_s,x_mm'");
  const auto json = foreign_file_kind("\xEF\xBB\xBF{\"a\": 1}");
  ASSERT_TRUE(json);
  EXPECT_EQ(json->line, 1);
  EXPECT_EQ(json->what.rfind("JSON", 0), 0u);
  const std::string long_line = "x" + std::string(5000, 'y');
  EXPECT_LT(what_of(long_line).size(), 120u);
}

TEST(ForeignFile, WhatMayBeXmlOrIsForTheXmlReaderIsLeftAlone) {
  EXPECT_FALSE(foreign_file_kind(""));
  EXPECT_FALSE(foreign_file_kind(" \n\t\r\n"));
  EXPECT_FALSE(foreign_file_kind("<?xml version=\"1.0\"?><vibroimage/>"));
  EXPECT_FALSE(foreign_file_kind("\xEF\xBB\xBF\n  <vibroimage/>"));
  EXPECT_FALSE(foreign_file_kind("\xFF\xFE<\0v\0"));     // UTF-16: the XML reader names it
  EXPECT_FALSE(foreign_file_kind(std::string(8, '\0')));  // NUL: the XML reader gives its offset
  EXPECT_FALSE(foreign_file_kind("\xE9t\xE9"));           // not UTF-8: the XML reader quotes it
  EXPECT_FALSE(foreign_file_kind("\x89PNG\r\n\x1A\n...."));
}

TEST(ForeignFile, AnImageIsStillParsedWhateverItsFirstBlanks) {
  const std::string xml = "\n\n<vibroimage version=\"1.0\" width=\"10\" height=\"10\"><dot x=\"1\" y=\"1\" radius=\"1\"/></vibroimage>\n";
  EXPECT_TRUE(parse_image_xml(xml, "blank-lines.vimg").ok());
  EXPECT_FALSE(foreign_file_kind(xml));
}

}  // namespace
}  // namespace vimg
