// Rules of the XML image format (spec section 1) beyond the file corpus: defaults, versions,
// verbatim unknowns in place, limits, locale independence, the number format.
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

std::string document(const std::string& body, const std::string& root_attributes = "version=\"1.0\" width=\"100\" height=\"80\"") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<vibroimage " + root_attributes + ">\n" + body + "</vibroimage>\n";
}

Image load_ok(const std::string& xml) {
  const LoadResult r = parse_image_xml(xml, "t.vimg");
  EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? xml : r.diagnostics[0].to_string());
  return r.image.value_or(Image{});
}

TEST(XmlRules, DefaultsApplyToOmittedAttributes) {
  const Image image = load_ok(document(
      "<dot x=\"1\" y=\"2\"/>\n<line x1=\"0\" y1=\"0\" x2=\"5\" y2=\"5\"/>\n"
      "<surface shape=\"rect\" x=\"0\" y=\"0\" width=\"10\" height=\"10\"/>\n<interaction/>\n"));
  ASSERT_EQ(image.children.size(), 3u);
  const Dot& d = std::get<Dot>(image.children[0].body);
  EXPECT_EQ(d.radius_mm, 1.0);
  EXPECT_EQ(d.gain, 1.0);
  const Line& l = std::get<Line>(image.children[1].body);
  EXPECT_EQ(l.width_mm, 1.5);
  EXPECT_EQ(l.frequency_hz, 175.0);
  EXPECT_EQ(l.damping, 0.05);
  EXPECT_EQ(l.gain, 1.0);
  const Surface& s = std::get<Surface>(image.children[2].body);
  EXPECT_EQ(s.period_mm, 2.0);
  EXPECT_EQ(s.relief_mm, 0.5);
  EXPECT_EQ(s.pattern, SurfacePattern::sine);
  EXPECT_EQ(s.gain, 1.0);
  ASSERT_TRUE(image.interaction.has_value());
  EXPECT_EQ(image.interaction->mass_kg, 0.01);
  EXPECT_EQ(image.interaction->full_speed_mm_per_s, 100.0);
  EXPECT_EQ(image.interaction->max_deformation_mm, 1.0);
}

TEST(XmlRules, AbsentInteractionMeansDefaults) {
  const Image image = load_ok(document(""));
  EXPECT_FALSE(image.interaction.has_value());
  EXPECT_EQ(image.effective_interaction(), InteractionParams{});
}

TEST(XmlRules, AcceptsMajorOneWithAnyMinorAndKeepsIt) {
  const Image image = load_ok(document("", "version=\"1.27\" width=\"10\" height=\"10\""));
  EXPECT_EQ(image.version_major, 1);
  EXPECT_EQ(image.version_minor, 27);
  EXPECT_NE(write_image_xml(image).find("version=\"1.27\""), std::string::npos);
}

TEST(XmlRules, HigherMajorNamesBothVersions) {
  const LoadResult r = parse_image_xml(document("", "version=\"3.4\" width=\"10\" height=\"10\""), "f.vimg");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_NE(r.diagnostics[0].message.find("3.4"), std::string::npos);
  EXPECT_NE(r.diagnostics[0].message.find("1.0"), std::string::npos);
  EXPECT_EQ(r.diagnostics[0].line, 2);
}

TEST(XmlRules, CanvasLimitsAreInclusiveAtTheTop) {
  EXPECT_TRUE(parse_image_xml(document("", "version=\"1.0\" width=\"10000\" height=\"1e-3\""), "f").ok());
  EXPECT_FALSE(parse_image_xml(document("", "version=\"1.0\" width=\"-1\" height=\"1\""), "f").ok());
}

TEST(XmlRules, RangeEdgesFollowTheSpec) {
  const auto ok = [](const std::string& element) { return parse_image_xml(document(element + "\n"), "f").ok(); };
  EXPECT_TRUE(ok("<dot x=\"1\" y=\"1\" gain=\"0\"/>"));
  EXPECT_TRUE(ok("<dot x=\"1\" y=\"1\" gain=\"1\"/>"));
  EXPECT_FALSE(ok("<dot x=\"1\" y=\"1\" radius=\"0\"/>"));
  EXPECT_TRUE(ok("<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" frequency=\"1000\"/>"));
  EXPECT_FALSE(ok("<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" frequency=\"-5\"/>"));
  EXPECT_FALSE(ok("<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" damping=\"0\"/>"));
  EXPECT_TRUE(ok("<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" damping=\"0.999\"/>"));
  EXPECT_FALSE(ok("<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" gain=\"1.0000001\"/>"));
  EXPECT_FALSE(ok("<interaction maxDeformation=\"0\"/>"));
  EXPECT_TRUE(ok("<surface shape=\"polygon\" points=\" 0,0  10,0\n5,5 \"/>"));
  EXPECT_TRUE(ok("<dot x=\"-5e1\" y=\"1.5E+1\"/>"));
}

