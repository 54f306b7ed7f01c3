// The ambiguity of colinear neighbours (Sec. 4.8, Fig. 22): where edges of different angles come
// to lie in one line, the one of higher priority takes the whole line. Priorities are those of
// the segments the edges are on at that height, so where a stage boundary falls cannot matter.
// Oracles: height fields of convex plans (the roof over a convex region is the lower envelope
// of its edges' profiles), integrated on a fine grid, and heights by hand.
#include "core/project_io.h"
#include "core/scene.h"
#include "shell_checks.h"
#include "support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>

namespace corbel::extrude::test {
namespace {

void expectClosed(const ExtrusionSpec& spec, const ExtrusionResult& r) {
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, spec, "plaster"));
  const ValidityReport v = scene.validate(1);
  for (const auto& p : v.problems()) ADD_FAILURE() << p;
  EXPECT_EQ(v.euler, 2);
  EXPECT_EQ(shellGeometryProblem(r.shell, spec), "");
}

// Highest point of the faces a profile segment made on input edge `edge` of loop 0.
double topOf(const ExtrusionResult& r, int edge, int profile, int segment) {
  double top = -1;
  for (const ShellFace& f : r.shell.faces)
    if (f.step < 0 && f.sourceLoop == 0 && f.sourceEdge == edge && f.profile == profile && f.segment == segment)
      for (const auto& l : f.loops)
        for (int v : l) top = std::max(top, r.shell.points[v][2]);
  return top;
}

// Fig. 22: two canted bays on the front of a 10 × 6 house (walls 3 m, 45°). Each bay is 3 m
// wide at the wall, 1 m deep, its front 1 m wide; its walls rise 1.5 m, then 45°. The bay's
// front reaches the facade at 2.5 m, exactly as its canted sides shrink to nothing: two
// ambiguous events at one height, a 45° bay roof in line with a vertical wall. Maximising, the
// wall goes on (the bay roofs end at the facade); minimising, the bay roof's plane takes the
// whole facade from 2.5 m up.
ExtrusionSpec twoBays(Priority priority) {
  ExtrusionSpec s;
  s.priority = priority;
  s.profiles = {polyline("main", {{0, 0}, {0, 3}, {1, 4}}, {"wall", "roof"}),
                polyline("bay", {{0, 0}, {0, 1.5}, {1, 2.5}}, {"bay wall", "bay roof"})};
  s.loops.push_back({rectangle(10, 6), {0, 0, 0, 0}});
  for (double at : {2.5, 7.5}) {
    PlanStep b;
    b.shape = StepShape::Bay;
    b.anchor = {0, 0, true, at, 0.0};
    b.width = 3;
    b.depth = 1;
    b.cant = 1;
    b.frontProfile = b.sideProfile = 1;
    s.steps.push_back(b);
  }
  return s;
}

// The bays' volume below the facade (y < 0): each bay's roof is the lower envelope of its
// front and canted sides, 1.5 m plus the distance in from each; the facade stands still.
double bayHeight(double x, double y) {
  if (y >= 0 || y < -1) return 0;
  for (double c : {2.5, 7.5}) {
    const double u = x - c;  // across the bay
    const double front = y + 1, left = ((u + 1.5) + y) / std::sqrt(2.0), right = ((1.5 - u) + y) / std::sqrt(2.0);
    if (left < 0 || right < 0) continue;
    return 1.5 + std::min({front, left, right});
  }
  return 0;
}

double twoBaysVolume(double facadeWall) {
  // The house: a convex plan, so its top is the least of its edges' heights at each point.
  const double house = integrate(0, 10, 0, 6, 2000, 1200, [&](double x, double y) {
    return std::min({3 + x, 13 - x, 9 - y, facadeWall + y});
  });
  return house + integrate(0, 10, -1, 0, 4000, 400, bayHeight);
}

