// live_sync.h: edits are built off the UI thread. A quick build shows in the same call; a slow
// one never blocks update() and the Scene keeps its last result meanwhile; edits made during a
// build are coalesced so only the newest is built next, and nothing older replaces it; a
// superseded build that runs long is cancelled. The builders here are gated by the test, so
// every property is checked by construction (who ran, in which order, what the Scene holds),
// not by timing.
#include "core/error.h"
#include "core/live_sync.h"
#include "core/massing.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace {

using namespace corbel;

// A gate the test opens; builders wait at it (never longer than a few seconds, so a broken
// LiveSync fails the test instead of hanging it).
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  bool open = true;
  std::vector<std::string> built;  // materials, in build order
  int inside = 0;                  // builders waiting at the gate now
  void set(bool o) {
    std::lock_guard l(m);
    open = o;
    cv.notify_all();
  }
  int waiting() {
    std::lock_guard l(m);
    return inside;
  }
};

// An extrusion object whose "geometry" is a box as wide as its material string is long, so
// the Scene tells which state it shows by the object's bounds.
ExtrusionSpec tagged(const std::string& material) {
  ExtrusionSpec e;
  e.material = material;
  return e;
}
double shownWidth(const Scene& scene, ObjectId id) {
  const BBox b = scene.bounds(id);
  return b.hi[0] - b.lo[0];
}

void gatedKernel(SceneSync& sync, Gate& gate, bool honourCancel = false) {
  sync.setBuilder<ExtrusionSpec>([&gate, honourCancel](const DocObject& o, Progress* progress) {
    const std::string material = std::get<ExtrusionSpec>(o.spec).material;
    {
      std::unique_lock l(gate.m);
      ++gate.inside;
      const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
      while (!gate.open) {
        if (honourCancel && progress && progress->cancelled()) {
          --gate.inside;
          gate.built.push_back(material + " (cancelled)");
          throw Cancelled();
        }
        if (gate.cv.wait_until(l, std::min(until, std::chrono::steady_clock::now() + std::chrono::milliseconds(2))) ==
                std::cv_status::timeout &&
            std::chrono::steady_clock::now() >= until)
          break;
      }
      --gate.inside;
      gate.built.push_back(material);
    }
    BoxSpec b;
    b.size = Vec3(static_cast<double>(material.size()), 1, 1);
    BuildResult r;
    r.kind = Kind::Shell;
    r.mesh = buildBoxes(b);
    return r;
  });
}

