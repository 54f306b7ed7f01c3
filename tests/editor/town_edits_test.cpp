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

// Setting an edge's profile adds it to the building's override, keeping what else it holds;
// clearing the last thing removes the override.
TEST(TownEdits, AnEdgeProfileJoinsTheOverrideAndClearingItRemovesIt) {
  Document doc = example();
  const ObjectId id = townId(doc);
  TownOverride o;
  o.type = "town house";
  setTownOverride(doc, id, "b1", o);
  setTownEdgeProfile(doc, id, "b1", 0, 2, "oldtown gable");
  setTownEdgeProfile(doc, id, "b2", 1, 0, "oldtown eaves");
  const TownSpec& t = std::get<TownSpec>(doc.find(id)->spec);
  EXPECT_EQ(t.overrides.at("b1").type, "town house");
  EXPECT_EQ(t.overrides.at("b1").edges, (std::map<std::string, std::string>{{"0:2", "oldtown gable"}}));
  EXPECT_EQ(t.overrides.at("b2").edges, (std::map<std::string, std::string>{{"1:0", "oldtown eaves"}}));
  setTownEdgeProfile(doc, id, "b2", 1, 0, "");
  EXPECT_EQ(std::get<TownSpec>(doc.find(id)->spec).overrides.count("b2"), 0u);
  setTownEdgeProfile(doc, id, "b1", 0, 2, "");
  EXPECT_TRUE(std::get<TownSpec>(doc.find(id)->spec).overrides.at("b1").edges.empty());
  EXPECT_THROW(setTownEdgeProfile(doc, id + 100, "b1", 0, 0, "x"), Error);
}

// The plan view's pick: the edge nearest the click (distance to the segment, by hand), none
// beyond the reach, holes included.
TEST(TownEdits, NearestEdgeIsTheClosestSegmentWithinReach) {
  // A 10 × 6 rectangle (counter-clockwise) with a 2 × 2 hole (clockwise) at (4..6, 2..4).
  const std::vector<std::vector<Vec2>> loops = {{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {{4, 2}, {4, 4}, {6, 4}, {6, 2}}};
  using E = std::optional<std::pair<int, int>>;
  EXPECT_EQ(nearestEdge(loops, Vec2(5, -0.5), 1.0), E(std::pair{0, 0}));  // 0.5 below the bottom
  EXPECT_EQ(nearestEdge(loops, Vec2(10.4, 3), 1.0), E(std::pair{0, 1}));  // right of the right wall
  EXPECT_EQ(nearestEdge(loops, Vec2(5, 5.2), 1.0), E(std::pair{0, 2}));   // 0.8 from the top, 1.2 from the hole
  EXPECT_EQ(nearestEdge(loops, Vec2(3.7, 3), 1.0), E(std::pair{1, 0}));   // the hole's left side, (4,2)→(4,4)
  EXPECT_EQ(nearestEdge(loops, Vec2(5, 1.6), 1.0), E(std::pair{1, 3}));   // the hole's bottom, (6,2)→(4,2)
  EXPECT_EQ(nearestEdge(loops, Vec2(5, 3), 0.9), E());                    // the hole's middle: 1 from every side
  EXPECT_EQ(nearestEdge(loops, Vec2(-3, -4), 4.9), E());                  // 5 from the corner (0, 0)
  EXPECT_EQ(nearestEdge(loops, Vec2(-3, -4), 5.1), E(std::pair{0, 0}));   // a tie of edges 0 and 3: the first
  EXPECT_EQ(nearestEdge({}, Vec2(0, 0), 100.0), E());
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

// A street added beside the old town: its plots build (the default lies 20 m clear of the
// town's bounds, and its plots reach 19 m), the footprints are not extruded again, dragging its
// middle point re-cuts its plots and is one undo step back to the street as added; a point
// moved onto its neighbour is refused with the street's path and changes nothing.
TEST(TownEdits, AStreetBesideTheTownBuildsItsPlotsAndUndoesInOneStep) {
  Document doc = example();
  const ObjectId id = townId(doc);
  SceneSync sync;
  extrude::registerKernel(sync);
  const auto cache = city::registerKernel(sync);
  Scene scene;
  sync.update(doc, scene);
  ASSERT_EQ(cache->extrusions(), 32u);
  const TownStreet st = defaultStreet(*cache, id);
  ASSERT_EQ(st.points.size(), 3u);
  History history;
  history.reset(doc);
  Document added = doc;
  EXPECT_EQ(addStreet(added, id, st), 0u);
  history.commit(added, "add street");
  sync.update(history.current(), scene);
  std::size_t plots = 0, refused = 0;
  for (const city::BuiltBuilding& b : cache->buildings(id))
    if (b.id.rfind("street 1/", 0) == 0) (b.error.empty() ? plots : refused) += 1;
  EXPECT_GE(plots, 8u);
  EXPECT_EQ(refused, 0u);
  EXPECT_TRUE(sync.status().at(id).error.empty()) << sync.status().at(id).error;
  EXPECT_TRUE(scene.validate(id).closedManifold());
  const std::size_t afterAdd = cache->extrusions();
  EXPECT_LE(afterAdd, 32u + plots + 32u);  // the plots, and at most the footprints whose labels the street changed

  // A drag: many moves of the middle point, one undo step.
  const Vec2 mid(st.points[1][0], st.points[1][1]);
  for (int k = 1; k <= 5; ++k) {
    Document d = history.current();
    moveStreetPoint(d, id, 0, 1, mid + Vec2(0, -2.0 * k));
    history.commit(d, "move street point", "town.street.0.1");
  }
  EXPECT_EQ(std::get<TownSpec>(history.current().find(id)->spec).streets[0].points[1][1], mid[1] - 10);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), added);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), doc);

  Document bad = added;
  try {
    moveStreetPoint(bad, id, 0, 1, Vec2(st.points[0][0], st.points[0][1]));
    FAIL() << "a point on its neighbour should be refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("town.streets[0].points[1]: repeats the point before it"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(bad, added);
  EXPECT_THROW(moveStreetPoint(bad, id, 3, 0, mid), Error);
  EXPECT_THROW(moveStreetPoint(bad, id, 0, 7, mid), Error);
}

