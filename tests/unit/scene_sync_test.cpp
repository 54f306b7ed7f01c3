// scene_sync.h: SceneSync rebuilds exactly the objects whose spec changed, and the Scene
// always mirrors the Document afterwards.
#include "core/error.h"
#include "core/scene_sync.h"

#include "core/massing.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace {

using corbel::BoxSpec;
using corbel::Document;
using corbel::ObjectId;
using corbel::Progress;
using corbel::Scene;
using corbel::SceneSync;
using corbel::Vec3;

BoxSpec box(double x, double y, double w, double d, double h, const std::string& material = "plaster") {
  BoxSpec b;
  b.origin = Vec3(x, y, 0);
  b.size = Vec3(w, d, h);
  b.material = material;
  return b;
}

// The Scene mirrors the Document: same ids and names, and each object's faces, material and
// bounds are those of its (unrotated) spec, computed by hand.
void expectMirrors(const Document& doc, const Scene& scene) {
  std::set<ObjectId> docIds, sceneIds;
  for (const auto& o : doc.objects) docIds.insert(o.id);
  for (const auto& [id, info] : scene.objects()) sceneIds.insert(id);
  EXPECT_EQ(sceneIds, docIds);
  std::size_t totalFaces = 0;
  for (const auto& o : doc.objects) {
    SCOPED_TRACE(o.name);
    ASSERT_TRUE(scene.hasObject(o.id));
    EXPECT_EQ(scene.objects().at(o.id).name, o.name);
    EXPECT_EQ(scene.objects().at(o.id).kind, corbel::Kind::Mass);
    const BoxSpec& b = std::get<BoxSpec>(o.spec);
    const auto faces = scene.faces(o.id);
    EXPECT_EQ(faces.size(), static_cast<std::size_t>(6 * b.repeat_x * b.repeat_y));
    totalFaces += faces.size();
    for (auto f : faces) EXPECT_EQ(scene.faceMaterial(f), b.material);
    const double hx = 0.5 * ((b.repeat_x - 1) * std::abs(b.spacing_x) + b.size[0]);
    const double hy = 0.5 * ((b.repeat_y - 1) * std::abs(b.spacing_y) + b.size[1]);
    const corbel::BBox bb = scene.bounds(o.id);
    EXPECT_NEAR(bb.lo[0], b.origin[0] - hx, 1e-9);
    EXPECT_NEAR(bb.hi[0], b.origin[0] + hx, 1e-9);
    EXPECT_NEAR(bb.lo[1], b.origin[1] - hy, 1e-9);
    EXPECT_NEAR(bb.hi[1], b.origin[1] + hy, 1e-9);
    EXPECT_NEAR(bb.lo[2], b.origin[2], 1e-9);
    EXPECT_NEAR(bb.hi[2], b.origin[2] + b.size[2], 1e-9);
    EXPECT_TRUE(scene.validate(o.id).closedManifold());
  }
  EXPECT_EQ(scene.mesh().n_faces(), totalFaces);
}

// Positions of an object's points, to see whether it was left alone.
std::multiset<std::tuple<double, double, double>> pointsOf(const Scene& s, ObjectId id) {
  std::multiset<std::tuple<double, double, double>> out;
  for (auto f : s.faces(id))
    for (auto v : s.mesh().fv_range(f)) out.emplace(s.mesh().point(v)[0], s.mesh().point(v)[1], s.mesh().point(v)[2]);
  return out;
}

TEST(SceneSync, BuildsEveryObjectOnce) {
  Document doc;
  const ObjectId a = doc.add("Hall", box(0, 0, 18, 10, 7, "stone"));
  doc.add("Tower", box(12, 2, 5, 5, 19, "brick"));
  BoxSpec row = box(-2, -16, 6, 8, 5);
  row.repeat_x = 4;
  row.spacing_x = 7;
  doc.add("Terrace", row);
  Scene scene;
  SceneSync sync;
  EXPECT_EQ(sync.update(doc, scene), 3u);
  expectMirrors(doc, scene);
  const auto revision = scene.revision();
  EXPECT_EQ(sync.update(doc, scene), 0u);
  EXPECT_EQ(scene.revision(), revision);  // nothing changed, nothing touched
  EXPECT_NEAR(scene.validate(a).volume, 18.0 * 10 * 7, 1e-9);
}

