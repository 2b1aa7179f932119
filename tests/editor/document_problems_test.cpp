// Opening a file with problems in the editor: every readable primitive, one entry per problem, a
// clamp per value that fixes exactly it, undo restoring it, and the saved result valid.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "editor/core/document_editor.hpp"
#include "editor/core/document_problems.hpp"
#include "editor/core/element_ids.hpp"
#include "storage/image_io.hpp"

namespace vimg::editor {
namespace {

const std::string kGainThree =
    "<?xml version=\"1.0\"?>\n"
    "<vibroimage version=\"1.0\" width=\"100\" height=\"80\">\n"
    "  <dot id=\"a\" x=\"10\" y=\"10\"/>\n"
    "  <group id=\"g\">\n"
    "    <dot id=\"c\" x=\"20\" y=\"20\" gain=\"3\"/>\n"
    "  </group>\n"
    "  <line x1=\"0\" y1=\"0\" x2=\"5\" y2=\"5\"/>\n"
    "</vibroimage>\n";

OpenedDocument open_text(const std::string& xml) {
  auto opened = open_document_with_problems(parse_image_xml(xml, "f.vimg"));
  EXPECT_TRUE(opened.has_value());
  return opened.value_or(OpenedDocument{});
}

std::vector<Problem> problems_of(const DocumentEditor& doc, const OpenedDocument& opened) {
  const LoadResult live = parse_image_xml(write_image_xml(doc.image()), "f.vimg");
  return problem_list(doc.image(), opened.diagnostics, live.diagnostics);
}

const Element& nested(const Image& image, std::size_t group, std::size_t child) {
  return std::get<Group>(image.children.at(group).body).children.at(child);
}

TEST(DocumentProblems, GainThreeOpensWithEveryPrimitiveAndOneProblem) {
  const OpenedDocument opened = open_text(kGainThree);
  EXPECT_TRUE(opened.has_errors());
  ASSERT_EQ(opened.image.children.size(), 3u);
  EXPECT_FALSE(opened.image.children[2].id.empty()) << "every element is named so that it can be edited";
  DocumentEditor doc(opened.image);
  const std::vector<Problem> problems = problems_of(doc, opened);
  ASSERT_EQ(problems.size(), 1u) << "the reader's message and the live check's are one problem";
  EXPECT_EQ(problems[0].text, "dot c: gain 3 is outside [0, 1]");
  ASSERT_TRUE(problems[0].fix.has_value());
  EXPECT_EQ(problems[0].fix->element_id, "c");
}

TEST(DocumentProblems, ClampFixesExactlyThatValueAndUndoRestoresIt) {
  const OpenedDocument opened = open_text(kGainThree);
  DocumentEditor doc(opened.image);
  const Image before = doc.image();
  const std::vector<Problem> problems = problems_of(doc, opened);
  ASSERT_EQ(doc.clamp_values({*problems.at(0).fix}), 1u);
  Image expected = before;
  std::get<Dot>(std::get<Group>(expected.children[1].body).children[0].body).gain = 1.0;
  EXPECT_EQ(doc.image(), expected) << "only the gain of c changed, to the bound";
  EXPECT_TRUE(problems_of(doc, opened).empty()) << "fixed: nothing left in the list";
  EXPECT_TRUE(parse_image_xml(write_image_xml(doc.image()), "saved.vimg").ok());
  ASSERT_TRUE(doc.can_undo());
  doc.undo();
  EXPECT_EQ(doc.image(), before);
  EXPECT_EQ(std::get<Dot>(nested(doc.image(), 1, 0).body).gain, 3.0);
  doc.redo();
  EXPECT_EQ(doc.image(), expected);
}

TEST(DocumentProblems, ClampAllIsOneStepOverCanvasFingerAndNestedPrimitives) {
  const OpenedDocument opened = open_text(
      "<vibroimage version=\"1.0\" width=\"0\" height=\"80\">\n"
      "<interaction mass=\"-1\" fullSpeed=\"100\"/>\n"
      "<dot id=\"d\" x=\"1\" y=\"1\" radius=\"-3\" gain=\"-0.5\"/>\n"
      "<group><line id=\"l\" x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" frequency=\"5000\" damping=\"1\"/></group>\n"
      "<surface id=\"s\" shape=\"ellipse\" cx=\"5\" cy=\"5\" rx=\"0\" ry=\"2\" period=\"0\"/>\n"
      "</vibroimage>\n");
  DocumentEditor doc(opened.image);
  const std::vector<ClampFix> fixes = find_out_of_range(doc.image());
  ASSERT_EQ(fixes.size(), 8u);
  const std::size_t depth = doc.undo_depth();
  EXPECT_EQ(doc.clamp_values(fixes), 8u);
  EXPECT_EQ(doc.undo_depth(), depth + 1);
  EXPECT_TRUE(find_out_of_range(doc.image()).empty());
  const LoadResult saved = parse_image_xml(write_image_xml(doc.image()), "saved.vimg");
  EXPECT_TRUE(saved.ok()) << (saved.diagnostics.empty() ? "" : saved.diagnostics[0].to_string());
  EXPECT_EQ(std::get<Dot>(doc.image().children[0].body).gain, 0.0);
  EXPECT_EQ(std::get<Line>(nested(doc.image(), 1, 0).body).frequency_hz, 1000.0);
  EXPECT_EQ(std::get<Line>(nested(doc.image(), 1, 0).body).damping, 0.999);
  EXPECT_EQ(doc.clamp_values(fixes), 0u) << "nothing left to clamp: no step";
  EXPECT_EQ(doc.undo_depth(), depth + 1);
  doc.undo();
  EXPECT_EQ(doc.image(), opened.image);
}

TEST(DocumentProblems, IdenticalMessagesAppearOnceNamingTheirLines) {
  const OpenedDocument opened = open_text(
      "<vibroimage version=\"1.0\" width=\"100\" height=\"80\">\n"
      "<dot x=\"1\" y=\"1\" glow=\"1\"/>\n"
      "<dot x=\"2\" y=\"2\" glow=\"1\"/>\n"
      "<dot x=\"a\" y=\"2\"/>\n"
      "</vibroimage>\n");
  DocumentEditor doc(opened.image);
  const std::vector<Problem> problems = problems_of(doc, opened);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].text, "lines 2, 3: unknown attribute 'glow' on <dot> kept as is");
  EXPECT_EQ(problems[0].severity, Diagnostic::Severity::warning);
  EXPECT_EQ(problems[1].text, "line 4: <dot> attribute 'x' = \"a\" is not a number");
  EXPECT_EQ(problems[1].severity, Diagnostic::Severity::error);
  EXPECT_EQ(opened.image.children.size(), 2u) << "the dot that cannot be read is left out";
}

