// A file with problems (LoadResult::readable): every element that could be read is there, values out
// of range as read with one problem each, unreadable elements left out, and no image for tools.
#include <gtest/gtest.h>

#include <string>

#include "storage/image_io.hpp"
#include "storage/parameter_table.hpp"

namespace vimg {
namespace {

std::string document(const std::string& body, const std::string& root = "version=\"1.0\" width=\"100\" height=\"80\"") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<vibroimage " + root + ">\n" + body + "</vibroimage>\n";
}

const Element& at(const Image& image, const std::vector<std::size_t>& path) {
  const Element* e = &image.children.at(path.at(0));
  for (std::size_t i = 1; i < path.size(); ++i) e = &std::get<Group>(e->body).children.at(path[i]);
  return *e;
}

TEST(ReadingWithProblems, GainThreeOpensWithEveryPrimitiveAndOneProblem) {
  const LoadResult r = parse_image_xml(document("<dot id=\"a\" x=\"10\" y=\"10\"/>\n"
                                                "<group id=\"g\">\n"
                                                "  <line id=\"b\" x1=\"0\" y1=\"0\" x2=\"5\" y2=\"5\"/>\n"
                                                "  <dot id=\"c\" x=\"20\" y=\"20\" gain=\"3\"/>\n"
                                                "</group>\n"
                                                "<surface id=\"s\" shape=\"rect\" x=\"0\" y=\"0\" width=\"5\" height=\"5\"/>\n"),
                                       "g.vimg");
  EXPECT_FALSE(r.ok()) << "tools still refuse it (spec: a value out of range is an error)";
  ASSERT_TRUE(r.readable.has_value());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "g.vimg:6: error: <dot> attribute 'gain' must be in [0, 1], got 3");
  ASSERT_EQ(r.value_problems.size(), 1u);
  const ValueProblem& p = r.value_problems[0];
  EXPECT_EQ(p.line, 6);
  EXPECT_EQ(p.parameter, find_parameter(ParameterOwner::dot, "gain"));
  EXPECT_EQ(p.value, 3.0);
  const Image& image = *r.readable;
  ASSERT_EQ(image.children.size(), 3u);
  ASSERT_EQ(std::get<Group>(image.children[1].body).children.size(), 2u);
  const Element& dot = at(image, p.path);
  EXPECT_EQ(dot.id, "c");
  EXPECT_EQ(std::get<Dot>(dot.body).gain, 3.0);
}

TEST(ReadingWithProblems, AnUnreadableElementIsLeftOutAndTheRestKept) {
  const LoadResult r = parse_image_xml(document("<dot id=\"a\" x=\"1\" y=\"1\" radius=\"-2\"/>\n"
                                                "<dot id=\"b\" x=\"abc\" y=\"1\" gain=\"7\"/>\n"
                                                "<surface id=\"c\" shape=\"star\"/>\n"
                                                "<surface id=\"d\" shape=\"polygon\" points=\"0,0 1,1\"/>\n"
                                                "<line id=\"e\" x1=\"0\" y1=\"0\" x2=\"5\" y2=\"5\" damping=\"1\"/>\n"
                                                "<dot id=\"9bad\" x=\"2\" y=\"2\"/>\n"),
                                       "u.vimg");
  ASSERT_TRUE(r.readable.has_value());
  const Image& image = *r.readable;
  ASSERT_EQ(image.children.size(), 3u);
  EXPECT_EQ(image.children[0].id, "a");
  EXPECT_EQ(image.children[1].id, "e");
  EXPECT_EQ(image.children[2].id, "") << "an invalid id is left empty (a writer or the editor names it)";
  // Only the kept elements' values are problems to fix; b's gain went with b.
  ASSERT_EQ(r.value_problems.size(), 2u);
  EXPECT_EQ(r.value_problems[0].path, std::vector<std::size_t>{0});
  EXPECT_EQ(r.value_problems[0].parameter->name, "radius");
  EXPECT_EQ(r.value_problems[1].path, std::vector<std::size_t>{1});
  EXPECT_EQ(r.value_problems[1].parameter->name, "damping");
  // Every problem is still reported.
  EXPECT_EQ(r.diagnostics.size(), 7u);
}