TEST(SceneSync, EditingRebuildsOnlyThatObject) {
  Document doc;
  const ObjectId a = doc.add("A", box(0, 0, 4, 4, 4));
  const ObjectId b = doc.add("B", box(10, 0, 4, 4, 4));
  const ObjectId c = doc.add("C", box(20, 0, 4, 4, 4));
  Scene scene;
  SceneSync sync;
  sync.update(doc, scene);
  const auto pointsA = pointsOf(scene, a), pointsC = pointsOf(scene, c);

  std::get<BoxSpec>(doc.find(b)->spec).size[2] = 9;
  EXPECT_EQ(sync.update(doc, scene), 1u);
  expectMirrors(doc, scene);
  EXPECT_EQ(pointsOf(scene, a), pointsA);
  EXPECT_EQ(pointsOf(scene, c), pointsC);
  EXPECT_DOUBLE_EQ(scene.bounds(b).hi[2], 9.0);

  // Two edits at once: two rebuilds.
  std::get<BoxSpec>(doc.find(a)->spec).material = "glass";
  std::get<BoxSpec>(doc.find(c)->spec).repeat_y = 3;
  std::get<BoxSpec>(doc.find(c)->spec).spacing_y = 5;
  EXPECT_EQ(sync.update(doc, scene), 2u);
  expectMirrors(doc, scene);
}

TEST(SceneSync, RenamingRebuildsNothing) {
  Document doc;
  const ObjectId a = doc.add("Old name", box(0, 0, 4, 4, 4));
  Scene scene;
  SceneSync sync;
  sync.update(doc, scene);
  const auto points = pointsOf(scene, a);
  const auto revision = scene.revision();
  doc.find(a)->name = "New name";
  EXPECT_EQ(sync.update(doc, scene), 0u);
  EXPECT_EQ(scene.objects().at(a).name, "New name");
  EXPECT_NE(scene.revision(), revision);
  EXPECT_EQ(pointsOf(scene, a), points);
  expectMirrors(doc, scene);
  // Rename and edit together: one rebuild, new name.
  doc.find(a)->name = "Newer";
  std::get<BoxSpec>(doc.find(a)->spec).origin[0] = 3;
  EXPECT_EQ(sync.update(doc, scene), 1u);
  expectMirrors(doc, scene);
  // Visibility is not geometry.
  doc.find(a)->visible = false;
  EXPECT_EQ(sync.update(doc, scene), 0u);
}

TEST(SceneSync, AddingAndRemoving) {
  Document doc;
  const ObjectId a = doc.add("A", box(0, 0, 4, 4, 4));
  const ObjectId b = doc.add("B", box(10, 0, 4, 4, 4));
  Scene scene;
  SceneSync sync;
  sync.update(doc, scene);
  const auto pointsA = pointsOf(scene, a);

  doc.remove(b);
  EXPECT_EQ(sync.update(doc, scene), 0u);
  EXPECT_FALSE(scene.hasObject(b));
  EXPECT_EQ(pointsOf(scene, a), pointsA);
  expectMirrors(doc, scene);

  const ObjectId c = doc.add("C", box(-10, 5, 2, 3, 4, "slate"));
  EXPECT_EQ(sync.update(doc, scene), 1u);
  EXPECT_TRUE(scene.hasObject(c));
  EXPECT_EQ(pointsOf(scene, a), pointsA);
  expectMirrors(doc, scene);

  // A removed id that comes back with a new spec is rebuilt.
  doc.remove(c);
  sync.update(doc, scene);
  corbel::DocObject again;
  again.id = c;
  again.name = "C again";
  again.spec = box(40, 40, 1, 1, 1);
  doc.objects.push_back(again);
  EXPECT_EQ(sync.update(doc, scene), 1u);
  expectMirrors(doc, scene);

  doc.objects.clear();
  EXPECT_EQ(sync.update(doc, scene), 0u);
  EXPECT_TRUE(scene.objects().empty());
  EXPECT_EQ(scene.mesh().n_faces(), 0u);
}

TEST(SceneSync, RepairsASceneChangedBehindItsBack) {
  Document doc;
  const ObjectId a = doc.add("A", box(0, 0, 4, 4, 4));
  doc.add("B", box(10, 0, 4, 4, 4));
  Scene scene;
  SceneSync sync;
  sync.update(doc, scene);
  scene.removeObject(a);                                                                // lost
  scene.replaceObject(77, corbel::Kind::Site, "stray", corbel::buildBoxes(BoxSpec{}));  // foreign
  EXPECT_EQ(sync.update(doc, scene), 1u);
  expectMirrors(doc, scene);
}

