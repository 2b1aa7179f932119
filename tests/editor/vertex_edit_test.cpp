#include "editor/core/vertex_edit.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "editor/core/document_editor.hpp"

namespace vimg::editor {
namespace {

Element polygon(std::vector<Point2Mm> points) {
  Surface s;
  s.shape = SurfaceShape::polygon;
  s.points = std::move(points);
  Element e;
  e.id = "p";
  e.body = s;
  return e;
}

Element line(double x1, double y1, double x2, double y2) {
  Line l;
  l.x1_mm = x1;
  l.y1_mm = y1;
  l.x2_mm = x2;
  l.y2_mm = y2;
  Element e;
  e.id = "l";
  e.body = l;
  return e;
}

const std::vector<Point2Mm>& points(const Element& e) { return std::get<Surface>(e.body).points; }

TEST(VertexEdit, ALinesPointsAreItsEndsAPolygonsItsVerticesOthersHaveNone) {
  EXPECT_EQ(vertex_points(line(1, 2, 3, 4)), (std::vector<Point2Mm>{{1, 2}, {3, 4}}));
  const Element square = polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  EXPECT_EQ(vertex_points(square), points(square));
  Element dot;
  dot.body = Dot{1, 1, 1, 1};
  EXPECT_TRUE(vertex_points(dot).empty());
  Surface rect;
  rect.width_mm = rect.height_mm = 5;
  Element r;
  r.body = rect;
  EXPECT_TRUE(vertex_points(r).empty());
  std::vector<Point2Mm> many(kMaxHandleVertices + 1);
  for (std::size_t i = 0; i < many.size(); ++i) {
    const double a = 0.001 * static_cast<double>(i);
    many[i] = {std::cos(a), std::sin(a)};
  }
  EXPECT_TRUE(vertex_points(polygon(many)).empty());
}

TEST(VertexEdit, AVertexIsHitWithinTheToleranceAndTheNearestWins) {
  const Element square = polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  EXPECT_EQ(vertex_at(square, {10.5, 9.6}, 1.0), std::optional<std::size_t>(2));
  EXPECT_EQ(vertex_at(square, {5, 5}, 1.0), std::nullopt);
  const Element close = polygon({{0, 0}, {1, 0}, {0, 5}});
  EXPECT_EQ(vertex_at(close, {0.8, 0}, 2.0), std::optional<std::size_t>(1));
  EXPECT_EQ(vertex_at(line(0, 0, 20, 0), {19.5, 0.3}, 1.0), std::optional<std::size_t>(1));
}

// Property: the hit point lies on the edge it names, at the foot of the perpendicular, and
// inserting it there keeps the outline (the new vertex splits that edge).
TEST(VertexEdit, AnEdgeHitIsTheFootOfThePerpendicularOnTheNearestEdge) {
  const Element square = polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  for (double x = 0.5; x < 10; x += 0.75) {
    const auto top = edge_at(square, {x, -0.4}, 1.0);
    ASSERT_TRUE(top) << x;
    EXPECT_EQ(top->index, 1u);
    EXPECT_DOUBLE_EQ(top->point.x_mm, x);
    EXPECT_DOUBLE_EQ(top->point.y_mm, 0.0);
  }
  const auto closing = edge_at(square, {-0.3, 4}, 1.0);  // the edge from the last vertex back to the first
  ASSERT_TRUE(closing);
  EXPECT_EQ(closing->index, 4u);
  EXPECT_EQ(closing->point, (Point2Mm{0, 4}));
  EXPECT_FALSE(edge_at(square, {5, 5}, 1.0));
  EXPECT_FALSE(edge_at(line(0, 0, 10, 0), {5, 0}, 1.0));

  Element split = square;
  ASSERT_TRUE(insert_vertex(split, *closing));
  EXPECT_EQ(points(split), (std::vector<Point2Mm>{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 4}}));
  Element mid = square;
  ASSERT_TRUE(insert_vertex(mid, *edge_at(square, {10.2, 3}, 1.0)));
  EXPECT_EQ(points(mid), (std::vector<Point2Mm>{{0, 0}, {10, 0}, {10, 3}, {10, 10}, {0, 10}}));
}

TEST(VertexEdit, MovingAPointMovesOnlyThatPoint) {
  Element l = line(0, 0, 10, 0);
  ASSERT_TRUE(move_vertex(l, 1, {7, 3}));
  EXPECT_EQ(vertex_points(l), (std::vector<Point2Mm>{{0, 0}, {7, 3}}));
  EXPECT_FALSE(move_vertex(l, 2, {1, 1}));
  Element tri = polygon({{0, 0}, {10, 0}, {5, 8}});
  ASSERT_TRUE(move_vertex(tri, 2, {5, 12}));
  EXPECT_EQ(points(tri), (std::vector<Point2Mm>{{0, 0}, {10, 0}, {5, 12}}));
  EXPECT_FALSE(move_vertex(tri, 3, {1, 1}));
}

TEST(VertexEdit, APolygonNeverLosesItsThirdVertexAndALineKeepsBothEnds) {
  Element quad = polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  ASSERT_TRUE(delete_vertex(quad, 1));
  EXPECT_EQ(points(quad), (std::vector<Point2Mm>{{0, 0}, {10, 10}, {0, 10}}));
  EXPECT_FALSE(delete_vertex(quad, 0));
  EXPECT_EQ(points(quad).size(), 3u);
  EXPECT_FALSE(delete_vertex(quad, 7));
  Element l = line(0, 0, 10, 0);
  EXPECT_FALSE(delete_vertex(l, 0));
}

// Through the document editor, each edit is one undo step and a drag is one gesture.
TEST(VertexEdit, EditsAreUndoableThroughTheDocumentEditor) {
  DocumentEditor doc;
  const std::string id = doc.add_element(polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  const Element before = *doc.find(id);
  const std::size_t depth = doc.undo_depth();

  doc.begin_gesture();
  for (int step = 1; step <= 5; ++step) {
    Element e = *doc.find(id);
    ASSERT_TRUE(move_vertex(e, 2, {10.0 + step, 10.0 + step}));
    doc.replace_element(id, e);
  }
  doc.end_gesture();
  EXPECT_EQ(doc.undo_depth(), depth + 1);
  EXPECT_EQ(points(*doc.find(id))[2], (Point2Mm{15, 15}));

  Element e = *doc.find(id);
  ASSERT_TRUE(delete_vertex(e, 0));
  doc.replace_element(id, e);
  EXPECT_EQ(points(*doc.find(id)).size(), 3u);
  doc.undo();
  EXPECT_EQ(points(*doc.find(id)).size(), 4u);
  doc.undo();
  EXPECT_EQ(*doc.find(id), before);
}

}  // namespace
}  // namespace vimg::editor
