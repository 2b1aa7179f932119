// The strict JSON reader and the predicted confusion read from `vimg compare`'s report: what it
// accepts, and every refusal at its line (FILE:LINE: error).
#include <gtest/gtest.h>

#include <string>

#include "storage/json_reader.hpp"
#include "study/report_predicted.hpp"

namespace vimg::study {
namespace {

std::string first_message(const std::vector<Diagnostic>& diagnostics) {
  return diagnostics.empty() ? "" : diagnostics.front().to_string();
}

TEST(JsonReader, ReadsValues) {
  const JsonParseResult r = parse_json(
      " {\"a\": [1, -0.5e2, 0, true, false, null],\n \"s\": \"x\\u00e9\\ud83d\\ude00\\n\\\"\", \"o\": {}, \"e\": [], \"tiny\": 1e-400}\n",
      "t.json");
  ASSERT_TRUE(r.value) << first_message(r.diagnostics);
  const JsonValue& v = *r.value;
  ASSERT_EQ(v.kind, JsonValue::Kind::object);
  const JsonValue* a = v.find("a");
  ASSERT_TRUE(a);
  ASSERT_EQ(a->items.size(), 6u);
  EXPECT_EQ(a->items[1].number, -50.0);
  EXPECT_TRUE(a->items[3].boolean);
  EXPECT_EQ(a->items[5].kind, JsonValue::Kind::null);
  EXPECT_EQ(v.find("s")->text, "x\xC3\xA9\xF0\x9F\x98\x80\n\"");
  EXPECT_EQ(v.find("s")->line, 2);
  EXPECT_EQ(v.find("tiny")->number, 0.0);
  EXPECT_EQ(v.find("missing"), nullptr);
}

TEST(JsonReader, RefusesWhatJsonDoesNotAllowAtItsLine) {
  const struct {
    const char* text;
    int line;
    const char* words;
  } cases[] = {
      {"", 1, "expected a value, found the end of the file"},
      {"{\"a\": 1,}", 1, "expected a member name"},
      {"[1,\n2,\n]", 3, "expected a value"},
      {"[01]", 1, "leading zero"},
      {"[1.]", 1, "no digit after '.'"},
      {"[1e]", 1, "no digit in its exponent"},
      {"[+1]", 1, "expected a value"},
      {"[NaN]", 1, "expected a value"},
      {"[1e400]", 1, "does not fit a double"},
      {"{\"a\": 1,\n \"a\": 2}", 2, "appears twice"},
      {"[\"a\tb\"]", 1, "control character (0x09)"},
      {"[\"\\x\"]", 1, "unknown escape"},
      {"[\"\\ud800\"]", 1, "without its low surrogate"},
      {"[\"\\udc00\"]", 1, "lone low surrogate"},
      {"[\"\xC3\x28\"]", 1, "not UTF-8"},
      {"[\"abc", 1, "not closed"},
      {"{} {}", 1, "text after the JSON value"},
      {"\xEF\xBB\xBF{}", 1, "byte-order mark"},
      {"// c\n{}", 1, "expected a value"},
      {"{'a': 1}", 1, "member name in quotes"},
      {"[1 2]", 1, "expected ',' or ']'"},
  };
  for (const auto& c : cases) {
    const JsonParseResult r = parse_json(c.text, "t.json");
    EXPECT_FALSE(r.value) << c.text;
    ASSERT_EQ(r.diagnostics.size(), 1u) << c.text;
    EXPECT_EQ(r.diagnostics[0].line, c.line) << c.text;
    EXPECT_NE(r.diagnostics[0].message.find(c.words), std::string::npos) << c.text << " -> " << r.diagnostics[0].message;
    EXPECT_EQ(r.diagnostics[0].to_string().rfind("t.json:" + std::to_string(c.line) + ": error: ", 0), 0u);
  }
}

TEST(JsonReader, BoundsDepthAndValues) {
  const std::string deep = std::string(kMaxJsonDepth + 1, '[') + std::string(kMaxJsonDepth + 1, ']');
  const JsonParseResult r = parse_json(deep, "d.json");
  EXPECT_FALSE(r.value);
  EXPECT_NE(first_message(r.diagnostics).find("nested deeper than 64"), std::string::npos);
  EXPECT_TRUE(parse_json(std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']'), "d.json").value);
  std::string many = "[0";
  for (std::size_t i = 0; i < kMaxJsonValues; ++i) many += ",0";
  many += "]";
  const JsonParseResult m = parse_json(many, "m.json");
  EXPECT_FALSE(m.value);
  EXPECT_NE(first_message(m.diagnostics).find("values (the limit)"), std::string::npos);
}

TEST(PredictedConfusion, ReadsImagesByStemAndTheMatrix) {
  const PredictedLoadResult r = parse_predicted_confusion(
      "{\"images\": [\"sets/a/dot.vimg\", \"line.png\"],\n \"stsim\": [[1, 0.2], [0.2, 1]],\n"
      " \"predicted_confusion\": [[0.75, 0.25], [0.1, 0.9]], \"warnings\": []}",
      "c.json");
  ASSERT_TRUE(r.predicted) << first_message(r.diagnostics);
  EXPECT_EQ(r.predicted->stems, (std::vector<std::string>{"dot", "line"}));
  EXPECT_EQ(r.predicted->matrix[0][1], 0.25);
  EXPECT_EQ(r.predicted->source, "c.json");
}

TEST(PredictedConfusion, RefusesAtTheLine) {
  const struct {
    const char* text;
    int line;
    const char* words;
  } cases[] = {
      {"[]", 1, "must be an object"},
      {"{\n\"predicted_confusion\": []}", 1, "no \"images\" key"},
      {"{\"images\": [\"a.vimg\"]}", 1, "no \"predicted_confusion\" key"},
      {"{\"images\":\n [\"a.vimg\", 3],\n \"predicted_confusion\": [[1]]}", 2, "an image path must be a string"},
      {"{\"images\": [\"a.vimg\", \"b.vimg\"],\n \"predicted_confusion\": [[1, 0]]}", 2, "has 1 rows for 2 images"},
      {"{\"images\": [\"a.vimg\", \"b.vimg\"], \"predicted_confusion\": [[1, 0],\n [0.5]]}", 2, "row 2 of"},
      {"{\"images\": [\"a.vimg\", \"b.vimg\"], \"predicted_confusion\": [[1, 0],\n [0.5, 0.4]]}", 2, "does not sum to 1"},
      {"{\"images\": [\"a.vimg\", \"b.vimg\"], \"predicted_confusion\": [[1.5, -0.5],\n [0.5, 0.5]]}", 1, "not a probability"},
      {"{\"images\": [\"a.vimg\", \"b.vimg\"], \"predicted_confusion\": [[1, \"0\"], [0.5, 0.5]]}", 1, "must be a number"},
      {"{\"images\": [], \"predicted_confusion\": []}", 1, "\"images\" is empty"},
      {"{\"images\": [\"\"], \"predicted_confusion\": [[1]]}", 1, "no file name"},
  };
  for (const auto& c : cases) {
    const PredictedLoadResult r = parse_predicted_confusion(c.text, "c.json");
    EXPECT_FALSE(r.predicted) << c.text;
    ASSERT_FALSE(r.diagnostics.empty()) << c.text;
    EXPECT_EQ(r.diagnostics[0].line, c.line) << c.text << " -> " << r.diagnostics[0].to_string();
    EXPECT_NE(r.diagnostics[0].message.find(c.words), std::string::npos) << c.text << " -> " << r.diagnostics[0].message;
  }
}

}  // namespace
}  // namespace vimg::study
