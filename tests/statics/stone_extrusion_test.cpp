// Extrusions built in stone (compose/stone_extrusion.h): the roof's loads against a hand
// computation for a hipped roof, and the shipped stone houses: the one meant to stand stands by
// the LP, the thin-walled one does not until its roof has ties, its walls are thickened or Make
// It Stand adds buttresses (steps of the extrusion: their volume by hand).
#include "core/error.h"
#include "core/history.h"
#include "core/project_io.h"
#include "statics/analysis.h"
#include "statics/search.h"
#include "compose/stone_extrusion.h"
#include "extrude/extrude.h"

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

// The hipped house with a buttress step on edge 1 (from (8, 0) to (8, 6)): 0.8 m wide about a
// quarter of the way along (u = 1.5 m), 0.5 m out, its front profile vertical for 2 m.
ExtrusionSpec buttressedHouse() {
  ExtrusionSpec e = hippedHouse();
  e.profiles.push_back({"pier", {Vec2(0, 0), Vec2(0, 2), Vec2(0.5, 3)}, {}});
  PlanStep st;
  st.name = "pier";
  st.anchor = Anchor{0, 1, false, 0.25, 0.0};
  st.width = 0.8;
  st.depth = 0.5;
  st.frontProfile = st.sideProfile = 1;
  e.steps = {st};
  return e;
}

// The point loads' total downward force (N).
double downwardLoad(const Assembly& as) {
  Vec3 total(0.0);
  for (const Block& b : as.blocks)
    for (const PointLoad& l : b.pointLoads) total += l.force;
  return -total[2];
}

double wallVolume(const Assembly& as) {
  BBox box;
  for (const Block& b : as.blocks)
    for (const Vec3& v : b.vertices) box.add(v);
  const std::vector<BlockProperties> props = validateAssembly(as, 1e-9 * box.diagonal());
  double v = 0;
  for (std::size_t i = 0; i < as.blocks.size(); ++i)
    if (as.blocks[i].name != "ground") v += props[i].volume;
  return v;
}

// By hand: the ring of 0.5 m walls on the 8 × 6 plan is 28·0.5 − 4·0.25 = 13 m² over 3 m; the
// door takes 1 × 2 m and the window 1 × 1 m (0.9 to 2.1 m snapped to the 0.5 m courses) through
// 0.5 m; the pier adds 0.8 × 0.5 m over 2 m. The roof still bears on the main walls.
TEST(StoneExtrusion, ButtressStepsArePiersCoursedWithTheWalls) {
  const ExtrusionSpec e = buttressedHouse();
  const StoneHouse h = stoneHouseOf(e);
  ASSERT_EQ(h.walls.buttresses.size(), 1u);
  const WallButtress& b = h.walls.buttresses[0];
  EXPECT_EQ(b.edge, 1);
  EXPECT_NEAR(b.from, 1.1, 1e-9);
  EXPECT_NEAR(b.to, 1.9, 1e-9);
  EXPECT_DOUBLE_EQ(b.depth, 0.5);
  EXPECT_DOUBLE_EQ(b.top, 2.0);
  EXPECT_EQ(h.roofArea, stoneHouseOf(hippedHouse()).roofArea);
  const ParametricModel model = stoneModel(e);
  EXPECT_DOUBLE_EQ(model.parameters["buttressDepth"], 0.5);
  const Assembly as = model.build(model.parameters);
  EXPECT_NEAR(wallVolume(as), 13.0 * 3 - 1.0 * 2.0 * 0.5 - 1.0 * 1.0 * 0.5 + 0.8 * 0.5 * 2.0, 1e-9);
  EXPECT_TRUE(checkFeasibility(as).feasible);
  // buttressDepth sizes it (the extrusion's step written back too).
  ParameterSet deeper = model.parameters;
  deeper.set("buttressDepth", 1.0);
  EXPECT_NEAR(wallVolume(model.build(deeper)), 13.0 * 3 - 1.0 - 0.5 + 0.8 * 1.0 * 2.0, 1e-9);
  const ExtrusionSpec written = stoneSpecAt(e, deeper);
  ASSERT_EQ(written.steps.size(), 1u);
  EXPECT_DOUBLE_EQ(written.steps[0].depth, 1.0);
  EXPECT_EQ(written.profiles, e.profiles);
}

