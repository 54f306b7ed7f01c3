// editor/unit_edits.h: unit objects edited by hand. A wall pushed against another unit object
// and a growth site's core stops at each where a hand sketch says; a split keeps every part's
// volume; a merge takes touching units only; a ray picks the side a hand ray-box test gives.
#include "editor/unit_edits.h"

#include "core/error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace corbel::editor {
namespace {

UnitSpec unitOf(std::vector<std::array<double, 6>> boxes) {
  UnitSpec u;
  for (const auto& b : boxes) u.parts.push_back({Vec3(b[0], b[1], b[2]), Vec3(b[3], b[4], b[5])});
  return u;
}

double volume(const UnitSpec& u) {
  double v = 0;
  for (const UnitPart& p : u.parts) v += (p.hi[0] - p.lo[0]) * (p.hi[1] - p.lo[1]) * (p.hi[2] - p.lo[2]);
  return v;
}

const UnitSpec& spec(const Document& d, ObjectId id) { return std::get<UnitSpec>(d.find(id)->spec); }

TEST(UnitEdits, APushedWallStopsAtTheNeighbourAndAtTheCoreOfASiteNearby) {
  Document d;
  const ObjectId a = d.add("A", unitOf({{0, 0, 0, 10, 10, 3}}));
  // A neighbour 2 m east over y 0..4 (placed by its placement), and a site whose 4 × 4 core
  // stands 3 m east over y 6..10.
  const ObjectId b = d.add("B", unitOf({{0, 0, 0, 6, 4, 3}}));
  d.find(b)->placement.translation = Vec3(12, 0, 0);
  GrowthSpec g;
  g.site = R"({"envelope": {"origin": [0, 0], "size": [40, 40]}, "storeys": 2, "storey_height": 3,
               "cores": [{"at": [13, 6], "size": [4, 4]}], "seeds": []})";
  d.add("Site", g);
  const Document pushed = pushUnitFace(d, a, 0, growth::Side::PosX, 5);
  const UnitSpec& u = spec(pushed, a);
  // By hand: y 0..4 reaches 2 m (to B), y 4..6 the full 5 m, y 6..10 3 m (to the core). The
  // 2 m stretch is narrower than a room and joins the neighbour that reaches less, B's.
  ASSERT_EQ(u.parts.size(), 2u);
  EXPECT_EQ(u.parts[0].lo, Vec3(0, 0, 0));
  EXPECT_EQ(u.parts[0].hi, Vec3(12, 6, 3));
  EXPECT_EQ(u.parts[1].lo, Vec3(0, 6, 0));
  EXPECT_EQ(u.parts[1].hi, Vec3(13, 10, 3));
  // Without the neighbour and the site it runs the whole 5 m.
  Document alone;
  const ObjectId only = alone.add("A", unitOf({{0, 0, 0, 10, 10, 3}}));
  EXPECT_EQ(spec(pushUnitFace(alone, only, 0, growth::Side::PosX, 5), only).parts[0].hi, Vec3(15, 10, 3));
  // B pushed 3 m west meets A 2 m away (in B's own frame, placed 12 m east).
  EXPECT_EQ(spec(pushUnitFace(d, b, 0, growth::Side::NegX, 3), b).parts[0].lo, Vec3(-2, 0, 0));
  // Pushed up against it, A cannot move east there at all.
  const Document flush = pushUnitFace(d, b, 0, growth::Side::NegX, 2);
  Document narrow = flush;
  std::get<UnitSpec>(narrow.find(a)->spec).parts[0].hi[1] = 4;  // A only as wide as B's face
  EXPECT_THROW(pushUnitFace(narrow, a, 0, growth::Side::PosX, 1), InputError);
}

