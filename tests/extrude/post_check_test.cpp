// The post inter-chain check of Sec. 4.4: after an event, the corners it made must keep the
// active plan simple just above it. A plan that overlaps itself there comes from an earlier
// degenerate configuration (here: a random plan, random73059, saved by the random robustness
// test; the plans used before close now, see below), and the user is told so. The
// oracle that the warning is deserved is the shell itself: its edges do not pair up. (That no closed real footprint or
// example carries the warning is checked in footprints_test.cpp and examples_test.cpp.)
#include "cli_support.h"
#include "core/error.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "extrude/extrude.h"
#include "support.h"
#include "volume_oracle.h"

#include <gtest/gtest.h>

#include <string>

namespace corbel::extrude::test {
namespace {

TEST(PostInterChain, WarnsWhereThePlanOverlapsItselfAboveAnEvent) {
  const Document d =
      loadProject(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/overlap_after_event.corbel").document;
  ASSERT_EQ(d.objects.size(), 1u);
  const ExtrusionResult r = extrude(std::get<ExtrusionSpec>(d.objects[0].spec));
  std::string warning;
  for (const std::string& w : r.shell.warnings)
    if (w.find("overlapped itself") != std::string::npos) warning = w;
  ASSERT_FALSE(warning.empty()) << "no post inter-chain warning";
  // It names where: the event point (x, y, z).
  EXPECT_NE(warning.find("(0.1154"), std::string::npos) << warning;
  EXPECT_NE(warning.find(", -0.5580"), std::string::npos) << warning;
  EXPECT_NE(warning.find(", 2.609"), std::string::npos) << warning;
  EXPECT_GT(unpairedEdges(r.shell), 0u) << "the warned shell closed after all: the check would be crying wolf";
}

// The same plan with the winding rule of Sec. 4.4 (ExtrudeOptions::windingRule): where the check
// fails, the sweep stops just above the event, the plan there is rebuilt as the region it
// winds round at least once (extrude/winding.h), the doubly covered and inverted parts are
// capped, and the sweep goes on. The shell closes without the warning and is a 2-manifold where
// the plain build stays open. Its volume is not the skeleton's: 1.1e-6 under CGAL's straight
// skeleton under its one profile here, where the batch's 10x rebuild agrees with CGAL to 1e-12;
// the region the plan winds round is a valid plan, not the weighted skeleton's (so the rule is off
// by default; docs/extrude.md, "Rebuilding by the winding rule"). The plan it was right on before,
// random34510, no longer overlaps itself (the test after next).
TEST(PostInterChain, TheWindingRuleClosesTheOverlappingPlan) {
  const Document d =
      loadProject(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/overlap_after_event.corbel").document;
  ASSERT_EQ(d.objects.size(), 1u);
  const auto& spec = std::get<ExtrusionSpec>(d.objects[0].spec);
  ExtrudeOptions options;
  options.windingRule = true;
  const ExtrusionResult r = extrude(spec, nullptr, options);
  for (const std::string& w : r.shell.warnings) ADD_FAILURE() << "warning: " << w;
  ASSERT_EQ(unpairedEdges(r.shell), 0u);
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "rebuilt", toMeshData(r.shell, spec, spec.material));
  EXPECT_TRUE(scene.validate(1).closedManifold());
  // Without the rule the same build stays open (the test above).
  EXPECT_GT(unpairedEdges(extrude(spec).shell), 0u);
}

// corbel-cli extrude --winding-rule reaches the same repair through the batch: the first build
// closes with the library's volume, where without the flag it fails.
TEST(PostInterChain, CorbelCliExtrudeTakesTheWindingRuleOnRequest) {
  auto stats = [](const std::string& extra) {
    return cliExtrudeStats("tests/data/extrude/overlap_after_event.corbel", " --no-retry" + extra);
  };
  const auto plain = stats("");
  EXPECT_TRUE(plain.contains("error")) << plain;
  const auto ruled = stats(" --winding-rule");
  ASSERT_FALSE(ruled.contains("error")) << ruled;
  EXPECT_TRUE(ruled["watertight"].get<bool>());
  EXPECT_TRUE(ruled["manifold"].get<bool>());
  const Document d =
      loadProject(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/overlap_after_event.corbel").document;
  ExtrudeOptions options;
  options.windingRule = true;
  const ExtrusionResult r = extrude(std::get<ExtrusionSpec>(d.objects[0].spec), nullptr, options);
  EXPECT_EQ(ruled["volume"].get<double>(), measure(r.shell).volume);
}

// The plan the test above used to be warned on (random8674, a skyline perturbed by 1e-7 m):
// since corners that an event made at a point no longer meet again there
// (EqualAngles.CornersMadeAtAPointDoNotMeetAgainThere), it closes unwarned, and its roof
// projects onto the footprint exactly once.
// The plan the test above was warned on next (random69086) closes unwarned too, since racing
// corners predict events within δ1 of their making and two-edge ridge loops close at once
// (RegressionCases.PerturbedRacingCornersCloseAsTheUnperturbedPlan). So does the next
// (random34510), since a corner of two walls of one angle whose lines meet beyond an end of its
// edges stays where its event made it (Conditioning.AStraightCornerStaysWhereItsLinesMeetPastAnEnd).
TEST(PostInterChain, APlanThatUsedToOverlapItselfClosesWithTheProjectionIdentity) {
  for (const char* file :
       {"former_overlap_closes.corbel", "former_overlap_closes_too.corbel", "random/random34510.corbel"}) {
    SCOPED_TRACE(file);
    const Document d = loadProject(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/" + file).document;
    ASSERT_EQ(d.objects.size(), 1u);
    const auto& spec = std::get<ExtrusionSpec>(d.objects[0].spec);
    const ExtrusionResult r = extrude(spec);
    for (const std::string& w : r.shell.warnings) ADD_FAILURE() << "warning: " << w;
    EXPECT_EQ(unpairedEdges(r.shell), 0u);
    double footprint = 0, projected = 0;
    for (const auto& l : spec.loops) footprint += shoelace(l.points);
    for (const ShellFace& f : r.shell.faces)
      if (!f.base) projected += faceArea(r.shell, f) * f.normal[2];
    EXPECT_NEAR(projected, footprint, 1e-7 * footprint);
  }
}

// A random plan (random13237 of the robustness run) whose active plan comes to overlap itself
// along a line: two chains share a wall in the same direction, and every relinking of their
// four edges leaves a corner on the other chain's wall, a sliver (1e-7 m) higher. The sweep
// used to crawl up through hundreds of thousands of such events until its time limit; it now
// stops after 64 rounds with a reason naming the point. (Should a later kernel resolve the
// overlap, a closed shell is the better answer and passes too; a time-out never does.)
TEST(PostInterChain, AnEventCycleStopsWithAReasonInsteadOfRunningOut) {
  const Document d = loadProject(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/event_cycle.corbel").document;
  ASSERT_EQ(d.objects.size(), 1u);
  try {
    const ExtrusionResult r = extrude(std::get<ExtrusionSpec>(d.objects[0].spec), nullptr, 30.0);
    EXPECT_EQ(unpairedEdges(r.shell), 0u) << "neither closed nor stopped";
  } catch (const corbel::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("event cycle at (48.7"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace corbel::extrude::test