TEST(SceneSync, InvalidateRebuildsEverything) {
  Document doc;
  doc.add("A", box(0, 0, 4, 4, 4));
  doc.add("B", box(10, 0, 4, 4, 4));
  Scene scene;
  SceneSync sync;
  sync.update(doc, scene);
  sync.invalidate();
  EXPECT_EQ(sync.update(doc, scene), 2u);
  expectMirrors(doc, scene);
  // A fresh SceneSync on a fresh Scene builds all as well.
  Scene other;
  SceneSync second;
  EXPECT_EQ(second.update(doc, other), 2u);
  expectMirrors(doc, other);
}

TEST(SceneSync, ProgressAndCancellation) {
  Document doc;
  for (int i = 0; i < 5; ++i) doc.add("House", box(10.0 * i, 0, 4, 4, 4));
  Scene scene;
  SceneSync sync;
  Progress cancelled;
  cancelled.cancel();
  EXPECT_EQ(sync.update(doc, scene, &cancelled), 0u);
  EXPECT_TRUE(scene.objects().empty());
  // A later call finishes the work.
  Progress p;
  EXPECT_EQ(sync.update(doc, scene, &p), 5u);
  EXPECT_EQ(p.fraction(), 1.0);
  EXPECT_EQ(p.stage(), "building objects");
  expectMirrors(doc, scene);
}

TEST(SceneSync, TheBuiltInBoxKernelGivesTheBoxesGeometry) {
  corbel::Document d;
  BoxSpec b = box(1, 2, 3, 4, 5, "timber");
  b.repeat_x = 2;
  b.spacing_x = 6;
  const corbel::ObjectId id = d.add("x", b);
  corbel::Scene scene;
  SceneSync sync;
  sync.update(d, scene);
  EXPECT_EQ(scene.objects().at(id).kind, corbel::Kind::Mass);
  const corbel::MeshData direct = corbel::buildBoxes(b);
  EXPECT_EQ(scene.faces(id).size(), direct.faces.size());
  EXPECT_EQ(scene.validate(id).vertices, direct.points.size());
}

// A registered kernel builds its spec type; a kernel that fails keeps the object's last good
// geometry in the Scene and reports the error; fixing the spec clears it.
TEST(SceneSync, KernelFailureKeepsTheLastGoodGeometryAndIsReported) {
  corbel::Document d;
  corbel::ExtrusionSpec e;
  e.material = "good";
  const corbel::ObjectId id = d.add("shell", e);
  corbel::Scene scene;
  SceneSync sync;
  int calls = 0;
  sync.setBuilder<corbel::ExtrusionSpec>([&](const corbel::DocObject& o, corbel::Progress*) {
    ++calls;
    const auto& spec = std::get<corbel::ExtrusionSpec>(o.spec);
    if (spec.material == "bad") throw corbel::Error("the plan intersects itself");
    corbel::BuildResult r;
    r.kind = corbel::Kind::Shell;
    r.mesh = corbel::buildBoxes(box(0, 0, 0, 2, 2, "plaster"));
    r.warnings = {"a note"};
    return r;
  });
  EXPECT_EQ(sync.update(d, scene), 1u);
  EXPECT_EQ(scene.faces(id).size(), 6u);
  EXPECT_EQ(sync.status().at(id).warnings, std::vector<std::string>{"a note"});
  std::get<corbel::ExtrusionSpec>(d.find(id)->spec).material = "bad";
  EXPECT_EQ(sync.update(d, scene), 0u);
  EXPECT_EQ(sync.status().at(id).error, "the plan intersects itself");
  EXPECT_EQ(scene.faces(id).size(), 6u) << "the last good shell stays";
  EXPECT_EQ(sync.update(d, scene), 0u);
  EXPECT_EQ(calls, 2) << "a failing spec is not re-run until it changes";
  std::get<corbel::ExtrusionSpec>(d.find(id)->spec).material = "good again";
  EXPECT_EQ(sync.update(d, scene), 1u);
  EXPECT_EQ(sync.status().at(id).error, "");
}

