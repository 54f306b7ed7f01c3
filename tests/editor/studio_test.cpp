// The studio's rooms without a window: editor/transform.h (G and R: the pointer on the ground
// plane, axis constraints, typed values, snapping, turns about the pivot), editor/box_select.h
// and editor/clipboard.h (copy and paste between projects in different folders). Every expected
// value is worked by hand in the comments.
#include "core/error.h"
#include "core/project_io.h"
#include "editor/box_select.h"
#include "editor/clipboard.h"
#include "editor/transform.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::editor {
namespace {

// A ray straight down onto (x, y) of the ground.
Ray down(double x, double y) { return {Vec3(x, y, 10), Vec3(0, 0, -1)}; }

void expectNear(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12) << k;
}

TEST(StudioTransform, MoveFollowsThePointerOnTheGroundAndKeepsToAnAxis) {
  Transform t;
  Placement start;
  start.translation = Vec3(1, 1, 0);
  t.begin(Transform::Mode::Move, {{7, start}}, Vec3(0, 0, 0), down(0, 0));
  t.pointer(down(3, 4));
  expectNear(t.offset(), Vec3(3, 4, 0));  // from (0, 0) to (3, 4) on z = 0
  expectNear(t.placements().at(7).translation, Vec3(4, 5, 0));
  t.setAxis(Transform::Axis::X);
  expectNear(t.offset(), Vec3(3, 0, 0));
  t.setAxis(Transform::Axis::X);  // the same axis again frees it
  EXPECT_EQ(t.axis(), Transform::Axis::Free);
  // Typed: 3.5 along the way the pointer went, (3, 4)/5 · 3.5 = (2.1, 2.8).
  for (char c : std::string("3.5")) EXPECT_TRUE(t.type(c));
  EXPECT_FALSE(t.type('g'));
  expectNear(t.offset(), Vec3(2.1, 2.8, 0));
  t.setAxis(Transform::Axis::Y);
  expectNear(t.offset(), Vec3(0, 3.5, 0));
  t.type('-');  // a minus anywhere negates
  expectNear(t.offset(), Vec3(0, -3.5, 0));
  t.backspace();  // "-3." is −3
  expectNear(t.offset(), Vec3(0, -3, 0));
}

TEST(StudioTransform, SnappingRoundsToTheGrid) {
  Transform t;
  t.begin(Transform::Mode::Move, {{1, Placement{}}}, Vec3(0, 0, 0), down(0, 0));
  t.pointer(down(0.3, 0.8));
  t.setSnap(true);
  expectNear(t.offset(), Vec3(0.5, 1.0, 0));  // 0.3 → 0.5, 0.8 → 1.0 on a 0.5 m grid
  t.setSnap(false);
  expectNear(t.offset(), Vec3(0.3, 0.8, 0));
}

TEST(StudioTransform, UpAndDownOnTheVerticalPlaneFacingTheCamera) {
  Transform t;
  // Looking along +x at the pivot (0, 0, 0): z moves on the plane x = 0.
  t.begin(Transform::Mode::Move, {{1, Placement{}}}, Vec3(0, 0, 0), {Vec3(-10, 0, 1), Vec3(1, 0, 0)});
  t.setAxis(Transform::Axis::Z);
  t.pointer({Vec3(-10, 0.5, 3.2), Vec3(1, 0, 0)});
  expectNear(t.offset(), Vec3(0, 0, 2.2));  // from z = 1 to z = 3.2
}

TEST(StudioTransform, TheUprightSquaresMoveOnTheirVerticalPlanes) {
  Transform t;
  // Looking along +y at the pivot (1, 2, 0): the XZ square moves on the plane y = 2, from
  // (1, 2, 1) to (4, 2, 5): (3, 0, 4), whatever the ray's slant.
  t.begin(Transform::Mode::Move, {{1, Placement{}}}, Vec3(1, 2, 0), {Vec3(1, -8, 1), Vec3(0, 1, 0)});
  t.setAxis(Transform::Axis::XZ);
  t.pointer({Vec3(4, -8, 0), Vec3(0, 1, 0.5)});  // meets y = 2 at z = 0 + 10 · 0.5 = 5
  expectNear(t.offset(), Vec3(3, 0, 4));
  // Typed: 10 along the way the pointer went, (3, 0, 4)/5 · 10.
  t.type('1');
  t.type('0');
  expectNear(t.offset(), Vec3(6, 0, 8));
  // The YZ square, looking along −x: the plane x = 1, from (1, 2, 1) to (1, −1, −3).
  Transform u;
  u.begin(Transform::Mode::Move, {{1, Placement{}}}, Vec3(1, 2, 0), {Vec3(11, 2, 1), Vec3(-1, 0, 0)});
  u.setAxis(Transform::Axis::YZ);
  u.pointer({Vec3(11, -1, -3), Vec3(-1, 0, 0)});
  expectNear(u.offset(), Vec3(0, -3, -4));
  EXPECT_NE(u.describe().find("on YZ"), std::string::npos);
}