TEST(XmlRules, RejectsNonDecimalNumbers) {
  for (const char* bad : {"nan", "NaN", "-inf", "infinity", "0x1p3", "0X10", "+1", "1.", "1,5", "1 ", "", "1e999", "--1", ".5e"}) {
    SCOPED_TRACE(bad);
    const std::string xml = document(std::string("<dot x=\"") + bad + "\" y=\"1\"/>\n");
    const LoadResult r = parse_image_xml(xml, "f.vimg");
    if (std::string(bad) == "1.") {
      // "1." is a valid decimal for from_chars; it is accepted and means 1.
      EXPECT_TRUE(r.ok());
      continue;
    }
    EXPECT_FALSE(r.ok());
  }
}

TEST(XmlRules, UnknownElementsStayInPlaceVerbatim) {
  const Image image = load_ok(document(
      "<dot id=\"a\" x=\"1\" y=\"1\"/>\n<future kind=\"x\"><inner>t &amp; u</inner></future>\n"
      "<group id=\"g\"><dot id=\"b\" x=\"2\" y=\"2\"/><other/></group>\n"));
  ASSERT_EQ(image.children.size(), 3u);
  const auto* unknown = std::get_if<UnknownElement>(&image.children[1].body);
  ASSERT_NE(unknown, nullptr);
  EXPECT_EQ(unknown->xml, "<future kind=\"x\"><inner>t &amp; u</inner></future>");
  const Group& g = std::get<Group>(image.children[2].body);
  ASSERT_EQ(g.children.size(), 2u);
  EXPECT_EQ(std::get<UnknownElement>(g.children[1].body).xml, "<other/>");
  const std::string xml = write_image_xml(image);
  EXPECT_LT(xml.find("id=\"a\""), xml.find("<future"));
  EXPECT_LT(xml.find("<future"), xml.find("id=\"g\""));
  EXPECT_LT(xml.find("id=\"b\""), xml.find("<other/>"));
}

TEST(XmlRules, UnknownAttributesAreKeptInOrderWithWarnings) {
  const LoadResult r = parse_image_xml(document("<dot x=\"1\" y=\"1\" zeta=\"2\" alpha=\"&quot;q&quot;\"/>\n"), "f.vimg");
  ASSERT_TRUE(r.ok());
  const Element& e = r.image->children[0];
  ASSERT_EQ(e.extra_attributes.size(), 2u);
  EXPECT_EQ(e.extra_attributes[0], (std::pair<std::string, std::string>{"zeta", "2"}));
  EXPECT_EQ(e.extra_attributes[1], (std::pair<std::string, std::string>{"alpha", "\"q\""}));
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.diagnostics[0].severity, Diagnostic::Severity::warning);
  EXPECT_EQ(r.diagnostics[0].to_string(), "f.vimg:3: warning: unknown attribute 'zeta' on <dot> kept as is");
}

TEST(XmlRules, UnknownContentOfMetaToolAndInteractionSurvivesTheRoundTrip) {
  const LoadResult r = parse_image_xml(
      document("<meta lang=\"de\"><title>T</title><tool name=\"x\" version=\"2\" build=\"7\"/></meta>\n"
               "<interaction mass=\"0.02\"><finger model=\"soft\"/></interaction>\n"),
      "f.vimg");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 3u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "f.vimg:3: warning: unknown attribute 'lang' on <meta> kept as is");
  EXPECT_EQ(r.diagnostics[1].to_string(), "f.vimg:3: warning: unknown attribute 'build' on <tool> kept as is");
  EXPECT_EQ(r.diagnostics[2].to_string(), "f.vimg:4: warning: unknown element <finger> in <interaction> kept as is");
  const Image& image = *r.image;
  EXPECT_EQ(image.meta->extra_attributes, (ExtraAttributes{{"lang", "de"}}));
  EXPECT_EQ(image.meta->tool->extra_attributes, (ExtraAttributes{{"build", "7"}}));
  ASSERT_EQ(image.interaction->unknown_children.size(), 1u);
  EXPECT_EQ(image.interaction->unknown_children[0].xml, "<finger model=\"soft\"/>");
  const std::string xml = write_image_xml(image);
  const LoadResult again = parse_image_xml(xml, "again.vimg");
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(*again.image, image);
  EXPECT_EQ(write_image_xml(*again.image), xml);
}

TEST(XmlRules, WarningsDoNotStopLoading) {
  const LoadResult r = parse_image_xml(document("<dot x=\"500\" y=\"1\"/>\n<blob/>\n"), "f.vimg");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.diagnostics.size(), 2u);
  EXPECT_FALSE(has_errors(r.diagnostics));
}

TEST(XmlRules, PrimitivePartlyOnTheCanvasIsNotWarned) {
  const LoadResult r = parse_image_xml(document("<dot x=\"100.5\" y=\"40\" radius=\"1\"/>\n"), "f.vimg");
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.diagnostics.empty());
}

