// Attributes per file (docs/limits.md, "Structure"): with the elements per file they bound the
// time tinyxml2 spends building its tree, so that any file under the size limit validates in
// under 2 s. The count is checked by the linear pass before tinyxml2; a file over it is refused at
// the line of the first attribute too many, and nothing is parsed.
#include <gtest/gtest.h>

#include <string>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/xml_limits.hpp"

namespace vimg {
namespace {

// The root (3 attributes) and unknown elements of 60 attributes each, one per line, holding
// `attributes` attributes in all (the last element takes the rest).
std::string file_with_attributes(std::size_t attributes) {
  std::string xml = "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n";
  std::size_t left = attributes - 3;
  while (left > 0) {
    const std::size_t n = std::min<std::size_t>(left, 60);
    xml += "<x";
    for (std::size_t i = 0; i < n; ++i) xml += " a" + std::to_string(i) + "=\"\"";
    xml += "/>\n";
    left -= n;
  }
  return xml + "</vibroimage>\n";
}

TEST(XmlFileLimits, AttributesPerFileUpToTheLimitPassTheCheck) {
  EXPECT_FALSE(check_xml_limits(file_with_attributes(kMaxXmlAttributes)).has_value());
}

TEST(XmlFileLimits, OneAttributeOverTheLimitIsRefusedBeforeParsing) {
  const std::string xml = file_with_attributes(kMaxXmlAttributes + 1);
  const auto error = check_xml_limits(xml);
  ASSERT_TRUE(error.has_value());
  // The root holds 3, every element line 60: the one too many sits on the last element's line.
  const std::size_t line = 2 + (kMaxXmlAttributes - 3) / 60;
  EXPECT_EQ(error->line, static_cast<int>(line));
  const LoadResult r = parse_image_xml(xml, "a.vimg");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "a.vimg:" + std::to_string(line) + ": error: more than " +
                                              std::to_string(kMaxXmlAttributes) + " attributes in the file (limit " +
                                              std::to_string(kMaxXmlAttributes) + ")");
}

TEST(XmlFileLimits, TheLimitsLeaveRoomForTheLargestBenchmarkImage) {
  // The storage benchmark's image of 100 000 primitives in groups of ten: 110 002 elements and
  // 750 006 attributes (bench/storage_bench.cpp, docs/limits.md).
  EXPECT_GE(kMaxXmlElements * kLimitScale, 2 * 110'002u);
  EXPECT_GE(kMaxXmlAttributes * kLimitScale, 2 * 750'006u);
}

}  // namespace
}  // namespace vimg
