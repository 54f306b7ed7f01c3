// The town kernel (city/kernel.h): a town object of a project builds like `corbel-cli city`,
// and rebuilding after a change re-extrudes exactly the buildings whose inputs changed.
#include "city/kernel.h"

#include "core/error.h"
#include "core/project_io.h"
#include "extrude/kernel.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <set>
#include <thread>

namespace corbel::city {
namespace {

DocObject exampleTown(const std::string& style = "oldtown") {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/town-" + style + ".corbel");
  for (const DocObject& o : p.document.objects)
    if (std::holds_alternative<TownSpec>(o.spec)) return o;
  ADD_FAILURE() << "no town in the example";
  return {};
}

std::size_t builtCount(const TownCache& cache, ObjectId id) {
  std::size_t n = 0;
  for (const BuiltBuilding& b : cache.buildings(id)) n += b.error.empty() ? 1 : 0;
  return n;
}

TEST(TownKernel, BuildsEveryFootprintOfTheExampleOnce) {
  const DocObject town = exampleTown();
  TownCache cache;
  const BuildResult r = cache.build(town, nullptr);
  const auto list = cache.buildings(town.id);
  ASSERT_EQ(list.size(), 32u);
  EXPECT_EQ(builtCount(cache, town.id), 32u) << (r.warnings.empty() ? "" : r.warnings[0]);
  EXPECT_EQ(cache.extrusions(), 32u);
  EXPECT_EQ(r.kind, Kind::Shell);
  // The object's mesh is the buildings' meshes one after another.
  std::size_t faces = 0;
  for (const BuiltBuilding& b : list) {
    EXPECT_EQ(b.firstFace, faces);
    EXPECT_EQ(b.faceCount, cache.mesh(town.id, b.id).faces.size());
    faces += b.faceCount;
  }
  EXPECT_EQ(faces, r.mesh.faces.size());
  // Building again with nothing changed extrudes nothing and gives the same mesh.
  const BuildResult again = cache.build(town, nullptr);
  EXPECT_EQ(cache.extrusions(), 32u);
  EXPECT_EQ(again.mesh.points, r.mesh.points);
  EXPECT_EQ(again.mesh.faces, r.mesh.faces);
}

TEST(TownKernel, AnOverrideReExtrudesExactlyThatBuilding) {
  DocObject town = exampleTown();
  TownCache cache;
  const BuildResult before = cache.build(town, nullptr);
  const auto list = cache.buildings(town.id);
  const BuiltBuilding target = list[5];
  const std::string other = target.type == "town house" ? "brick town house" : "town house";
  std::get<TownSpec>(town.spec).overrides[target.id].type = other;
  const BuildResult after = cache.build(town, nullptr);
  EXPECT_EQ(cache.extrusions(), 33u);  // one more
  const auto list2 = cache.buildings(town.id);
  for (std::size_t i = 0; i < list.size(); ++i) {
    EXPECT_EQ(list2[i].type, i == 5 ? other : list[i].type) << list[i].id;
    EXPECT_EQ(list2[i].hash != list[i].hash, i == 5) << list[i].id;
  }
  EXPECT_NE(after.mesh.points, before.mesh.points);
  // What the cache gives equals a build from scratch.
  TownCache fresh;
  const BuildResult scratch = fresh.build(town, nullptr);
  EXPECT_EQ(scratch.mesh.points, after.mesh.points);
  EXPECT_EQ(scratch.mesh.faces, after.mesh.faces);
  // A profile override of the same building: again one extrusion.
  std::get<TownSpec>(town.spec).overrides[target.id].profiles["street"] = "oldtown gable";
  cache.build(town, nullptr);
  EXPECT_EQ(cache.extrusions(), 34u);
  // Dropping the override brings back the first look, again by one extrusion.
  std::get<TownSpec>(town.spec).overrides.clear();
  const BuildResult back = cache.build(town, nullptr);
  EXPECT_EQ(cache.extrusions(), 35u);
  EXPECT_EQ(back.mesh.points, before.mesh.points);
}

// An edge override changes that one edge's profile and nothing else of the building: the
// oracle is the style's own draw for the building without the override.
TEST(TownKernel, AnEdgeOverrideChangesThatEdgeOnlyAndWinsOverItsOrientation) {
  DocObject town = exampleTown();
  TownCache cache;
  cache.build(town, nullptr);
  const auto inputs = cache.inputs(town.id);
  ASSERT_TRUE(inputs);
  const std::size_t bi = 5;
  const Building& b = inputs->town.buildings[bi];
  auto& spec = std::get<TownSpec>(town.spec);
  const StyledBuilding plain = styleBuilding(inputs->style, b, inputs->labels[bi], spec.seed);
  ASSERT_TRUE(plain.problem.empty()) << plain.problem;
  // A street edge of the building, and a profile it does not have.
  const EdgeLabel* street = nullptr;
  for (const EdgeLabel& e : inputs->labels[bi].edges)
    if (e.orientation == Orientation::Street && !street) street = &e;
  ASSERT_TRUE(street);
  const int before = plain.spec.loops[street->loop].profile[street->edge];
  int wanted = -1;
  for (std::size_t i = 0; i < inputs->style.profiles.size(); ++i)
    if (static_cast<int>(i) != before && inputs->style.profiles[i].name.find("dormer") == std::string::npos)
      wanted = static_cast<int>(i);
  ASSERT_GE(wanted, 0);
  const std::string key = townEdgeKey(street->loop, street->edge);
  const auto styledUnder = [&](const TownOverride& o) {
    TownSpec one = spec;
    one.overrides = {{b.id, o}};
    const auto resolved = resolveOverrides(inputs->style, one);
    StyledBuilding s = styleBuilding(inputs->style, b, inputs->labels[bi], spec.seed, &resolved.at(b.id));
    EXPECT_TRUE(s.problem.empty()) << s.problem;
    return s;
  };
  // Equal profiles everywhere but at the target edge, which takes `wanted`.
  const auto expectOnlyTargetDiffers = [&](const StyledBuilding& base, const StyledBuilding& changed) {
    for (std::size_t l = 0; l < base.spec.loops.size(); ++l)
      for (std::size_t e = 0; e < base.spec.loops[l].profile.size(); ++e) {
        const bool target = static_cast<int>(l) == street->loop && static_cast<int>(e) == street->edge;
        EXPECT_EQ(changed.spec.loops[l].profile[e], target ? wanted : base.spec.loops[l].profile[e]) << l << ":" << e;
      }
  };
  TownOverride edgeOnly;
  edgeOnly.edges[key] = inputs->style.profiles[wanted].name;
  expectOnlyTargetDiffers(plain, styledUnder(edgeOnly));
  // With every street edge overridden to `before` too, the edge's own override still wins.
  TownOverride streetOnly;
  streetOnly.profiles["street"] = inputs->style.profiles[before].name;
  TownOverride both = streetOnly;
  both.edges = edgeOnly.edges;
  expectOnlyTargetDiffers(styledUnder(streetOnly), styledUnder(both));
  spec.overrides[b.id] = edgeOnly;
  // The cache re-extrudes that building only, and its mesh equals a build from scratch.
  const std::size_t extrusions = cache.extrusions();
  const auto list = cache.buildings(town.id);
  const BuildResult after = cache.build(town, nullptr);
  EXPECT_EQ(cache.extrusions(), extrusions + 1);
  const auto list2 = cache.buildings(town.id);
  for (std::size_t i = 0; i < list.size(); ++i)
    EXPECT_EQ(list2[i].hash != list[i].hash, list[i].id == b.id) << list[i].id;
  EXPECT_TRUE(list2[bi].error.empty()) << list2[bi].error;
  TownCache fresh;
  const BuildResult scratch = fresh.build(town, nullptr);
  EXPECT_EQ(scratch.mesh.points, after.mesh.points);
  EXPECT_EQ(scratch.mesh.faces, after.mesh.faces);
}

TEST(TownKernel, BadEdgeOverridesNameTheEdge) {
  DocObject town = exampleTown();
  TownCache cache;
  cache.build(town, nullptr);
  const auto inputs = cache.inputs(town.id);
  const Building& b = inputs->town.buildings[0];
  auto& spec = std::get<TownSpec>(town.spec);
  const auto expectFault = [&](const std::string& key, const std::string& profile, const std::string& reason) {
    spec.overrides.clear();
    spec.overrides[b.id].edges[key] = profile;
    try {
      cache.build(town, nullptr);
      ADD_FAILURE() << key << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where, "town.overrides[\"" + b.id + "\"].edges[\"" + key + "\"]");
      EXPECT_EQ(e.reason, reason);
    }
  };
  const std::size_t n = b.loops[0].size();
  expectFault("0:" + std::to_string(n), "oldtown gable",
              "loop 0 of the footprint has " + std::to_string(n) + " edges (0 to " + std::to_string(n - 1) + ")");
  expectFault(std::to_string(b.loops.size()) + ":0", "oldtown gable",
              "the footprint has " + std::to_string(b.loops.size()) + " loop(s) (0 to " +
                  std::to_string(b.loops.size() - 1) + ")");
  expectFault("0:0", "spire", "the style \"gabled old town\" has no profile named \"spire\"");
}

TEST(TownKernel, ASeedChangeReExtrudesOnlyBuildingsThatDrawDifferently) {
  DocObject town = exampleTown("suburban");
  TownCache cache;
  cache.build(town, nullptr);
  const auto list = cache.buildings(town.id);
  std::get<TownSpec>(town.spec).seed = 2;
  cache.build(town, nullptr);
  const auto list2 = cache.buildings(town.id);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < list.size(); ++i) changed += list[i].hash != list2[i].hash;
  EXPECT_EQ(cache.extrusions(), 32u + changed);
  EXPECT_GT(changed, 0u);
}