TEST(ReadingWithProblems, CanvasAndInteractionValuesAreProblemsWithAnEmptyPath) {
  const LoadResult r = parse_image_xml(document("<interaction mass=\"0\"/>\n<dot x=\"1\" y=\"1\"/>\n",
                                                "version=\"1.0\" width=\"20000\" height=\"80\""),
                                       "c.vimg");
  ASSERT_TRUE(r.readable.has_value());
  ASSERT_EQ(r.value_problems.size(), 2u);
  EXPECT_TRUE(r.value_problems[0].path.empty());
  EXPECT_EQ(r.value_problems[0].parameter, find_parameter(ParameterOwner::canvas, "width"));
  EXPECT_EQ(r.readable->width_mm, 20000.0);
  EXPECT_EQ(r.value_problems[1].parameter, find_parameter(ParameterOwner::interaction, "mass"));
  EXPECT_EQ(r.readable->interaction->mass_kg, 0.0);
  EXPECT_EQ(r.readable->children.size(), 1u);
}

TEST(ReadingWithProblems, UnreadableFilesStayUnreadable) {
  for (const std::string& xml : {std::string("<vibroimage version=\"1.0\" width=\"10\" height=\"10\"><dot"),
                                 document("<dot x=\"1\" y=\"1\"/>\n", "version=\"2.0\" width=\"10\" height=\"10\""),
                                 document("<dot x=\"1\" y=\"1\"/>\n", "version=\"1.0\" width=\"ten\" height=\"10\""),
                                 document("<dot x=\"1\" y=\"1\"/>\n", "version=\"1.0\" height=\"10\""),
                                 std::string("<picture/>")}) {
    const LoadResult r = parse_image_xml(xml, "x.vimg");
    EXPECT_FALSE(r.ok()) << xml;
    EXPECT_FALSE(r.readable.has_value()) << xml;
    EXPECT_FALSE(r.diagnostics.empty()) << xml;
  }
}

TEST(ReadingWithProblems, AValidFileHasNoReadableCopyAndNoProblems) {
  const LoadResult r = parse_image_xml(document("<dot x=\"1\" y=\"1\"/>\n"), "v.vimg");
  ASSERT_TRUE(r.ok());
  EXPECT_FALSE(r.readable.has_value());
  EXPECT_TRUE(r.value_problems.empty());
}

TEST(ReadingWithProblems, ProblemsBeyondTheDiagnosticCapAreAllKept) {
  std::string body;
  for (int i = 0; i < 200; ++i) body += "<dot x=\"1\" y=\"1\" gain=\"2\"/>\n";
  const LoadResult r = parse_image_xml(document(body), "many.vimg");
  ASSERT_TRUE(r.readable.has_value());
  EXPECT_EQ(r.readable->children.size(), 200u);
  EXPECT_EQ(r.value_problems.size(), 200u);
  EXPECT_LT(r.diagnostics.size(), 200u);
}

TEST(ReadingWithProblems, GroupsTooDeepAreLeftOutWithTheirContents) {
  std::string body = "<dot id=\"keep\" x=\"1\" y=\"1\"/>\n";
  for (int i = 0; i < 33; ++i) body += "<group>";
  body += "<dot x=\"1\" y=\"1\"/>";
  for (int i = 0; i < 33; ++i) body += "</group>";
  const LoadResult r = parse_image_xml(document(body + "\n"), "deep.vimg");
  ASSERT_TRUE(r.readable.has_value());
  ASSERT_EQ(r.readable->children.size(), 2u);
  // 32 levels kept, the 33rd (with the dot) left out.
  const Element* e = &r.readable->children[1];
  int levels = 1;
  while (!std::get<Group>(e->body).children.empty()) {
    e = &std::get<Group>(e->body).children[0];
    ++levels;
  }
  EXPECT_EQ(levels, 32);
}

}  // namespace
}  // namespace vimg
