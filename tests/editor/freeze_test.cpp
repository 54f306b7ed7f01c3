// editor/growth_edits.h freezeGrowth and growth/kernel.h's units already there: Freeze turns a
// grown model into unit objects without losing or moving anything (every part where it grew,
// the roofs, doors and windows as they were, every face of the Scene accounted for), and new
// seeds grow around the frozen units, where without them they would have grown into them.
#include "editor/growth_edits.h"

#include "core/error.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "core/scene_sync.h"
#include "growth/kernel.h"
#include "growth/tolerances.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace corbel::editor {
namespace {

std::string finishedSite() {
  std::ifstream in(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-finished.json");
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str()).dump();
}

// The finished block grown to the end, at a quarter turn and moved, so that Freeze must carry
// the site's placement over to its units.
Document grownBlock(ObjectId& id) {
  Document d;
  GrowthSpec g;
  g.site = finishedSite();
  g.steps = -1;
  id = d.add("Block", g);
  d.find(id)->placement.translation = Vec3(100, -20, 0);
  d.find(id)->placement.rotation_deg = 90;
  return d;
}

bool overlaps(const growth::Unit& a, const growth::Unit& b) {
  for (const growth::Box& p : a.parts)
    for (const growth::Box& q : b.parts)
      if (growth::interiorsOverlap(p, q, growth::kEps)) return true;
  return false;
}

std::size_t facesOf(const Scene& scene, ObjectId id) { return scene.hasObject(id) ? scene.faces(id).size() : 0; }

TEST(Freeze, EveryUnitStaysWhereItGrewAndTheSiteStillFinishesIt) {
  ObjectId id = 0;
  const Document doc = grownBlock(id);
  const growth::GrownModel grown = growth::grow(growth::growthInputOf(doc, *doc.find(id)));
  ASSERT_GE(grown.units.size(), 8u);
  std::vector<std::string> warnings;
  const MeshData finishBefore = growth::finishMesh(grown.site, grown.units, warnings);
  ASSERT_FALSE(finishBefore.faces.empty()) << "the example has roofs, doors and windows";

  std::vector<ObjectId> added;
  const Document frozen = freezeGrowth(doc, id, grown, &added);
  ASSERT_EQ(added.size(), grown.units.size());
  for (std::size_t i = 0; i < added.size(); ++i) {
    const DocObject* o = frozen.find(added[i]);
    ASSERT_NE(o, nullptr);
    EXPECT_EQ(o->name, "Block unit " + std::to_string(grown.units[i].id));
    EXPECT_EQ(o->placement, doc.find(id)->placement);
    const auto& u = std::get<UnitSpec>(o->spec);
    ASSERT_EQ(u.parts.size(), grown.units[i].parts.size());
    for (std::size_t k = 0; k < u.parts.size(); ++k) {
      EXPECT_EQ(u.parts[k].lo, grown.units[i].parts[k].lo);
      EXPECT_EQ(u.parts[k].hi, grown.units[i].parts[k].hi);
    }
  }
  const auto& site = std::get<GrowthSpec>(frozen.find(id)->spec);
  EXPECT_TRUE(site.aroundUnits);
  EXPECT_EQ(nlohmann::json::parse(site.site)["seeds"], nlohmann::json::array()) << "the seeds are spent";

  // Grown again, the site grows nothing and has every frozen unit, with the same ids, as a unit
  // already there; its roofs, doors and windows are the same faces as before, point for point.
  const growth::GrownModel again = growth::grow(growth::growthInputOf(frozen, *frozen.find(id)));
  EXPECT_TRUE(again.site.seeds.empty());
  ASSERT_EQ(again.units.size(), grown.units.size());
  for (std::size_t i = 0; i < again.units.size(); ++i) {
    EXPECT_EQ(again.units[i].id, grown.units[i].id);
    EXPECT_EQ(again.units[i].parts, grown.units[i].parts);
  }
  warnings.clear();
  const MeshData finishAfter = growth::finishMesh(again.site, again.units, warnings);
  EXPECT_EQ(finishAfter.points, finishBefore.points);
  EXPECT_EQ(finishAfter.faces, finishBefore.faces);

  // In the Scene: the site's faces before are its faces after plus every unit object's, and
  // each unit object is a closed shell of kind Unit.
  Scene before, after;
  SceneSync sync;
  growth::registerKernel(sync);
  sync.update(doc, before);
  SceneSync sync2;
  growth::registerKernel(sync2);
  sync2.update(frozen, after);
  ASSERT_EQ(sync2.status().at(id).error, "");
  std::size_t unitFaces = 0;
  for (ObjectId u : added) {
    EXPECT_EQ(after.objects().at(u).kind, Kind::Unit);
    EXPECT_TRUE(after.validate(u).closedManifold());
    unitFaces += facesOf(after, u);
  }
  EXPECT_EQ(facesOf(before, id), facesOf(after, id) + unitFaces);
  EXPECT_NEAR(after.bounds(id).lo[0], before.bounds(id).lo[0], 1e-9) << "the cores stay in the site";

  // Saved and read back, the frozen project is the same Document.
  const LoadedProject read = parseProject(serializeProject(frozen));
  EXPECT_EQ(read.document, frozen);
}

TEST(Freeze, NewSeedsGrowAroundTheFrozenUnits) {
  ObjectId id = 0;
  const Document doc = grownBlock(id);
  const growth::GrownModel grown = growth::grow(growth::growthInputOf(doc, *doc.find(id)));
  Document frozen = freezeGrowth(doc, id, grown);

  // A new seed where the grid first has room beside the frozen units, grown to the end.
  growth::GrownModel empty = growth::grow(growth::growthInputOf(frozen, *frozen.find(id)));
  growth::Seed like;
  like.targetArea = 80;
  const auto spot = freeSeedSpot(empty.site, like);
  ASSERT_TRUE(spot) << "the block leaves room for a seed";
  const SiteEditResult r = setSeed(std::get<GrowthSpec>(frozen.find(id)->spec), 0, *spot);
  ASSERT_TRUE(r.spec) << r.error;
  std::get<GrowthSpec>(frozen.find(id)->spec) = *r.spec;

  const growth::GrownModel around = growth::grow(growth::growthInputOf(frozen, *frozen.find(id)));
  ASSERT_EQ(around.units.size(), grown.units.size() + 1);
  const growth::Unit& fresh = around.units[0];
  EXPECT_GT(fresh.floorArea(), like.size[0] * like.size[1]) << "it grew";
  for (std::size_t i = 1; i < around.units.size(); ++i) {
    EXPECT_FALSE(overlaps(fresh, around.units[i])) << "into frozen unit " << around.units[i].id;
    EXPECT_EQ(around.units[i].parts, grown.units[i - 1].parts) << "a frozen unit never moves";
  }

  // The same seed on the site not told to grow around them grows into their space: the test
  // above could fail.
  GrowthSpec blind = std::get<GrowthSpec>(frozen.find(id)->spec);
  blind.aroundUnits = false;
  const growth::GrownModel alone = growth::grow(blind);
  ASSERT_EQ(alone.units.size(), 1u);
  bool into = false;
  for (const growth::Unit& u : grown.units) into = into || overlaps(alone.units[0], u);
  EXPECT_TRUE(into);
}

TEST(Freeze, ASeedOnAFrozenUnitIsRefusedNamingIt) {
  ObjectId id = 0;
  const Document doc = grownBlock(id);
  const growth::GrownModel grown = growth::grow(growth::growthInputOf(doc, *doc.find(id)));
  Document frozen = freezeGrowth(doc, id, grown);
  GrowthSpec& spec = std::get<GrowthSpec>(frozen.find(id)->spec);
  // A 3 × 3 seed in the corner of the first frozen unit's first part, on its storey.
  const growth::Box& p = grown.units[0].parts[0];
  auto now = nlohmann::json::parse(spec.site);
  now["seeds"] = nlohmann::json::array(
      {{{"at", {p.lo[0], p.lo[1]}}, {"size", {3, 3}}, {"storey", int(std::lround(p.lo[2] / 3))}, {"target_area", 20}}});
  spec.site = now.dump();
  try {
    growth::grow(growth::growthInputOf(frozen, *frozen.find(id)));
    FAIL() << "a seed inside a frozen unit grew";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("overlaps the unit \"Block unit"), std::string::npos) << e.what();
  }
}

TEST(Freeze, WhatCannotBeFrozenIsRefusedAndAUnitTurnedAgainstTheSiteIsNamed) {
  ObjectId id = 0;
  Document doc = grownBlock(id);
  const ObjectId box = doc.add("Box", BoxSpec{});
  EXPECT_THROW(freezeGrowth(doc, box, growth::GrownModel{}), InputError);
  EXPECT_THROW(freezeGrowth(doc, id, growth::GrownModel{}), InputError) << "nothing grown: nothing to freeze";

  UnitSpec u;
  u.parts = {{Vec3(0, 0, 0), Vec3(4, 4, 3)}};
  const ObjectId turned = doc.add("turned", u);
  doc.find(turned)->placement.rotation_deg = 30;
  std::get<GrowthSpec>(doc.find(id)->spec).aroundUnits = true;
  std::vector<std::string> warnings;
  const auto fixed = growth::unitsAround(*doc.find(id), growth::unitObjectsFor(doc, *doc.find(id)), &warnings);
  EXPECT_TRUE(fixed.empty());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("\"turned\""), std::string::npos) << warnings[0];
}

}  // namespace
}  // namespace corbel::editor