TEST(TownKernel, BadOverridesNameTheirPath) {
  DocObject town = exampleTown();
  TownCache cache;
  cache.build(town, nullptr);
  const std::string id = cache.buildings(town.id)[0].id;
  auto& spec = std::get<TownSpec>(town.spec);
  spec.overrides[id].type = "castle";
  try {
    cache.build(town, nullptr);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "town.overrides[\"" + id + "\"].type");
    EXPECT_EQ(e.reason, "the style \"gabled old town\" has no type named \"castle\"");
  }
  spec.overrides.clear();
  spec.overrides[id].profiles["back"] = "spire";
  EXPECT_THROW(cache.build(town, nullptr), InputError);
  spec.overrides.clear();
  spec.overrides["nobody"].type = "town house";
  try {
    cache.build(town, nullptr);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "town.overrides[\"nobody\"]");
  }
  spec.overrides.clear();
  spec.style = "/no/such/style.json";
  try {
    cache.build(town, nullptr);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "town.style");
  }
}

// Cancelling keeps what was built: the next build extrudes only the rest.
TEST(TownKernel, CancelKeepsTheBuildingsAlreadyExtruded) {
  const DocObject town = exampleTown();
  TownCache cache;
  Progress cancelled;
  cancelled.cancel();
  EXPECT_THROW(cache.build(town, &cancelled), Cancelled);
  EXPECT_EQ(cache.extrusions(), 0u);
  // Cancelled once the first chunk (one building here) is reported: what was extruded stays cached.
  Progress p;
  std::thread t([&] {
    while (p.fraction() == 0) std::this_thread::yield();
    p.cancel();
  });
  EXPECT_THROW(cache.build(town, &p, 1), Cancelled);
  t.join();
  const std::size_t first = cache.extrusions();
  EXPECT_GE(first, 1u);
  EXPECT_LT(first, 32u);
  cache.build(town, nullptr);
  EXPECT_EQ(cache.extrusions(), 32u);
  EXPECT_EQ(builtCount(cache, town.id), 32u);
}

}  // namespace
}  // namespace corbel::city