// Removing a street drops the overrides of its plots and renumbers those of later streets.
TEST(TownEdits, RemovingAStreetKeepsTheOverridesOfOtherStreetsPlots) {
  Document doc = example();
  const ObjectId id = townId(doc);
  TownStreet a, b;
  a.points = {{500, 0}, {570, 0}};
  b.points = {{500, 100}, {570, 100}};
  addStreet(doc, id, a);
  addStreet(doc, id, b);
  const std::size_t before = std::get<TownSpec>(doc.find(id)->spec).overrides.size();  // the footprints'
  TownOverride garage;
  garage.type = "garage";
  setTownOverride(doc, id, "street 1/left/0", garage);
  setTownOverride(doc, id, "street 2/right/3", garage);
  removeStreet(doc, id, 0);
  const TownSpec& t = std::get<TownSpec>(doc.find(id)->spec);
  ASSERT_EQ(t.streets.size(), 1u);
  EXPECT_EQ(t.streets[0], b);
  EXPECT_EQ(t.overrides.size(), before + 1);
  EXPECT_EQ(t.overrides.count("street 1/right/3"), 1u);
}

TEST(TownEdits, AClickOnTheGroundGivesThePointUnderIt) {
  const auto p = groundPoint(Vec3(10, 20, 30), Vec3(0.6, 0, -0.8));
  ASSERT_TRUE(p);
  EXPECT_NEAR((*p)[0], 10 + 0.6 * 37.5, 1e-12);
  EXPECT_NEAR((*p)[1], 20, 1e-12);
  EXPECT_FALSE(groundPoint(Vec3(0, 0, 5), Vec3(1, 0, 0)));
  EXPECT_FALSE(groundPoint(Vec3(0, 0, 5), Vec3(0, 0.6, 0.8)));
}

}  // namespace
}  // namespace corbel::editor
