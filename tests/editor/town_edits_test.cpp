// editor/town_edits.h: an override is one undoable Document change that re-extrudes exactly the
// building it names; a click picks the building a ray meets first.
#include "editor/town_edits.h"

#include "core/error.h"
#include "core/history.h"
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "extrude/kernel.h"

#include <gtest/gtest.h>

namespace corbel::editor {
namespace {

Document example() {
  return loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/town-oldtown.corbel").document;
}

ObjectId townId(const Document& d) {
  for (const DocObject& o : d.objects)
    if (std::holds_alternative<TownSpec>(o.spec)) return o.id;
  return 0;
}

TEST(TownEdits, AnOverrideIsOneUndoStepAndRebuildsOneBuilding) {
  Document doc = example();
  const ObjectId id = townId(doc);
  ASSERT_NE(id, 0u);
  SceneSync sync;
  extrude::registerKernel(sync);
  const auto cache = city::registerKernel(sync);
  Scene scene;
  sync.update(doc, scene);
  const std::size_t first = cache->extrusions();
  EXPECT_EQ(first, 32u);
  // The town in the Scene: one closed shell per building (feature meshes are closed too).
  const ValidityReport v = scene.validate(id);
  EXPECT_TRUE(v.closedManifold()) << (v.problems().empty() ? "" : v.problems()[0]);
  EXPECT_GE(v.components, 32u);
  const auto list = cache->buildings(id);
  const std::string target = list[3].id;

  History history;
  history.reset(doc);
  Document edited = doc;
  TownOverride o;
  o.type = list[3].type == "town house" ? "brick town house" : "town house";
  setTownOverride(edited, id, target, o);
  history.commit(edited, "override");
  EXPECT_EQ(sync.update(history.current(), scene), 1u);  // the town object
  EXPECT_EQ(cache->extrusions(), first + 1);
  EXPECT_EQ(cache->buildings(id)[3].type, o.type);
  EXPECT_TRUE(sync.status().at(id).error.empty());

  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), doc);
  sync.update(history.current(), scene);
  EXPECT_EQ(cache->extrusions(), first + 2);
  EXPECT_EQ(cache->buildings(id)[3].type, list[3].type);

  // An empty override removes the entry.
  setTownOverride(edited, id, target, TownOverride{});
  EXPECT_TRUE(std::get<TownSpec>(edited.find(id)->spec).overrides.empty());
  EXPECT_THROW(setTownOverride(edited, 999, target, o), Error);
}

TEST(TownEdits, SetTownSpecRefusesBadValues) {
  Document doc = example();
  const ObjectId id = townId(doc);
  TownSpec t = std::get<TownSpec>(doc.find(id)->spec);
  t.detail = "ultra";
  EXPECT_THROW(setTownSpec(doc, id, t), Error);
  t.detail = "massing";
  setTownSpec(doc, id, t);
  EXPECT_EQ(std::get<TownSpec>(doc.find(id)->spec).detail, "massing");
}

TEST(TownEdits, PickFindsTheBuildingARayMeetsFirst) {
  Document doc = example();
  const ObjectId id = townId(doc);
  SceneSync sync;
  extrude::registerKernel(sync);
  const auto cache = city::registerKernel(sync);
  Scene scene;
  sync.update(doc, scene);
  const auto list = cache->buildings(id);
  std::size_t checked = 0;
  for (const auto& b : list) {
    if (b.bounds.empty()) continue;
    // Straight down onto the middle of its box: that building, where the middle lies on it.
    const Vec3 c = b.bounds.center();
    const auto hit = pickBuilding(*cache, id, Vec3(c[0], c[1], 500), Vec3(0, 0, -1));
    if (hit && *hit == b.id) ++checked;
  }
  EXPECT_GE(checked, list.size() * 9 / 10);  // courtyards and L shapes can put the middle over another
  EXPECT_FALSE(pickBuilding(*cache, id, Vec3(5000, 5000, 500), Vec3(0, 0, -1)).has_value());
}

TEST(TownEdits, StylesAreTheShippedJsonFiles) {
  const auto styles = stylesIn(std::string(CORBEL_SOURCE_DIR) + "/assets/styles");
  ASSERT_EQ(styles.size(), 4u);
  EXPECT_NE(styles[0].find("mixed.json"), std::string::npos);
}

}  // namespace
}  // namespace corbel::editor