namespace corbel::city {
namespace {

// A town of hand-placed square footprints in metres ("frame": units m) in the old-town style.
DocObject squareTown(const std::vector<std::array<double, 4>>& squares) {
  nlohmann::json fc = {{"type", "FeatureCollection"}, {"frame", {{"units", "m"}}}, {"features", nlohmann::json::array()}};
  for (std::size_t i = 0; i < squares.size(); ++i) {
    const auto [x0, y0, x1, y1] = squares[i];
    fc["features"].push_back({{"type", "Feature"},
                              {"id", "f" + std::to_string(i)},
                              {"properties", nlohmann::json::object()},
                              {"geometry",
                               {{"type", "Polygon"},
                                {"coordinates", {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}}}}}});
  }
  DocObject o;
  o.id = 7;
  o.name = "Town";
  TownSpec t;
  t.footprintsJson = fc.dump();
  t.style = std::string(CORBEL_SOURCE_DIR) + "/assets/styles/oldtown.json";
  t.detail = "massing";
  o.spec = t;
  return o;
}

const BuiltBuilding* find(const std::vector<BuiltBuilding>& list, const std::string& id) {
  for (const BuiltBuilding& b : list)
    if (b.id == id) return &b;
  return nullptr;
}

// A straight street from (0, 0) to (70, 0), 10 m wide, 2 m setback, 12 m deep, 7 m plots: by hand
// ten plots a side, the left ones x in [7k, 7k + 7], y in [7, 19]. A footprint at x 20..24,
// y 10..14 overlaps left/2 (x 14..21) and left/3 (21..28) and nothing else; one behind the plots
// (y 19.5..25) and one across the street's far side beyond its plots overlap nothing.
TEST(TownStreets, PlotsThatOverlapAFootprintAreReportedByName) {
  DocObject town = squareTown({{20, 10, 24, 14}, {30, 19.5, 36, 25}, {40, -40, 46, -34}});
  TownStreet st;
  st.points = {{0, 0}, {70, 0}};
  std::get<TownSpec>(town.spec).streets = {st};
  TownCache cache;
  cache.build(town, nullptr);
  const auto list = cache.buildings(town.id);
  ASSERT_EQ(list.size(), 3u + 20u);
  for (const std::string side : {"left", "right"})
    for (int k = 0; k < 10; ++k) {
      const std::string id = "street 1/" + side + "/" + std::to_string(k);
      const BuiltBuilding* b = find(list, id);
      ASSERT_NE(b, nullptr) << id;
      if (side == "left" && (k == 2 || k == 3)) {
        EXPECT_EQ(b->error, "the plot overlaps footprint f0") << id;
      } else {
        EXPECT_EQ(b->error, "") << id;
      }
    }
  for (const std::string id : {"f0", "f1", "f2"}) EXPECT_EQ(find(list, id)->error, "") << id;
  // A built plot stands where the hand computation puts it: left/5's base spans x 35..42, y 7..19.
  const MeshData m = cache.mesh(town.id, "street 1/left/5");
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const Vec3& q : m.points)
    if (std::abs(q[2]) < 1e-9) x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]), y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
  EXPECT_NEAR(x0, 35, 1e-9);
  EXPECT_NEAR(x1, 42, 1e-9);
  EXPECT_NEAR(y0, 7, 1e-9);
  EXPECT_NEAR(y1, 19, 1e-9);
}

