// Doors and windows on grown units (growth/openings.h), counted by hand on a small site.
#include "growth/openings.h"

#include "core/scene.h"
#include "support.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace corbel::growth {
namespace {

using test::box;
using test::unitOf;

// A landing (x 10–13, y 0–4) and four units:
//  1: 7 × 4 east of the landing (its −x side against the landing: the entrance);
//  2: 3 × 4 north of unit 1's west end; 3: 4 × 4 two metres east of unit 1 (hiding its +x side
//  and hidden behind it from −x); 4: a 6 × 4 double volume apart.
struct Small {
  Site site = test::openSite(30, 20, 2);
  std::vector<Unit> units;
  Small() {
    site.circulation = {box(10, 0, 0, 13, 4, 3)};
    units = {unitOf(1, {box(13, 0, 0, 20, 4, 3)}), unitOf(2, {box(13, 4, 0, 16, 8, 3)}),
             unitOf(3, {box(22, 0, 0, 26, 4, 3)}), unitOf(4, {box(0, 12, 0, 6, 16, 6)})};
  }
};

std::size_t count(const std::vector<Opening>& o, FeatureKind k, int unit) {
  return std::size_t(std::count_if(o.begin(), o.end(), [&](const Opening& x) { return x.kind == k && x.unit == unit; }));
}

TEST(Openings, ADoorAtTheEntranceAndAWindowPer3mOfFacadeWithAViewPerStorey) {
  const Small s;
  const std::vector<Opening> o = placeOpenings(s.site, s.units, OpeningSettings{});
  // Doors: only unit 1 meets circulation (4 m along the landing); unit 2 touches it at a corner.
  EXPECT_EQ(count(o, FeatureKind::Door, 1), 1u);
  for (int u : {2, 3, 4}) EXPECT_EQ(count(o, FeatureKind::Door, u), 0u) << u;
  const auto door = std::find_if(o.begin(), o.end(), [](const Opening& x) { return x.kind == FeatureKind::Door; });
  ASSERT_NE(door, o.end());
  EXPECT_EQ(door->side, Side::NegX);
  EXPECT_EQ(door->position, Vec3(13, 2, 0));
  // Windows, by hand:
  //  1: −y 7 m → 2; +y free 16–20 (unit 2 covers 13–16) → 1; +x hidden by unit 3 → 0; −x the landing.
  //  2: −x 4 m → 1; +x 4 m → 1; +y 3 m → 1; −y against unit 1.
  //  3: +x, −y, +y 4 m → 1 each; −x hidden behind unit 1.
  //  4: two storeys of −x, +x (4 m: 1) and −y, +y (6 m: 2) → 2 × 6.
  EXPECT_EQ(count(o, FeatureKind::Window, 1), 3u);
  EXPECT_EQ(count(o, FeatureKind::Window, 2), 3u);
  EXPECT_EQ(count(o, FeatureKind::Window, 3), 3u);
  EXPECT_EQ(count(o, FeatureKind::Window, 4), 12u);
  for (const Opening& w : o)
    if (w.unit == 1 && w.kind == FeatureKind::Window) {
      EXPECT_NE(w.side, Side::PosX);
      if (w.side == Side::NegY) {
        EXPECT_TRUE(w.position == Vec3(14.75, 0, 0.9) || w.position == Vec3(18.25, 0, 0.9));
      }
      if (w.side == Side::PosY) {
        EXPECT_EQ(w.position, Vec3(18, 4, 0.9));
      }
    }
  int upper = 0;
  for (const Opening& w : o) upper += w.unit == 4 && w.position[2] == 3.9;
  EXPECT_EQ(upper, 6);
}

TEST(Openings, SpacingAndSizesComeFromTheSettings) {
  const Small s;
  OpeningSettings settings;
  settings.spacing = 2.0;  // 7 m → 3, 4 m → 2, 3 m → 1, 6 m → 3
  const std::vector<Opening> o = placeOpenings(s.site, s.units, settings);
  EXPECT_EQ(count(o, FeatureKind::Window, 1), 3u + 2u);
  EXPECT_EQ(count(o, FeatureKind::Window, 2), 2u + 2u + 1u);
  EXPECT_EQ(count(o, FeatureKind::Window, 4), 2u * (2 + 2 + 3 + 3));
  settings.door.width = 4.5;  // wider than the contact: no door
  EXPECT_EQ(count(placeOpenings(s.site, s.units, settings), FeatureKind::Door, 1), 0u);
}

TEST(Openings, AStretchsViewIsWhatTheViewMapShowsOfIt) {
  const Small s;
  std::vector<ViewBox> boxes;
  for (const Unit& u : s.units) boxes.push_back({u.parts[0], std::uint32_t(u.id)});
  boxes.push_back({s.site.circulation[0], kObstacleId});
  const ViewMaps maps = ExactViewMapper().render(boxes, s.site.bounds());
  EXPECT_DOUBLE_EQ(stretchView(maps, 1, Side::NegY, 0, 13, 20, 0, 3), 21);
  EXPECT_DOUBLE_EQ(stretchView(maps, 1, Side::PosX, 20, 0, 4, 0, 3), 0);
  EXPECT_DOUBLE_EQ(stretchView(maps, 1, Side::PosY, 4, 16, 20, 0, 3), 12);
}

TEST(Openings, TheFeatureMeshesAreClosedPartsTaggedDoorAndWindow) {
  const Small s;
  const std::vector<Opening> o = placeOpenings(s.site, s.units, OpeningSettings{});
  const MeshData m = openingsMesh(o);
  Scene scene;
  scene.replaceObject(1, Kind::Mass, "openings", m);
  const ValidityReport r = scene.validate(1);
  EXPECT_TRUE(r.watertight());
  // A door: step, frame, leaf; a window: frame, pane, sill (extrude/features.h).
  EXPECT_EQ(r.components, 3u * o.size());
  EXPECT_NE(std::find(m.tags.begin(), m.tags.end(), "door"), m.tags.end());
  EXPECT_NE(std::find(m.tags.begin(), m.tags.end(), "window"), m.tags.end());
  EXPECT_NE(std::find(m.materials.begin(), m.materials.end(), "glass"), m.materials.end());
}

}  // namespace
}  // namespace corbel::growth
