// A proposed change of `vimg separate` made in the editor (editor/app_proposal.cpp): the document
// with other tactile values is one undoable step (DocumentEditor::replace_tactile_values), undo
// gives the values back, redo makes the change again, and the same values make no step.
#include <gtest/gtest.h>

#include "editor/core/document_editor.hpp"

namespace vimg::editor {
namespace {

Image textures() {
  Image image;
  for (const double period : {2.0, 2.4}) {
    Surface s;
    s.shape = SurfaceShape::rect;
    s.width_mm = s.height_mm = 10.0;
    s.period_mm = period;
    Element e;
    e.body = s;
    image.children.push_back(e);
  }
  return image;
}

TEST(ProposalEdit, EachChangeIsOneUndoableStep) {
  DocumentEditor ed(textures());
  ed.select_all();
  const Image original = ed.image();
  Image one = original;
  std::get<Surface>(one.children[0].body).period_mm = 3.1;
  ed.replace_tactile_values(one);
  EXPECT_EQ(ed.image(), one);
  EXPECT_EQ(ed.undo_depth(), 1u);
  EXPECT_TRUE(ed.dirty());
  Image both = one;  // "Apply all": two values at once, one step
  std::get<Surface>(both.children[1].body).period_mm = 4.0;
  std::get<Surface>(both.children[1].body).pattern = SurfacePattern::square;
  ed.replace_tactile_values(both);
  EXPECT_EQ(ed.undo_depth(), 2u);
  ed.undo();
  EXPECT_EQ(ed.image(), one);
  ed.undo();
  EXPECT_EQ(ed.image(), original);
  EXPECT_EQ(ed.selection().size(), 2u);  // the elements kept their ids: the selection holds
  ed.redo();
  EXPECT_EQ(ed.image(), one);
  ed.replace_tactile_values(one);  // nothing changes: no step
  EXPECT_EQ(ed.undo_depth(), 1u);
}

}  // namespace
}  // namespace vimg::editor
