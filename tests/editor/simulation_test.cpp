// editor/simulation.h: the statics panel's Simulate section. The design state is the model as
// statics builds it, a removed block is not drawn, the Document is never touched, and playing
// spends a bounded slice of wall time per frame while simulated time only moves forward.
#include "editor/simulation.h"

#include "core/error.h"
#include "core/history.h"
#include "core/project_io.h"
#include "statics/kernel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

namespace corbel::editor {
namespace {

// The example arch as saved: thinner than it needs to be to stand (the editor test checks the
// CLI's analysis says so), so it falls without a push.
Document exampleDocument() {
  return loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/masonry-arch.corbel").document;
}

MasonrySpec exampleArch() { return std::get<MasonrySpec>(exampleDocument().objects.at(0).spec); }

// The design's blocks as statics builds them from the spec, independently of the simulation.
statics::Assembly designOf(const MasonrySpec& spec) {
  const statics::ParametricModel model = statics::modelOf(spec);
  return model.build(model.parameters);
}

std::size_t faceCount(const statics::Assembly& a) {
  std::size_t n = 0;
  for (const statics::Block& b : a.blocks) n += b.faces.size();
  return n;
}

TEST(Simulation, StartsAndResetsToTheDesign) {
  const MasonrySpec spec = exampleArch();
  const statics::Assembly design = designOf(spec);
  Simulation s(spec);
  EXPECT_FALSE(s.playing()) << "a new simulation waits for Play";
  EXPECT_EQ(s.time(), 0.0);

  s.removeBlock(s.topBlock());
  s.shake();
  s.play();
  s.step(240);
  ASSERT_GT(s.largestDisplacement(), 0.01) << "the thin arch, shaken and without its keystone, should move";

  s.reset();
  EXPECT_FALSE(s.playing()) << "reset pauses";
  EXPECT_EQ(s.time(), 0.0);
  EXPECT_EQ(s.largestDisplacement(), 0.0);
  EXPECT_EQ(s.fallenCount(), 0);
  for (const sim::Pose& p : s.poses()) EXPECT_EQ(p, sim::Pose{}) << "every block back where it was built";
  // What is drawn is the design again: every block, at its design vertices, in order.
  const MeshData mesh = s.mesh();
  ASSERT_EQ(mesh.faces.size(), faceCount(design));
  std::size_t k = 0;
  for (const statics::Block& b : design.blocks)
    for (const Vec3& v : b.vertices) {
      ASSERT_LT(k, mesh.points.size());
      EXPECT_LT((mesh.points[k++] - v).norm(), 1e-12) << b.name;
    }
  EXPECT_EQ(mesh.materials.at(mesh.faceMaterial.at(0)), spec.material);
}

TEST(Simulation, ARemovedBlockIsNotDrawnAndCannotBeRemovedAgain) {
  const MasonrySpec spec = exampleArch();
  const statics::Assembly design = designOf(spec);
  Simulation s(spec);
  // The top block is the one reaching highest among those that can move.
  const std::string top = s.topBlock();
  double highest = -1e300, topHeight = -1e300;
  std::size_t topFaces = 0;
  for (const statics::Block& b : design.blocks) {
    if (b.fixed) continue;
    for (const Vec3& v : b.vertices) {
      highest = std::max(highest, v[2]);
      if (b.name == top) topHeight = std::max(topHeight, v[2]);
    }
    if (b.name == top) topFaces = b.faces.size();
  }
  ASSERT_GT(topFaces, 0u) << "the top block \"" << top << "\" is one of the design's";
  EXPECT_EQ(topHeight, highest);

  const std::size_t before = s.removableBlocks().size();
  s.removeBlock(top);
  EXPECT_EQ(s.removableBlocks().size(), before - 1);
  for (const std::string& name : s.removableBlocks()) EXPECT_NE(name, top);
  EXPECT_EQ(s.mesh().faces.size(), faceCount(design) - topFaces);
  EXPECT_THROW(s.removeBlock(top), Error) << "removing it twice";
  EXPECT_THROW(s.removeBlock("no such block"), Error);
  for (const statics::Block& b : design.blocks) {
    if (b.fixed) {
      EXPECT_THROW(s.removeBlock(b.name), Error) << "the ground stays";
    }
  }

  // In the viewport's Scene the object shows the simulation; another object is left alone.
  Scene scene;
  MeshData designMesh, other;
  for (const statics::Block& b : design.blocks) {
    const int first = int(designMesh.points.size());
    for (const Vec3& v : b.vertices) designMesh.addPoint(v);
    for (const auto& f : b.faces) {
      std::vector<int> loop;
      for (int v : f) loop.push_back(first + v);
      designMesh.addFace(std::move(loop));
    }
  }
  for (const Vec3& v : design.blocks.front().vertices) other.addPoint(v + Vec3(10, 0, 0));
  for (const auto& f : design.blocks.front().faces) other.addFace(f);
  scene.replaceObject(1, Kind::Block, "Arch", designMesh);
  scene.replaceObject(2, Kind::Block, "Other", other);
  ASSERT_EQ(scene.faces(1).size(), faceCount(design));
  s.step(60);
  showSimulation(scene, 1, s);
  EXPECT_EQ(scene.faces(1).size(), faceCount(design) - topFaces);
  EXPECT_EQ(scene.faces(2).size(), design.blocks.front().faces.size());
  EXPECT_EQ(scene.objects().at(1).name, "Arch");
}

TEST(Simulation, NeverChangesTheDocument) {
  History history(exampleDocument());
  const Document before = history.current();
  const ObjectId id = before.objects.at(0).id;
  {
    Simulation s(std::get<MasonrySpec>(history.current().find(id)->spec));
    s.removeBlock(s.topBlock());
    s.shake();
    s.play();
    s.step(120);
    s.reset();
    s.step(10);
  }
  EXPECT_EQ(history.current(), before);
  EXPECT_FALSE(history.canUndo()) << "a simulation makes no undo step";
  EXPECT_FALSE(history.dirty());
}

TEST(Simulation, PlayingSpendsAtMostTheBudgetPerFrame) {
  // A clock that moves 3 ms each time it is read: every step looks like it took 3 ms.
  double now = 0;
  Simulation s(exampleArch(), [&now] { return now += 0.003; });
  const double dt = s.settings().timeStep;
  EXPECT_EQ(s.advance(0.1), 0) << "paused: no steps";
  s.play();
  // A 0.1 s frame is 24 steps due; with a 10 ms budget it stops after the step that uses it up:
  // the 4th, read at 12 ms.
  EXPECT_EQ(s.advance(0.1, 0.010), 4);
  EXPECT_NEAR(s.time(), 4 * dt, 1e-12);
  // The backlog is dropped: the next short frame takes only what it is due.
  EXPECT_EQ(s.advance(dt * 1.5, 0.010), 1);
  EXPECT_FALSE(s.stepping()) << "3 ms steps fit a 10 ms frame: no worker";
}

TEST(Simulation, AStepLongerThanTheBudgetGoesToTheWorker) {
  // Every step looks like it took 50 ms, five times the frame budget (the clock is read from
  // the worker too).
  std::atomic<long> reads{0};
  Simulation s(exampleArch(), [&reads] { return 0.050 * double(++reads); });
  const double dt = s.settings().timeStep;
  s.play();
  // The first step is timed on the frame (nothing is known yet): one step, over budget.
  EXPECT_EQ(s.advance(1.0 / 60), 1);
  EXPECT_FALSE(s.stepping());
  // From now on a frame hands its steps to the worker and returns at once; a 0.1 s frame covers
  // two 50 ms steps. What is shown stays the last state until they are collected.
  EXPECT_EQ(s.advance(0.1), 0);
  EXPECT_TRUE(s.stepping());
  EXPECT_EQ(s.steps(), 1);
  const std::uint64_t revision = s.revision();
  int collected = 0;
  for (int tries = 0; tries < 5000 && collected == 0; ++tries) {
    collected = s.advance(0.1);
    if (!collected) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_EQ(collected, 2) << "a later frame collects the worker's two steps";
  EXPECT_EQ(s.steps(), 3);
  EXPECT_NEAR(s.time(), 3 * dt, 1e-12);
  EXPECT_GT(s.revision(), revision) << "the view is redrawn with them";
  // A command waits for running steps before it acts: Reset gives the design however it is called.
  EXPECT_EQ(s.advance(0.1), 0);
  s.reset();
  EXPECT_FALSE(s.stepping());
  EXPECT_EQ(s.time(), 0.0);
  for (const sim::Pose& p : s.poses()) EXPECT_EQ(p, sim::Pose{});
}

TEST(Simulation, PlayingKeepsUpWithRealTimeWithinTheBudget) {
  Simulation s(exampleArch(), [] { return 0.0; });  // stepping costs nothing
  const double dt = s.settings().timeStep;
  s.play();
  double last = s.time();
  long steps = 0;
  for (int frame = 0; frame < 60; ++frame) {
    steps += s.advance(1.0 / 60);
    EXPECT_GE(s.time(), last) << "simulated time never goes back";
    last = s.time();
  }
  // One second of frames is one simulated second, to a step (the remainder carries over).
  EXPECT_NEAR(s.time(), 1.0, dt * 1.001);
  EXPECT_EQ(s.steps(), steps);
  s.pause();
  EXPECT_EQ(s.advance(1.0), 0);
  EXPECT_EQ(s.time(), last);
}

TEST(Simulation, TheThinArchWithoutItsKeystoneFalls) {
  // Fig. 14b: a block taken out of an arch brings it down within a couple of seconds.
  Simulation s(exampleArch());
  s.removeBlock(s.topBlock());
  s.step(480);
  EXPECT_GT(s.fallenCount(), 1);
}

TEST(Simulation, PicksTheBlockARayEntersFirst) {
  const MasonrySpec spec = exampleArch();
  const statics::Assembly design = designOf(spec);
  Simulation s(spec);
  const std::string top = s.topBlock();
  int topIndex = -1;
  BBox box;
  for (std::size_t i = 0; i < design.blocks.size(); ++i)
    if (design.blocks[i].name == top) {
      topIndex = int(i);
      for (const Vec3& v : design.blocks[i].vertices) box.add(v);
    }
  ASSERT_GE(topIndex, 0);
  // Straight down onto the middle of the keystone, from well above the model.
  const Vec3 above(box.center()[0], box.center()[1], box.hi[2] + 10);
  EXPECT_EQ(s.blockAt(above, Vec3(0, 0, -1)), topIndex);
  EXPECT_EQ(s.blockAt(above, Vec3(0, 0, 1)), -1) << "looking up, away from the model";
  // With the keystone gone the ray goes through the gap to whatever lies below, never to it.
  s.removeBlock(top);
  EXPECT_NE(s.blockAt(above, Vec3(0, 0, -1)), topIndex);
}

TEST(Simulation, ABadSpecIsReported) {
  MasonrySpec spec = exampleArch();
  spec.model = "no-such-model";
  EXPECT_THROW(Simulation{spec}, Error);
}

}  // namespace
}  // namespace corbel::editor