TEST(StoneExtrusion, RefusesStepsItCannotBuild) {
  ExtrusionSpec e = buttressedHouse();
  e.profiles.push_back({"tall", {Vec2(0, 0), Vec2(0, 4), Vec2(1, 5)}, {}});
  e.steps[0].shape = StepShape::Bay;  // a bay whose walls rise 4 m, above the house's 3 m
  e.steps[0].frontProfile = e.steps[0].sideProfile = 2;
  EXPECT_THROW(stoneModel(e), InputError);
  e = buttressedHouse();
  e.steps[0].depth = -0.3;  // a recess whose front rises 2 m (the pier profile) and cheeks 3 m
  e.steps[0].sideProfile = 0;
  EXPECT_THROW(stoneModel(e), InputError);
  e = buttressedHouse();
  e.steps[0].shape = StepShape::Forced;
  e.steps[0].points = {Vec2(-0.4, 0), Vec2(0, 0.5), Vec2(0.4, 0)};
  EXPECT_THROW(stoneModel(e), InputError);
  e = buttressedHouse();
  e.steps[0].anchor.height = 1.0;  // off the ground
  EXPECT_THROW(stoneModel(e), InputError);
  e = buttressedHouse();
  e.steps[0].anchor.along = 0.5;  // on the window
  EXPECT_THROW(stoneModel(e).build(stoneModel(e).parameters), Error);
}

// The hipped house with a canted bay window on its back wall (edge 2, from (8, 6) to (0, 6)):
// 3 m wide at the wall about its middle, 1 m out, its front 0.5 m narrower each side, its
// cheeks and front rising with the house's hip profile (3 m walls, 45° roof).
ExtrusionSpec bayHouse() {
  ExtrusionSpec e = hippedHouse();
  PlanStep st;
  st.name = "bay";
  st.anchor = Anchor{0, 2, false, 0.5, 0.0};
  st.shape = StepShape::Bay;
  st.width = 3.0;
  st.depth = 1.0;
  st.cant = 0.5;
  st.frontProfile = st.sideProfile = 0;
  e.steps = {st};
  return e;
}