TEST(XmlRules, ErrorLinesAreTheLinesOfTheProblem) {
  const LoadResult r = parse_image_xml(document("\n\n\n<dot x=\"1\" y=\"1\"/>\n\n<dot x=\"1\" y=\"1\"\n   gain=\"7\"/>\n"), "f.vimg");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].line, 9);
}

TEST(XmlRules, FilesOverTheSizeLimitAreRejectedBeforeParsing) {
  std::string xml = document("<dot x=\"1\" y=\"1\"/>\n");
  xml.append(kMaxImageFileBytes + 1 - xml.size(), ' ');
  const LoadResult r = parse_image_xml(xml, "big.vimg");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].to_string(), "big.vimg: error: file is larger than 64 MiB (limit 67108864)");
  xml.pop_back();
  EXPECT_TRUE(parse_image_xml(xml, "ok.vimg").ok()) << "exactly 64 MiB is allowed";
}

TEST(XmlRules, LoadFileRejectsOversizedFiles) {
  test::TempDir dir("big");
  std::string xml = document("");
  xml.append(kMaxImageFileBytes + 10 - xml.size(), '\n');
  test::write_text_file(dir / "big.vimg", xml);
  const LoadResult r = load_image_file(dir / "big.vimg");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.diagnostics[0].message.find("larger than 64 MiB"), std::string::npos);
}

TEST(XmlRules, MissingFileIsAnErrorNamingIt) {
  const LoadResult r = load_image_file("/nonexistent/dir/x.vimg");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].file, "/nonexistent/dir/x.vimg");
  EXPECT_NE(r.diagnostics[0].to_string().find("cannot open"), std::string::npos);
}

TEST(XmlRules, MetaTextSurvivesIncludingWhitespaceAndMarkup) {
  Image image;
  Meta meta;
  meta.title = "  ";
  meta.description = "line one\n  line two & <three>\t\"q\"";
  meta.tags = {"", "a b"};
  meta.created = "2026-01-02";
  image.meta = meta;
  const Image back = load_ok(write_image_xml(image));
  EXPECT_EQ(back, image);
}

TEST(NumberText, FormatIsShortestAndReadsBackExactly) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::uint64_t> bits;
  int checked = 0;
  while (checked < 20000) {
    const std::uint64_t b = bits(rng);
    double v = 0.0;
    std::memcpy(&v, &b, sizeof v);
    if (!std::isfinite(v)) continue;
    ++checked;
    const std::string text = format_decimal(v);
    const ParsedNumber back = parse_decimal(text);
    ASSERT_TRUE(std::holds_alternative<double>(back)) << text;
    ASSERT_EQ(std::get<double>(back), v) << text;
  }
  EXPECT_EQ(format_decimal(0.1), "0.1");
  EXPECT_EQ(format_decimal(175.0), "175");
  EXPECT_EQ(format_decimal(0.05), "0.05");
  EXPECT_EQ(format_decimal(1.0 / 3.0), "0.3333333333333333");
}

// Switches the process to a comma-decimal locale for one test, building it with localedef when the
// system has none installed.
class CommaLocale {
 public:
  CommaLocale() {
    for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8"}) {
      if (std::setlocale(LC_ALL, name) != nullptr) {
        active_ = true;
        return;
      }
    }
    const std::string cmd = "localedef -i de_DE -f UTF-8 " + (dir_.path() / "de_DE.UTF-8").string() + " >/dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0) {
      ::setenv("LOCPATH", dir_.path().c_str(), 1);
      active_ = std::setlocale(LC_ALL, "de_DE.UTF-8") != nullptr;
    }
  }
  ~CommaLocale() {
    std::setlocale(LC_ALL, "C");
    ::unsetenv("LOCPATH");
  }
  bool active() const { return active_ && std::localeconv()->decimal_point[0] == ','; }

 private:
  test::TempDir dir_{"locale"};
  bool active_ = false;
};

TEST(XmlRules, NumbersIgnoreTheProcessLocale) {
  CommaLocale locale;
  if (!locale.active()) GTEST_SKIP() << "no comma-decimal locale available and localedef could not build one";
  const Image image = load_ok(document("<dot x=\"12.75\" y=\"3.5e-1\" radius=\"0.25\"/>\n"));
  const Dot& d = std::get<Dot>(image.children[0].body);
  EXPECT_EQ(d.x_mm, 12.75);
  EXPECT_EQ(d.y_mm, 0.35);
  EXPECT_EQ(d.radius_mm, 0.25);
  EXPECT_FALSE(parse_image_xml(document("<dot x=\"12,75\" y=\"1\"/>\n"), "f").ok());
  const std::string xml = write_image_xml(image);
  EXPECT_NE(xml.find("x=\"12.75\""), std::string::npos);
  EXPECT_NE(xml.find("y=\"0.35\""), std::string::npos);
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Image random = test::RandomImages(seed).make();
    const LoadResult back = parse_image_xml(write_image_xml(random), "r");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back.image, random);
  }
}

}  // namespace
}  // namespace vimg
