// editor/face_snap.h and the move's face snap (editor/transform.h): a face moved near another
// object's facing face is laid on it. The oracles are hand positions of boxes, and the kernel's
// own composed arch on columns: three masonry objects placed 3 mm apart and snapped analyse as
// the one model does, with no contact tolerance at all.
#include "core/scene_sync.h"
#include "editor/face_snap.h"
#include "editor/transform.h"
#include "statics/analysis.h"
#include "statics/composite.h"
#include "statics/examples.h"
#include "statics/kernel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::editor {
namespace {

// An axis-aligned box from lo to hi, its faces outward.
MeshData box(const Vec3& lo, const Vec3& hi) {
  MeshData m;
  for (int k = 0; k < 8; ++k) m.addPoint(Vec3(k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]));
  m.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  m.faceTag.assign(6, 0);
  m.faceMaterial.assign(6, 0);
  return m;
}

// A ray straight down onto (x, y) of the ground.
Ray down(double x, double y) { return {Vec3(x, y, 10), Vec3(0, 0, -1)}; }

struct TwoBoxes {
  Scene scene;
  TwoBoxes(const Vec3& lo, const Vec3& hi) {
    scene.replaceObject(1, Kind::Mass, "fixed", box(Vec3(0, 0, 0), Vec3(1, 1, 1)));
    scene.replaceObject(2, Kind::Mass, "moving", box(lo, hi));
  }
  // A move of object 2 with the pointer's offset `by` on the ground, faces within `reach`.
  Transform move(const Vec3& by, double reach, Transform::Axis axis = Transform::Axis::Free) {
    Transform t;
    t.begin(Transform::Mode::Move, {{2, Placement{}}}, Vec3(0, 0, 0), down(0, 0));
    t.setFaceSnap(axisFaces(scene, {2}), std::make_shared<FaceSnapTargets>(axisFaces(scene, {1})), reach);
    if (axis != Transform::Axis::Free) t.setAxis(axis);
    t.pointer(down(by[0], by[1]));
    return t;
  }
};

TEST(FaceSnap, AFaceOfTheBoxIsAnAxisFaceWithItsPlaneAndExtent) {
  Scene scene;
  scene.replaceObject(1, Kind::Mass, "b", box(Vec3(1, 2, 3), Vec3(2, 4, 7)));
  const std::vector<AxisFace> faces = axisFaces(scene, {1});
  ASSERT_EQ(faces.size(), 6u);
  int tops = 0;
  for (const AxisFace& f : faces)
    if (f.axis == 2 && f.side == 1) {
      ++tops;
      EXPECT_DOUBLE_EQ(f.plane, 7);
      EXPECT_DOUBLE_EQ(f.lo[0], 1);  // x
      EXPECT_DOUBLE_EQ(f.hi[0], 2);
      EXPECT_DOUBLE_EQ(f.lo[1], 2);  // y
      EXPECT_DOUBLE_EQ(f.hi[1], 4);
    }
  EXPECT_EQ(tops, 1);
}

// The moving box's −x face starts 1.03 m from the fixed box's +x face (x = 1); the pointer moves
// it 1 m: 3 cm short, within a 5 cm reach, so it lands on x = 1 exactly, and y is untouched.
TEST(FaceSnap, ASideFaceLandsOnTheFacingSideWithinTheReach) {
  TwoBoxes s(Vec3(2.03, 0.2, 0), Vec3(3.03, 0.8, 1));
  Transform t = s.move(Vec3(-1, 0.1, 0), 0.05);
  const FaceSnap f = t.faceSnap();
  ASSERT_TRUE(f.onto[0]);
  EXPECT_EQ(*f.onto[0], 1u);
  EXPECT_FALSE(f.onto[1]);
  EXPECT_DOUBLE_EQ(2.03 + t.offset()[0], 1.0);
  EXPECT_DOUBLE_EQ(t.offset()[1], 0.1);
  EXPECT_NE(t.describe().find("face on face: x"), std::string::npos) << t.describe();
  // 3 cm is beyond a 2 cm reach; Alt (off), the grid and a typed value each move freely.
  EXPECT_FALSE(s.move(Vec3(-1, 0.1, 0), 0.02).faceSnap().any());
  Transform off = s.move(Vec3(-1, 0.1, 0), 0.05);
  off.setFaceSnapOn(false);
  EXPECT_DOUBLE_EQ(off.offset()[0], -1);
  Transform grid = s.move(Vec3(-1, 0.1, 0), 0.05);
  grid.setSnap(true);
  EXPECT_DOUBLE_EQ(grid.offset()[0], -1);  // −1 is on the 0.5 m grid, 1.03 is not
  Transform typed = s.move(Vec3(-1, 0.1, 0), 0.05);
  typed.type('1');  // 1 m along the pointer's way, (−1, 0.1)/√1.01
  EXPECT_DOUBLE_EQ(typed.offset()[0], -1 / std::sqrt(1.01));
  EXPECT_FALSE(typed.faceSnap().any());
}

