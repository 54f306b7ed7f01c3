// Rebuilding failed shells with wider tolerances (extrude/batch.h, docs/extrude.md "Rebuilding
// with wider tolerances"). The saved plans under tests/data/extrude/rebuilt/ are random plans
// (RandomRobustness) whose first build failed, a few of each failure class: each must still
// fail at 1× (else it tests nothing), be rebuilt and accepted with a warning, and agree with an
// independent volume (volume_oracle.h: CGAL's skeleton under the one profile, or the
// unperturbed orthogonal plan). A rebuild that wider rebuilds contradict is refused; bad input
// is never rebuilt; a building that passes is built once and keeps its shell.
#include "cli_support.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "core/scene_sync.h"
#include "extrude/batch.h"
#include "extrude/kernel.h"
#include "shell_checks.h"
#include "skeleton_oracle.h"
#include "support.h"
#include "volume_oracle.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace corbel::extrude::test {
namespace {

ExtrusionSpec saved(const std::string& name) { return savedSpec("tests/data/extrude/" + name); }

BatchResult buildOne(const ExtrusionSpec& spec, bool retry, bool keepMesh = false) {
  BatchOptions options;
  options.jobs = 1;
  options.keepMeshes = keepMesh;
  if (!retry) options.retryFactors.clear();
  return extrudeBatch({{"case", spec, ""}}, options)[0];
}

bool warned(const BatchResult& r, const std::string& text) {
  for (const std::string& w : r.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

// firstBuild: a phrase of the first build's error or warnings that puts it in its class
// (scripts/extrude_failure_classes.py), checked so the case keeps testing what it is named for.
void expectRebuiltAndRight(const std::string& name, const std::string& firstBuild, VolumeOracle::Kind oracleKind) {
  SCOPED_TRACE(name);
  const ExtrusionSpec spec = saved(name);
  const BatchResult first = buildOne(spec, false);
  ASSERT_FALSE(first.ok) << "the first build passes now: the case no longer needs a rebuild";
  EXPECT_TRUE(first.error.find(firstBuild) != std::string::npos || warned(first, firstBuild))
      << "not in its class any more: " << first.error;
  const BatchResult r = buildOne(spec, true);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.toleranceFactor, 10.0);
  EXPECT_EQ(r.builds, 4) << "the first build, then 10×, 100× and 1000×";
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings[0].rfind("rebuilt with 10× tolerances (the first build failed: " + first.error, 0), 0u)
      << r.warnings[0];
  EXPECT_TRUE(r.watertight && r.manifold);
  const VolumeOracle o = independentVolume(spec);
  ASSERT_EQ(o.kind, oracleKind) << "the case's oracle does not apply";
  EXPECT_NEAR(r.measures.volume, o.volume, 1e-6 * o.volume);
  if (o.kind == VolumeOracle::Unperturbed) {
    EXPECT_NEAR(r.measures.roofArea, o.roofArea, 1e-6 * o.roofArea);
  }
  // The roof still projects onto the footprint once (vertices moved by at most the wider δ2).
  const ExtrusionResult er = extrude(spec, nullptr, ExtrudeOptions{0.0, r.toleranceFactor, false});
  double projected = 0, footprint = 0;
  for (const ShellFace& f : er.shell.faces)
    if (!f.base) projected += faceArea(er.shell, f) * f.normal[2];
  for (const auto& l : spec.loops) footprint += shoelace(l.points);
  EXPECT_NEAR(projected, footprint, 1e-6 * footprint);
}

// The oracle itself: under walls 3 m high and a 45° hip, a 10 × 6 rectangle holds
// 60 · 3 + b²(3a − b)/12 with a = 10, b = 6; under a two-slope profile an L plan holds what the
// kernel's first build gives (the kernel is checked against CGAL at one pitch elsewhere).
TEST(Rebuilt, TheSkeletonVolumeUnderAProfileMatchesHandAndKernel) {
  EXPECT_NEAR(cgalVolumeUnderProfile({rectangle(10, 6)}, {{0, 0}, {0, 3}, {4, 7}}), 180 + 36.0 * 24 / 12, 1e-9);
  Profile two;
  two.points = {{0, 0}, {0, 2.5}, {1.2, 4.1}, {3.0, 4.9}};
  const ExtrusionSpec spec =
      uniformSpec({{Vec2(0, 0), Vec2(12, 0), Vec2(12, 5), Vec2(5, 5), Vec2(5, 14), Vec2(0, 14)}}, two);
  const double kernel = measure(extrude(spec).shell).volume;
  EXPECT_NEAR(cgalVolumeUnderProfile({spec.loops[0].points}, two.points), kernel, 1e-9 * kernel);
  EXPECT_EQ(independentVolume(spec).kind, VolumeOracle::Cgal);
}

TEST(Rebuilt, DivergedSweepsCloseWithWiderTolerances) {
  expectRebuiltAndRight("rebuilt/random21797.corbel", "diverged", VolumeOracle::Cgal);
  expectRebuiltAndRight("rebuilt/random27143.corbel", "diverged", VolumeOracle::Cgal);
  expectRebuiltAndRight("rebuilt/random14968.corbel", "diverged", VolumeOracle::Unperturbed);
}

TEST(Rebuilt, CappedRoofsCloseWithWiderTolerances) {
  expectRebuiltAndRight("rebuilt/random26267.corbel", "did not close", VolumeOracle::Cgal);
  expectRebuiltAndRight("rebuilt/random28647.corbel", "did not close", VolumeOracle::Cgal);
  expectRebuiltAndRight("rebuilt/random10685.corbel", "did not close", VolumeOracle::Unperturbed);
}

TEST(Rebuilt, ShellsLeftOpenWithoutAWarningCloseWithWiderTolerances) {
  expectRebuiltAndRight("rebuilt/random28832.corbel", "not closed", VolumeOracle::Cgal);
  expectRebuiltAndRight("rebuilt/random12886.corbel", "not closed", VolumeOracle::Unperturbed);
}

TEST(Rebuilt, NonManifoldShellsCloseWithWiderTolerances) {
  expectRebuiltAndRight("rebuilt/random2986.corbel", "2-manifold", VolumeOracle::Unperturbed);
}

// random84957 was left non-manifold by its first build while priorities were taken at each
// stage's base (a wall's, for edges long on their roof slopes); with the priority of the
// segment at the event it closes at once, as its unperturbed plan does.
TEST(Rebuilt, FormerNonManifoldCaseClosesAtItsFirstBuild) {
  const ExtrusionSpec spec = saved("rebuilt/random84957.corbel");
  const BatchResult first = buildOne(spec, false);
  ASSERT_TRUE(first.ok) << first.error;
  EXPECT_TRUE(first.warnings.empty());
  const VolumeOracle o = independentVolume(spec);
  ASSERT_EQ(o.kind, VolumeOracle::Unperturbed);
  EXPECT_NEAR(first.measures.volume, o.volume, 1e-6 * o.volume);
  EXPECT_NEAR(first.measures.roofArea, o.roofArea, 1e-6 * o.roofArea);
}

// random57969 and random85200 drop a piece of a face at tracing (a loop of no area turned the
// wrong way, outside its face: "could not be placed") and were left open, a face beside it
// running out to a corner and back to a second vertex 7e-7 m from the first (random57969: a
// roof's, 2.6 m up to the apex; random85200: a wall's, up its edge). With those two welded (weldLoopCorners) the spur
// goes and the shell closes at its first build, keeping the warning, and agrees with its oracle: CGAL's skeleton for
// random57969, the unperturbed plan for random85200.
TEST(Rebuilt, FormerFacePlacementCasesCloseAtTheirFirstBuild) {
  for (const auto& [name, kind] : {std::pair{"rebuilt/random57969.corbel", VolumeOracle::Cgal},
                                   std::pair{"random/random85200.corbel", VolumeOracle::Unperturbed}}) {
    SCOPED_TRACE(name);
    const ExtrusionSpec spec = saved(name);
    const BatchResult first = buildOne(spec, false);
    ASSERT_TRUE(first.ok) << first.error;
    EXPECT_TRUE(first.watertight && first.manifold);
    EXPECT_EQ(first.warnings,
              std::vector<std::string>{"a face boundary piece could not be placed (hole outside its face)"});
    EXPECT_EQ(shellGeometryProblem(extrude(spec).shell, spec), "");
    const VolumeOracle o = independentVolume(spec);
    ASSERT_EQ(o.kind, kind);
    EXPECT_NEAR(first.measures.volume, o.volume, 1e-6 * o.volume);
    if (o.kind == VolumeOracle::Unperturbed) {
      EXPECT_NEAR(first.measures.roofArea, o.roofArea, 1e-6 * o.roofArea);
    }
  }
}

// random70947 and random21457 close as 2-manifolds at their first build, yet a face of each
// runs past its own side or its ridge and back: a lobe turned the wrong way round, which other
// faces close (docs/extrude.md, "Known limits"). The batch takes such a build as failed; the
// 10× rebuild has simple faces, crosses nowhere, and agrees with the unperturbed plan.
TEST(Rebuilt, ShellsWithAFaceCrossingItselfAreRebuilt) {
  for (const char* name : {"random/random70947.corbel", "random/random21457.corbel"}) {
    SCOPED_TRACE(name);
    const ExtrusionSpec spec = saved(name);
    const ExtrusionResult first = extrude(spec);
    ASSERT_EQ(unpairedEdges(first.shell), 0u) << "the first build is open now: the case tests something else";
    ASSERT_NE(faceLoopProblem(first.shell), "") << "the first build's faces are simple now: the case tests nothing";
    expectRebuiltAndRight(name, "crosses itself", VolumeOracle::Unperturbed);
    const BatchResult r = buildOne(spec, true);
    const ExtrusionResult kept = extrude(spec, nullptr, ExtrudeOptions{0.0, r.toleranceFactor, false});
    EXPECT_EQ(shellGeometryProblem(kept.shell, spec), "");
  }
}

TEST(Rebuilt, PlansThatOverlappedThemselvesCloseWithWiderTolerances) {
  // random73059, also the post inter-chain check's case (post_check_test.cpp: it stays warned
  // and open at 1×).
  expectRebuiltAndRight("overlap_after_event.corbel", "overlapped itself", VolumeOracle::Cgal);
}

// The Scene's builder run on a saved project's one object, whose first build fails: the Scene
// shows the batch's accepted 10× rebuild, warned with the first build's error, closed, with the
// batch's faces and vertices.
void expectTheSceneShowsTheRebuild(const Document& d, SceneSync& sync, Scene& scene) {
  const ObjectId id = d.objects.at(0).id;
  const ExtrusionSpec& spec = std::get<ExtrusionSpec>(d.objects.at(0).spec);
  const BatchResult first = buildOne(spec, false);
  ASSERT_FALSE(first.ok) << "the first build passes now: the case tests nothing";
  registerKernel(sync);
  sync.update(d, scene);
  const SceneSync::Status& st = sync.status().at(id);
  ASSERT_TRUE(st.error.empty()) << st.error;
  ASSERT_FALSE(st.warnings.empty());
  EXPECT_EQ(st.warnings[0].rfind("rebuilt with 10× tolerances (the first build failed: " + first.error, 0), 0u)
      << st.warnings[0];
  const ValidityReport v = scene.validate(id);
  EXPECT_TRUE(v.closedManifold()) << (v.problems().empty() ? "" : v.problems()[0]);
  const BatchResult r = buildOne(spec, true, true);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(v.faces, r.meshFaces);
  EXPECT_EQ(v.vertices, r.meshVertices);
}

Document savedProject(const std::string& name) {
  return loadProject(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/" + name).document;
}

// The Scene's builder (the editor, `corbel-cli render`) rebuilds as the batch does: a plan whose
// first shell is left open shows the batch's accepted rebuild, with its warning, closed.
TEST(Rebuilt, TheSceneBuilderShowsTheBatchsRebuild) {
  const Document d = savedProject("rebuilt/random28832.corbel");
  ASSERT_GT(unpairedEdges(extrude(std::get<ExtrusionSpec>(d.objects.at(0).spec)).shell), 0u)
      << "the first build closes now: the case tests nothing";
  SceneSync sync;
  Scene scene;
  expectTheSceneShowsTheRebuild(d, sync, scene);
  // Bad input is refused by the builder with the kernel's message, never rebuilt.
  const ObjectId id = d.objects.at(0).id;
  Document bad = d;
  auto& badSpec = std::get<ExtrusionSpec>(bad.objects.at(0).spec);
  badSpec.loops[0].points[1] = badSpec.loops[0].points[0];
  sync.update(bad, scene);
  EXPECT_NE(sync.status().at(id).error.find("loops[0]"), std::string::npos) << sync.status().at(id).error;
}

// A first shell that closes around a face crossing itself goes to the batch as an open one
// does, and the Scene shows the rebuild.
TEST(Rebuilt, TheSceneBuilderRebuildsAFaceCrossingItself) {
  const Document d = savedProject("random/random70947.corbel");
  const ExtrusionResult first = extrude(std::get<ExtrusionSpec>(d.objects.at(0).spec));
  ASSERT_EQ(unpairedEdges(first.shell), 0u);
  ASSERT_NE(faceLoopProblem(first.shell), "") << "the first build's faces are simple now: the case tests nothing";
  SceneSync sync;
  Scene scene;
  expectTheSceneShowsTheRebuild(d, sync, scene);
}

// random15198: the 10× rebuild alone closes, but 1.4e-3 away from the unperturbed plan's
// volume, and the 100× rebuild disagrees with it by as much. The disagreement refuses it, and
// the failure says so.
TEST(Rebuilt, ARebuildThatAWiderOneContradictsIsRefused) {
  const ExtrusionSpec spec = saved("rebuilt/random15198.corbel");
  const VolumeOracle o = independentVolume(spec);
  ASSERT_EQ(o.kind, VolumeOracle::Unperturbed);
  BatchOptions tenOnly;
  tenOnly.jobs = 1;
  tenOnly.retryFactors = {10.0};  // one rebuild, nothing to check it against
  const BatchResult alone = extrudeBatch({{"case", spec, ""}}, tenOnly)[0];
  ASSERT_TRUE(alone.ok) << alone.error;
  EXPECT_GT(std::abs(alone.measures.volume - o.volume), 1e-4 * o.volume) << "the 10× shell was right after all";
  const BatchResult r = buildOne(spec, true);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.toleranceFactor, 1.0);
  EXPECT_EQ(r.builds, 3) << "stopped at the first disagreement (100×)";
  EXPECT_NE(r.error.find("10× and 100× disagree"), std::string::npos) << r.error;
  EXPECT_FALSE(warned(r, "rebuilt with"));
}

TEST(Rebuilt, BadInputIsNeverRebuilt) {
  // A bow tie (self-intersecting) and a zero-length edge: plan_check refuses both, whatever
  // the tolerances.
  const Profile hip = hipProfile(30 * kDeg);
  for (const auto& loop : {std::vector<Vec2>{{0, 0}, {10, 10}, {10, 0}, {0, 10}},
                           std::vector<Vec2>{{0, 0}, {10, 0}, {10, 0}, {10, 6}, {0, 6}}}) {
    const BatchResult r = buildOne(uniformSpec({loop}, hip), true);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.error.rfind("loops[0]", 0), 0u) << r.error;
    EXPECT_EQ(r.builds, 1);
    EXPECT_EQ(r.toleranceFactor, 1.0);
    EXPECT_EQ(r.error.find("rebuilt"), std::string::npos) << r.error;
  }
}

