// core/placement.h and its paths: an object's placement moves its kernel's geometry as a whole
// (p ↦ t + Rz(θ)·(s·p)), the project file keeps it (format version 2; version-1 files load
// unplaced), SceneSync places what the kernel built, and a ray picks the object where it is
// drawn. Expected coordinates are worked by hand in the comments.
#include "core/error.h"
#include "core/project_io.h"
#include "core/scene_pick.h"
#include "core/scene_sync.h"
#include "render/overlay.h"

#include <gtest/gtest.h>

#include <set>

namespace corbel {
namespace {

// A 2 × 4 × 6 m box centred on the origin: x −1..1, y −2..2, z 0..6 in its own frame.
DocObject boxObject(ObjectId id, const std::string& name) {
  DocObject o;
  o.id = id;
  o.name = name;
  BoxSpec b;
  b.size = Vec3(2, 4, 6);
  o.spec = b;
  return o;
}

// t = (10, 20, 1), a quarter turn, half size. Own corner (x, y, z) → (10 − y/2, 20 + x/2, 1 + z/2).
Placement quarterTurn() {
  Placement p;
  p.translation = Vec3(10, 20, 1);
  p.rotation_deg = 90;
  p.scale = 0.5;
  return p;
}

TEST(Placement, MovesTurnsAndScalesAPointAndBack) {
  const Placement p = quarterTurn();
  EXPECT_EQ(p.apply(Vec3(1, 2, 6)), Vec3(9, 20.5, 4));  // (10 − 1, 20 + 0.5, 1 + 3)
  EXPECT_EQ(p.apply(Vec3(-1, -2, 0)), Vec3(11, 19.5, 1));
  EXPECT_EQ(p.unapply(Vec3(9, 20.5, 4)), Vec3(1, 2, 6));
  EXPECT_EQ(p.applyDirection(Vec3(1, 0, 0)), Vec3(0, 0.5, 0));
  // 30°: (1, 0) → (cos 30°, sin 30°) = (0.8660…, 0.5), and back.
  Placement q;
  q.rotation_deg = 30;
  const Vec3 a = q.apply(Vec3(1, 0, 0));
  EXPECT_NEAR(a[0], std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(a[1], 0.5, 1e-15);
  const Vec3 back = q.unapply(a);
  EXPECT_NEAR(back[0], 1, 1e-15);
  EXPECT_NEAR(back[1], 0, 1e-15);
  // Multiples of 90° are exact, negative ones too: −90° takes (1, 0) to (0, −1).
  q.rotation_deg = -90;
  EXPECT_EQ(q.apply(Vec3(1, 0, 0)), Vec3(0, -1, 0));
  q.rotation_deg = 540;
  EXPECT_EQ(q.apply(Vec3(1, 2, 0)), Vec3(-1, -2, 0));
  EXPECT_TRUE(Placement{}.identity());
  EXPECT_FALSE(p.identity());
}

TEST(Placement, ValuesAreChecked) {
  Placement p;
  p.scale = 0;
  EXPECT_EQ(checkPlacement(p).value_or(""), "scale: must be in [1e-4, 1e4]");
  p.scale = 1;
  p.translation = Vec3(2e7, 0, 0);
  EXPECT_NE(checkPlacement(p).value_or("").find("translation:"), std::string::npos);
  p.translation = Vec3(0, 0, 0);
  p.rotation_deg = std::nan("");
  EXPECT_NE(checkPlacement(p).value_or("").find("rotation:"), std::string::npos);
  EXPECT_FALSE(checkPlacement(quarterTurn()));
}

TEST(Placement, TheProjectFileKeepsItAndWritesVersion2) {
  Document doc;
  doc.objects.push_back(boxObject(1, "Moved"));
  doc.objects.push_back(boxObject(2, "Still"));
  doc.objects[0].placement = quarterTurn();
  doc.objects[1].locked = true;
  const std::string text = serializeProject(doc);
  EXPECT_NE(text.find("\"version\": 2"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("placement": {"translation": [10.0, 20.0, 1.0], "rotation": 90.0, "scale": 0.5})"), std::string::npos)
      << text;
  // An unplaced object has no placement key, an unlocked one no lock key.
  EXPECT_EQ(text.find("placement"), text.rfind("placement"));
  EXPECT_EQ(text.find("locked"), text.rfind("locked"));
  const LoadedProject back = parseProject(text);
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(back.document, doc);
  EXPECT_EQ(serializeProject(back.document), text);
}

TEST(Placement, Version1FilesLoadUnplacedAndDropAStrayPlacementKey) {
  const LoadedProject p = parseProject(R"({"format": "corbel", "version": 1, "objects": [
      {"id": 1, "name": "A", "box": {"size": [1, 2, 3]}},
      {"id": 2, "name": "B", "locked": true, "placement": {"translation": [5, 0, 0]}, "box": {"size": [1, 2, 3]}}]})");
  ASSERT_EQ(p.document.objects.size(), 2u);
  for (const DocObject& o : p.document.objects) {
    EXPECT_TRUE(o.placement.identity()) << o.name;
    EXPECT_FALSE(o.locked) << o.name;
  }
  // Version 1 had neither key: kept, a save as version 2 would read them as corbel's. Dropped.
  const std::set<std::string> warnings(p.warnings.begin(), p.warnings.end());
  EXPECT_EQ(warnings, (std::set<std::string>{"objects[1].placement: not part of format version 1 (this file's); dropped",
                                             "objects[1].locked: not part of format version 1 (this file's); dropped"}));
  EXPECT_EQ(serializeProject(p.document).find("placement"), std::string::npos);
}

TEST(Placement, BadPlacementsAreRefusedWithTheirPath) {
  auto fault = [](const std::string& object) {
    try {
      parseProject(R"({"format": "corbel", "version": 2, "objects": [)" + object + "]}");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(fault(R"({"id": 1, "name": "A", "box": {"size": [1, 2, 3]}, "placement": {"scale": -1}})"),
            "objects[0].placement.scale: must be in [1e-4, 1e4]");
  EXPECT_EQ(fault(R"({"id": 1, "name": "A", "box": {"size": [1, 2, 3]}, "placement": {"translation": [1, 2]}})"),
            "objects[0].placement.translation: expected [x, y, z] numbers");
  // Masonry is analysed at its real size: a placement may move and turn it, not scale it.
  EXPECT_EQ(fault(R"({"id": 1, "name": "A", "masonry": {"model": "tower"}, "placement": {"scale": 2}})"),
            "objects[0].placement.scale: this kind of object cannot be scaled (only boxes, extrusions and units can); "
            "it must be 1");
  EXPECT_EQ(fault(R"({"id": 1, "name": "A", "masonry": {"model": "tower"}, "placement": {"rotation": 45}})"),
            "accepted");
}

// Every vertex of the placed box is one of the 8 hand-computed corners, and each corner is there.
void expectPlacedBox(const Scene& scene, ObjectId id) {
  const std::set<std::array<double, 3>> corners = {
      {9, 19.5, 1}, {11, 19.5, 1}, {9, 20.5, 1}, {11, 20.5, 1}, {9, 19.5, 4}, {11, 19.5, 4}, {9, 20.5, 4}, {11, 20.5, 4}};
  std::set<std::array<double, 3>> seen;
  const PolyMesh& mesh = scene.mesh();
  const auto byObject = scene.facesByObject();
  for (auto f : byObject.at(id))
    for (auto v : mesh.fv_range(f)) {
      const Vec3 p = mesh.point(v);
      seen.insert({p[0], p[1], p[2]});
    }
  EXPECT_EQ(seen, corners);
}

TEST(Placement, SceneSyncPlacesTheBuildAndMovesItWithoutRebuilding) {
  Document doc;
  doc.objects.push_back(boxObject(1, "Box"));
  doc.objects[0].placement = quarterTurn();
  SceneSync sync;
  Scene scene;
  EXPECT_EQ(sync.update(doc, scene), 1u);
  expectPlacedBox(scene, 1);
  // Moving it again plans no build, only a move; the result is the new placement of the same box.
  doc.objects[0].placement.translation = Vec3(0, 0, 0);
  doc.objects[0].placement.rotation_deg = 0;
  doc.objects[0].placement.scale = 1;
  const SceneSync::Job job = sync.plan(doc, scene);
  EXPECT_TRUE(job.build.empty());
  ASSERT_EQ(job.moved.size(), 1u);
  sync.update(doc, scene);
  const BBox b = scene.bounds(1);
  EXPECT_EQ(b.lo, Vec3(-1, -2, 0));
  EXPECT_EQ(b.hi, Vec3(1, 2, 6));
  doc.objects[0].placement = quarterTurn();
  sync.update(doc, scene);
  expectPlacedBox(scene, 1);
}

TEST(Placement, ARayPicksTheObjectWhereItIsDrawn) {
  Document doc;
  doc.objects.push_back(boxObject(1, "Box"));
  doc.objects[0].placement = quarterTurn();
  SceneSync sync;
  Scene scene;
  sync.update(doc, scene);
  // Straight down onto the placed top (z = 4) at (10, 20): t = 10 − 4 = 6.
  const auto hit = pickScene(scene, Vec3(10, 20, 10), Vec3(0, 0, -1));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->object, 1u);
  EXPECT_NEAR(hit->t, 6.0, 1e-12);
  // Where the unplaced box stood (the origin) there is nothing now.
  EXPECT_FALSE(pickScene(scene, Vec3(0, 0, 10), Vec3(0, 0, -1)));
  // (10.9, 20, ·) lies inside the turned footprint (x 9..11) but (10, 21, ·) does not (y 19.5..20.5).
  EXPECT_TRUE(pickScene(scene, Vec3(10.9, 20, 10), Vec3(0, 0, -1)));
  EXPECT_FALSE(pickScene(scene, Vec3(10, 21, 10), Vec3(0, 0, -1)));
}

TEST(Placement, OverlaysDrawnInAnObjectsFrameArePlacedAfterTheMark) {
  render::Overlay o;
  o.line(Vec3(0, 0, 0), Vec3(1, 0, 0), {1, 1, 1, 1});  // before the mark: left alone
  const render::Overlay::Mark mark = o.mark();
  o.line(Vec3(1, 2, 6), Vec3(-1, -2, 0), {1, 0, 0, 1});
  o.placeSince(mark, quarterTurn());
  const std::vector<float>& v = o.lineVertices();  // [x y z r g b a] per vertex
  ASSERT_EQ(v.size(), 4u * 7u);
  EXPECT_EQ((std::array<float, 3>{v[7], v[8], v[9]}), (std::array<float, 3>{1, 0, 0}));
  EXPECT_EQ((std::array<float, 3>{v[14], v[15], v[16]}), (std::array<float, 3>{9, 20.5f, 4}));   // by hand above
  EXPECT_EQ((std::array<float, 3>{v[21], v[22], v[23]}), (std::array<float, 3>{11, 19.5f, 1}));
  EXPECT_EQ(v[17], 1.0f);  // the colour stays
}

}  // namespace
}  // namespace corbel
