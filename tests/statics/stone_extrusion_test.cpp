// Extrusions built in stone (compose/stone_extrusion.h): the roof's loads against a hand
// computation for a hipped roof, and the shipped stone houses: the one meant to stand stands by
// the LP, the thin-walled one does not until its roof has ties or its walls are thickened.
#include "core/error.h"
#include "core/history.h"
#include "core/project_io.h"
#include "statics/analysis.h"
#include "statics/search.h"
#include "compose/stone_extrusion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace corbel::statics {
namespace {

// An 8 × 6 m plan, 3 m walls, a hipped roof at 45°.
ExtrusionSpec hippedHouse() {
  ExtrusionSpec e;
  e.profiles = {{"hip", {Vec2(0, 0), Vec2(0, 3), Vec2(3, 6)}, {}}};
  e.loops = {PlanLoop({Vec2(0, 0), Vec2(8, 0), Vec2(8, 6), Vec2(0, 6)}, {0, 0, 0, 0})};
  e.anchors = {MeshAnchor("door", Anchor{0, 0, false, 0.5, 0.0}, FeatureKind::Door, {1.0, 2.0, 0.1}),
               MeshAnchor("window", Anchor{0, 1, false, 0.5, 0.9}, FeatureKind::Window, {1.0, 1.2, 0.1})};
  e.masonry = StoneWalls{};
  e.masonry->courseHeight = 0.5;
  e.masonry->openings = {{"window", OpeningHead::FlatArch}};
  return e;
}

// By hand: each long slope's plan is a trapezoid (8 + 2)/2 · 3 = 15 m², each hip end a triangle
// 6 · 3 / 2 = 9 m²; at 45° the surface is the plan area × √2, and a rafter's thrust w/(2 tan 45°)
// is half its weight.
TEST(StoneExtrusion, HippedRoofLoadsAreTheHandComputedOnes) {
  const StoneHouse h = stoneHouseOf(hippedHouse());
  ASSERT_EQ(h.roofArea.size(), 4u);
  EXPECT_NEAR(h.roofArea[0], 15 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(h.roofArea[1], 9 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(h.roofArea[2], 15 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(h.roofArea[3], 9 * std::sqrt(2.0), 1e-6);
  for (int e = 0; e < 4; ++e) EXPECT_NEAR(h.thrustArea[std::size_t(e)], h.roofArea[std::size_t(e)] / 2, 1e-6);
  EXPECT_NEAR(h.roofPitchDeg, 45.0, 1e-6);
  EXPECT_DOUBLE_EQ(h.walls.height, 3.0);
  // The door on edge 0 at its middle, the window on edge 1.
  ASSERT_EQ(h.walls.openings.size(), 2u);
  EXPECT_NEAR(h.walls.openings[0].from, 3.5, 1e-9);
  EXPECT_NEAR(h.walls.openings[0].to, 4.5, 1e-9);
  EXPECT_NEAR(h.walls.openings[1].bottom, 0.9, 1e-9);

  // The model's point loads: the covering's whole weight down, no net horizontal force, and
  // each wall pushed out by q·A/2 of its slope.
  ExtrusionSpec spec = hippedHouse();
  const double q = 800;
  spec.masonry->coveringWeight = q;
  const ParametricModel model = stoneModel(spec);
  const Assembly as = model.build(model.parameters);
  Vec3 total(0.0);
  double outFront = 0;
  for (const Block& b : as.blocks)
    for (const PointLoad& l : b.pointLoads) {
      total += l.force;
      outFront += l.force[1] < 0 ? -l.force[1] : 0;  // edge 0's wall faces −y
    }
  EXPECT_NEAR(total[2], -q * 48 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(total[0], 0.0, 1e-6);
  EXPECT_NEAR(total[1], 0.0, 1e-6);
  EXPECT_NEAR(outFront, q * 15 * std::sqrt(2.0) / 2, 1e-6);
  EXPECT_TRUE(checkFeasibility(as).feasible);
  // With ties, nothing pushes outwards.
  spec.masonry->ties = true;
  const ParametricModel tied = stoneModel(spec);
  for (const Block& b : tied.build(tied.parameters).blocks)
    for (const PointLoad& l : b.pointLoads) EXPECT_EQ(l.force[1], 0.0);
}

// Wind through the model: blowing towards +y it meets only edge 0's wall, 8 × 3 m less the
// 1 × 2 m door; towards 45° also edge 3's (6 × 3 m, unpierced), each by cos 45°.
TEST(StoneExtrusion, WindLoadsTheWallsItMeets) {
  ExtrusionSpec spec = hippedHouse();
  spec.masonry->coveringWeight = 0;
  spec.masonry->windPressure = 500;
  auto total = [&](double direction) {
    spec.masonry->windDirection = direction;
    const ParametricModel model = stoneModel(spec);
    Vec3 f(0.0);
    for (const Block& b : model.build(model.parameters).blocks)
      for (const PointLoad& l : b.pointLoads) f += l.force;
    return f;
  };
  const Vec3 north = total(90);
  EXPECT_NEAR(north[0], 0.0, 1e-9);
  EXPECT_NEAR(north[1], 500 * 22.0, 1e-9);
  EXPECT_EQ(north[2], 0.0);
  const Vec3 diagonal = total(45);
  EXPECT_NEAR(diagonal[0], 500 * 18.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(diagonal[1], 500 * 22.0 / std::sqrt(2.0), 1e-9);
}

TEST(StoneExtrusion, RefusesWhatItCannotBuild) {
  ExtrusionSpec e = hippedHouse();
  e.masonry->openings = {{"chimney", OpeningHead::Lintel}};
  EXPECT_THROW(stoneModel(e), InputError);
  e = hippedHouse();
  e.profiles.push_back({"low", {Vec2(0, 0), Vec2(0, 2), Vec2(3, 5)}, {}});
  e.loops[0].profile[1] = 1;  // walls of two heights
  EXPECT_THROW(stoneModel(e), InputError);
  e = hippedHouse();
  e.masonry.reset();
  EXPECT_THROW(stoneModel(e), InputError);
}

ParametricModel shippedStone(const std::string& object) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/stone-house.corbel");
  const DocObject* o = p.document.findByName(object);
  if (!o) throw std::runtime_error("no object " + object);
  return stoneModel(std::get<ExtrusionSpec>(o->spec));
}

TEST(StoneExtrusion, ShippedStoneHouseStandsAndTheThinWalledOneNeedsThickerWalls) {
  const ParametricModel house = shippedStone("Stone house");
  const Assembly a = house.build(house.parameters);
  EXPECT_GE(a.blocks.size(), 200u);
  EXPECT_LE(a.blocks.size(), 500u);
  EXPECT_TRUE(checkFeasibility(a).feasible);
  EXPECT_TRUE(analyse(a).feasible);

  const ParametricModel thin = shippedStone("Stone house, thin walls");
  EXPECT_FALSE(checkFeasibility(thin.build(thin.parameters)).feasible);
  ParameterSet tied = thin.parameters;
  tied.set("ties", 1);
  EXPECT_TRUE(checkFeasibility(thin.build(tied)).feasible);
  // Make It Stand on the walls' thickness: the result stands by the LP too.
  SearchOptions options;
  const SearchResult r = searchParameters(thin, thin.suggestedFree, options);
  ASSERT_EQ(r.status, SearchStatus::Feasible) << r.message;
  EXPECT_GT(r.values["thickness"], thin.parameters["thickness"]);
  EXPECT_TRUE(checkFeasibility(thin.build(r.values)).feasible);
}

// Make It Stand on the thin-walled house as a project edit: the values found written back
// into the extrusion's masonry section (stoneWallsAt) and committed as one History step. The
// project after it stands by the LP, also once saved and read back; one undo restores the
// section that does not stand.
TEST(StoneExtrusion, MakeItStandIsOneUndoStepOfTheProjectThatStands) {
  const std::string name = "Stone house, thin walls";
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/stone-house.corbel");
  History history(p.document);
  const DocObject* before = history.current().findByName(name);
  ASSERT_NE(before, nullptr);
  const ExtrusionSpec thin = std::get<ExtrusionSpec>(before->spec);
  const ParametricModel model = stoneModel(thin);
  const SearchResult r = searchParameters(model, model.suggestedFree, SearchOptions{});
  ASSERT_EQ(r.status, SearchStatus::Feasible) << r.message;

  Document next = history.current();
  ExtrusionSpec& spec = std::get<ExtrusionSpec>(next.find(before->id)->spec);
  spec.masonry = stoneWallsAt(*spec.masonry, r.values);
  history.commit(next, "Make It Stand");
  EXPECT_EQ(history.size(), 2u);
  auto standsInProject = [&](const Document& d) {
    const ParametricModel m = stoneModel(std::get<ExtrusionSpec>(d.findByName(name)->spec));
    return checkFeasibility(m.build(m.parameters)).feasible;
  };
  const ExtrusionSpec& after = std::get<ExtrusionSpec>(history.current().findByName(name)->spec);
  EXPECT_GT(after.masonry->thickness, thin.masonry->thickness);
  EXPECT_EQ(after.masonry->openings, thin.masonry->openings);
  EXPECT_EQ(after.profiles, thin.profiles);  // still the same extrusion
  EXPECT_TRUE(standsInProject(history.current()));
  EXPECT_TRUE(standsInProject(parseProject(serializeProject(history.current())).document));
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(std::get<ExtrusionSpec>(history.current().findByName(name)->spec), thin);
  EXPECT_FALSE(standsInProject(history.current()));
}

}  // namespace
}  // namespace corbel::statics