TEST(UnitEdits, ASplitKeepsEveryPartsVolumeAndAMergeTakesOnlyTouchingUnits) {
  Document d;
  const ObjectId a = d.add("A", unitOf({{0, 0, 0, 10, 4, 3}, {0, 4, 0, 4, 10, 3}}));
  d.find(a)->placement.translation = Vec3(5, 5, 0);
  ObjectId added = 0;
  const Document split = splitUnit(d, a, 0, 6, &added);
  ASSERT_NE(split.find(added), nullptr);
  EXPECT_EQ(split.find(added)->name, "A (split)");
  EXPECT_EQ(split.find(added)->placement, d.find(a)->placement);
  EXPECT_DOUBLE_EQ(volume(spec(split, a)) + volume(spec(split, added)), volume(spec(d, a)));
  EXPECT_DOUBLE_EQ(volume(spec(split, added)), 4 * 4 * 3.0);
  EXPECT_THROW(splitUnit(d, a, 0, 20, nullptr), InputError) << "a plane past the unit splits nothing";

  // Merged back: one object with every part again, the same volume.
  const Document merged = mergeUnits(split, a, added);
  EXPECT_EQ(merged.find(added), nullptr);
  EXPECT_DOUBLE_EQ(volume(spec(merged, a)), volume(spec(d, a)));

  Document apart = d;
  const ObjectId far = apart.add("far", unitOf({{20, 0, 0, 24, 4, 3}}));
  EXPECT_THROW(mergeUnits(apart, a, far), InputError);
  const ObjectId edge = apart.add("edge", unitOf({{-5, -5, 0, 0, 0, 3}}));  // meets A only at a corner line
  apart.find(edge)->placement.translation = Vec3(5, 5, 0);
  EXPECT_THROW(mergeUnits(apart, a, edge), InputError);
  const ObjectId into = apart.add("into", unitOf({{2, 2, 0, 6, 6, 3}}));
  apart.find(into)->placement.translation = Vec3(5, 5, 0);
  EXPECT_THROW(mergeUnits(apart, a, into), InputError);
}

TEST(UnitEdits, ARayPicksTheFirstSideItEnters) {
  const UnitSpec u = unitOf({{0, 0, 0, 4, 4, 3}, {4, 0, 0, 8, 4, 3}});
  // From the east at mid height: the second part's +x side at x 8.
  auto f = pickUnitFace(u, Vec3(20, 2, 1.5), Vec3(-1, 0, 0));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->part, 1);
  EXPECT_EQ(f->side, growth::Side::PosX);
  EXPECT_EQ(f->hit, Vec3(8, 2, 1.5));
  // From above, slanting down onto the first part's roof.
  f = pickUnitFace(u, Vec3(1, 1, 10), Vec3(0.1, 0.1, -1));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->part, 0);
  EXPECT_EQ(f->side, growth::Side::Top);
  EXPECT_NEAR(f->hit[0], 1.7, 1e-12);
  EXPECT_FALSE(pickUnitFace(u, Vec3(20, 10, 1.5), Vec3(-1, 0, 0))) << "passes by";
}

TEST(UnitEdits, AFloorOrCeilingMovesByTheSitesWholeStoreys) {
  // A site of 3.5 m storeys: a ceiling dragged 2.5 m rises one storey, 3.5 m (the nearest whole
  // storey), and a drag of 1 m is no storey at all.
  Document d;
  const ObjectId a = d.add("A", unitOf({{0, 0, 0, 10, 10, 3.5}}));
  GrowthSpec g;
  g.site = R"({"envelope": {"origin": [0, 0], "size": [40, 40]}, "storeys": 3, "storey_height": 3.5, "seeds": []})";
  d.add("Site", g);
  const Document up = pushUnitFace(d, a, 0, growth::Side::Top, 2.5);
  EXPECT_EQ(spec(up, a).parts[0].hi, Vec3(10, 10, 7));
  EXPECT_DOUBLE_EQ(volume(spec(up, a)), 2 * volume(spec(d, a)));
  EXPECT_THROW(pushUnitFace(d, a, 0, growth::Side::Top, 1), InputError);
  // Back down, and its floor cannot go under the site's ground.
  EXPECT_EQ(spec(pushUnitFace(up, a, 0, growth::Side::Top, -3.5), a), spec(d, a));
  EXPECT_THROW(pushUnitFace(d, a, 0, growth::Side::Bottom, 3.5), InputError);
  // Without a site the unit's lowest room gives the storey: 4 m rooms rise by 4 m.
  Document alone;
  const ObjectId b = alone.add("B", unitOf({{0, 0, 0, 6, 6, 4}, {6, 0, 0, 12, 6, 4}}));
  EXPECT_EQ(spec(pushUnitFace(alone, b, 1, growth::Side::Top, 3), b).parts[1].hi, Vec3(12, 6, 8));
  // Another unit over the ceiling stops it.
  const ObjectId c = alone.add("C", unitOf({{0, 0, 4, 6, 6, 8}}));
  (void)c;
  EXPECT_THROW(pushUnitFace(alone, b, 0, growth::Side::Top, 4), InputError);
}

}  // namespace
}  // namespace corbel::editor
