// The parameter table against the reader, the writer, the model and docs/format.md: every range
// edge of every number attribute, every default, every attribute written, the docs' table the same.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "storage/image_io.hpp"
#include "storage/number_text.hpp"
#include "storage/parameter_table.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

std::string shape_of(const ParameterSpec& spec) { return spec.shape.empty() ? "rect" : std::string(spec.shape); }

// A valid value of a required attribute, used to fill the ones a test does not vary.
std::string filler(const ParameterSpec& s) {
  if (s.kind == ParameterKind::points) return "0,0 10,0 0,10";
  if (s.kind == ParameterKind::version) return "1.0";
  return format_decimal(clamp_to_range(s, 5.0));
}

// The attributes of a minimal valid `owner` element (shape `shape` for surfaces) with `name`
// set to `value`, or left out when `value` is empty.
std::string attributes(ParameterOwner owner, const std::string& shape, std::string_view name, const std::string& value) {
  std::string out;
  for (const ParameterSpec& s : parameter_table()) {
    if (s.owner != owner || s.name == name) continue;
    if (!s.shape.empty() && s.shape != shape) continue;
    if (s.name == "shape") {
      out += " shape=\"" + shape + "\"";
    } else if (s.required) {
      out += " " + std::string(s.name) + "=\"" + filler(s) + "\"";
    }
  }
  if (!value.empty()) out += " " + std::string(name) + "=\"" + value + "\"";
  return out;
}

// A document whose attribute `spec` has `value` (absent when empty), the element being the first child.
std::string document_with(const ParameterSpec& spec, const std::string& value) {
  std::string root = " version=\"1.0\"";
  std::string body;
  if (spec.owner == ParameterOwner::canvas) {
    root = attributes(ParameterOwner::canvas, "", spec.name, value);
  } else {
    root += " width=\"100\" height=\"100\"";
    body = "<" + std::string(owner_tag(spec.owner)) + attributes(spec.owner, shape_of(spec), spec.name, value) + "/>\n";
  }
  return "<?xml version=\"1.0\"?>\n<vibroimage" + root + ">\n" + body + "</vibroimage>\n";
}

// The number the reader put where `spec` says, from the image or the readable image.
double read_value(const LoadResult& r, const ParameterSpec& spec) {
  const Image& image = r.image ? *r.image : *r.readable;
  if (spec.owner == ParameterOwner::canvas || spec.owner == ParameterOwner::interaction) {
    return *number_in(image, spec);
  }
  return *number_in(image.children.at(0), spec);
}

void expect_accepted(const ParameterSpec& spec, double value) {
  const std::string text = format_decimal(value);
  const LoadResult r = parse_image_xml(document_with(spec, text), "t.vimg");
  ASSERT_TRUE(r.ok()) << spec.name << "=" << text << ": " << (r.diagnostics.empty() ? "" : r.diagnostics[0].to_string());
  EXPECT_EQ(read_value(r, spec), value) << spec.name;
}

void expect_reported(const ParameterSpec& spec, double value) {
  const std::string text = format_decimal(value);
  const LoadResult r = parse_image_xml(document_with(spec, text), "t.vimg");
  EXPECT_FALSE(r.ok()) << spec.name << "=" << text;
  ASSERT_TRUE(r.readable.has_value()) << spec.name << "=" << text;
  ASSERT_EQ(r.diagnostics.size(), 1u) << spec.name << "=" << text;
  EXPECT_EQ(r.diagnostics[0].message, out_of_range_message(spec, text));
  ASSERT_EQ(r.value_problems.size(), 1u);
  EXPECT_EQ(r.value_problems[0].parameter, &spec);
  EXPECT_EQ(r.value_problems[0].value, value);
  EXPECT_EQ(r.value_problems[0].line, r.diagnostics[0].line);
  EXPECT_EQ(read_value(r, spec), value) << "the value is kept as read";
  EXPECT_TRUE(in_range(spec, clamp_to_range(spec, value)));
}

std::vector<const ParameterSpec*> numbers() {
  std::vector<const ParameterSpec*> out;
  for (const ParameterSpec& s : parameter_table()) {
    if (s.kind == ParameterKind::number) out.push_back(&s);
  }
  return out;
}

TEST(ParameterTable, EveryRangeEdgeIsAcceptedOrReportedAsTheTableSays) {
  for (const ParameterSpec* spec : numbers()) {
    SCOPED_TRACE(std::string(owner_tag(spec->owner)) + " " + std::string(spec->name));
    if (std::isfinite(spec->min)) {
      // The nearest doubles either side (the smallest normal one next to 0: the text of a
      // subnormal number is not guaranteed to read back).
      const double above = spec->min == 0.0 ? std::numeric_limits<double>::min() : std::nextafter(spec->min, spec->max);
      const double below = spec->min == 0.0 ? -std::numeric_limits<double>::min()
                                            : std::nextafter(spec->min, -std::numeric_limits<double>::infinity());
      if (spec->min_open) {
        expect_reported(*spec, spec->min);
        expect_accepted(*spec, above);
      } else {
        expect_accepted(*spec, spec->min);
      }
      expect_reported(*spec, below);
    } else {
      expect_accepted(*spec, -1e300);
    }
    if (std::isfinite(spec->max)) {
      if (spec->max_open) {
        expect_reported(*spec, spec->max);
        expect_accepted(*spec, std::nextafter(spec->max, spec->min));
      } else {
        expect_accepted(*spec, spec->max);
      }
      expect_reported(*spec, std::nextafter(spec->max, std::numeric_limits<double>::infinity()));
    } else {
      expect_accepted(*spec, 1e300);
    }
  }
}

