#include "editor/core/document_editor.hpp"

#include <gtest/gtest.h>

#include "editor/core/element_ids.hpp"

namespace vimg::editor {
namespace {

Element dot_at(double x, double y, double r = 1.0) {
  Element e;
  e.body = Dot{x, y, r, 1.0};
  return e;
}

Element rect_at(double x, double y, double w, double h) {
  Surface s;
  s.shape = SurfaceShape::rect;
  s.x_mm = x;
  s.y_mm = y;
  s.width_mm = w;
  s.height_mm = h;
  Element e;
  e.body = s;
  return e;
}

TEST(DocumentEditor, AddGivesUniqueIdsAndSelectsTheNewElement) {
  DocumentEditor ed;
  const std::string a = ed.add_element(dot_at(10, 10));
  const std::string b = ed.add_element(dot_at(20, 20));
  EXPECT_NE(a, b);
  EXPECT_EQ(ed.selection(), std::vector<std::string>{b});
  EXPECT_EQ(collect_ids(ed.image()).size(), 2u);
}

TEST(DocumentEditor, EveryEditUndoesAndRedoesExactly) {
  DocumentEditor ed;
  std::vector<Image> states{ed.image()};
  ed.add_element(dot_at(10, 10));
  states.push_back(ed.image());
  ed.add_element(rect_at(0, 0, 5, 5));
  states.push_back(ed.image());
  ed.move_selection(3, 4);
  states.push_back(ed.image());
  ed.duplicate_selection(2);
  states.push_back(ed.image());
  ed.group_selection();
  states.push_back(ed.image());
  ed.delete_selection();
  states.push_back(ed.image());
  for (std::size_t i = states.size() - 1; i-- > 0;) {
    ASSERT_TRUE(ed.can_undo());
    ed.undo();
    EXPECT_EQ(ed.image(), states[i]) << "after undo to state " << i;
  }
  EXPECT_FALSE(ed.can_undo());
  for (std::size_t i = 1; i < states.size(); ++i) {
    ed.redo();
    EXPECT_EQ(ed.image(), states[i]) << "after redo to state " << i;
  }
  EXPECT_FALSE(ed.can_redo());
}

TEST(DocumentEditor, AnEditAfterUndoDropsTheRedoBranch) {
  DocumentEditor ed;
  ed.add_element(dot_at(1, 1));
  ed.undo();
  EXPECT_TRUE(ed.can_redo());
  ed.add_element(dot_at(2, 2));
  EXPECT_FALSE(ed.can_redo());
}

TEST(DocumentEditor, HistoryIsUnlimited) {
  DocumentEditor ed;
  for (int i = 0; i < 500; ++i) ed.add_element(dot_at(i, i));
  EXPECT_EQ(ed.undo_depth(), 500u);
  for (int i = 0; i < 500; ++i) ed.undo();
  EXPECT_TRUE(ed.image().children.empty());
}

TEST(DocumentEditor, AGestureIsOneUndoStep) {
  DocumentEditor ed;
  ed.add_element(dot_at(10, 10));
  const Image before = ed.image();
  ed.begin_gesture();
  for (int i = 0; i < 20; ++i) ed.move_selection(0.5, 0);
  ed.end_gesture();
  EXPECT_DOUBLE_EQ(std::get<Dot>(ed.image().children[0].body).x_mm, 20.0);
  ed.undo();
  EXPECT_EQ(ed.image(), before);
}

TEST(DocumentEditor, AGestureWithoutChangeLeavesNoStep) {
  DocumentEditor ed;
  ed.add_element(dot_at(10, 10));
  const auto depth = ed.undo_depth();
  ed.begin_gesture();
  ed.end_gesture();
  EXPECT_EQ(ed.undo_depth(), depth);
}

TEST(DocumentEditor, DirtyFollowsSaveAndUndo) {
  DocumentEditor ed;
  EXPECT_FALSE(ed.dirty());
  ed.add_element(dot_at(1, 1));
  EXPECT_TRUE(ed.dirty());
  ed.mark_saved();
  EXPECT_FALSE(ed.dirty());
  ed.move_selection(1, 0);
  EXPECT_TRUE(ed.dirty());
  ed.undo();
  EXPECT_FALSE(ed.dirty()) << "back at the saved state";
  ed.undo();
  EXPECT_TRUE(ed.dirty());
}

TEST(DocumentEditor, ClickSelectsTheTopmostElement) {
  DocumentEditor ed;
  const std::string below = ed.add_element(rect_at(0, 0, 50, 50));
  const std::string above = ed.add_element(dot_at(10, 10, 2));
  EXPECT_EQ(ed.element_at({10.5, 10}, 0), above);
  EXPECT_EQ(ed.element_at({40, 40}, 0), below);
  EXPECT_EQ(ed.element_at({80, 80}, 0), std::nullopt);
}

TEST(DocumentEditor, ShiftAndBoxSelection) {
  DocumentEditor ed;
  const std::string a = ed.add_element(dot_at(10, 10));
  const std::string b = ed.add_element(dot_at(50, 50));
  const std::string c = ed.add_element(dot_at(90, 90));
  ed.select_only(a);
  ed.toggle_selected(c);
  EXPECT_TRUE(ed.is_selected(a));
  EXPECT_TRUE(ed.is_selected(c));
  ed.toggle_selected(a);
  EXPECT_FALSE(ed.is_selected(a));
  ed.select_in_rect(rect_from_corners({0, 0}, {60, 60}), false);
  EXPECT_EQ(ed.selection(), (std::vector<std::string>{a, b}));
  ed.select_in_rect(rect_from_corners({85, 85}, {95, 95}), true);
  EXPECT_EQ(ed.selection().size(), 3u);
}

TEST(DocumentEditor, GroupKeepsMembersAndPaintOrderAndUngroupRestoresThem) {
  DocumentEditor ed;
  const std::string a = ed.add_element(dot_at(10, 10));
  const std::string b = ed.add_element(dot_at(20, 20));
  const std::string c = ed.add_element(dot_at(30, 30));
  const Image flat = ed.image();
  ed.select_only(a);
  ed.toggle_selected(c);
  ed.group_selection();
  ASSERT_EQ(ed.image().children.size(), 2u);
  EXPECT_EQ(ed.image().children[0].id, b);
  const auto& g = std::get<Group>(ed.image().children[1].body);
  ASSERT_EQ(g.children.size(), 2u);
  EXPECT_EQ(g.children[0].id, a);
  EXPECT_EQ(g.children[1].id, c);
  // A click on a member selects the group.
  EXPECT_EQ(ed.element_at({30, 30}, 0), ed.image().children[1].id);
  ed.ungroup_selection();
  EXPECT_EQ(ed.image().children.size(), 3u);
  EXPECT_EQ(ed.selection(), (std::vector<std::string>{a, c}));
  ed.undo();
  ed.undo();
  EXPECT_EQ(ed.image(), flat);
}

TEST(DocumentEditor, DuplicateAndPasteMakeFreshIdsAtAnOffset) {
  DocumentEditor ed;
  ed.add_element(dot_at(10, 10));
  ed.add_element(dot_at(20, 20));
  ed.select_all();
  ed.group_selection();
  ed.duplicate_selection(5);
  ASSERT_EQ(ed.image().children.size(), 2u);
  EXPECT_EQ(collect_ids(ed.image()).size(), 6u) << "2 groups and 4 dots, all distinct";
  const auto& copy = std::get<Group>(ed.image().children[1].body);
  EXPECT_DOUBLE_EQ(std::get<Dot>(copy.children[0].body).x_mm, 15.0);
  ed.copy_selection();
  ed.paste(5);
  ed.paste(5);
  EXPECT_EQ(ed.image().children.size(), 4u);
  EXPECT_EQ(collect_ids(ed.image()).size(), 12u);
  const auto& second_paste = std::get<Group>(ed.image().children[3].body);
  EXPECT_DOUBLE_EQ(std::get<Dot>(second_paste.children[0].body).x_mm, 25.0);
}

TEST(DocumentEditor, ZOrder) {
  DocumentEditor ed;
  const std::string a = ed.add_element(dot_at(1, 1));
  const std::string b = ed.add_element(dot_at(2, 2));
  const std::string c = ed.add_element(dot_at(3, 3));
  auto order = [&] {
    std::vector<std::string> ids;
    for (const auto& e : ed.image().children) ids.push_back(e.id);
    return ids;
  };
  ed.select_only(a);
  ed.raise_selection();
  EXPECT_EQ(order(), (std::vector<std::string>{b, a, c}));
  ed.bring_selection_to_front();
  EXPECT_EQ(order(), (std::vector<std::string>{b, c, a}));
  ed.lower_selection();
  EXPECT_EQ(order(), (std::vector<std::string>{b, a, c}));
  ed.send_selection_to_back();
  EXPECT_EQ(order(), (std::vector<std::string>{a, b, c}));
  ed.lower_selection();  // already at the back: no step
  EXPECT_EQ(ed.undo_depth(), 7u);
}

TEST(DocumentEditor, ResizeMapsTheSelectionBounds) {
  DocumentEditor ed;
  ed.add_element(rect_at(10, 10, 20, 10));
  const RectMm from = *ed.selection_bounds();
  const RectMm to{10, 10, 50, 40};
  ed.resize_selection(from, to);
  EXPECT_EQ(*ed.selection_bounds(), to);
}

TEST(DocumentEditor, PropertyEditReplacesOneElement) {
  DocumentEditor ed;
  const std::string id = ed.add_element(dot_at(1, 1));
  Element e = *ed.find(id);
  std::get<Dot>(e.body).radius_mm = 4.0;
  ed.replace_element(id, e);
  EXPECT_DOUBLE_EQ(std::get<Dot>(ed.find(id)->body).radius_mm, 4.0);
  ed.undo();
  EXPECT_DOUBLE_EQ(std::get<Dot>(ed.find(id)->body).radius_mm, 1.0);
}

TEST(DocumentEditor, ResetAssignsMissingIdsWithoutDirtying) {
  Image img;
  img.children.push_back(dot_at(1, 1));
  img.children.push_back(dot_at(2, 2));
  img.children[1].id = "dot1";
  DocumentEditor ed(img);
  EXPECT_FALSE(ed.dirty());
  EXPECT_EQ(collect_ids(ed.image()).size(), 2u);
  EXPECT_FALSE(ed.image().children[0].id.empty());
}

}  // namespace
}  // namespace vimg::editor