// Reshaping a street far (more than the 200 m street reach) from every footprint re-extrudes its
// plots only; the example's 32 footprints are not extruded again and keep their meshes.
// A street whose plots are grown by the skeleton (Fig. 26): the same number of plots as its
// normal cuts, every one built, the two sets of plots covering the same frontage area (Steiner:
// on a bend gentle enough that no back folds, both are the strip) and differing in shape; switching is an input change
// that re-extrudes the plots.
TEST(TownStreets, GrownPlotsBuildAndSwitchingReExtrudesThem) {
  DocObject town = exampleTown();
  TownCache cache;
  TownStreet st;
  st.points = {{400, 0}, {435, 6}, {470, 0}};  // a gentle bend: no plot's back folds
  auto& spec = std::get<TownSpec>(town.spec);
  spec.streets = {st};
  cache.build(town, nullptr);
  const auto inputsCut = cache.inputs(town.id);
  const std::size_t afterCuts = cache.extrusions();
  spec.streets[0].skeletonPlots = true;
  cache.build(town, nullptr);
  const auto inputsGrown = cache.inputs(town.id);
  ASSERT_NE(inputsCut, inputsGrown);  // new inputs: the plots were cut again
  double cutArea = 0, grownArea = 0;
  std::size_t cut = 0, grown = 0, differ = 0;
  for (std::size_t i = 0; i < inputsGrown->town.buildings.size(); ++i) {
    const Building& g = inputsGrown->town.buildings[i];
    if (g.id.rfind("street 1/", 0) != 0) continue;
    ++grown;
    grownArea += g.area;
    EXPECT_NE(g.notes.front().find("grown from its seed"), std::string::npos) << g.id;
    for (const Building& c : inputsCut->town.buildings)
      if (c.id == g.id) ++cut, cutArea += c.area, differ += c.loops != g.loops;
  }
  EXPECT_EQ(grown, cut);
  EXPECT_GT(differ, 0u);
  EXPECT_NEAR(grownArea, cutArea, 1e-3 * cutArea);
  std::size_t built = 0;
  for (const BuiltBuilding& b : cache.buildings(town.id)) built += b.id.rfind("street 1/", 0) == 0 && b.error.empty();
  EXPECT_EQ(built, grown);
  EXPECT_GE(cache.extrusions(), afterCuts + differ);
}

