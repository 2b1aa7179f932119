// storage/xml_attributes.hpp: the attribute checks every XML reader shares, with their wording, the
// one number grammar (storage/number_text.hpp) and the ranges' words (storage/number_range.hpp).
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <limits>
#include <string>
#include <vector>

#include "storage/actuator_profile.hpp"
#include "storage/xml_attributes.hpp"

namespace vimg {
namespace {

// Runs `body` on the root of `xml` and returns the messages, "f.xml:LINE: error: ...".
template <class Body>
std::vector<std::string> messages_of(const std::string& xml, Body body) {
  tinyxml2::XMLDocument doc;
  EXPECT_EQ(doc.Parse(xml.c_str()), tinyxml2::XML_SUCCESS);
  DiagnosticList list("f.xml");
  XmlAttributes attributes(list);
  body(attributes, *doc.RootElement());
  std::vector<std::string> out;
  for (const Diagnostic& d : list.take()) out.push_back(d.to_string());
  return out;
}

TEST(XmlAttributes, NumbersUseTheOneGrammarAndTheRangesWords) {
  const auto number = [](const std::string& value, NumberRange range) {
    return messages_of("<e\n a=\"" + value + "\"/>", [&](XmlAttributes& x, const tinyxml2::XMLElement& e) { x.number(e, "a", range); });
  };
  EXPECT_TRUE(number("2.5", NumberRange::closed(0, 10)).empty());
  EXPECT_EQ(number("11", NumberRange::closed(0, 10)), std::vector<std::string>{"f.xml:1: error: attribute 'a' must be in [0, 10], got 11"});
  EXPECT_EQ(number("0", NumberRange::above(0)), std::vector<std::string>{"f.xml:1: error: attribute 'a' must be > 0, got 0"});
  EXPECT_EQ(number("-1", NumberRange::at_least(0)), std::vector<std::string>{"f.xml:1: error: attribute 'a' must be >= 0, got -1"});
  // What the grammar refuses, every reader refuses: a sign, blanks, hexadecimal, NaN.
  for (const char* bad : {"+5", " 5", "0x10", "nan", "5 mm", ""}) {
    const auto m = number(bad, NumberRange{});
    ASSERT_EQ(m.size(), 1u) << bad;
    EXPECT_EQ(m[0].rfind(std::string("f.xml:1: error: attribute 'a': '") + bad + "' ", 0), 0u) << m[0];
  }
}

TEST(XmlAttributes, MissingWholeBooleanAndUnknownAttributes) {
  const auto m = messages_of("<e n=\"12\" b=\"yes\" odd=\"1\" w=\"-3\"/>", [](XmlAttributes& x, const tinyxml2::XMLElement& e) {
    EXPECT_FALSE(x.text(e, "missing", true));
    EXPECT_FALSE(x.text(e, "optional"));
    EXPECT_EQ(x.whole(e, "n", 0, 20), 12u);
    EXPECT_FALSE(x.whole(e, "w", 0, 20));
    EXPECT_FALSE(x.boolean(e, "b"));
    x.check_attributes(e, {"n", "b", "w"});
  });
  const std::vector<std::string> want = {
      "f.xml:1: error: <e> needs attribute 'missing'",
      "f.xml:1: error: attribute 'w' must be a whole number in 0..20, got '-3'",
      "f.xml:1: error: attribute 'b' must be true or false, got 'yes'",
      "f.xml:1: error: unknown attribute 'odd' on <e>",
  };
  EXPECT_EQ(m, want);
}

TEST(XmlAttributes, InputInMessagesIsEscaped) {
  const auto m = messages_of("<e a=\"\x1b[2J\"/>", [](XmlAttributes& x, const tinyxml2::XMLElement& e) { x.number(e, "a", NumberRange{}); });
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].find('\x1b'), std::string::npos) << m[0];
}

// The actuator profile reads its numbers through the helper: a sign or blanks are no longer numbers
// there (they were, through a stream), and its ranges are worded as the image reader's.
TEST(XmlAttributes, TheActuatorProfileSharesThem) {
  const auto r = parse_actuator_profile("<actuator name=\"x\" type=\"lra\">\n<resonance hz=\"+175\"/>\n</actuator>\n", "p.xml");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0], "p.xml:2: error: attribute 'hz': '+175' is not a number");
}

}  // namespace
}  // namespace vimg
