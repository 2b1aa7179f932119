// What `vimg separate` may change (study/separate_space.hpp): tactile parameters only, inside the
// format's ranges, every primitive of an image by the same step; the changes as a report lists them.
#include <gtest/gtest.h>

#include <random>

#include "storage/image_io.hpp"
#include "storage/parameter_table.hpp"
#include "study/separate_space.hpp"

namespace vimg {
namespace {

using study::SeparationSetting;
using study::TactileParameter;

Image parse(const std::string& body) {
  const std::string xml = "<?xml version=\"1.0\"?>\n<vibroimage version=\"1.0\" width=\"60\" height=\"110\">\n" + body +
                          "</vibroimage>\n";
  LoadResult r = parse_image_xml(xml, "test.vimg");
  EXPECT_TRUE(r.image.has_value());
  return r.image ? *r.image : Image{};
}

const char* kMixed =
    "<group id=\"g\"><surface id=\"crown\" shape=\"ellipse\" cx=\"30\" cy=\"40\" rx=\"9\" ry=\"9\" period=\"3\" "
    "relief=\"0.8\" pattern=\"triangle\" gain=\"0.7\"/>\n"
    "<line id=\"trunk\" x1=\"30\" y1=\"50\" x2=\"30\" y2=\"70\" width=\"3\" frequency=\"80\" damping=\"0.15\" gain=\"0.8\"/></group>\n"
    "<surface id=\"skin\" shape=\"rect\" x=\"5\" y=\"80\" width=\"20\" height=\"20\" period=\"1.2\" relief=\"0.3\" "
    "pattern=\"sine\" gain=\"1\"/>\n<dot id=\"valve\" x=\"10\" y=\"10\" radius=\"1\" gain=\"0.05\"/>\n";

// Every number of every primitive, in paint order, with what it is.
void collect(const std::vector<Element>& elements, std::vector<std::pair<std::string, double>>& out,
             std::vector<std::pair<std::string, double>>& geometry) {
  for (const Element& e : elements) {
    if (const auto* g = std::get_if<Group>(&e.body)) {
      collect(g->children, out, geometry);
    } else if (const auto* s = std::get_if<Surface>(&e.body)) {
      out.insert(out.end(), {{"surface.period", s->period_mm}, {"surface.relief", s->relief_mm}, {"surface.gain", s->gain}});
      geometry.insert(geometry.end(), {{"x", s->x_mm}, {"cx", s->cx_mm}, {"rx", s->rx_mm}, {"w", s->width_mm}});
    } else if (const auto* l = std::get_if<Line>(&e.body)) {
      out.insert(out.end(), {{"line.frequency", l->frequency_hz}, {"line.damping", l->damping}, {"line.gain", l->gain}});
      geometry.insert(geometry.end(), {{"x1", l->x1_mm}, {"y2", l->y2_mm}, {"width", l->width_mm}});
    } else if (const auto* d = std::get_if<Dot>(&e.body)) {
      out.push_back({"dot.gain", d->gain});
      geometry.insert(geometry.end(), {{"x", d->x_mm}, {"radius", d->radius_mm}});
    }
  }
}

TEST(SeparateSpace, TheOriginalSettingGivesTheImageBack) {
  const Image image = parse(kMixed);
  EXPECT_EQ(study::apply_setting(image, SeparationSetting{}), image);
  EXPECT_TRUE(study::list_changes(image, image).empty());
}

// Property: any setting keeps every value inside the format's range and the geometry untouched.
TEST(SeparateSpace, EverySettingStaysInRangeAndKeepsGeometry) {
  const Image image = parse(kMixed);
  std::vector<std::pair<std::string, double>> values0, geometry0;
  collect(image.children, values0, geometry0);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 500; ++trial) {
    SeparationSetting s{};
    for (std::size_t p = 0; p < study::kTactileParameterCount; ++p) {
      const study::StepRange r = study::step_range(static_cast<TactileParameter>(p));
      s[p] = static_cast<std::int8_t>(std::uniform_int_distribution<int>(r.lowest, r.highest)(rng));
    }
    const Image out = study::apply_setting(image, s);
    std::vector<std::pair<std::string, double>> values, geometry;
    collect(out.children, values, geometry);
    EXPECT_EQ(geometry, geometry0);
    for (const auto& [name, v] : values) {
      const auto dot = name.find('.');
      const std::string owner = name.substr(0, dot);
      const ParameterSpec* spec = find_parameter(owner == "surface" ? ParameterOwner::surface
                                                 : owner == "line"  ? ParameterOwner::line
                                                                    : ParameterOwner::dot,
                                                 name.substr(dot + 1));
      ASSERT_NE(spec, nullptr) << name;
      EXPECT_TRUE(in_range(*spec, v)) << name << " = " << v;
    }
  }
}

TEST(SeparateSpace, EveryPrimitiveTakesTheSameStep) {
  const Image image = parse(kMixed);
  SeparationSetting s{};
  s[static_cast<std::size_t>(TactileParameter::period)] = 3;  // x 2
  s[static_cast<std::size_t>(TactileParameter::gain)] = -3;   // -6 dB
  s[static_cast<std::size_t>(TactileParameter::pattern)] = 2;  // square
  const Image out = study::apply_setting(image, s);
  const auto changes = study::list_changes(image, out);
  std::vector<std::string> texts;
  for (const auto& c : changes) texts.push_back(c.text);
  const std::vector<std::string> want = {
      "surface 'crown': period 3 \u2192 6 mm",   "surface 'crown': pattern triangle \u2192 square",
      "surface 'crown': gain 0.7 \u2192 0.35",   "line 'trunk': gain 0.8 \u2192 0.4",
      "surface 'skin': period 1.2 \u2192 2.4 mm", "surface 'skin': pattern sine \u2192 square",
      "surface 'skin': gain 1 \u2192 0.5",        "dot 'valve': gain 0.05 \u2192 0.03"};
  EXPECT_EQ(texts, want);
}

TEST(SeparateSpace, StepsAreRoundedForPeople) {
  const Image image = parse(kMixed);
  SeparationSetting s{};
  s[static_cast<std::size_t>(TactileParameter::period)] = 1;  // x 2^(1/3) = 1.26
  const Image out = study::apply_setting(image, s);
  const auto changes = study::list_changes(image, out);
  ASSERT_FALSE(changes.empty());
  EXPECT_EQ(changes[0].to, "3.78");  // 3 * 1.2599 = 3.7798
}

TEST(SeparateSpace, ParameterListsAndTheirErrors) {
  const auto ok = study::parse_tactile_parameter_list("period,pattern");
  EXPECT_TRUE(ok.error.empty());
  EXPECT_TRUE(ok.set[static_cast<std::size_t>(TactileParameter::period)]);
  EXPECT_TRUE(ok.set[static_cast<std::size_t>(TactileParameter::pattern)]);
  EXPECT_FALSE(ok.set[static_cast<std::size_t>(TactileParameter::gain)]);
  const auto bad = study::parse_tactile_parameter_list("period,width");
  EXPECT_NE(bad.error.find("unknown parameter 'width'"), std::string::npos) << bad.error;
  EXPECT_FALSE(study::parse_tactile_parameter_list("").error.empty());
}

TEST(SeparateSpace, ParametersPresentFollowTheKinds) {
  const auto dots = study::parameters_present(parse("<dot x=\"1\" y=\"1\"/>\n"));
  EXPECT_TRUE(dots[static_cast<std::size_t>(TactileParameter::gain)]);
  EXPECT_FALSE(dots[static_cast<std::size_t>(TactileParameter::period)]);
  EXPECT_FALSE(dots[static_cast<std::size_t>(TactileParameter::frequency)]);
  const auto mixed = study::parameters_present(parse(kMixed));
  for (const bool b : mixed) EXPECT_TRUE(b);
}

TEST(SeparateSpace, TheKeyTellsSettingsApartOnlyWhenTheImagesDiffer) {
  const Image image = parse("<dot x=\"1\" y=\"1\" gain=\"1\"/>\n");
  SeparationSetting louder{};
  louder[static_cast<std::size_t>(TactileParameter::gain)] = 2;  // clamped at 1: the same image
  SeparationSetting period{};
  period[static_cast<std::size_t>(TactileParameter::period)] = 2;  // no surface: the same image
  EXPECT_EQ(study::tactile_key(study::apply_setting(image, louder)), study::tactile_key(image));
  EXPECT_EQ(study::tactile_key(study::apply_setting(image, period)), study::tactile_key(image));
  SeparationSetting softer{};
  softer[static_cast<std::size_t>(TactileParameter::gain)] = -1;
  EXPECT_NE(study::tactile_key(study::apply_setting(image, softer)), study::tactile_key(image));
}

// Property: the changes listed between an original and any proposal, made one by one (the editor's
// Apply), give the proposal; each one alone changes exactly one value.
TEST(SeparateSpace, ApplyingEveryListedChangeGivesTheProposal) {
  const Image image = parse(kMixed);
  std::mt19937 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    SeparationSetting s{};
    for (std::size_t p = 0; p < study::kTactileParameterCount; ++p) {
      const study::StepRange r = study::step_range(static_cast<TactileParameter>(p));
      s[p] = static_cast<std::int8_t>(std::uniform_int_distribution<int>(r.lowest, r.highest)(rng));
    }
    const Image proposal = study::apply_setting(image, s);
    Image applied = image;
    for (const study::ParameterChange& c : study::list_changes(image, proposal)) {
      const Image next = study::apply_change(applied, c);
      EXPECT_EQ(study::list_changes(applied, next).size(), 1u) << c.text;
      applied = next;
    }
    EXPECT_EQ(applied, proposal);
  }
}

}  // namespace
}  // namespace vimg