TEST(ParameterTable, DefaultsApplyWhenAbsentAndAreTheModelsDefaults) {
  for (const ParameterSpec* spec : numbers()) {
    SCOPED_TRACE(std::string(owner_tag(spec->owner)) + " " + std::string(spec->name));
    const LoadResult r = parse_image_xml(document_with(*spec, ""), "t.vimg");
    if (spec->required) {
      ASSERT_FALSE(r.ok());
      ASSERT_FALSE(r.diagnostics.empty());
      EXPECT_NE(r.diagnostics[0].message.find("missing required attribute '" + std::string(spec->name) + "'"),
                std::string::npos);
      continue;
    }
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(read_value(r, *spec), spec->default_value);
    EXPECT_TRUE(in_range(*spec, spec->default_value));
    // The model's own default is the table's.
    Image fresh;
    fresh.interaction = InteractionParams{};
    Element element;
    if (spec->owner == ParameterOwner::dot) element.body = Dot{};
    if (spec->owner == ParameterOwner::line) element.body = Line{};
    if (spec->owner == ParameterOwner::surface) element.body = Surface{};
    const double* model = spec->owner == ParameterOwner::interaction ? number_in(fresh, *spec) : number_in(element, *spec);
    ASSERT_NE(model, nullptr);
    EXPECT_EQ(*model, spec->default_value);
  }
}

TEST(ParameterTable, ClampLandsInsideAndKeepsValuesInside) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> exponent(-6.0, 6.0);
  for (const ParameterSpec* spec : numbers()) {
    for (int i = 0; i < 200; ++i) {
      const double magnitude = std::pow(10.0, exponent(rng));
      const double v = (i % 2 == 0 ? 1.0 : -1.0) * magnitude;
      const double clamped = clamp_to_range(*spec, v);
      ASSERT_TRUE(in_range(*spec, clamped)) << spec->name << " " << v << " -> " << clamped;
      if (in_range(*spec, v)) {
        EXPECT_EQ(clamped, v);
      }
      // Out of range: the bound on that side (a step inside an open one).
      if (v < spec->min) {
        EXPECT_EQ(clamped, spec->min_open ? spec->min + spec->step : spec->min);
      }
      if (v > spec->max) {
        EXPECT_EQ(clamped, spec->max_open ? spec->max - spec->step : spec->max);
      }
    }
    EXPECT_TRUE(in_range(*spec, clamp_to_range(*spec, std::numeric_limits<double>::quiet_NaN())));
  }
}

TEST(ParameterTable, WriterWritesEveryAttributeOfTheTableInItsOrder) {
  for (const SurfaceShape shape : {SurfaceShape::rect, SurfaceShape::ellipse, SurfaceShape::polygon}) {
    Image image;
    image.interaction = InteractionParams{};
    Surface s;
    s.shape = shape;
    s.width_mm = s.height_mm = s.rx_mm = s.ry_mm = 1.0;
    s.points = {{0, 0}, {1, 0}, {0, 1}};
    image.children = {Element{"d", Dot{}, {}, {}, 0}, Element{"l", Line{}, {}, {}, 0}, Element{"s", s, {}, {}, 0}};
    const std::string xml = write_image_xml(image);
    for (const ParameterOwner owner : {ParameterOwner::canvas, ParameterOwner::interaction, ParameterOwner::dot,
                                       ParameterOwner::line, ParameterOwner::surface}) {
      const std::size_t start = xml.find("<" + std::string(owner_tag(owner)) + " ");
      ASSERT_NE(start, std::string::npos);
      const std::string tag = xml.substr(start, xml.find('>', start) - start);
      std::size_t last = 0;
      for (const ParameterSpec& spec : parameter_table()) {
        if (spec.owner != owner || (owner == ParameterOwner::surface && !applies_to_shape(spec, shape))) continue;
        const std::size_t at = tag.find(" " + std::string(spec.name) + "=\"");
        ASSERT_NE(at, std::string::npos) << tag << " lacks " << spec.name;
        EXPECT_GT(at, last) << spec.name << " out of the table's order in " << tag;
        last = at;
      }
    }
  }
}

// docs/format.md holds the table between two markers; it must be the code's table.
TEST(ParameterTable, DocsFormatTableIsTheCodeTable) {
  const std::string docs = test::read_text_file(std::filesystem::path(VIMG_SOURCE_DIR) / "docs" / "format.md");
  const std::string begin = "<!-- parameter-table: begin (tests/storage/parameter_table_test.cpp) -->\n";
  const std::string end = "<!-- parameter-table: end -->";
  const std::size_t b = docs.find(begin);
  const std::size_t e = docs.find(end);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(e, std::string::npos);
  const std::string in_docs = docs.substr(b + begin.size(), e - b - begin.size());
  EXPECT_EQ(in_docs, parameter_table_markdown()) << "docs/format.md's parameter table differs; it should read:\n"
                                                  << parameter_table_markdown();
}

TEST(ParameterTable, EveryAttributeHasAMeaningAndNumbersAUnitAndStep) {
  for (const ParameterSpec& spec : parameter_table()) {
    EXPECT_FALSE(spec.meaning.empty()) << spec.name;
    EXPECT_EQ(find_parameter(spec.owner, spec.name), &spec) << "names are unique per element";
    if (spec.kind != ParameterKind::number) continue;
    EXPECT_FALSE(spec.unit.empty()) << spec.name;
    EXPECT_GT(spec.step, 0.0) << spec.name;
    EXPECT_FALSE(std::holds_alternative<std::monostate>(spec.field)) << spec.name;
  }
}

}  // namespace
}  // namespace vimg