TEST(TownStreets, ReshapingAStreetReExtrudesItsPlotsAndNothingElse) {
  DocObject town = exampleTown();
  TownCache cache;
  const BuildResult plain = cache.build(town, nullptr);
  ASSERT_EQ(cache.extrusions(), 32u);
  TownStreet st;
  st.points = {{400, 0}, {435, 10}, {470, 0}};
  auto& spec = std::get<TownSpec>(town.spec);
  spec.streets = {st};
  cache.build(town, nullptr);
  const auto list = cache.buildings(town.id);
  std::size_t plots = 0;
  for (const BuiltBuilding& b : list) plots += b.id.rfind("street 1/", 0) == 0 && b.error.empty();
  ASSERT_GE(plots, 16u);
  EXPECT_EQ(cache.extrusions(), 32u + plots);
  spec.streets[0].points[1] = {435, 20};  // the middle point moves
  const BuildResult reshaped = cache.build(town, nullptr);
  std::size_t plots2 = 0;
  for (const BuiltBuilding& b : cache.buildings(town.id)) plots2 += b.id.rfind("street 1/", 0) == 0 && b.error.empty();
  EXPECT_EQ(cache.extrusions(), 32u + plots + plots2);
  // The footprints' faces come first and are unchanged.
  ASSERT_GE(reshaped.mesh.faces.size(), plain.mesh.faces.size());
  for (std::size_t f = 0; f < plain.mesh.faces.size(); ++f) ASSERT_EQ(reshaped.mesh.faces[f], plain.mesh.faces[f]);
  // Without the street the town is the plain one again, without extruding.
  spec.streets.clear();
  const BuildResult back = cache.build(town, nullptr);
  EXPECT_EQ(cache.extrusions(), 32u + plots + plots2);
  EXPECT_EQ(back.mesh.points, plain.mesh.points);
}

