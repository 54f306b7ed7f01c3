// kifs/follow.h: a KIFS building on another object's shell (footprint "object"). The box mass
// model's closed form (Eq. 1) is the oracle where the followed object is the same box; CGAL's
// exact distance to the house shell placed by hand where it is the Fig. 1 house.
#include "kifs/follow.h"

#include "city/kernel.h"
#include "core/error.h"
#include "core/placement.h"
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "extrude/extrude.h"
#include "extrude/features.h"
#include "extrude/kernel.h"
#include "kifs/kernel.h"
#include "kifs/mesher.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <tuple>

namespace corbel::kifs {
namespace {

struct Built {
  Document doc;
  Scene scene;
  SceneSync sync;
  explicit Built(Document d) : doc(std::move(d)) {
    extrude::registerKernel(sync);
    kifs::registerKernel(sync);
    sync.update(doc, scene);
  }
  const DocObject& object(const std::string& name) const { return *doc.findByName(name); }
};

// The `box` preset following an object named `mass`, baked at `resolution`.
KifsSpec follower(const std::string& mass, int resolution) {
  KifsSpec k = specOf(preset("box"), "box");
  k.mass.footprint = "object";
  k.mass.object = mass;
  k.mass.resolution = resolution;
  return k;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// The followed box is the preset's own mass (12 × 12 m, 22.8 m high, at the origin): the two
// buildings differ only in d_o and d_i, the closed form against the bake, so box − one cell
// diagonal ≤ follower ≤ box for both the estimate and the bound (g is monotone and 1-Lipschitz
// in d_o, d_i = d_o + shell), and the ids and storeys are the same. The preset's inner box
// keeps the outer one's bottom while the follower's inner shell is inset there too, so the
// points are taken 6 m above that inset, where no bottom is the nearest face of an inner box.
TEST(KifsFollow, OnTheBoxItIsTheBoxPresetWithinOneCell) {
  Document d;
  BoxSpec box;
  box.size = Vec3(12.0, 12.0, 22.8);
  d.add("Mass", box);
  const ObjectId k = d.add("Ornament", follower("Mass", 40));
  d.find(k)->placement.translation = Vec3(50.0, 0.0, 0.0);  // ignored while it follows
  const Built b(std::move(d));
  const Building follow = buildingOf(b.doc, b.scene, *b.doc.find(k));
  const Building ref(preset("box"));
  const double diagonal = std::sqrt(3.0) * follow.mass()->cell;
  EXPECT_NEAR(follow.mass()->cell, 22.8 / 40, 1e-12);
  std::mt19937_64 rng(3);
  int inWall = 0;
  for (int i = 0; i < 6000; ++i) {
    const glm::dvec3 p = test::uniformIn(rng, {-9, -9, 1.2 + 6.0}, {9, 9, 26});
    const Sample f = follow.evaluate(p), r = ref.evaluate(p);
    // Float samples: one ulp (2⁻²³) of values below 40 m.
    const double ulp = std::ldexp(40.0, -23);
    ASSERT_LE(f.surface, r.surface + ulp) << p.x << " " << p.y << " " << p.z;
    ASSERT_GE(f.surface, r.surface - diagonal - ulp) << p.x << " " << p.y << " " << p.z;
    ASSERT_LE(f.bound, r.bound + ulp) << p.x << " " << p.y << " " << p.z;
    ASSERT_GE(f.bound, r.bound - diagonal - ulp) << p.x << " " << p.y << " " << p.z;
    EXPECT_EQ(f.idX, r.idX);
    EXPECT_EQ(f.idZ, r.idZ);
    EXPECT_EQ(f.floor, r.floor);
    if (massModelDistance(ref.params().mass, {p.x, p.z, p.y}, 0.0) < 0 && f.surface > 0) ++inWall;
  }
  EXPECT_GT(inWall, 100);  // the fractal's holes in the walls were sampled
  // Below, the follower's inner shell starts `shell` above the bottom, the preset's at it.
  EXPECT_LT(ref.evaluate({0.0, 0.0, 0.5}).surface, 0.0);
  EXPECT_GT(follow.evaluate({0.0, 0.0, 0.5}).surface + 0.5, 0.0);
  // Its bounds are the followed box's, not its placement's.
  EXPECT_NEAR(follow.worldBounds().lo.x, -6.0, 0.05);
  EXPECT_NEAR(follow.worldBounds().hi.z, 22.8, 0.05);
}

// The Fig. 1 house, moved and turned: the follower stands where the house stands. Oracle: CGAL's
// exact distance to the house's shell and features placed by hand. The follower's d_o (from the
// Scene's placed faces) is at most the exact one, and within one cell diagonal of it on its
// grid; more than a diagonal
// outside the house the building is not hit (bound and estimate positive); deeper inside than
// the wall (shell) plus one diagonal, it is solid.
TEST(KifsFollow, OnTheFig1HouseItStandsInTheHousesShell) {
  Document d = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/house.corbel").document;
  DocObject& house = *d.find(d.findByName("House")->id);
  house.placement.translation = Vec3(7.0, -4.0, 0.5);
  house.placement.rotation_deg = 30.0;
  const ExtrusionSpec spec = std::get<ExtrusionSpec>(house.spec);
  const Placement placement = house.placement;
  KifsSpec k = follower("House", 48);
  k.mass.shell = 0.6;
  const ObjectId id = d.add("Ornament", k);
  const Built b(std::move(d));
  const Building follow = buildingOf(b.doc, b.scene, *b.doc.find(id));

  const extrude::ExtrusionResult r = extrude::extrude(spec);
  MeshData soup = extrude::toMeshData(r.shell, spec, "plaster");
  std::vector<std::string> warnings;
  extrude::appendFeatures(soup, spec, r, warnings);
  applyPlacement(soup, placement);
  const ShellDistance exact(trianglesOf(soup));
  const double diagonal = std::sqrt(3.0) * follow.mass()->cell;
  std::mt19937_64 rng(9);
  const Aabb box = exact.bounds();
  int outside = 0, deep = 0, inGrid = 0;
  for (int i = 0; i < 4000; ++i) {
    const glm::dvec3 p = test::uniformIn(rng, box.lo - 2.0, box.hi + 2.0);
    const double e = exact.signedDistance(p);
    const Sample s = follow.evaluate(p);
    const double d0 = follow.mass()->distance(p);
    ASSERT_LE(d0, e + 1e-9) << p.x << " " << p.y << " " << p.z;
    const Aabb g = follow.mass()->grid();
    if (glm::all(glm::greaterThanEqual(p, g.lo)) && glm::all(glm::lessThanEqual(p, g.hi))) {
      ++inGrid;
      ASSERT_GE(d0, e - diagonal - std::ldexp(40.0, -22)) << p.x << " " << p.y << " " << p.z;
    }
    if (e > diagonal + 1e-6) {
      ++outside;
      EXPECT_GT(s.bound, 0.0) << p.x << " " << p.y << " " << p.z;
      EXPECT_GT(s.surface, 0.0) << p.x << " " << p.y << " " << p.z;
    } else if (e < -0.6 - diagonal) {
      ++deep;
      EXPECT_LT(s.surface, 0.0) << p.x << " " << p.y << " " << p.z;
      EXPECT_LT(s.bound, 0.0) << p.x << " " << p.y << " " << p.z;
    }
  }
  EXPECT_GT(outside, 1000);
  EXPECT_GT(inGrid, 2000);
  EXPECT_GT(deep, 100);
}

// Facades and storeys are folded in the followed object's frame: moved up 2 m and turned by 35°,
// the box carries its bays and storeys with it. At the placed image of a point the ids and the
// storey are those of the unplaced box at the point, and the distances agree within the two
// bakes' errors (one cell diagonal each way: the two grids are not aligned alike).
TEST(KifsFollow, FacadesAndStoreysMoveAndTurnWithTheMass) {
  auto build = [](const Placement& placement) {
    Document d;
    BoxSpec box;
    box.size = Vec3(12.0, 12.0, 22.8);
    const ObjectId m = d.add("Mass", box);
    d.find(m)->placement = placement;
    const ObjectId k = d.add("Ornament", follower("Mass", 40));
    const Built b(std::move(d));
    return buildingOf(b.doc, b.scene, *b.doc.find(k));
  };
  Placement turned;
  turned.translation = Vec3(30.0, -10.0, 2.0);
  turned.rotation_deg = 35.0;
  const Building at = build(Placement{}), moved = build(turned);
  const double diagonal = std::sqrt(3.0) * moved.mass()->cell;
  std::mt19937_64 rng(21);
  int compared = 0;
  for (int i = 0; i < 4000; ++i) {
    const glm::dvec3 p = test::uniformIn(rng, {-8, -8, -1}, {8, 8, 24});
    const Vec3 q = turned.apply(Vec3(p.x, p.y, p.z));
    const Sample a = at.evaluate(p), b = moved.evaluate({q[0], q[1], q[2]});
    // Rounding moves a point on an id or storey plane to either side: compare away from them.
    const double storey = std::fmod(p.z + 30.0, 3.0);
    if (storey < 1e-9 || storey > 3.0 - 1e-9) continue;
    ++compared;
    EXPECT_EQ(a.idX, b.idX);
    EXPECT_EQ(a.idZ, b.idZ);
    EXPECT_EQ(a.floor, b.floor);
    EXPECT_NEAR(a.surface, b.surface, diagonal + 1e-4);
  }
  EXPECT_GT(compared, 3900);
  // Its bounds hold the turned box.
  EXPECT_NEAR(moved.worldBounds().lo.z, 2.0, 0.05);
}

TEST(KifsFollow, BadMassesAreNamed) {
  Document d;
  d.add("Mass", BoxSpec{});
  const ObjectId none = d.add("A", follower("Nothing", 16));
  const ObjectId empty = d.add("B", follower("", 16));
  const ObjectId self = d.add("C", follower("C", 16));
  const ObjectId loop1 = d.add("D", follower("E", 16));
  d.add("E", follower("D", 16));
  const ObjectId chained = d.add("F", follower("G", 16));
  d.add("G", follower("Mass", 16));
  const ObjectId open = d.add("H", follower("Open", 16));
  const ObjectId openMass = d.add("Open", BoxSpec{});
  Built b(d);
  // The Scene's faces of "Open" replaced by a box without its top.
  MeshData lid;
  for (int c = 0; c < 8; ++c) lid.addPoint(Vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1));
  for (const auto& f : std::vector<std::vector<int>>{{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}})
    lid.addFace(f);
  b.scene.replaceObject(openMass, Kind::Mass, "Open", lid);
  auto error = [&](ObjectId id) { return errorOf([&] { buildingOf(b.doc, b.scene, *b.doc.find(id)); }); };
  EXPECT_EQ(error(none), "kifs.mass.object: no object named \"Nothing\"");
  EXPECT_EQ(error(empty), "kifs.mass.object: names no object (the footprint \"object\" needs one)");
  EXPECT_EQ(error(self), "kifs.mass.object: a cycle: \"C\" → \"C\"");
  EXPECT_EQ(error(loop1), "kifs.mass.object: a cycle: \"D\" → \"E\" → \"D\"");
  EXPECT_NE(error(chained).find("kifs.mass.object: \"G\" is a KIFS building that follows another object"),
            std::string::npos);
  EXPECT_EQ(error(open), "kifs.mass.object: \"Open\" is not closed (4 open edges)");
  // Without the mass it cannot be built at all.
  EXPECT_THROW(Building(paramsOf(follower("Mass", 16))), Error);
  // Meshed into the Scene, the same errors are the object's build errors.
  for (const char* name : {"A", "C", "D", "F"}) b.doc.find(b.doc.findByName(name)->id)->spec = [&] {
      KifsSpec k = std::get<KifsSpec>(b.doc.findByName(name)->spec);
      k.meshResolution = 16;
      return k;
    }();
  b.sync.update(b.doc, b.scene);
  EXPECT_EQ(b.sync.status().at(none).error, "kifs.mass.object: no object named \"Nothing\"");
  EXPECT_EQ(b.sync.status().at(self).error, "kifs.mass.object: a cycle: \"C\" → \"C\"");
  EXPECT_EQ(b.sync.status().at(loop1).error, "kifs.mass.object: a cycle: \"D\" → \"E\" → \"D\"");
  EXPECT_NE(b.sync.status().at(chained).error.find("\"G\" is a KIFS building that follows another object"),
            std::string::npos);
}

Aabb boundsOf(const TriangleSoup& soup) {
  Aabb box{glm::dvec3(1e300), glm::dvec3(-1e300)};
  for (const glm::dvec3& p : soup.points) box.lo = glm::min(box.lo, p), box.hi = glm::max(box.hi, p);
  return box;
}

// Meshed into the Scene (meshResolution > 0), a follower stands on its mass where the mass
// stands. Oracles: the closed form of the box it follows, and the mass's move. (1) Every vertex
// lies within the box grown by what the mesh may add: the mesher's level set lies kMeshOffset
// mesher cells out, a vertex interpolated on a tetrahedron's edge lies within one mesher cell
// diagonal of it, and the baked d_o lies within one bake cell diagonal of the exact one. (2) Its
// own placement changes nothing. (3) Moving the mass by a whole number of metres rebuilds it
// (the mass is one of its inputs) and moves every vertex by exactly that.
TEST(KifsFollow, MeshedIntoTheSceneItStandsOnItsMassAndMovesWithIt) {
  Document d;
  BoxSpec box;
  box.size = Vec3(12.0, 12.0, 22.8);
  const ObjectId mass = d.add("Mass", box);
  Placement turned;
  turned.translation = Vec3(30.0, -10.0, 0.0);
  turned.rotation_deg = 35.0;
  d.find(mass)->placement = turned;
  KifsSpec k = follower("Mass", 24);
  k.meshResolution = 40;
  const ObjectId id = d.add("Ornament", k);
  d.find(id)->placement.translation = Vec3(100.0, 100.0, 0.0);  // ignored while it follows
  Built b(std::move(d));
  ASSERT_EQ(b.sync.status().at(id).error, "");
  const TriangleSoup mesh = sceneTriangles(b.scene, id);
  ASSERT_GT(mesh.triangles.size(), 1000u);

  const Building follow = buildingOf(b.doc, b.scene, *b.doc.find(id));
  const glm::dvec3 size = follow.worldBounds().size();
  const double meshCell = std::max({size.x, size.y, size.z}) / k.meshResolution;
  const double slack = (kMeshOffset + std::sqrt(3.0)) * meshCell + std::sqrt(3.0) * follow.mass()->cell;
  const auto [c, s] = cosSinDegrees(35.0);
  double worst = -1e300;
  for (const glm::dvec3& p : mesh.points) {
    const double x = p.x - 30.0, y = p.y + 10.0;  // back into the box's frame: turn by −35°
    const glm::dvec3 q(c * x + s * y, -s * x + c * y, p.z);
    const double out = std::max({std::abs(q.x) - 6.0, std::abs(q.y) - 6.0, q.z - 22.8, -q.z});
    worst = std::max(worst, out);
  }
  EXPECT_LE(worst, slack);
  EXPECT_GT(worst, -meshCell);  // it reaches the box's faces: the facade is on the walls

  b.doc.find(id)->placement.translation = Vec3(-50.0, 0.0, 7.0);
  b.sync.update(b.doc, b.scene);
  const TriangleSoup same = sceneTriangles(b.scene, id);
  ASSERT_EQ(same.points.size(), mesh.points.size());
  for (std::size_t i = 0; i < mesh.points.size(); ++i) ASSERT_EQ(same.points[i], mesh.points[i]);

  b.doc.find(mass)->placement.translation = Vec3(38.0, -14.0, 2.0);
  EXPECT_EQ(b.sync.update(b.doc, b.scene), 2u);  // the mass and its follower
  const TriangleSoup moved = sceneTriangles(b.scene, id);
  ASSERT_EQ(moved.points.size(), mesh.points.size());
  const Aabb before = boundsOf(mesh), after = boundsOf(moved);
  const glm::dvec3 shift(8.0, -4.0, 2.0);
  EXPECT_LT(glm::length(after.lo - (before.lo + shift)), 1e-6);
  EXPECT_LT(glm::length(after.hi - (before.hi + shift)), 1e-6);
}

// A follower of one building of a town is ray-marched only: meshing it says so.
TEST(KifsFollow, AMeshedFollowerOfATownsBuildingIsRefused) {
  Document d;
  d.add("Town", BoxSpec{});
  KifsSpec k = follower("Town", 16);
  k.mass.building = "w1";
  k.meshResolution = 16;
  const ObjectId id = d.add("K", k);
  const Built b(std::move(d));
  EXPECT_NE(b.sync.status().at(id).error.find("kifs.meshResolution: a building that follows one building of a town"),
            std::string::npos);
}

// A town of two square footprints in metres, massing only: "small" x 30..36, y 0..6 and
// "large" x 0..10, y 0..8, the town moved 100 m along x.
DocObject twoBuildingTown() {
  nlohmann::json fc = {{"type", "FeatureCollection"}, {"frame", {{"units", "m"}}}, {"features", nlohmann::json::array()}};
  for (const auto& [id, x0, x1, y1] : {std::tuple{"large", 0.0, 10.0, 8.0}, std::tuple{"small", 30.0, 36.0, 6.0}})
    fc["features"].push_back({{"type", "Feature"},
                              {"id", id},
                              {"properties", nlohmann::json::object()},
                              {"geometry",
                               {{"type", "Polygon"},
                                {"coordinates", {{{x0, 0.0}, {x1, 0.0}, {x1, y1}, {x0, y1}, {x0, 0.0}}}}}}});
  DocObject o;
  TownSpec t;
  t.footprintsJson = fc.dump();
  t.style = std::string(CORBEL_SOURCE_DIR) + "/assets/styles/oldtown.json";
  t.detail = "massing";
  o.name = "Town";
  o.spec = t;
  o.placement.translation = Vec3(100.0, 0.0, 0.0);
  return o;
}

// kifs.mass.building: the follower stands on one building of a town, placed with the town. The
// oracle is the footprint by hand: the baked shell's box is that square moved 100 m (and its eaves), the field is
// negative at its centre and, at the other building's centre, at least the 20 m gap between them.
TEST(KifsFollow, ATownsBuildingIsItsMass) {
  Document d;
  const DocObject town = twoBuildingTown();
  const ObjectId townId = d.add(town.name, std::get<TownSpec>(town.spec));
  d.find(townId)->placement = town.placement;
  KifsSpec k = follower("Town", 24);
  k.mass.building = "small";
  const ObjectId kid = d.add("Ornament", k);
  d.add("Mass", BoxSpec{});
  Scene scene;
  SceneSync sync;
  extrude::registerKernel(sync);
  kifs::registerKernel(sync);
  const std::shared_ptr<city::TownCache> towns = city::registerKernel(sync);
  sync.update(d, scene);
  ASSERT_EQ(sync.status().at(townId).error, "");
  const Building b = buildingOf(d, scene, *d.find(kid), nullptr, city::buildingMeshes(towns));
  // Every profile of the old-town style overhangs 0.3 m at the wall head (assets/styles/oldtown.json:
  // [0, h] to [-0.3, h]), so the shell's plan box is the square grown by 0.3 m.
  const Aabb shell = b.mass()->shell;
  EXPECT_NEAR(shell.lo.x, 130.0 - 0.3, 1e-6);
  EXPECT_NEAR(shell.hi.x, 136.0 + 0.3, 1e-6);
  EXPECT_NEAR(shell.lo.y, 0.0 - 0.3, 1e-6);
  EXPECT_NEAR(shell.hi.y, 6.0 + 0.3, 1e-6);
  EXPECT_NEAR(shell.lo.z, 0.0, 1e-6);
  const double h = shell.hi.z;
  EXPECT_GT(h, 2.0);
  EXPECT_LT(b.mass()->distance({133.0, 3.0, 0.5 * h}), 0.0);
  EXPECT_GE(b.mass()->distance({105.0, 4.0, 0.5 * h}), 20.0 - std::sqrt(3.0) * b.mass()->cell);
  // Errors name kifs.mass.building and what is wrong.
  auto error = [&](const std::string& building, const std::string& mass, const TownBuildings& buildings) {
    KifsSpec bad = follower(mass, 16);
    bad.mass.building = building;
    Document e = d;
    const ObjectId id = e.add("Bad", bad);
    return errorOf([&] { buildingOf(e, scene, *e.find(id), nullptr, buildings); });
  };
  EXPECT_EQ(error("nope", "Town", city::buildingMeshes(towns)), "kifs.mass.building: town \"Town\" has no building \"nope\"");
  EXPECT_EQ(error("small", "Mass", city::buildingMeshes(towns)),
            "kifs.mass.building: \"Mass\" is not a town; only a town's buildings can be named (leave it empty)");
  EXPECT_EQ(error("small", "Town", {}), "kifs.mass.building: the buildings of town \"Town\" are not at hand here");
}

TEST(KifsFollow, TheProjectFileKeepsTheMassObject) {
  Document d;
  d.add("Mass", BoxSpec{});
  d.add("K", follower("Mass", 24));
  KifsSpec onTown = follower("Town", 24);
  onTown.mass.building = "w17";
  d.add("L", onTown);
  const std::string path = ::testing::TempDir() + "follow.corbel";
  saveProject(d, path);
  const Document back = loadProject(path).document;
  const auto& k = std::get<KifsSpec>(back.findByName("K")->spec);
  EXPECT_EQ(k.mass.footprint, "object");
  EXPECT_EQ(k.mass.object, "Mass");
  EXPECT_EQ(k.mass.resolution, 24);
  EXPECT_EQ(std::get<KifsSpec>(back.findByName("L")->spec).mass.building, "w17");
  EXPECT_EQ(back, d);
  // A resolution out of range is the kernel's to name.
  KifsSpec bad = follower("Mass", 600);
  EXPECT_NE(errorOf([&] { paramsOf(bad); }).find("kifs.mass.resolution"), std::string::npos);
}

}  // namespace
}  // namespace corbel::kifs