TEST(Priority, Figure22BothOutcomes) {
  const double maxVolume = twoBaysVolume(3.0), minVolume = twoBaysVolume(2.5);
  ASSERT_GT(maxVolume - minVolume, 0.03 * maxVolume) << "the two outcomes must be far apart";
  {
    SCOPED_TRACE("maximise volume");
    const ExtrusionSpec s = twoBays(Priority::MaximiseVolume);
    const ExtrusionResult r = extrude(s);
    EXPECT_TRUE(r.shell.warnings.empty());
    expectClosed(s, r);
    EXPECT_NEAR(measure(r.shell).volume, maxVolume, 1e-4 * maxVolume);
    EXPECT_NEAR(topOf(r, 0, 0, 0), 3.0, 1e-9) << "the facade's wall goes on to 3 m";
  }
  {
    SCOPED_TRACE("minimise volume");
    const ExtrusionSpec s = twoBays(Priority::MinimiseVolume);
    const ExtrusionResult r = extrude(s);
    EXPECT_TRUE(r.shell.warnings.empty());
    expectClosed(s, r);
    EXPECT_NEAR(measure(r.shell).volume, minVolume, 1e-4 * minVolume);
    EXPECT_NEAR(topOf(r, 0, 0, 0), 2.5, 1e-9) << "the facade's wall ends where the bay roofs reach it";
    EXPECT_LT(topOf(r, 0, 0, 1), 0) << "no main roof on the facade: the bays' roof took it";
  }
  // Manual: the bay's roof segment tagged high wins as minimising does; tagged low, the wall
  // wins as maximising does.
  for (const char* tag : {"high", "low"}) {
    SCOPED_TRACE(std::string("manual, bay roof ") + tag);
    ExtrusionSpec s = twoBays(Priority::Manual);
    s.profiles[1].tags[1] = tag;
    const ExtrusionResult r = extrude(s);
    EXPECT_TRUE(r.shell.warnings.empty());
    expectClosed(s, r);
    const double expect = std::string(tag) == "high" ? minVolume : maxVolume;
    EXPECT_NEAR(measure(r.shell).volume, expect, 1e-4 * expect);
  }
}

// The Fig. 1 house: minimising, the bay's roof takes the facade at the bay's top, so the
// dormers anchored on the facade's wall at 5.5 m find no wall and are not placed; maximising,
// they are.
TEST(Priority, Figure1HouseMinimisedLosesItsDormersToTheBayRoof) {
  const Document house = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/house.corbel").document;
  ExtrusionSpec s = std::get<ExtrusionSpec>(house.objects[0].spec);
  const ExtrusionResult kept = extrude(s);
  EXPECT_TRUE(kept.shell.warnings.empty());
  s.priority = Priority::MinimiseVolume;
  const ExtrusionResult r = extrude(s);
  expectClosed(s, r);
  std::size_t notPlaced = 0;
  for (const std::string& w : r.shell.warnings) {
    EXPECT_NE(w.find("not placed: its edge is not in the active plan"), std::string::npos) << w;
    notPlaced += w.find("dormer") != std::string::npos;
  }
  EXPECT_EQ(notPlaced, 2u) << "both dormers";
  EXPECT_LT(measure(r.shell).volume, measure(kept.shell).volume);
}

// A step that is never placed (its absolute anchor lies beyond its edge) stops the sweep at
// its height and changes nothing else: the shell must be the same wherever that is.
ExtrusionSpec withEmptyBoundary(ExtrusionSpec s, double height) {
  PlanStep st;
  st.name = "nowhere";
  st.anchor = {0, 0, true, 1e3, height};
  s.steps.push_back(st);
  return s;
}

std::map<std::string, double> tagAreas(const ExtrusionSpec& spec, const ExtrusionResult& r) {
  std::map<std::string, double> out;
  for (const ShellFace& f : r.shell.faces) {
    std::string tag = f.base ? "base" : "";
    if (!f.base && f.profile >= 0 && f.segment >= 0 &&
        static_cast<std::size_t>(f.segment) < spec.profiles[f.profile].tags.size())
      tag = spec.profiles[f.profile].tags[f.segment];
    out[tag + "/" + std::to_string(f.profile) + "/" + std::to_string(f.segment)] += faceArea(r.shell, f);
  }
  return out;
}

void expectBoundariesChangeNothing(const ExtrusionSpec& s, double from, double to, double step) {
  const ExtrusionResult plain = extrude(s);
  const ShellMeasures pm = measure(plain.shell);
  const auto areas = tagAreas(s, plain);
  for (double h = from; h <= to + 1e-9; h += step) {
    SCOPED_TRACE("boundary at " + std::to_string(h) + " m");
    const ExtrusionSpec b = withEmptyBoundary(s, h);
    const ExtrusionResult r = extrude(b);
    std::vector<std::string> warnings;
    std::vector<std::string> nowhere;
    for (const std::string& w : r.shell.warnings)
      (w.find("nowhere") == std::string::npos ? warnings : nowhere).push_back(w);
    EXPECT_EQ(warnings, plain.shell.warnings);
    // The sweep stopped at the step's height to look for its edge (a stage boundary there).
    ASSERT_EQ(nowhere.size(), 1u) << "the step was never looked at";
    EXPECT_NE(nowhere[0].find("at height " + std::to_string(s.baseZ + h)), std::string::npos) << nowhere[0];
    const ShellMeasures m = measure(r.shell);
    EXPECT_NEAR(m.volume, pm.volume, 1e-9 * pm.volume);
    EXPECT_NEAR(m.maxHeight, pm.maxHeight, 1e-9 * pm.maxHeight);
    EXPECT_EQ(m.faces, pm.faces);
    const auto a = tagAreas(b, r);
    ASSERT_EQ(a.size(), areas.size());
    for (const auto& [k, v] : areas) EXPECT_NEAR(a.at(k), v, 1e-9 * std::max(1.0, v)) << k;
    EXPECT_EQ(unpairedEdges(r.shell), unpairedEdges(plain.shell));
  }
}