// By hand: the back wall opened from x = 5.5 to 2.5, the bay's corners (5, 7) and (3, 7). The
// roof: every face pitched 45° over the stepped plan (48 m² + the bay's trapezoid (3 + 2)/2 · 1
// = 2.5 m²), so its surface is 50.5·√2 m² and a covering q weighs q·50.5·√2 on the walls. The
// walls: perimeter 28 − 3 + 2·√1.25 + 2 m, the four house corners' miters t² each and the
// bay's four cancelling (its cheeks turn by ±φ: tan(φ/2) − tan(φ/2)), less the door and the
// window as in ButtressStepsArePiersCoursedWithTheWalls.
TEST(StoneExtrusion, BayIsPartOfTheCoursedPlanAndCarriesItsRoof) {
  const ExtrusionSpec e = bayHouse();
  const StoneHouse h = stoneHouseOf(e);
  const std::vector<Vec2> plan = {Vec2(0, 0), Vec2(8, 0), Vec2(8, 6), Vec2(5.5, 6), Vec2(5, 7),
                                  Vec2(3, 7), Vec2(2.5, 6), Vec2(0, 6)};
  ASSERT_EQ(h.walls.plan.size(), plan.size());
  for (std::size_t k = 0; k < plan.size(); ++k) EXPECT_NEAR((h.walls.plan[k] - plan[k]).norm(), 0.0, 1e-9) << k;
  EXPECT_EQ(h.edgeSource, (std::vector<int>{0, 1, 2, -1, -1, -1, 2, 3}));
  EXPECT_NEAR(h.edgeOffset[6], 5.5, 1e-9);
  EXPECT_EQ(h.bayStep, std::vector<int>{0});
  double roof = 0, thrust = 0;
  for (std::size_t k = 0; k < plan.size(); ++k) roof += h.roofArea[k], thrust += h.thrustArea[k];
  EXPECT_NEAR(roof, 50.5 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(thrust, roof / 2, 1e-6);  // every face at 45°: w / (2 tan 45°) = w/2
  for (std::size_t k = 3; k < 6; ++k) EXPECT_GT(h.roofArea[k], 0.0) << "the bay's wall " << k;
  // The main roof's share per metre is the same on both pieces of the opened back wall.
  EXPECT_NEAR(h.roofArea[2] / 2.5, h.roofArea[6] / 2.5, 1e-9);

  ExtrusionSpec loaded = e;
  const double q = 800;
  loaded.masonry->coveringWeight = q;
  const ParametricModel model = stoneModel(loaded);
  const Assembly as = model.build(model.parameters);
  EXPECT_NEAR(downwardLoad(as), q * 50.5 * std::sqrt(2.0), 1e-6);
  const double ring = (27 + 2 * std::sqrt(1.25)) * 0.5 - 0.25 * 4;
  EXPECT_NEAR(wallVolume(as), ring * 3 - 1.0 * 2.0 * 0.5 - 1.0 * 1.0 * 0.5, 1e-9);
  EXPECT_TRUE(checkFeasibility(as).feasible);
  // Make It Stand proposes buttresses on the main walls only, written back on input edges:
  // the extrusion read again builds the same piers.
  ParameterSet withPiers = model.parameters;
  withPiers.set("buttressDepth", 0.5);
  const std::vector<WallButtress> proposed = proposedButtresses(h, 0.8, 0.5, 0.5);
  for (const WallButtress& b : proposed) EXPECT_GE(h.edgeSource[std::size_t(b.edge)], 0) << b.name;
  const ExtrusionSpec written = stoneSpecAt(loaded, withPiers);
  ASSERT_EQ(written.steps.size(), 1 + proposed.size());
  const StoneHouse again = stoneHouseOf(written);
  ASSERT_EQ(again.walls.buttresses.size(), proposed.size());
  for (std::size_t k = 0; k < proposed.size(); ++k) {
    EXPECT_EQ(again.walls.buttresses[k].edge, proposed[k].edge) << k;
    EXPECT_NEAR(again.walls.buttresses[k].from, proposed[k].from, 1e-9) << k;
  }
}

// Wind blowing towards −y onto the bay house's back: the two pieces of the back wall (2.5 m
// each) and the bay's front (2 m) face it squarely; each cheek (√1.25 m, its outward normal
// (1, ±0.5)/√1.25) meets it at cos θ = 0.5/√1.25 and takes p·A·cos θ along its normal, of which
// cos θ along y and the x parts cancel. By hand: p·3·(2.5 + 2.5 + 2 + 2·√1.25·0.2) towards −y.
TEST(StoneExtrusion, WindOnABayMeetsItsCheeksAtTheirSlant) {
  ExtrusionSpec e = bayHouse();
  e.masonry->coveringWeight = 0;
  e.masonry->windPressure = 500;
  e.masonry->windDirection = -90;
  const ParametricModel model = stoneModel(e);
  Vec3 f(0.0);
  for (const Block& b : model.build(model.parameters).blocks)
    for (const PointLoad& l : b.pointLoads) f += l.force;
  EXPECT_NEAR(f[0], 0.0, 1e-9);
  EXPECT_NEAR(f[1], -500 * 3 * (7 + 2 * std::sqrt(1.25) * 0.2), 1e-9);
  EXPECT_EQ(f[2], 0.0);
}

// A recess: the same step reaching 1 m into the plan (a rectangle, no cant). Its roof covers
// the notched plan, 48 − 3 = 45 m² at 45°; its walls' ring: perimeter 28 + 2 m, the house's
// four corners and the recess's two convex ones at the mouth against its two reflex ones at the
// back: Σ tan(τ/2) = 4.
TEST(StoneExtrusion, RecessNotchesThePlan) {
  ExtrusionSpec e = bayHouse();
  e.steps[0].shape = StepShape::Rectangle;
  e.steps[0].depth = -1.0;
  e.steps[0].cant = 0.0;
  const StoneHouse h = stoneHouseOf(e);
  const std::vector<Vec2> plan = {Vec2(0, 0), Vec2(8, 0), Vec2(8, 6), Vec2(5.5, 6), Vec2(5.5, 5),
                                  Vec2(2.5, 5), Vec2(2.5, 6), Vec2(0, 6)};
  ASSERT_EQ(h.walls.plan.size(), plan.size());
  for (std::size_t k = 0; k < plan.size(); ++k) EXPECT_NEAR((h.walls.plan[k] - plan[k]).norm(), 0.0, 1e-9) << k;
  EXPECT_TRUE(h.walls.buttresses.empty());
  double roof = 0;
  for (double a : h.roofArea) roof += a;
  EXPECT_NEAR(roof, 45 * std::sqrt(2.0), 1e-6);
  const ParametricModel model = stoneModel(e);
  const Assembly as = model.build(model.parameters);
  EXPECT_NEAR(wallVolume(as), (30 * 0.5 - 0.25 * 4) * 3 - 1.0 * 2.0 * 0.5 - 1.0 * 1.0 * 0.5, 1e-9);
  EXPECT_TRUE(checkFeasibility(as).feasible);
}

// An L-shaped house (one reflex corner at (4, 4)) with the hipped house's profile, door and
// window. By hand: its roof covers the 48 m² plan at 45°; its walls' ring is 32·0.5 − 0.25·(5 − 1)
// = 15 m² over 3 m, less the door and the window.
TEST(StoneExtrusion, LShapedHouseIsCoursedAndStands) {
  ExtrusionSpec e = hippedHouse();
  e.loops = {PlanLoop({Vec2(0, 0), Vec2(8, 0), Vec2(8, 4), Vec2(4, 4), Vec2(4, 8), Vec2(0, 8)}, {0, 0, 0, 0, 0, 0})};
  const StoneHouse h = stoneHouseOf(e);
  EXPECT_EQ(h.walls.plan, e.loops[0].points);
  double roof = 0;
  for (double a : h.roofArea) roof += a;
  EXPECT_NEAR(roof, 48 * std::sqrt(2.0), 1e-6);
  const ParametricModel model = stoneModel(e);
  const Assembly as = model.build(model.parameters);
  EXPECT_NEAR(wallVolume(as), 15.0 * 3 - 1.0 * 2.0 * 0.5 - 1.0 * 1.0 * 0.5, 1e-9);
  EXPECT_TRUE(checkFeasibility(as).feasible);
}

// The canted bay lower than the walls: its front and cheeks rise 1.5 m (three of the six 0.5 m
// courses), then its roof leans in at 45° to the wall. Below 1.5 m the walls follow the plan
// with the bay, above it the rectangle, the back wall spanning the bay's mouth on a lintel; the
// door (2 m) goes on through both bands. By hand: walls (ring with the bay, as in
// BayIsPartOfTheCoursedPlanAndCarriesItsRoof) × 1.5 m + 13 m² × 1.5 m less door and window;
// the bay's roof (2.5 m² of plan at 45°) bears on the bay, the house's (48 m² at 45°) on the
// walls above.
TEST(StoneExtrusion, LowerBayCarriesTheWallOverItsMouthOnALintel) {
  ExtrusionSpec e = bayHouse();
  e.profiles.push_back({"bay", {Vec2(0, 0), Vec2(0, 1.5), Vec2(3, 4.5)}, {}});
  e.steps[0].frontProfile = e.steps[0].sideProfile = 1;
  const StoneHouse h = stoneHouseOf(e);
  EXPECT_DOUBLE_EQ(h.bayTop, 1.5);
  EXPECT_EQ(h.walls.plan.size(), 8u);
  EXPECT_EQ(h.upper.plan, e.loops[0].points);
  ASSERT_EQ(h.mouths.size(), 1u);
  EXPECT_EQ(h.mouths[0].edge, 2);
  EXPECT_NEAR(h.mouths[0].from, 2.5, 1e-9);
  EXPECT_NEAR(h.mouths[0].to, 5.5, 1e-9);
  double low = 0, high = 0;
  for (double a : h.roofArea) low += a;
  for (double a : h.upperRoofArea) high += a;
  EXPECT_NEAR(low, 2.5 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(high, 48 * std::sqrt(2.0), 1e-6);

  ExtrusionSpec loaded = e;
  const double q = 800;
  loaded.masonry->coveringWeight = q;
  const ParametricModel model = stoneModel(loaded);
  const Assembly as = model.build(model.parameters);
  EXPECT_NEAR(downwardLoad(as), q * 50.5 * std::sqrt(2.0), 1e-6);
  const double ring = (27 + 2 * std::sqrt(1.25)) * 0.5 - 0.25 * 4;
  EXPECT_NEAR(wallVolume(as), ring * 1.5 + 13.0 * 1.5 - 1.0 * 2.0 * 0.5 - 1.0 * 1.0 * 0.5, 1e-9);
  // Over the mouth (x from 2.5 to 5.5 in the back wall) stone from 1.5 m up, none below.
  auto stone = [&](const Vec3& p) {
    int count = 0;
    for (const Block& b : as.blocks) {
      bool in = b.name != "ground";
      for (const auto& f : b.faces) {
        std::vector<Vec3> poly;
        for (int i : f) poly.push_back(b.vertices[std::size_t(i)]);
        in = in && dot(p - poly[0], newellNormal(poly)) <= 0;
      }
      count += in;
    }
    return count;
  };
  EXPECT_EQ(stone(Vec3(4.0, 5.75, 0.8)), 0);
  EXPECT_EQ(stone(Vec3(4.0, 5.75, 1.75)), 1);
  EXPECT_EQ(stone(Vec3(4.0, 6.75, 0.8)), 1);  // the bay's front
  EXPECT_EQ(stone(Vec3(4.0, 6.75, 1.75)), 0);
  EXPECT_TRUE(checkFeasibility(as).feasible);
  // Proposed buttresses keep clear of the lintel over the mouth ([2.5, 5.5] of edge 2, a
  // course and three quarters of a 0.8 m block beyond), and the model builds with them.
  for (const WallButtress& b : proposedButtresses(h, 0.8, 0.5, 0.5)) {
    if (h.edgeSource[std::size_t(b.edge)] != 2) continue;
    const double from = h.edgeOffset[std::size_t(b.edge)] + b.from, to = h.edgeOffset[std::size_t(b.edge)] + b.to;
    EXPECT_TRUE(to <= 2.5 - 1.1 + 1e-9 || from >= 5.5 + 1.1 - 1e-9) << b.name << " " << from << " " << to;
  }
  ParameterSet piers = model.parameters;
  piers.set("buttressDepth", 0.5);
  EXPECT_NO_THROW(model.build(piers));
}

TEST(StoneExtrusion, RefusesBaysItCannotBuild) {
  auto where = [](const ExtrusionSpec& e) {
    try {
      stoneHouseOf(e);
    } catch (const InputError& x) {
      return x.where;
    }
    return std::string("built");
  };
  ExtrusionSpec e = bayHouse();
  e.profiles.push_back({"low", {Vec2(0, 0), Vec2(0, 2), Vec2(1, 3)}, {}});
  e.steps[0].frontProfile = 1;  // its front 2 m high, its cheeks 3 m
  EXPECT_EQ(where(e), "steps[0]");
  e.steps[0].sideProfile = 1;  // all 2 m, beside another bay of 1.5 m
  e.profiles.push_back({"lower", {Vec2(0, 0), Vec2(0, 1.5), Vec2(1, 2.5)}, {}});
  e.steps.push_back(e.steps[0]);
  e.steps[1].anchor.edge = 0;
  e.steps[1].anchor.along = 0.2;
  e.steps[1].frontProfile = e.steps[1].sideProfile = 2;
  EXPECT_EQ(where(e), "steps[1]");
  e = bayHouse();
  e.steps[0].width = 8.5;  // past the ends of its 8 m edge
  EXPECT_EQ(where(e), "steps[0]");
  e = bayHouse();
  e.steps.push_back(e.steps[0]);
  e.steps[1].anchor.along = 0.6;  // on the first
  EXPECT_EQ(where(e), "steps[1]");
  e = bayHouse();
  e.anchors.push_back(MeshAnchor("back window", Anchor{0, 2, false, 0.5, 0.9}, FeatureKind::Window, {1.0, 1.2, 0.1}));
  EXPECT_EQ(where(e), "steps[0]");  // the bay opens the wall where the window is
  EXPECT_EQ(where(bayHouse()), "built");
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

namespace corbel::statics {
namespace {

// Where buttresses go on the thin-walled house (8 × 6 m, 5 m walls, a 1 m door mid-front), by
// the rule of proposedButtresses worked by hand: ⌊8/5⌋ = ⌊6/5⌋ = 1 pier mid-wall, 0.8 m long;
// the front one would meet the door, whose keep-out is [3.5 − 1.1, 4.5 + 1.1] (a course 0.5 m
// and three quarters of a 0.8 m block), so it moves to both sides: [1.6, 2.4] and [5.6, 6.4].
TEST(StoneExtrusion, ProposedButtressesStandMidWallAndBesideTheDoor) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/stone-house.corbel");
  const StoneHouse h = stoneHouseOf(std::get<ExtrusionSpec>(p.document.findByName("Stone house, thin walls")->spec));
  const std::vector<WallButtress> b = proposedButtresses(h, 0.8, 0.5, 0.2);
  ASSERT_EQ(b.size(), 5u);
  const double expected[5][3] = {{0, 1.6, 2.4}, {0, 5.6, 6.4}, {1, 2.6, 3.4}, {2, 3.6, 4.4}, {3, 2.6, 3.4}};
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(b[k].edge, int(expected[k][0])) << k;
    EXPECT_NEAR(b[k].from, expected[k][1], 1e-9) << k;
    EXPECT_NEAR(b[k].to, expected[k][2], 1e-9) << k;
    EXPECT_DOUBLE_EQ(b[k].top, 5.0);
  }
}

// Make It Stand allowed only the buttresses' depth (Kelly & Wonka's buttresses as natural steps,
// Fig. 23) on the thin-walled house, which has none: it adds them, and what it finds stands by
// the strict LP; written back they are rectangle steps of the extrusion, whose own model builds
// the same blocks and stands.
TEST(StoneExtrusion, MakeItStandAddsButtressStepsToTheThinWalledHouse) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/stone-house.corbel");
  const ExtrusionSpec thin = std::get<ExtrusionSpec>(p.document.findByName("Stone house, thin walls")->spec);
  const ParametricModel model = stoneModel(thin);
  EXPECT_EQ(model.parameters["buttressDepth"], 0.0);
  const SearchResult r = searchParameters(model, {{"buttressDepth", 0.1, 2.0}}, SearchOptions{});
  ASSERT_EQ(r.status, SearchStatus::Feasible) << r.message;
  EXPECT_TRUE(r.standsStrictly);
  EXPECT_EQ(r.values["thickness"], thin.masonry->thickness);
  const Assembly found = model.build(r.values);
  EXPECT_TRUE(checkFeasibility(found).feasible);

  const ExtrusionSpec after = stoneSpecAt(thin, r.values);
  EXPECT_FALSE(after.steps.empty());
  for (const PlanStep& st : after.steps) {
    EXPECT_EQ(st.shape, StepShape::Rectangle);
    EXPECT_DOUBLE_EQ(st.depth, r.values["buttressDepth"]);
    EXPECT_EQ(st.anchor.height, 0.0);
  }
  EXPECT_NO_THROW(extrude::extrude(after));
  const ParametricModel again = stoneModel(after);
  EXPECT_DOUBLE_EQ(again.parameters["buttressDepth"], r.values["buttressDepth"]);
  const Assembly built = again.build(again.parameters);
  EXPECT_EQ(built.blocks.size(), found.blocks.size());
  EXPECT_NEAR(wallVolume(built), wallVolume(found), 1e-9);
  EXPECT_TRUE(checkFeasibility(built).feasible);
  // Saved and read back, the steps and their profile stay.
  Document doc = p.document;
  std::get<ExtrusionSpec>(doc.find(p.document.findByName("Stone house, thin walls")->id)->spec) = after;
  const ExtrusionSpec reread =
      std::get<ExtrusionSpec>(parseProject(serializeProject(doc)).document.findByName("Stone house, thin walls")->spec);
  EXPECT_EQ(reread.steps.size(), after.steps.size());
  const ParametricModel read = stoneModel(reread);
  EXPECT_TRUE(checkFeasibility(read.build(read.parameters)).feasible);
}

}  // namespace
}  // namespace corbel::statics

