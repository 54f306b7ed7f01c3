// The town kernel (city/kernel.h): a town object of a project builds like `corbel-cli city`,
// and rebuilding after a change re-extrudes exactly the buildings whose inputs changed.
#include "city/kernel.h"

#include "core/error.h"
#include "core/project_io.h"
#include "extrude/kernel.h"

#include <gtest/gtest.h>

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