TEST(Priority, AnEmptyStageBoundaryChangesNoShell) {
  {
    SCOPED_TRACE("Fig. 22 bays");
    for (Priority p : {Priority::MaximiseVolume, Priority::MinimiseVolume})
      expectBoundariesChangeNothing(twoBays(p), 0.25, 6.0, 0.25);
  }
  {
    SCOPED_TRACE("Fig. 1 house");
    const Document house = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/house.corbel").document;
    ExtrusionSpec s = std::get<ExtrusionSpec>(house.objects[0].spec);
    for (Priority p : {Priority::MaximiseVolume, Priority::MinimiseVolume}) {
      s.priority = p;
      expectBoundariesChangeNothing(s, 0.5, 9.5, 0.5);
    }
  }
  {
    // A 10 × 6 house (walls 2 m, then 20°) with one bay (walls 2.6 m, then 70°): the main
    // side wall comes into line with the bay's side once the facade between them is gone.
    SCOPED_TRACE("one bay, 20° and 70°");
    ExtrusionSpec s;
    s.profiles = {polyline("main", {{0, 0}, {0, 2}, {1 / std::tan(20 * kDeg), 3}}),
                  polyline("bay", {{0, 0}, {0, 2.6}, {1 / std::tan(70 * kDeg), 3.6}})};
    s.loops.push_back({rectangle(10, 6), {0, 0, 0, 0}});
    PlanStep b;
    b.shape = StepShape::Bay;
    b.anchor = {0, 0, false, 0.5, 0.0};
    b.width = 3;
    b.depth = 1;
    b.cant = 0.5;
    b.frontProfile = b.sideProfile = 1;
    s.steps.push_back(b);
    for (Priority p : {Priority::MaximiseVolume, Priority::MinimiseVolume}) {
      s.priority = p;
      expectBoundariesChangeNothing(s, 1.0, 4.0, 0.1);
    }
  }
}

// Dormers anchored by a fraction of the facade, above bays that split it: the terrace
// (assets/examples/terrace.corbel: four bays on its 28 m facade, a dormer at 6 m at each bay's
// fraction, 0.125–0.875) and the Fig. 1 house (a bay in the middle of its 12 m facade, dormers
// at 5.5 m at 0.22 and 0.78). The bays' roofs reach the facade below the dormers and the facade
// wins (maximising); its pieces on either side of each bay then lie in one line with one
// profile and are one edge again (Sec. 4.8 merges all consecutive colinear edges), so every
// dormer's front is centred at its fraction of the whole facade (over its bay on the terrace,
// symmetric on the house), not of the longest piece left between two bays.
TEST(Priority, DormersStandAtTheirFractionOfTheWholeFacade) {
  for (const char* name : {"terrace", "house"}) {
    SCOPED_TRACE(name);
    const Document d = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + name + ".corbel").document;
    const ExtrusionSpec s = std::get<ExtrusionSpec>(d.objects[0].spec);
    const ExtrusionResult r = extrude(s);
    EXPECT_TRUE(r.shell.warnings.empty());
    expectClosed(s, r);
    int dormers = 0;
    for (int k = 0; k < static_cast<int>(s.steps.size()); ++k) {
      const PlanStep& st = s.steps[k];
      if (st.name.find("dormer") == std::string::npos) continue;
      ++dormers;
      SCOPED_TRACE(st.name);
      // The facade (the anchor's input edge), from a to b.
      const auto& pts = s.loops[st.anchor.loop].points;
      const Vec2 a = pts[st.anchor.edge], b = pts[(st.anchor.edge + 1) % pts.size()];
      const Vec2 dir = (b - a) / (b - a).norm();
      double lo = 1e300, hi = -1e300;
      for (const ShellFace& f : r.shell.faces)
        if (f.step == k && f.profile == st.frontProfile)
          for (const auto& l : f.loops)
            for (int v : l) {
              const double t = OpenMesh::dot(dir, Vec2(r.shell.points[v][0], r.shell.points[v][1]) - a);
              lo = std::min(lo, t), hi = std::max(hi, t);
            }
      ASSERT_LT(lo, hi) << "no front face";
      EXPECT_NEAR(0.5 * (lo + hi), st.anchor.along * (b - a).norm(), 1e-9);
      EXPECT_NEAR(hi - lo, st.width, 1e-9);
    }
    EXPECT_EQ(dormers, std::string(name) == "terrace" ? 4 : 2);
  }
}

}  // namespace
}  // namespace corbel::extrude::test