TEST(Rebuilt, APlanThatPassesIsBuiltOnceAndKeepsItsShell) {
  const std::vector<ExtrusionSpec> specs{
      uniformSpec({{Vec2(0, 0), Vec2(12, 0), Vec2(12, 5), Vec2(5, 5), Vec2(5, 14), Vec2(0, 14)}},
                  hipProfile(40 * kDeg)),
      uniformSpec({rectangle(20, 16), reversed(rectangle(8, 6, 6, 5))}, wallAndRoofProfile(3, 35 * kDeg)),
      saved("corners_meet_again.corbel")};
  for (const ExtrusionSpec& spec : specs) {
    const BatchResult with = buildOne(spec, true, true), without = buildOne(spec, false, true);
    ASSERT_TRUE(with.ok) << with.error;
    EXPECT_EQ(with.builds, 1);
    EXPECT_EQ(with.toleranceFactor, 1.0);
    EXPECT_FALSE(warned(with, "rebuilt"));
    EXPECT_EQ(with.warnings, without.warnings);
    // The same shell, bit for bit, as with rebuilds switched off and as the kernel's own.
    EXPECT_EQ(with.mesh.points, without.mesh.points);
    EXPECT_EQ(with.mesh.faces, without.mesh.faces);
    const MeshData direct = toMeshData(extrude(spec).shell, spec, spec.material);
    EXPECT_EQ(with.mesh.points, direct.points);
    EXPECT_EQ(with.mesh.faces, direct.faces);
  }
}