TEST(DocumentProblems, EveryProblemTextIsUniqueInTheList) {
  std::string body;
  for (int i = 0; i < 30; ++i) body += "<dot x=\"1\" y=\"1\" gain=\"2\" glow=\"1\"/>\n<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" damping=\"0\"/>\n";
  const OpenedDocument opened =
      open_text("<vibroimage version=\"1.0\" width=\"100\" height=\"80\">\n" + body + "</vibroimage>\n");
  DocumentEditor doc(opened.image);
  const std::vector<Problem> problems = problems_of(doc, opened);
  std::set<std::string> texts;
  std::size_t fixes = 0;
  for (const Problem& p : problems) {
    EXPECT_TRUE(texts.insert(p.text).second) << "repeated: " << p.text;
    fixes += p.fix.has_value();
  }
  EXPECT_EQ(fixes, 60u) << "one per value, each naming its element";
}

TEST(DocumentProblems, DuplicateAndInvalidIdsAreRenamedSoEveryElementCanBeEdited) {
  const OpenedDocument opened = open_text(
      "<vibroimage version=\"1.0\" width=\"100\" height=\"80\">\n"
      "<dot id=\"a\" x=\"1\" y=\"1\"/>\n<dot id=\"a\" x=\"2\" y=\"2\"/>\n<dot id=\"1x\" x=\"3\" y=\"3\"/>\n"
      "</vibroimage>\n");
  ASSERT_EQ(opened.image.children.size(), 3u);
  EXPECT_EQ(collect_ids(opened.image).size(), 3u);
  EXPECT_EQ(opened.image.children[0].id, "a");
}

TEST(DocumentProblems, UnreadableFilesDoNotOpen) {
  EXPECT_FALSE(open_document_with_problems(parse_image_xml("<vibroimage version=\"1.0\"", "m.vimg")).has_value());
  EXPECT_FALSE(open_document_with_problems(load_image_file("/nonexistent/x.vimg")).has_value());
}

}  // namespace
}  // namespace vimg::editor