// Polls update() until the Scene is current (bounded, so a bug fails instead of hanging).
void untilCurrent(LiveSync& live, const Document& d, std::uint64_t state, Scene& scene) {
  for (int i = 0; i < 5000 && !live.current(); ++i) {
    live.update(d, state, scene);
    if (!live.current()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

void waitUntilBlocked(Gate& gate) {
  for (int i = 0; i < 5000 && gate.waiting() == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

TEST(LiveSync, AQuickBuildShowsInTheSameCall) {
  SceneSync sync;
  Gate gate;
  gatedKernel(sync, gate);
  LiveSync live(sync, {.waitSeconds = 5.0, .cancelAfterSeconds = 1.0});
  Document d;
  const ObjectId id = d.add("shell", tagged("abc"));
  Scene scene;
  EXPECT_TRUE(live.update(d, 1, scene));
  EXPECT_TRUE(live.current());
  EXPECT_EQ(shownWidth(scene, id), 3.0);
  // Nothing changed: nothing is built again.
  EXPECT_FALSE(live.update(d, 1, scene));
  EXPECT_EQ(live.buildsStarted(), 1u);
}

TEST(LiveSync, ASlowBuildNeverBlocksAndTheLastResultStaysMeanwhile) {
  SceneSync sync;
  Gate gate;
  gatedKernel(sync, gate);
  LiveSync live(sync, {.waitSeconds = 0.0, .cancelAfterSeconds = 10.0});
  Document d;
  const ObjectId id = d.add("shell", tagged("ab"));
  Scene scene;
  live.settle(d, 1, scene);
  ASSERT_EQ(shownWidth(scene, id), 2.0);

  gate.set(false);
  std::get<ExtrusionSpec>(d.find(id)->spec).material = "abcd";
  EXPECT_FALSE(live.update(d, 2, scene)) << "returned with a result although the builder is held at the gate";
  waitUntilBlocked(gate);
  EXPECT_EQ(gate.waiting(), 1) << "the build is running off this thread";
  EXPECT_TRUE(live.building());
  EXPECT_FALSE(live.current()) << "the Scene still shows the previous state and says so";
  EXPECT_EQ(shownWidth(scene, id), 2.0);
  EXPECT_EQ(live.shownState(), std::optional<std::uint64_t>(1));

  gate.set(true);
  untilCurrent(live, d, 2, scene);
  EXPECT_TRUE(live.current());
  EXPECT_EQ(shownWidth(scene, id), 4.0);
}

TEST(LiveSync, EditsDuringABuildAreCoalescedAndTheNewestWins) {
  SceneSync sync;
  Gate gate;
  gatedKernel(sync, gate);
  LiveSync live(sync, {.waitSeconds = 0.0, .cancelAfterSeconds = 10.0});
  Document d;
  const ObjectId id = d.add("shell", tagged("a"));
  Scene scene;
  live.settle(d, 1, scene);

  gate.set(false);
  std::get<ExtrusionSpec>(d.find(id)->spec).material = "bb";
  live.update(d, 2, scene);
  waitUntilBlocked(gate);
  for (const auto& [state, m] : {std::pair{3, "ccc"}, std::pair{4, "dddd"}, std::pair{5, "eeeee"}}) {
    std::get<ExtrusionSpec>(d.find(id)->spec).material = m;
    live.update(d, state, scene);
    EXPECT_EQ(shownWidth(scene, id), 1.0) << "nothing new is shown while the first build runs";
  }
  gate.set(true);
  untilCurrent(live, d, 5, scene);
  EXPECT_EQ(shownWidth(scene, id), 5.0);
  // The running build finished and was shown (it was newer than what the Scene had); the
  // states made meanwhile were skipped except the newest.
  EXPECT_EQ(gate.built, (std::vector<std::string>{"a", "bb", "eeeee"}));
}

TEST(LiveSync, ASupersededBuildThatRunsLongIsCancelled) {
  SceneSync sync;
  Gate gate;
  gatedKernel(sync, gate, /*honourCancel=*/true);
  LiveSync live(sync, {.waitSeconds = 0.0, .cancelAfterSeconds = 0.0});
  Document d;
  const ObjectId id = d.add("shell", tagged("a"));
  Scene scene;
  live.settle(d, 1, scene);

  gate.set(false);
  std::get<ExtrusionSpec>(d.find(id)->spec).material = "slow";
  live.update(d, 2, scene);
  waitUntilBlocked(gate);
  gate.set(false);
  std::get<ExtrusionSpec>(d.find(id)->spec).material = "newest";
  live.update(d, 3, scene);  // the build of state 2 is now superseded and over its time
  // It stops at its next cancellation check; then state 3 is built (the gate opened for it).
  for (int i = 0; i < 5000; ++i) {
    {
      std::lock_guard l(gate.m);
      if (!gate.built.empty() && gate.built.back() == "slow (cancelled)") break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  gate.set(true);
  untilCurrent(live, d, 3, scene);
  EXPECT_EQ(gate.built, (std::vector<std::string>{"a", "slow (cancelled)", "newest"}));
  EXPECT_EQ(shownWidth(scene, id), 6.0);
}

TEST(LiveSync, SettleLeavesTheSceneAsASynchronousUpdateWould) {
  SceneSync sync, reference;
  LiveSync live(sync);
  Document d;
  BoxSpec b;
  b.repeat_x = 3;
  b.spacing_x = 12;
  const ObjectId a = d.add("row", b);
  const ObjectId c = d.add("single", BoxSpec{});
  Scene scene, expected;
  live.settle(d, 1, scene);
  reference.update(d, expected);
  for (ObjectId id : {a, c}) {
    EXPECT_EQ(scene.faces(id).size(), expected.faces(id).size());
    EXPECT_EQ(scene.objects().at(id).name, expected.objects().at(id).name);
  }
  // A removal and a rename reach the Scene at once.
  d.remove(c);
  d.find(a)->name = "terrace";
  EXPECT_TRUE(live.update(d, 2, scene));
  EXPECT_TRUE(live.current());
  EXPECT_FALSE(scene.hasObject(c));
  EXPECT_EQ(scene.objects().at(a).name, "terrace");
}

TEST(LiveSync, AFailedBuildKeepsTheLastGoodGeometryAndReportsIt) {
  SceneSync sync;
  sync.setBuilder<ExtrusionSpec>([](const DocObject& o, Progress*) -> BuildResult {
    if (std::get<ExtrusionSpec>(o.spec).material == "bad") throw Error("the plan intersects itself");
    BuildResult r;
    r.kind = Kind::Shell;
    r.mesh = buildBoxes(BoxSpec{});
    return r;
  });
  LiveSync live(sync);
  Document d;
  const ObjectId id = d.add("shell", tagged("good"));
  Scene scene;
  live.settle(d, 1, scene);
  const std::size_t faces = scene.faces(id).size();
  ASSERT_GT(faces, 0u);
  std::get<ExtrusionSpec>(d.find(id)->spec).material = "bad";
  live.settle(d, 2, scene);
  EXPECT_TRUE(live.current());
  EXPECT_EQ(sync.status().at(id).error, "the plan intersects itself");
  EXPECT_EQ(scene.faces(id).size(), faces);
}

}  // namespace

namespace {

// The user's Cancel (the Town panel's): the running build stops, the Scene keeps the last
// result, and that state is not built again by itself; retry() or a newer edit builds again.
TEST(LiveSync, ACancelledStateIsNotRebuiltUntilRetriedOrEdited) {
  SceneSync sync;
  Gate gate;
  gatedKernel(sync, gate, /*honourCancel=*/true);
  LiveSync live(sync, {.waitSeconds = 0.0, .cancelAfterSeconds = 10.0});
  Document d;
  const ObjectId id = d.add("shell", tagged("ab"));
  Scene scene;
  live.settle(d, 1, scene);
  gate.set(false);
  std::get<ExtrusionSpec>(d.find(id)->spec).material = "abcd";
  live.update(d, 2, scene);
  waitUntilBlocked(gate);
  live.cancel();
  for (int i = 0; i < 5000 && live.building(); ++i) {
    live.update(d, 2, scene);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_TRUE(live.cancelled());
  EXPECT_FALSE(live.current());
  EXPECT_EQ(shownWidth(scene, id), 2.0);
  const std::size_t started = live.buildsStarted();
  for (int i = 0; i < 5; ++i) live.update(d, 2, scene);
  EXPECT_EQ(live.buildsStarted(), started) << "a cancelled state must not restart by itself";
  gate.set(true);
  live.retry();
  untilCurrent(live, d, 2, scene);
  EXPECT_EQ(shownWidth(scene, id), 4.0);
  EXPECT_FALSE(live.cancelled());
}

}  // namespace
