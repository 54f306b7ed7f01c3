// Conditioning of the sweep's geometry between almost colinear edges, where two lines meet
// at a sine of 1e-8 and their meeting point is 1e8 times as sensitive as the lines.
#include "core/project_io.h"
#include "extrude/extrude.h"
#include "extrude/tolerances.h"
#include "saved_plan_checks.h"
#include "shell_checks.h"
#include "skeleton_oracle.h"
#include "support.h"
#include "volume_oracle.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace corbel::extrude::test {
namespace {

// What every shell here must be: closed, unwarned, every face simple in its plane.
void expectCleanShell(const ExtrusionResult& r, const ExtrusionSpec& spec) {
  EXPECT_EQ(unpairedEdges(r.shell), 0u);
  for (const auto& w : r.shell.warnings) ADD_FAILURE() << "warning: " << w;
  EXPECT_EQ(shellGeometryProblem(r.shell, spec), "");
}

// A perturbed heptagon from the random robustness run (random28836): its corner v4 turns by
// 1.1e-8 rad, and its profile (a wall, a steep segment, a 35° roof) changes direction twice.
// At each change the new planes were anchored at corners computed on the old lines; the
// kinked corner's residual off its line (1e-8 m, Cramer's rule) moved it 2 m along its wall
// by the second change, and the roof did not close. The oracle: the same plan without the
// kink (a triangle of 8e-8 m² less) gives the same roof.
TEST(Conditioning, AnAlmostStraightCornerDoesNotDriftThroughProfileChanges) {
  const std::vector<Vec2> kinked{
      Vec2(5.726730863878337, 2.788329535356239),   Vec2(4.036525708989348, 3.688491560656181),
      Vec2(-0.8822017921323752, 6.308085926298023), Vec2(-6.271961561710608, 1.1102819714928482),
      Vec2(-4.332811163817222, -2.872386664217829), Vec2(-2.9940836300024705, -5.621893877041154),
      Vec2(4.4215161310218205, -4.5848034933385495)};
  std::vector<Vec2> straight = kinked;
  straight.erase(straight.begin() + 4);
  Profile p;
  p.name = "p0";
  p.points = {Vec2(0.0, 0.0), Vec2(0.0, 3.104247493283743), Vec2(0.6142226958933118, 4.496182974743258),
              Vec2(4.394829214215852, 7.1624563175236045)};
  const ExtrusionResult a = extrude(uniformSpec({kinked}, p));
  const ExtrusionResult b = extrude(uniformSpec({straight}, p));
  for (const auto* r : {&a, &b}) {
    EXPECT_EQ(unpairedEdges(r->shell), 0u);
    for (const auto& w : r->shell.warnings) ADD_FAILURE() << "warning: " << w;
  }
  const ShellMeasures ma = measure(a.shell), mb = measure(b.shell);
  EXPECT_NEAR(ma.maxHeight, mb.maxHeight, 1e-7 * mb.maxHeight);
  EXPECT_NEAR(ma.volume, mb.volume, 1e-7 * mb.volume);
  EXPECT_NEAR(ma.roofArea, mb.roofArea, 1e-7 * mb.roofArea);
  EXPECT_NEAR(ma.wallArea, mb.wallArea, 1e-7 * mb.wallArea);
  // And the roof projects onto the footprint once (to 1e-8: the sweep joins points within
  // δ2 = 1e-8 of the plan size, and the kink is far below that).
  double projected = 0;
  for (const ShellFace& f : a.shell.faces)
    if (!f.base) projected += faceArea(a.shell, f) * f.normal[2];
  EXPECT_NEAR(projected, shoelace(kinked), 1e-8 * shoelace(kinked));
}

// A perturbed orthogonal plan from the random run (random20886, one profile on every edge): at
// 18.93 m a split leaves a corner between two edges 2.5e-8 rad from antiparallel, racing at
// 1.8e7 m per m of rise along a ridge toward the far end of its edge, where that edge meets a
// second wall of its own line 5e-8 rad off. Its path's crossing with that wall's plane is
// ill-conditioned (it fell 6 m short and below the corner's height), and the corner raced past
// the edge's end: the roof closed 3.28 m too high with a face crossing itself. The oracle: CGAL's
// straight skeleton of the same plan under the same profile; the top may lie above it by no
// more than the kernel's event height tolerance δ1, and every face must be simple.
TEST(Conditioning, ARacingCornerStopsAtTheFarEndOfItsEdge) {
  const ExtrusionSpec spec = savedSpec("tests/data/extrude/random/random20886.corbel");
  const ExtrusionResult r = extrude(spec);
  expectCleanShell(r, spec);
  std::vector<std::vector<Vec2>> loops;
  for (const auto& l : spec.loops) loops.push_back(l.points);
  const double cgal = cgalHeightUnderProfile(loops, spec.profiles[spec.loops[0].profile[0]].points);
  EXPECT_LE(r.shell.maxHeight, cgal + Tolerances::forScale(r.scale).height) << "CGAL's skeleton: " << cgal << " m";
}

// A perturbed orthogonal plan from the random run (random1023, three profiles, gables among
// them): where a roof between two gable walls of one line closes at 1.29 m, the walls (1.4e-7
// rad apart, above the merge sine) become neighbours at a point both lines pass within δ2; their
// lines meet 1.9 m away, past the far end of the shorter wall, and the corner between them,
// recomputed from the lines, jumped there: the gable's top ran 1.9 m past its corner and back, a
// face not simple in its plane. Kept at its event point, moving with the walls as between
// parallel ones, the corner leaves every face simple. The oracle: the same plan unperturbed
// (its exact axis-parallel plan, volume_oracle.h) gives the same volume and roof area to 1e-6.
TEST(Conditioning, AStraightCornerStaysWhereItsLinesMeetPastAnEnd) {
  const ExtrusionSpec spec = savedSpec("tests/data/extrude/straight_corner_past_an_end.corbel");
  const ExtrusionResult r = extrude(spec);
  expectCleanShell(r, spec);
  const VolumeOracle o = independentVolume(spec);
  ASSERT_EQ(o.kind, VolumeOracle::Unperturbed);
  const ShellMeasures m = measure(r.shell);
  EXPECT_NEAR(m.volume, o.volume, 1e-6 * o.volume);
  EXPECT_NEAR(m.roofArea, o.roofArea, 1e-6 * o.roofArea);
}

// Perturbed orthogonal plans from the random run where an event leaves a corner between two
// edges of almost one line whose lines, both passing within δ2 of the event, meet far from it:
// the corner starts there, and its path begins with a level step at the event's height
// (Sweeper::stepToWhereItStarts). Without the step the arc ran straight from the event to where
// the corner ended, across the top of one of its faces. random56778: two walls 1.2e-7 rad apart
// at 5.75 m, the corner 0.76 m along them; a wall's top ran out past its end and back.
// random84790: two roofs of one line 1.1e-7 rad apart at the ridge height 8.67 m, the corner
// 3.0 m along them; the roof face ran past its ridge into a flap of reversed orientation. The
// oracle: the same plans unperturbed (volume_oracle.h) give the same volume and roof area.
TEST(Conditioning, ACornerStartingAwayFromItsEventStepsThere) {
  expectCleanAndAgreeing("tests/data/extrude/corner_starts_away_on_a_wall_top.corbel", VolumeOracle::Unperturbed);
  expectCleanAndAgreeing("tests/data/extrude/corner_starts_away_below_a_ridge.corbel", VolumeOracle::Unperturbed);
}

// random89383: three corners between gable walls of one line (1.2e-7 to 2.2e-7 rad apart) start
// 0.76 to 1.98 m from their events at 0.99 m, and the gable's face had a notch its rake crossed.
// Stepped, the shell is closed and every face simple. (Its first build takes other branches than
// its unperturbed plan at near-colinear wall-and-roof corners, 3.9 % of the volume, as 1,700 of
// the random run's first builds do: docs/extrude.md, "Known limits"; so no volume oracle here.)
TEST(Conditioning, GableCornersStartingAwayFromTheirEventsStepThere) {
  const ExtrusionSpec spec = savedSpec("tests/data/extrude/corner_starts_away_at_a_gable.corbel");
  expectCleanShell(extrude(spec), spec);
}

}  // namespace
}  // namespace corbel::extrude::test