namespace corbel::statics {
namespace {

// Where a wall has buttresses the roof bears on them (its principal rafters over the piers, a
// wall plate between): the thin-walled house (8 × 6 m plan at x 12…20, y 0…6, 5 m walls, a
// hipped roof at 45° rising 3 m, 1,500 N/m²) with buttresses 0.5 m deep where
// proposedButtresses puts them (worked by hand above: front [1.6, 2.4] and [5.6, 6.4], sides
// and back one mid-wall). By hand: a long slope is 15√2 m² of roof, a hip end 9√2 m², and at
// 45° a rafter pair's thrust W / (2 tan θ) is half its weight. The front's two piers, at 2 and
// 6 m, each carry the 4 m of roof nearest them, half the slope; the others carry their whole
// wall's slope. Every load acts on the wall's centre line at its head, over its pier.
TEST(StoneExtrusion, TheRoofBearsOnThePiersWithAllItsWeightAndThrust) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/stone-house.corbel");
  const ParametricModel model = stoneModel(std::get<ExtrusionSpec>(p.document.findByName("Stone house, thin walls")->spec));
  ParameterSet values = model.parameters;
  values.set("buttressDepth", 0.5);
  const Assembly as = model.build(values);

  const double q = 1500, slope = q * 15 * std::sqrt(2.0), end = q * 9 * std::sqrt(2.0);
  struct Pier {
    Vec2 from, along, in;  // the edge's first corner, its direction, into the wall
    double lo, hi;         // the pier's stretch along the edge
    Vec3 force;            // by hand
  };
  const Pier piers[] = {
      {Vec2(12, 0), Vec2(1, 0), Vec2(0, 1), 1.6, 2.4, Vec3(0, -slope / 4, -slope / 2)},
      {Vec2(12, 0), Vec2(1, 0), Vec2(0, 1), 5.6, 6.4, Vec3(0, -slope / 4, -slope / 2)},
      {Vec2(20, 0), Vec2(0, 1), Vec2(-1, 0), 2.6, 3.4, Vec3(end / 2, 0, -end)},
      {Vec2(20, 6), Vec2(-1, 0), Vec2(0, -1), 3.6, 4.4, Vec3(0, slope / 2, -slope)},
      {Vec2(12, 6), Vec2(0, -1), Vec2(1, 0), 2.6, 3.4, Vec3(-end / 2, 0, -end)},
  };
  std::vector<Vec3> carried(std::size(piers), Vec3(0.0));
  Vec3 total(0.0);
  int loads = 0, placed = 0;
  for (const Block& b : as.blocks)
    for (const PointLoad& l : b.pointLoads) {
      ++loads;
      total += l.force;
      EXPECT_NEAR(l.at[2], 5.0, 1e-9) << "at the wall head";
      for (std::size_t k = 0; k < std::size(piers); ++k) {
        const Vec2 r = Vec2(l.at[0], l.at[1]) - piers[k].from;
        const double u = dot(r, piers[k].along);
        if (std::abs(dot(r, piers[k].in) - 0.1) < 1e-9 && u > piers[k].lo - 1e-9 && u < piers[k].hi + 1e-9) {
          carried[k] += l.force;
          ++placed;
        }
      }
    }
  EXPECT_GT(loads, 0);
  EXPECT_EQ(placed, loads) << "every load over a pier, on the wall's centre line";
  for (std::size_t k = 0; k < std::size(piers); ++k)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(carried[k][i], piers[k].force[i], 1e-6) << "pier " << k << " axis " << i;
  EXPECT_NEAR(total[2], -q * 48 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(total[0], 0.0, 1e-6);
  EXPECT_NEAR(total[1], 0.0, 1e-6);
}

}  // namespace
}  // namespace corbel::statics