// A window whose first rebuild fails outright moves one factor up (a failure says nothing about
// the answer; a disagreement would refuse). random24332, a perturbed orthogonal plan saved by the
// random test: its first build (a loop capped flat) and its 10× rebuild are left open; 100×,
// 1000× and 10000× close and agree, and the 100× shell is its unperturbed plan's within 1e-6
// (volume_oracle.h).
TEST(Rebuilt, AWindowWhoseFirstRebuildFailsMovesUpAFactor) {
  const ExtrusionSpec spec = saved("random/random24332.corbel");
  ASSERT_FALSE(buildOne(spec, false).ok) << "the first build passes now";
  BatchOptions tenOnly;
  tenOnly.jobs = 1;
  tenOnly.retryFactors = {10.0};
  const BatchResult ten = extrudeBatch({{"case", spec, ""}}, tenOnly)[0];
  ASSERT_FALSE(ten.ok) << "the 10× rebuild closes now: the case no longer moves the window";
  const BatchResult r = buildOne(spec, true);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.toleranceFactor, 100.0);
  EXPECT_EQ(r.builds, 5) << "the first build, then 10×, 100×, 1000× and 10000×";
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].find("; the 10× rebuild failed too; rebuilds with 1000× and 10000× agree"), std::string::npos)
      << r.warnings[0];
  const VolumeOracle o = independentVolume(spec);
  ASSERT_EQ(o.kind, VolumeOracle::Unperturbed);
  EXPECT_NEAR(r.measures.volume, o.volume, 1e-6 * o.volume);
  EXPECT_NEAR(r.measures.roofArea, o.roofArea, 1e-6 * o.roofArea);
}

// corbel-cli extrude goes through the batch: it rebuilds, says so in --stats, and --no-retry
// gives the first build's failure.
TEST(Rebuilt, CorbelCliExtrudeRebuildsAndNoRetryDoesNot) {
  auto stats = [](const std::string& extra) {
    return cliExtrudeStats("tests/data/extrude/rebuilt/random21797.corbel", extra);
  };
  const auto rebuilt = stats("");
  EXPECT_FALSE(rebuilt.contains("error")) << rebuilt;
  EXPECT_EQ(rebuilt["tolerance_factor"], 10.0);
  EXPECT_EQ(rebuilt["builds"], 4);
  ASSERT_FALSE(rebuilt["warnings"].empty());
  EXPECT_EQ(rebuilt["warnings"][0].get<std::string>().rfind("rebuilt with 10× tolerances", 0), 0u);
  const auto first = stats(" --no-retry");
  EXPECT_TRUE(first.contains("error")) << first;
  EXPECT_EQ(first["tolerance_factor"], 1.0);
  EXPECT_EQ(first["builds"], 1);
}

}  // namespace
}  // namespace corbel::extrude::test
