// What XML 1.0 forbids and tinyxml2 accepts (storage/xml_characters.hpp): control characters,
// references to undefined entities or to characters XML does not allow, a bare '&', and '<' in
// an attribute value. Each is refused before parsing with `FILE:LINE: error:` at its own line;
// everything well-formed still loads.
#include <gtest/gtest.h>

#include <string>

#include "storage/image_io.hpp"
#include "storage/xml_characters.hpp"
#include "storage/xml_limits.hpp"

namespace vimg {
namespace {

const std::string kRoot = "<vibroimage version=\"1.0\" width=\"100\" height=\"80\">\n";

std::string first_error(const LoadResult& r) {
  for (const auto& d : r.diagnostics) {
    if (d.severity == Diagnostic::Severity::error) return d.to_string();
  }
  return "";
}

// kRoot, a line of filler, then `line3`, then the end of the root.
std::string with_third_line(const std::string& line3) { return kRoot + "<!-- two -->\n" + line3 + "\n</vibroimage>\n"; }

TEST(XmlCharacters, PredefinedEntitiesAndAllowedCharacterReferencesPass) {
  for (const char* ok : {"&lt;", "&gt;", "&amp;", "&apos;", "&quot;", "&#9;", "&#10;", "&#13;", "&#32;", "&#x41;",
                         "&#xD7FF;", "&#xE000;", "&#xFFFD;", "&#x10000;", "&#x10FFFF;", "&#1114111;", "&#00000000000000065;", "&amp; more"}) {
    EXPECT_EQ(reference_error(ok), std::nullopt) << ok;
  }
}

TEST(XmlCharacters, EveryForbiddenReferenceIsNamed) {
  const struct {
    const char* text;
    const char* problem;
  } cases[] = {
      {"& b", "a '&' that starts no reference ('& b'); write '&amp;' for the character itself"},
      {"&", "a '&' that starts no reference ('&'); write '&amp;' for the character itself"},
      {"&nbsp;", "the entity '&nbsp;' is not defined (this format has no DTD: only &lt; &gt; &amp; &apos; &quot;)"},
      {"&;", "the entity '&;' is not defined (this format has no DTD: only &lt; &gt; &amp; &apos; &quot;)"},
      {"&#0;", "the character reference '&#0;' names a character XML does not allow"},
      {"&#x1B;", "the character reference '&#x1B;' names a character XML does not allow"},
      {"&#xD800;", "the character reference '&#xD800;' names a character XML does not allow"},
      {"&#xFFFE;", "the character reference '&#xFFFE;' names a character XML does not allow"},
      {"&#x110000;", "the character reference '&#x110000;' names a character XML does not allow"},
      {"&#99999999999;", "the character reference '&#99999999999;' names a character XML does not allow"},
      {"&#;", "the character reference '&#;' is malformed"},
      {"&#x;", "the character reference '&#x;' is malformed"},
      {"&#-5;", "the character reference '&#-5;' is malformed"},
      {"&#12a;", "the character reference '&#12a;' is malformed"},
      {"&#X41;", "the character reference '&#X41;' is malformed"},
      {"&#x1g;", "the character reference '&#x1g;' is malformed"},
      {"&lt", "a '&' that starts no reference ('&lt'); write '&amp;' for the character itself"},
  };
  for (const auto& c : cases) {
    const auto problem = reference_error(c.text);
    ASSERT_TRUE(problem.has_value()) << c.text;
    EXPECT_EQ(*problem, c.problem);
  }
}

TEST(XmlCharacters, ControlBytesOtherThanTabNewlineAndReturnAreFound) {
  for (int b = 1; b < 0x20; ++b) {
    const std::string text = std::string("ab") + static_cast<char>(b) + "c";
    const bool allowed = b == '\t' || b == '\n' || b == '\r';
    EXPECT_EQ(find_forbidden_control_byte(text), allowed ? std::string::npos : 2u) << b;
  }
  EXPECT_EQ(find_forbidden_control_byte("plain \x7F text \xC3\xA9"), std::string::npos);  // DEL and UTF-8 are allowed
}

TEST(XmlCharacters, EachIsRefusedAtItsLineBeforeParsing) {
  const struct {
    std::string line3;
    std::string error;
  } cases[] = {
      {"<meta>a \x01 b</meta>", "c.vimg:3: error: a control character (byte 0x01) at offset " + std::to_string((kRoot + "<!-- two -->\n<meta>a ").size()) +
           ", which XML does not allow"},
      {"<meta>Tom & Jerry</meta>",
       "c.vimg:3: error: a '&' that starts no reference ('& Jerry'); write '&amp;' for the character itself"},
      {"<meta>&copy;</meta>",
       "c.vimg:3: error: the entity '&copy;' is not defined (this format has no DTD: only &lt; &gt; &amp; &apos; &quot;)"},
      {"<meta>&#0;</meta>", "c.vimg:3: error: the character reference '&#0;' names a character XML does not allow"},
      {"<dot x=\"1\" y=\"1\" radius=\"1\" name=\"a&b\"/>",
       "c.vimg:3: error: a '&' that starts no reference ('&b'); write '&amp;' for the character itself"},
      {"<dot x=\"1\" y=\"1\" radius=\"1\" name='a<b'/>",
       "c.vimg:3: error: a '<' inside the value of an attribute of <dot>; write '&lt;' for the character itself"},
  };
  for (const auto& c : cases) {
    const std::string xml = with_third_line(c.line3);
    const auto checked = check_xml_limits(xml);
    ASSERT_TRUE(checked.has_value()) << c.line3;
    EXPECT_EQ(checked->line, 3) << c.line3;
    const LoadResult r = parse_image_xml(xml, "c.vimg");
    ASSERT_FALSE(r.ok()) << c.line3;
    EXPECT_EQ(first_error(r), c.error);
  }
}

TEST(XmlCharacters, OtherTextTinyxml2AcceptsButXmlForbidsIsRefusedAtItsLine) {
  const struct {
    std::string line3;
    std::string error;
  } cases[] = {
      {"<!-- a -- b -->", "c.vimg:3: error: '--' inside a comment (XML allows it only in the closing '-->')"},
      {"<!-- a --->", "c.vimg:3: error: '--' inside a comment (XML allows it only in the closing '-->')"},
      {"<meta>a ]]> b</meta>", "c.vimg:3: error: ']]>' in text outside a CDATA section; write ']]&gt;'"},
      {"<dot x=\"1\"y=\"1\"/>", "c.vimg:3: error: no space between two attributes of <dot> (before 'y')"},
      {"<?xml version=\"1.0\"?>",
       "c.vimg:3: error: an XML declaration '<?xml ...?>' that is not at the very start of the file (nothing, not even "
       "a blank, may come before it)"},
  };
  for (const auto& c : cases) {
    const LoadResult r = parse_image_xml(with_third_line(c.line3), "c.vimg");
    ASSERT_FALSE(r.ok()) << c.line3;
    EXPECT_EQ(first_error(r), c.error);
  }
  const LoadResult stray = parse_image_xml(with_third_line("</dot>"), "c.vimg");
  EXPECT_EQ(first_error(stray), "c.vimg:3: error: </dot> does not close <vibroimage> (opened at line 1)");
  const LoadResult after = parse_image_xml(kRoot + "</vibroimage>\n\n</vibroimage>\n", "c.vimg");
  EXPECT_EQ(first_error(after), "c.vimg:4: error: </vibroimage> closes no element (all are closed already)");
  const LoadResult cut = parse_image_xml(kRoot + "<group>\n<dot x=\"1\" y=\"1\"/>\n", "c.vimg");
  EXPECT_EQ(first_error(cut), "c.vimg:3: error: the file ends before <group> (opened at line 2) is closed");
  const LoadResult late = parse_image_xml(" <?xml version=\"1.0\"?>\n" + kRoot + "</vibroimage>\n", "late.vimg");
  EXPECT_EQ(first_error(late), "late.vimg:1: error: an XML declaration '<?xml ...?>' that is not at the very start of the "
                               "file (nothing, not even a blank, may come before it)");
}

TEST(XmlCharacters, WhatXmlAllowsNearThoseStillLoads) {
  const std::string xml = "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n<?xml-stylesheet href=\"a\"?>\n" + kRoot +
                          "<!-- a - b -->\n<meta>a ]] > b ]]&gt;</meta>\n<note><![CDATA[ -- ]] ]]></note>\n"
                          "<dot x=\"1\"\ty='1'\ny=\"1\" name=\"]]>\"/>\n<dot x=\"1\" y=\"1\"/>\n</vibroimage>\n";
  const LoadResult r = parse_image_xml(xml, "ok.vimg");
  EXPECT_EQ(first_error(r), "ok.vimg:8: error: not well-formed XML: a malformed attribute (a name without '=' and a quoted "
                            "value, or a name used twice in one element) (XML_ERROR_PARSING_ATTRIBUTE)")
      << "tinyxml2 finds the duplicate";
  std::string fixed = xml;
  fixed.replace(fixed.find("\ny=\"1\""), 6, "\nid=\"a\"");
  const LoadResult ok = parse_image_xml(fixed, "ok.vimg");
  EXPECT_TRUE(ok.ok()) << first_error(ok);
}

TEST(XmlCharacters, ReferencesInCommentsCdataAndInstructionsAreNotReferences) {
  const std::string xml = "<?xml version=\"1.0\"?>\n<?pi a & b?>\n" + kRoot + "<!-- a & b &nbsp; \x7F -->\n" +
                          "<note><![CDATA[ Tom & Jerry &#0; ]]></note>\n"
                          "<dot x=\"1\" y=\"1\" radius=\"1\" name=\"Tom &amp; Jerry &#x263A; &#10;\"/>\n"
                          "<meta>&lt;b&gt; &quot;&apos;</meta>\n</vibroimage>\n";
  EXPECT_EQ(check_xml_limits(xml), std::nullopt);
  const LoadResult r = parse_image_xml(xml, "ok.vimg");
  ASSERT_TRUE(r.ok()) << first_error(r);
}

TEST(XmlCharacters, ScanningStaysLinearWithManyTextSegmentsAndNoAmpersand) {
  // 200k elements with text between them and no '&' anywhere: each text segment is searched on
  // its own (a search to the end of the file from every segment would take minutes).
  std::string xml = kRoot;
  for (int i = 0; i < 100000; ++i) xml += "<x/> t\n";
  xml += "</vibroimage>\n";
  EXPECT_EQ(check_xml_limits(xml), std::nullopt);
}

}  // namespace
}  // namespace vimg
