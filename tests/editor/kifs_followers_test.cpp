// editor/kifs_followers.h: the editor's KIFS followers baked in the background. The oracle is
// the bake every other path uses (kifs::followedMass, as corbel-cli render and the golden tests
// bake from the project's Scene): the editor's field is sample for sample the same, and it is
// baked again exactly when the followed object changes.
#include "editor/kifs_followers.h"

#include "city/kernel.h"
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "kifs/kernel.h"
#include "kifs/params.h"

#include <gtest/gtest.h>

namespace corbel::editor {
namespace {

struct World {
  Document doc;
  Scene scene;
  SceneSync sync;
  std::vector<std::string> errors;
  World() {
    kifs::registerKernel(sync);
    DocObject mass;
    mass.id = 1;
    mass.name = "Mass";
    BoxSpec b;
    b.size = Vec3(10, 8, 12);
    mass.spec = b;
    DocObject k;
    k.id = 2;
    k.name = "Facade";
    KifsSpec spec;
    spec.mass.footprint = "object";
    spec.mass.object = "Mass";
    spec.mass.resolution = 12;
    k.spec = spec;
    doc.objects = {mass, k};
    sync.update(doc, scene);
  }
  bool update(KifsFollowers& f, bool current = true) {
    return f.update(doc, scene, current, nullptr, [this](const std::string& l, bool) { errors.push_back(l); }, true);
  }
};

TEST(KifsFollowers, TheFieldIsTheBakeOfTheFollowedObjectAndFollowsItsEdits) {
  World w;
  KifsFollowers f;
  EXPECT_TRUE(f.update(w.doc, w.scene, true, nullptr, nullptr, true));
  std::vector<KifsFollowers::Shown> shown = f.shown(w.doc, nullptr);
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_EQ(shown[0].id, 2u);
  const auto oracle = kifs::followedMass(w.doc, w.scene, *w.doc.find(2));
  EXPECT_EQ(shown[0].mass->values, oracle->values);
  EXPECT_EQ(shown[0].mass->count, oracle->count);
  // Nothing changed: no new bake.
  EXPECT_FALSE(w.update(f));
  EXPECT_EQ(f.shown(w.doc, nullptr)[0].mass, shown[0].mass);

  // The mass moved: while the Scene is not yet rebuilt nothing is baked and the old field stays;
  // once it is, the new field is the bake of the moved box (its frame at the new place).
  w.doc.find(1)->placement.translation = Vec3(3, -2, 0);
  EXPECT_FALSE(w.update(f, false));
  EXPECT_EQ(f.shown(w.doc, nullptr)[0].mass, shown[0].mass);
  w.sync.update(w.doc, w.scene);
  EXPECT_TRUE(w.update(f));
  shown = f.shown(w.doc, nullptr);
  EXPECT_EQ(shown[0].mass->values, kifs::followedMass(w.doc, w.scene, *w.doc.find(2))->values);
  EXPECT_EQ(shown[0].mass->frameOrigin, glm::dvec3(3, -2, 0));
  // The follower's own resolution: baked again at it.
  std::get<KifsSpec>(w.doc.find(2)->spec).mass.resolution = 20;
  EXPECT_TRUE(w.update(f));
  EXPECT_GT(f.shown(w.doc, nullptr)[0].mass->count.x, shown[0].mass->count.x);
  EXPECT_TRUE(w.errors.empty());
}

// A follower whose object is gone says so once, in the kernel's words, and shows nothing.
TEST(KifsFollowers, AMissingMassIsReportedOnce) {
  World w;
  std::get<KifsSpec>(w.doc.find(2)->spec).mass.object = "Nothing";
  KifsFollowers f;
  EXPECT_FALSE(w.update(f));
  EXPECT_FALSE(w.update(f));
  ASSERT_EQ(w.errors.size(), 1u);
  EXPECT_NE(w.errors[0].find("kifs.mass.object: no object named \"Nothing\""), std::string::npos) << w.errors[0];
  EXPECT_TRUE(f.shown(w.doc, nullptr).empty());
  EXPECT_FALSE(f.baking());
}

// A follower of one building of a town (kifs.mass.building): the field is the bake of that
// building, and naming another building bakes that one.
TEST(KifsFollowers, ATownsBuildingIsBakedAndNamingAnotherBakesThatOne) {
  LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/town-oldtown.corbel");
  Document doc;
  for (const DocObject& o : p.document.objects)
    if (auto* t = std::get_if<TownSpec>(&o.spec)) {
      TownSpec town = *t;
      town.detail = "massing";
      doc.add("Town", town);
    }
  KifsSpec spec;
  spec.mass.footprint = "object";
  spec.mass.object = "Town";
  spec.mass.resolution = 12;
  const ObjectId k = doc.add("Facade", spec);
  SceneSync sync;
  kifs::registerKernel(sync);
  const std::shared_ptr<city::TownCache> towns = city::registerKernel(sync);
  Scene scene;
  sync.update(doc, scene);
  const std::vector<city::BuiltBuilding> built = towns->buildings(doc.findByName("Town")->id);
  ASSERT_GE(built.size(), 2u);
  KifsFollowers f;
  std::vector<std::string> errors;
  auto update = [&] {
    return f.update(doc, scene, true, nullptr, [&](const std::string& l, bool) { errors.push_back(l); }, true,
                    city::buildingMeshes(towns));
  };
  for (const std::size_t i : {std::size_t(0), built.size() - 1}) {
    std::get<KifsSpec>(doc.find(k)->spec).mass.building = built[i].id;
    EXPECT_TRUE(update()) << built[i].id;
    const auto oracle = kifs::followedMass(doc, scene, *doc.find(k), nullptr, city::buildingMeshes(towns));
    const auto shown = f.shown(doc, nullptr);
    ASSERT_EQ(shown.size(), 1u);
    EXPECT_EQ(shown[0].mass->values, oracle->values);
    // The building's own box, not the town's.
    EXPECT_NEAR(shown[0].mass->shell.lo.x, built[i].bounds.lo[0], 1e-9);
    EXPECT_NEAR(shown[0].mass->shell.hi.y, built[i].bounds.hi[1], 1e-9);
  }
  EXPECT_TRUE(errors.empty()) << errors.front();
}

}  // namespace
}  // namespace corbel::editor