// Two streets crossing at right angles, A along y = 0 (x 0..70) and B along x = 35 (y −35..35),
// both 10 m wide with plots 7..19 m from their centrelines. By hand: B's plots 4 and 5 on each
// side (y −7..0 and 0..7) touch A's centreline and lie on A's roadway; B's plots 2, 3, 6 and 7
// (y −21..−7, 7..21) overlap A's plots, which come first; A's plots 4 and 5 (x 28..42) touch B's
// centreline and lie on B's roadway. Everything else builds.
TEST(TownStreets, CrossingStreetsDoNotBuildIntoEachOther) {
  DocObject town = squareTown({});
  TownStreet a, b;
  a.points = {{0, 0}, {70, 0}};
  b.points = {{35, -35}, {35, 35}};
  std::get<TownSpec>(town.spec).streets = {a, b};
  TownCache cache;
  cache.build(town, nullptr);
  const auto list = cache.buildings(town.id);
  ASSERT_EQ(list.size(), 40u);
  for (const std::string side : {"left", "right"})
    for (int k = 0; k < 10; ++k) {
      const BuiltBuilding* pa = find(list, "street 1/" + side + "/" + std::to_string(k));
      const BuiltBuilding* pb = find(list, "street 2/" + side + "/" + std::to_string(k));
      ASSERT_TRUE(pa && pb);
      EXPECT_EQ(pa->error, k == 4 || k == 5 ? "the plot lies across street 2" : "") << side << k;
      if (k == 4 || k == 5) {
        EXPECT_EQ(pb->error, "the plot lies across street 1") << side << k;
      } else if (k == 2 || k == 3 || k == 6 || k == 7) {
        EXPECT_EQ(pb->error.rfind("the plot overlaps plot street 1/", 0), 0u) << side << k << ": " << pb->error;
      } else {
        EXPECT_EQ(pb->error, "") << side << k;
      }
    }
}

TEST(TownStreets, BadStreetsAreNamedByTheirPath) {
  DocObject town = squareTown({});
  TownStreet st;
  st.points = {{0, 0}};
  std::get<TownSpec>(town.spec).streets = {st};
  TownCache cache;
  try {
    cache.build(town, nullptr);
    FAIL() << "a street of one point should be refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "town.streets[0].points");
  }
  std::get<TownSpec>(town.spec).streets[0].points = {{0, 0}, {0, 0}};
  EXPECT_THROW(cache.build(town, nullptr), InputError);
  std::get<TownSpec>(town.spec).streets[0].points = {{0, 0}, {10, 0}};
  std::get<TownSpec>(town.spec).streets[0].depth = 1;
  try {
    cache.build(town, nullptr);
    FAIL() << "a 1 m deep plot should be refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "town.streets[0].depth");
  }
}

}  // namespace
}  // namespace corbel::city

namespace corbel::city {
namespace {

// A town object with a footprint whose 4° corner is too sharp for the old town's 0.3 m
// overhangs builds it (without them on that corner's edges) and says so in the object's
// warnings, by building; a plain house beside it adds none.
TEST(TownKernel, ASharpCornerBuildsAndTheObjectWarnsByBuilding) {
  DocObject town = squareTown({{100, 0, 112, 9}});
  TownSpec& t = std::get<TownSpec>(town.spec);
  nlohmann::json fc = nlohmann::json::parse(t.footprintsJson);
  const double h = 60 * std::tan(4 * std::numbers::pi / 180);
  fc["features"].push_back({{"type", "Feature"},
                            {"id", "sharp"},
                            {"properties", nlohmann::json::object()},
                            {"geometry", {{"type", "Polygon"}, {"coordinates", {{{0, 0}, {60, 0}, {0, h}, {0, 0}}}}}}});
  t.footprintsJson = fc.dump();
  TownCache cache;
  const BuildResult r = cache.build(town, nullptr);
  EXPECT_EQ(builtCount(cache, town.id), 2u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].rfind("building sharp: loops[0].points[1]: at height ", 0), 0u) << r.warnings[0];
  EXPECT_NE(r.warnings[0].find(" m the 0.30 m overhang would push this 4.0° corner 8.6 m out"), std::string::npos)
      << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("edges 0 and 1 are built without their overhang"), std::string::npos) << r.warnings[0];
  // Built again from the cache, it still says so.
  EXPECT_EQ(cache.build(town, nullptr).warnings, r.warnings);
}

}  // namespace
}  // namespace corbel::city
