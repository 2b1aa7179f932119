// Structure limits of XML files, checked before tinyxml2 builds its tree (docs/limits.md,
// "Structure"): attributes per element, nesting depth, elements per file, points per polygon.
// Each refusal is `FILE:LINE: error: … (limit N)` at the line of the element at fault.
#include <gtest/gtest.h>

#include <string>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {
namespace {

const std::string kRoot = "<vibroimage version=\"1.0\" width=\"100\" height=\"80\">\n";

// A dot (x, y, radius) with `extra` unknown attributes a0, a1, ...: 3 + extra attributes.
std::string dot_with_attributes(std::size_t extra) {
  std::string dot = "<dot x=\"1\" y=\"1\" radius=\"1\"";
  for (std::size_t i = 0; i < extra; ++i) dot += " a" + std::to_string(i) + "=\"" + std::to_string(i) + "\"";
  return dot + "/>\n";
}

std::string first_error(const LoadResult& r) {
  for (const auto& d : r.diagnostics) {
    if (d.severity == Diagnostic::Severity::error) return d.to_string();
  }
  return "";
}

TEST(XmlLimits, AnElementMayHaveUpToTheAttributeLimit) {
  // The linear pass lets 64 attributes through; the reader then refuses the unknown ones beyond
  // kMaxUnknownAttributesPerElement, not the count.
  const LoadResult r = parse_image_xml(kRoot + dot_with_attributes(kMaxAttributesPerElement - 3) + "</vibroimage>\n", "a.vimg");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(first_error(r).find("(limit " + std::to_string(kMaxUnknownAttributesPerElement) + ")"), std::string::npos)
      << first_error(r);
}

TEST(XmlLimits, WhatTheReaderKeepsTheWriterWritesWithinTheAttributeLimit) {
  // A surface rect has the most known attributes (10): with the most unknown ones the reader keeps,
  // the canonical file written back still reads.
  std::string rect = "<surface shape=\"rect\" x=\"1\" y=\"1\" width=\"5\" height=\"5\"";
  for (std::size_t i = 0; i < kMaxUnknownAttributesPerElement; ++i) rect += " a" + std::to_string(i) + "=\"1\"";
  const LoadResult r = parse_image_xml(kRoot + rect + "/>\n</vibroimage>\n", "a.vimg");
  ASSERT_TRUE(r.ok()) << first_error(r);
  ASSERT_EQ(r.image->children[0].extra_attributes.size(), kMaxUnknownAttributesPerElement);
  const LoadResult again = parse_image_xml(write_image_xml(*r.image), "again.vimg");
  EXPECT_TRUE(again.ok()) << first_error(again);

  const LoadResult one_more = parse_image_xml(kRoot + dot_with_attributes(kMaxUnknownAttributesPerElement + 1) + "</vibroimage>\n", "b.vimg");
  ASSERT_FALSE(one_more.ok());
  EXPECT_EQ(first_error(one_more), "b.vimg:2: error: <dot> has 55 unknown attributes; at most 54 are kept, so that the file "
                                   "written back stays within 64 attributes per element (limit 54)");
}

TEST(XmlLimits, OneAttributeMoreIsRefusedAtTheElementsLine) {
  const LoadResult r =
      parse_image_xml(kRoot + "\n" + dot_with_attributes(kMaxAttributesPerElement - 2) + "</vibroimage>\n", "a.vimg");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "a.vimg:3: error: <dot> has more than 64 attributes (limit 64)");
}

TEST(XmlLimits, TwoHundredThousandAttributesAreRefusedWithoutBuildingThem) {
  // 2.3 MB: the element tinyxml2 would check in about 2e10 name comparisons.
  const std::string xml = kRoot + dot_with_attributes(200'000) + "</vibroimage>\n";
  ASSERT_GT(xml.size(), 2'000'000u);
  const LoadResult r = parse_image_xml(xml, "many.vimg");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "many.vimg:2: error: <dot> has more than 64 attributes (limit 64)");
}

TEST(XmlLimits, MarkupInsideValuesCommentsAndCdataIsNotCounted) {
  // An unknown element (kept verbatim, so not bound by the unknown-attribute limit of primitives).
  std::string dot = "<mark x=\"1\" y='1' radius=\"1\"";
  for (std::size_t i = 3; i < kMaxAttributesPerElement; ++i) {
    dot += " b" + std::to_string(i) + (i % 2 ? "=\"a=b /> &lt;c d='e'>\"" : "='x=\"y\" > z'");
  }
  dot += "/>\n";
  const std::string xml = "<?xml version=\"1.0\"?>\n<?pi a=b c=d?>\n" + kRoot + "<!-- <dot a=\"1\" b=\"2\"> = = = -->\n" + dot +
                          "<note><![CDATA[ <<x=y>> = </note> ]]></note>\n</vibroimage>\n";
  const LoadResult r = parse_image_xml(xml, "m.vimg");
  ASSERT_TRUE(r.ok()) << first_error(r);
  EXPECT_EQ(r.image->children.size(), 2u);
}