TEST(SceneSync, APlanBackgroundNeverRebuildsItsObject) {
  // The background is the plan pane's tracing aid: adding, moving or removing it leaves the
  // Scene untouched (same revision, same points).
  Document doc;
  const ObjectId id = doc.add("Hall", box(0, 0, 18, 10, 7));
  Scene scene;
  SceneSync sync;
  sync.update(doc, scene);
  const auto revision = scene.revision();
  const auto points = pointsOf(scene, id);
  doc.find(id)->background = corbel::PlanBackground{"/plans/hall.png", 0.02, corbel::Vec2(-5, -3), 0.6};
  EXPECT_EQ(sync.update(doc, scene), 0u);
  doc.find(id)->background->origin = corbel::Vec2(1, 1);
  doc.find(id)->background->image = "/missing/elsewhere.jpg";
  EXPECT_EQ(sync.update(doc, scene), 0u);
  doc.find(id)->background.reset();
  EXPECT_EQ(sync.update(doc, scene), 0u);
  EXPECT_EQ(scene.revision(), revision);
  EXPECT_EQ(pointsOf(scene, id), points);
  // A spec change still rebuilds (so the check above could fail).
  std::get<BoxSpec>(doc.find(id)->spec).size[2] = 8;
  EXPECT_EQ(sync.update(doc, scene), 1u);
}

}  // namespace

// A builder that reads other objects (SceneSync inputs) sees copies of them as the Document had
// them when the job was planned, and its object is rebuilt when they change, are added or are
// removed, but not when an object it does not read changes.
TEST(SceneSync, AnObjectThatReadsOthersIsRebuiltWhenTheyChange) {
  Document doc;
  corbel::ExtrusionSpec e;
  const ObjectId reader = doc.add("reader", e);
  const ObjectId a = doc.add("A", box(0, 0, 4, 4, 4));
  const ObjectId other = doc.add("other", box(10, 0, 4, 4, 4, "glass"));
  Scene scene;
  SceneSync sync;
  std::vector<std::vector<std::string>> seen;  // per build: the materials of the boxes read
  // The reader reads the plaster boxes; its shell has as many unit cubes as it read boxes.
  sync.setBuilder<corbel::ExtrusionSpec>(
      [](const Document& d, const corbel::DocObject&) {
        std::vector<corbel::DocObject> in;
        for (const auto& o : d.objects)
          if (const auto* b = std::get_if<BoxSpec>(&o.spec); b && b->material != "glass") in.push_back(o);
        return in;
      },
      [&](const corbel::DocObject&, const std::vector<corbel::DocObject>& in, Progress*) {
        std::vector<std::string> names;
        corbel::BuildResult r;
        r.kind = corbel::Kind::Shell;
        for (const auto& o : in) {
          names.push_back(o.name + ":" + std::get<BoxSpec>(o.spec).material);
          r.mesh.append(corbel::buildBoxes(box(double(names.size()) * 2, 0, 1, 1, 1)));
        }
        seen.push_back(names);
        return r;
      });
  sync.update(doc, scene);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen.back(), (std::vector<std::string>{"A:plaster"}));
  EXPECT_EQ(scene.faces(reader).size(), 6u);

  std::get<BoxSpec>(doc.find(other)->spec).size[2] = 9;  // not read: only `other` rebuilds
  EXPECT_EQ(sync.update(doc, scene), 1u);
  EXPECT_EQ(seen.size(), 1u);

  std::get<BoxSpec>(doc.find(a)->spec).material = "stone";  // read: A and the reader rebuild
  EXPECT_EQ(sync.update(doc, scene), 2u);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen.back(), (std::vector<std::string>{"A:stone"}));

  doc.find(a)->placement.translation = Vec3(1, 0, 0);  // a placement is part of what it reads
  sync.update(doc, scene);
  EXPECT_EQ(seen.size(), 3u);

  doc.add("B", box(20, 0, 4, 4, 4));  // a new object it reads
  sync.update(doc, scene);
  ASSERT_EQ(seen.size(), 4u);
  EXPECT_EQ(seen.back(), (std::vector<std::string>{"A:stone", "B:plaster"}));
  EXPECT_EQ(scene.faces(reader).size(), 12u);

  doc.remove(a);  // one it read goes
  sync.update(doc, scene);
  ASSERT_EQ(seen.size(), 5u);
  EXPECT_EQ(seen.back(), (std::vector<std::string>{"B:plaster"}));
  EXPECT_EQ(scene.faces(reader).size(), 6u);

  EXPECT_EQ(sync.update(doc, scene), 0u);  // nothing changed: nothing rebuilds
  EXPECT_EQ(seen.size(), 5u);
}