TEST(StudioTransform, RotateTurnsAboutThePivot) {
  Transform t;
  Placement a;
  a.translation = Vec3(2, 0, 0);
  a.rotation_deg = 10;
  t.begin(Transform::Mode::Rotate, {{1, a}}, Vec3(0, 0, 0), down(1, 0));
  t.pointer(down(0, 2));  // from +x to +y: a quarter turn
  EXPECT_NEAR(t.angle(), 90, 1e-12);
  const Placement p = t.placements().at(1);
  expectNear(p.translation, Vec3(0, 2, 0));  // (2, 0) turned 90° about the origin
  EXPECT_NEAR(p.rotation_deg, 100, 1e-12);
  t.pointer(down(std::cos(20 * M_PI / 180), std::sin(20 * M_PI / 180)));
  EXPECT_NEAR(t.angle(), 20, 1e-9);
  t.setSnap(true);
  EXPECT_NEAR(t.angle(), 15, 1e-12);  // 20° to the nearest 15°
  t.type('-');
  t.type('4');
  t.type('5');
  EXPECT_EQ(t.angle(), -45);
  t.setAxis(Transform::Axis::X);  // turns are about z only
  EXPECT_EQ(t.axis(), Transform::Axis::Free);
}

TEST(StudioBoxSelect, TheObjectsWithAPointInTheBox) {
  Viewport view;
  view.setRect(0, 0, 200, 100);
  view.camera.target = Vec3(0, 0, 0);
  view.camera.elevation_deg = 90;  // straight down
  view.camera.distance = 50;
  // The camera's target projects to the middle of the view.
  const auto mid = projectToWindow(view, Vec3(0, 0, 0));
  ASSERT_TRUE(mid);
  EXPECT_NEAR((*mid)[0], 100, 1e-9);
  EXPECT_NEAR((*mid)[1], 50, 1e-9);
  Scene scene;
  MeshData tri;
  tri.addFace({tri.addPoint(Vec3(-1, -1, 0)), tri.addPoint(Vec3(1, -1, 0)), tri.addPoint(Vec3(0, 1, 0))});
  scene.replaceObject(1, Kind::Mass, "near", tri);
  MeshData far = tri;
  for (Vec3& p : far.points) p += Vec3(1000, 0, 0);  // well outside the view
  scene.replaceObject(2, Kind::Mass, "far", far);
  BBox marched;
  marched.add(Vec3(-0.5, -0.5, 0));
  marched.add(Vec3(0.5, 0.5, 1));
  const auto inside = objectsInBox(scene, view, Vec2(90, 40), Vec2(110, 60), nullptr, {{3, marched}});
  EXPECT_EQ(inside, (std::vector<ObjectId>{1, 3}));
  // A box in a corner of the view holds none; a filter leaves out what it refuses.
  EXPECT_TRUE(objectsInBox(scene, view, Vec2(0, 0), Vec2(10, 10), nullptr, {{3, marched}}).empty());
  EXPECT_EQ(objectsInBox(scene, view, Vec2(110, 60), Vec2(90, 40), [](ObjectId id) { return id != 1; }, {{3, marched}}),
            (std::vector<ObjectId>{3}));
}

TEST(StudioClipboard, PathsAreReadAgainstTheSourceAndWrittenForTheTarget) {
  Document source;
  TownSpec town;
  town.footprints = "/data/projects/a/maps/town.geojson";  // as loaded: resolved against /data/projects/a
  town.style = "/data/styles/old.json";
  const ObjectId id = source.add("Town", town);
  source.find(id)->placement.translation = Vec3(5, 6, 0);
  source.add("Other", BoxSpec{});
  const std::string text = objectsToClipboard(source, {id}, "/data/projects/a");
  // In the clipboard, as in a.corbel: relative to the source's folder.
  EXPECT_NE(text.find("\"maps/town.geojson\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"../../styles/old.json\""), std::string::npos) << text;
  Document target;
  target.add("Town", BoxSpec{});  // the name is taken: the paste gets another
  const std::vector<ObjectId> pasted = pasteObjects(target, text);
  ASSERT_EQ(pasted.size(), 1u);
  const DocObject& o = *target.find(pasted[0]);
  EXPECT_EQ(o.name, "Town 2");
  EXPECT_EQ(o.placement.translation, Vec3(5, 6, 0));
  EXPECT_EQ(std::get<TownSpec>(o.spec).footprints, "/data/projects/a/maps/town.geojson");
  // Saved in /data/projects/b, the paths are written relative to b.
  const std::string saved = serializeProject(target, "/data/projects/b");
  EXPECT_NE(saved.find("\"../a/maps/town.geojson\""), std::string::npos) << saved;
  EXPECT_NE(saved.find("\"../../styles/old.json\""), std::string::npos) << saved;
  EXPECT_THROW(pasteObjects(target, "hello"), InputError);
  EXPECT_THROW(pasteObjects(target, R"({"format": "blender"})"), InputError);
}

}  // namespace
}  // namespace corbel::editor