// Faces that do not face each other, or that meet only along an edge, do not snap: a box moved
// beside the fixed one but past its end in y (their sides share no area), and the same faces
// with the moving one's normal turned the same way (+x against +x) when moved from the other side.
TEST(FaceSnap, OnlyFacingFacesThatOverlapSnap) {
  TwoBoxes past(Vec3(2.03, 1.0, 0), Vec3(3.03, 2.0, 1));  // y from 1: touches the fixed box's y = 1 edge only
  EXPECT_FALSE(past.move(Vec3(-1, 0, 0), 0.05).faceSnap().any());
  // The moving box's +x face (x = 0.98 after the move) nears the fixed box's +x face (x = 1):
  // the same way out, so no snap; its −x face at −0.02 nears the fixed −x face (x = 0): also no.
  TwoBoxes same(Vec3(-1.02 + 1, 0.2, 0), Vec3(0.98 + 1, 0.8, 1));
  EXPECT_FALSE(same.move(Vec3(-1, 0, 0), 0.05).faceSnap().any());
}

// Along a constrained axis only that axis snaps: moving along x, a bottom 1 cm above the fixed
// top stays where it is.
TEST(FaceSnap, AnAxisConstraintSnapsOnlyAlongIt) {
  TwoBoxes s(Vec3(0.2, 0.2, 1.01), Vec3(0.8, 0.8, 2));
  Transform free = s.move(Vec3(0.05, 0, 0), 0.05);  // on the ground: x and y free, z not
  EXPECT_FALSE(free.faceSnap().any());
  // Up and down on the vertical plane facing the camera (the test's rays look straight down, so
  // the plane is x = const): z snaps, 1.01 → 1.
  Transform t;
  t.begin(Transform::Mode::Move, {{2, Placement{}}}, Vec3(0, 0, 0), {Vec3(-10, 0, 0.5), Vec3(1, 0, 0)});
  t.setFaceSnap(axisFaces(s.scene, {2}), std::make_shared<FaceSnapTargets>(axisFaces(s.scene, {1})), 0.05);
  t.setAxis(Transform::Axis::Z);
  t.pointer({Vec3(-10, 0, 0.5), Vec3(1, 0, 0)});
  ASSERT_TRUE(t.faceSnap().onto[2]);
  EXPECT_DOUBLE_EQ(1.01 + t.offset()[2], 1.0);
}

// The arch on columns of Fig. 8 as three masonry objects, the arch 3 mm too high: snapped down
// by the move, it rests on the columns as the composed example's arch does (same interfaces,
// same y/W² to 1e-9) with no contact tolerance; unsnapped, the kernel finds nothing holding it.
TEST(FaceSnap, AnArchDroppedNearItsColumnsRestsOnThemAsTheComposedExample) {
  const double t = 0.3, w = 0.6, h = 1.5, lift = 0.003;
  Document doc;
  auto add = [&](ObjectId id, const std::string& name, MasonrySpec spec, const Vec3& at) {
    DocObject o;
    o.id = id;
    o.name = name;
    o.spec = std::move(spec);
    o.placement.translation = at;
    doc.objects.push_back(std::move(o));
  };
  MasonrySpec column;
  column.model = "column";
  column.parameters = {{"drums", 1}, {"height", h}, {"radius", w / std::sqrt(2.0)}, {"sides", 4}};
  MasonrySpec arch;
  arch.model = "semicircular-arch";
  arch.parameters = {{"radius", 1.0}, {"thickness", t}, {"voussoirs", 8}};
  add(1, "Left", column, Vec3(-1, 0, 0));
  add(2, "Right", column, Vec3(1, 0, 0));
  add(3, "Arch", arch, Vec3(0, 0, h + lift));
  SceneSync sync;
  statics::registerKernel(sync);
  Scene scene;
  sync.update(doc, scene);

  // Z from a camera looking along +y; the pointer does not move: the snap alone lowers it.
  Transform move;
  const Ray ray{Vec3(0, -10, h), Vec3(0, 1, 0)};
  move.begin(Transform::Mode::Move, {{3, doc.objects[2].placement}}, Vec3(0, 0, h + lift), ray);
  move.setFaceSnap(axisFaces(scene, {3}), std::make_shared<FaceSnapTargets>(axisFaces(scene, {1, 2})), 0.01);
  move.setAxis(Transform::Axis::Z);
  move.pointer(ray);
  ASSERT_TRUE(move.faceSnap().onto[2]);
  doc.objects[2].placement = move.placements().at(3);
  EXPECT_NEAR(doc.objects[2].placement.translation[2], h, 1e-12);

  std::vector<statics::CompositePart> parts;
  for (const DocObject& o : doc.objects)
    parts.push_back({o.name, statics::modelOf(std::get<MasonrySpec>(o.spec)), o.placement});
  const statics::ParametricModel together = statics::compositeModel(parts);
  statics::ParametricModel one = statics::exampleByName("arch-on-columns");
  one.parameters.set("thickness", t);
  one.parameters.set("columnWidth", w);
  one.parameters.set("columnHeight", h);
  statics::AnalysisOptions exact;
  exact.contactTolerance = 0;  // nothing joins what does not touch
  const statics::AnalysisResult a = statics::analyse(together.build(together.parameters), exact);
  const statics::AnalysisResult b = statics::analyse(one.build(one.parameters));
  EXPECT_EQ(a.interfaces.size(), b.interfaces.size());
  EXPECT_NEAR(a.yNormalised, b.yNormalised, 1e-9 * std::max(b.yNormalised, 1e-12));

  // Where it was, 3 mm up, the arch stands on nothing.
  parts[2].placement.translation[2] = h + lift;
  const statics::ParametricModel apart = statics::compositeModel(parts);
  EXPECT_ANY_THROW(statics::analyse(apart.build(apart.parameters), exact));
}

}  // namespace
}  // namespace corbel::editor