// Unknown elements nested inside each other below the root: the root is depth 1.
std::string nested(int depth) {
  std::string xml = kRoot;
  for (int i = 2; i <= depth; ++i) xml += "<x>\n";
  for (int i = 2; i <= depth; ++i) xml += "</x>";
  return xml + "\n</vibroimage>\n";
}

TEST(XmlLimits, NestingUpToTheLimitLoads) {
  const LoadResult r = parse_image_xml(nested(kMaxXmlNestingDepth), "n.vimg");
  EXPECT_TRUE(r.ok()) << first_error(r);
}

TEST(XmlLimits, NestingBeyondTheLimitIsRefusedAtTheDeepElement) {
  for (const int depth : {kMaxXmlNestingDepth + 1, 99, 600}) {
    SCOPED_TRACE(depth);
    const LoadResult r = parse_image_xml(nested(depth), "n.vimg");
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    // Line 1 is the root; the element at depth d starts line d.
    EXPECT_EQ(r.diagnostics[0].to_string(),
              "n.vimg:" + std::to_string(kMaxXmlNestingDepth + 1) + ": error: elements nested more than 64 deep (limit 64)");
  }
}

TEST(XmlLimits, ElementsPerFileAreCounted) {
  std::string xml = kRoot;
  xml.reserve(kMaxXmlElements * 5 + 100);
  for (std::size_t i = 1; i < kMaxXmlElements; ++i) xml += "<x/>";  // with the root: the limit exactly
  const LoadResult at_limit = parse_image_xml(xml + "\n</vibroimage>\n", "e.vimg");
  EXPECT_TRUE(at_limit.ok()) << first_error(at_limit);
  const LoadResult over = parse_image_xml(xml + "\n<!-- one more -->\n</vibroimage>\n", "e.vimg");
  ASSERT_FALSE(over.ok());
  ASSERT_EQ(over.diagnostics.size(), 1u);
  EXPECT_EQ(over.diagnostics[0].to_string(),
            "e.vimg:3: error: more than " + std::to_string(kMaxXmlElements) +
                " elements, comments and processing instructions (limit " + std::to_string(kMaxXmlElements) + ")");
}

std::string polygon(std::size_t points) {
  std::string xml = kRoot + "<surface shape=\"polygon\"\n  points=\"";
  for (std::size_t i = 0; i < points; ++i) xml += std::to_string(i % 100) + "," + std::to_string((i * 7) % 80) + " ";
  return xml + "\"/>\n</vibroimage>\n";
}

TEST(XmlLimits, PolygonPointsAreLimited) {
  const LoadResult at_limit = parse_image_xml(polygon(kMaxPolygonPoints), "p.vimg");
  ASSERT_TRUE(at_limit.ok()) << first_error(at_limit);
  EXPECT_EQ(std::get<Surface>(at_limit.image->children[0].body).points.size(), kMaxPolygonPoints);
  const LoadResult over = parse_image_xml(polygon(kMaxPolygonPoints + 1), "p.vimg");
  ASSERT_FALSE(over.ok());
  ASSERT_EQ(over.diagnostics.size(), 1u);
  EXPECT_EQ(over.diagnostics[0].to_string(), "p.vimg:3: error: <surface> polygon has more than 100000 points (limit 100000)");
}

TEST(XmlLimits, SceneElementsHaveTheSameLimits) {
  std::string device = "<device name=\"d\"";
  for (std::size_t i = 0; i < kMaxAttributesPerElement; ++i) device += " q" + std::to_string(i) + "=\"1\"";
  const VolumeSceneParseResult r =
      parse_volume_scene_xml("<volumeScene version=\"1.0\">\n" + device + "/>\n</volumeScene>\n", "s.xml");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "s.xml:2: error: <device> has more than 64 attributes (limit 64)");
  std::string deep = "<volumeScene version=\"1.0\">";
  for (int i = 0; i < 80; ++i) deep += "<a>";
  const VolumeSceneParseResult d = parse_volume_scene_xml(deep, "d.xml");
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.diagnostics[0].to_string(), "d.xml:1: error: elements nested more than 64 deep (limit 64)");
}

}  // namespace
}  // namespace vimg
