// Randomized editing (issue 4's acceptance): seeded sequences of the panes' operations —
// corners dragged, inserted (on an edge or off it) and deleted, profile points moved, overhangs
// added, anchors moved, undo and redo — applied to the Fig. 1 house. After every edit the spec
// is either refused by the kernel with a reason (the editor shows it and keeps the last good
// shell) or builds a closed 2-manifold shell; anything else is saved as a project file to
// reproduce it. Anchored things stay with their walls (issue 27): none is lost unless the edit
// names it, none moves unless its wall moved, and the kernel makes one feature instance per
// place of every mesh anchor, at the spec's point where the wall stands vertical. Every closed
// shell passes the shell checks (shell_checks.h: each face simple in its plane, no triangle
// crossing another).
// By default it runs 400 sessions of 60 edits (deterministic, about 10 s); with
// CORBEL_EDIT_FUZZ_SECONDS it runs sessions for that long instead (the long run: 1800).
#include "core/error.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "extrude/edit.h"
#include "shell_checks.h"
#include "support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <limits>
#include <cstdlib>
#include <optional>
#include <random>

namespace corbel::extrude::test {
namespace {

namespace ed = corbel::extrude::edit;

// Each anchored thing (steps, then mesh anchors): its wall and its point on the plan.
struct Placed {
  int loop = 0, wall = 0;
  std::optional<Vec2> at;
  std::vector<int> edges;  // of its wall
};
std::vector<Placed> placed(const ExtrusionSpec& s) {
  std::vector<Placed> out;
  auto one = [&](const Anchor& a) {
    Placed p;
    p.loop = a.loop;
    p.wall = a.loop < static_cast<int>(s.loops.size()) ? wallOf(s.loops[a.loop], a.edge) : 0;
    p.at = anchorPoint(s, a);
    p.edges = wallRun(s, a.loop, a.edge).edges;
    out.push_back(p);
  };
  for (const PlanStep& st : s.steps) one(st.anchor);
  for (const MeshAnchor& m : s.anchors) one(m.anchor);
  return out;
}

// Whether the wall (its edges, before the edit) touches corner c of loop `loop`.
bool touches(const Placed& p, int loop, int corner, int corners) {
  if (p.loop != loop) return false;
  for (int e : p.edges)
    if (e == corner || (e + 1) % corners == corner) return true;
  return false;
}

// The kernel's feature instances against the spec: one frame per place of every mesh anchor,
// and where a wall carries no step and stands vertical up to the anchor's height, the frame
// at the spec's point. Returns the first disagreement, or "".
std::string featureProblem(const ExtrusionSpec& s, const ExtrusionResult& r) {
  std::size_t expected = 0;
  for (const MeshAnchor& m : s.anchors) expected += repeatGrid(s, m.anchor, m.repeat).count();
  if (r.anchors.size() != expected)
    return std::to_string(r.anchors.size()) + " feature instances for " + std::to_string(expected) + " places";
  std::size_t k = 0;
  for (const MeshAnchor& m : s.anchors) {
    const WallRun run = wallRun(s, m.anchor.loop, m.anchor.edge);
    bool plain = !run.edges.empty();
    for (const PlanStep& st : s.steps) plain = plain && wallOf(s.loops[st.anchor.loop], st.anchor.edge) != wallOf(s.loops[m.anchor.loop], m.anchor.edge);
    for (const Anchor& a : repeatAnchors(s, m.anchor, m.repeat)) {
      const AnchorFrame& f = r.anchors[k++];
      if (!plain || !f.instanced) continue;
      const auto at = anchorPoint(s, a);
      // Where every wall of the loop stands straight up past the anchor, the plan at its height
      // is the input plan, so a fraction of the active edge is one of the wall.
      // Steps at or below it reshape the plan there, so those cases are left out.
      bool upright = true;
      for (const PlanStep& st : s.steps) upright = upright && st.anchor.height > a.height;
      for (int pi : s.loops[a.loop].profile)
        upright = upright && s.profiles[pi].points[1][0] == 0 && s.profiles[pi].points[1][1] > a.height + 0.5;
      if (!upright) continue;
      if ((Vec2(f.position[0], f.position[1]) - *at).norm() > 1e-6)
        return m.name + ": the kernel placed it " + std::to_string((Vec2(f.position[0], f.position[1]) - *at).norm()) +
               " m from its point on the wall";
    }
  }
  return "";
}

TEST(EditFuzz, RandomEditingNeverLeavesAnOpenShell) {
  const char* timed = std::getenv("CORBEL_EDIT_FUZZ_SECONDS");
  const double seconds = timed ? std::atof(timed) : 0.0;
  const int sessions = timed ? std::numeric_limits<int>::max() : 400;
  const Document house = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/house.corbel").document;
  const ExtrusionSpec start = std::get<ExtrusionSpec>(house.objects[0].spec);
  const char* seeded = std::getenv("CORBEL_EDIT_FUZZ_SEED");  // fresh ground for long runs
  std::mt19937_64 rng(seeded ? std::strtoull(seeded, nullptr, 10) : 20261122);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto pick = [&](std::size_t n) { return static_cast<int>(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng)); };

  const auto began = std::chrono::steady_clock::now();
  const std::filesystem::path dir = std::filesystem::current_path() / "edit-fuzz-failures";
  std::filesystem::remove_all(dir);
  std::size_t edits = 0, refusedByEdit = 0, refusedByKernel = 0, built = 0, failures = 0, badGeometry = 0;
  std::string firstBadGeometry;
  for (int session = 0; session < sessions; ++session) {
    if (timed && std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count() >= seconds) break;
    std::vector<ExtrusionSpec> undo{start}, redo;
    for (int step = 0; step < 60; ++step) {
      ExtrusionSpec s = undo.back();
      const int kind = pick(11);
      const std::vector<Placed> before = placed(s);
      std::vector<std::string> notes;
      int corner = -1;          // the corner an edit moved, inserted or deleted
      bool onTheEdge = false;   // an insert exactly on its edge
      try {
        PlanLoop& l = s.loops[0];
        switch (kind) {
          case 0:
          case 1:
          case 2: {  // drag a corner
            corner = pick(l.points.size());
            s = ed::moveCorner(s, 0, corner, l.points[corner] + Vec2(uniform(-1.5, 1.5), uniform(-1.5, 1.5)));
            break;
          }
          case 3: {  // insert a corner near an edge's middle
            const int e = pick(l.points.size());
            const Vec2 mid = (l.points[e] + l.points[(e + 1) % l.points.size()]) * 0.5;
            s = ed::insertCorner(s, 0, e, mid + Vec2(uniform(-0.5, 0.5), uniform(-0.5, 0.5)));
            corner = e + 1;
            break;
          }
          case 10: {  // split an edge where it is (the shape stays)
            const int e = pick(l.points.size());
            const Vec2 a = l.points[e], b = l.points[(e + 1) % l.points.size()];
            s = ed::insertCorner(s, 0, e, a + (b - a) * uniform(0.1, 0.9));
            corner = e + 1;
            onTheEdge = true;
            break;
          }
          case 4:
            corner = pick(l.points.size());
            s = ed::deleteCorner(s, 0, corner, &notes);
            break;
          case 5: {  // drag a profile point
            const int p = pick(s.profiles.size());
            const int i = pick(s.profiles[p].points.size());
            s = ed::moveProfilePoint(s, p, i, s.profiles[p].points[i] + Vec2(uniform(-0.5, 0.5), uniform(-0.5, 0.5)));
            break;
          }
          case 6:
            s = ed::addOverhang(s, uniform(1.0, 6.0), uniform(0.1, 0.6));
            break;
          case 7: {  // move an anchor
            if (s.steps.empty()) break;
            const int k = pick(s.steps.size());
            Anchor a = s.steps[k].anchor;
            if (!a.absolute) a.along = std::clamp(a.along + uniform(-0.2, 0.2), 0.0, 1.0);
            a.height = std::max(0.0, a.height + uniform(-0.5, 0.5));
            s = ed::moveAnchor(s, k, a);
            break;
          }
          case 8:  // undo
            if (undo.size() > 1) {
              redo.push_back(undo.back());
              undo.pop_back();
            }
            continue;
          case 9:  // redo
            if (!redo.empty()) {
              undo.push_back(redo.back());
              redo.pop_back();
            }
            continue;
        }
      } catch (const InputError&) {
        ++refusedByEdit;
        continue;
      }
      ++edits;
      // Anchored things: as many as before but those the edit named, each still on a wall; one
      // whose wall the edit did not touch has not moved, nor has any when an edge was split
      // where it was.
      const std::vector<Placed> after = placed(s);
      EXPECT_EQ(after.size() + notes.size(), before.size()) << "session " << session << " step " << step;
      for (const Placed& p : after) EXPECT_TRUE(p.at.has_value());
      if (notes.empty() && after.size() == before.size()) {
        const int corners = static_cast<int>(undo.back().loops[0].points.size());
        for (std::size_t i = 0; i < before.size(); ++i) {
          const bool moved = kind <= 4 && corner >= 0 && !onTheEdge && touches(before[i], 0, corner % corners, corners);
          const bool shifted = kind == 3 && corner >= 0 && before[i].loop == 0;  // a new corner on its wall
          if (moved || (shifted && !onTheEdge && touches(before[i], 0, (corner - 1 + corners) % corners, corners)) ||
              (kind == 7 && static_cast<int>(i) < static_cast<int>(s.steps.size())))
            continue;
          EXPECT_NEAR((*after[i].at - *before[i].at).norm(), 0.0, 1e-9)
              << "session " << session << " step " << step << ": anchored thing " << i << " moved (edit kind " << kind << ")";
        }
      }
      undo.push_back(s);
      redo.clear();
      if (checkSpec(s)) {
        ++refusedByKernel;
        continue;
      }
      std::string problem, geometry;
      try {
        const ExtrusionResult r = extrude(s, nullptr, 5.0);
        if (const std::size_t open = unpairedEdges(r.shell)) problem = std::to_string(open) + " open edges";
        else if (const std::string f = featureProblem(s, r); !f.empty()) problem = f;
        else {
          Scene scene;
          scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, s, "plaster"));
          const ValidityReport v = scene.validate(1);
          if (!v.problems().empty()) problem = v.problems()[0];
          else geometry = shellGeometryProblem(r.shell, s);
        }
      } catch (const InputError&) {
        ++refusedByKernel;
        continue;
      } catch (const std::exception& e) {
        problem = e.what();
      }
      if (problem.empty()) {
        ++built;
        if (!geometry.empty()) {
          // Issue 28, "no needle faces": every face simple in its plane, no shell intersecting
          // itself. Saved, and a failure.
          ADD_FAILURE() << "session " << session << " step " << step << ": " << geometry;
          if (badGeometry++ == 0) firstBadGeometry = geometry;
          std::filesystem::create_directories(dir / "geometry");
          Document d;
          d.add("edited", s);
          saveProject(d, (dir / "geometry" / ("session" + std::to_string(session) + "-step" + std::to_string(step) + ".corbel")).string());
        }
        continue;
      }
      ++failures;
      std::filesystem::create_directories(dir);
      Document d;
      d.add("edited", s);
      saveProject(d, (dir / ("session" + std::to_string(session) + "-step" + std::to_string(step) + ".corbel")).string());
      ADD_FAILURE() << "session " << session << " step " << step << ": " << problem;
      undo.pop_back();  // carry on from the last good state
    }
  }
  std::cout << edits << " edits: " << built << " closed shells, " << refusedByKernel << " refused by the kernel, "
            << refusedByEdit << " refused by the edit, " << failures << " failures (saved in " << dir << "); "
            << badGeometry << " closed shells with a face not simple in its plane or intersecting itself (first: "
            << firstBadGeometry << ")\n";
  EXPECT_GT(built, 100u);
}

// Documents that long runs (CORBEL_EDIT_FUZZ_SECONDS=1800) found the kernel cannot yet close:
// plans dragged into slivers and spikes under stacks of overhangs. Each must still be reported
// as a failure with a reason, never crash or hang; one that closes is to be moved out of
// tests/data/edit (it has become a regression case).
TEST(EditFuzz, KnownHardCasesFailWithAReason) {
  int cases = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(CORBEL_SOURCE_DIR) + "/tests/data/edit")) {
    if (entry.path().extension() != ".corbel") continue;
    const bool spike = entry.path().filename().string().rfind("spike-", 0) == 0;
    ++cases;
    const ExtrusionSpec s = std::get<ExtrusionSpec>(loadProject(entry.path().string()).document.objects[0].spec);
    SCOPED_TRACE(entry.path().filename().string());
    ASSERT_FALSE(checkSpec(s).has_value());
    if (spike) {
      // Needle-thin spikes under an overhang: refused by the mitre limit, naming the corner.
      try {
        extrude(s, nullptr, 5.0);
        ADD_FAILURE() << "accepted a spike whose overhang mitre passes the limit";
      } catch (const InputError& e) {
        EXPECT_EQ(e.where.rfind("loops[0].points[", 0), 0u) << e.what();
        EXPECT_NE(e.reason.find("overhang would push"), std::string::npos) << e.what();
      }
      continue;
    }
    const ExtrusionResult r = extrude(s, nullptr, 5.0);
    Scene scene;
    bool closed = unpairedEdges(r.shell) == 0;
    if (closed) {
      scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, s, "plaster"));
      closed = scene.validate(1).problems().empty();
    }
    EXPECT_FALSE(closed) << "now closes: move it to the regression cases";
  }
  EXPECT_GE(cases, 3);  // the three spikes; degenerate cases join them as long runs find them
}

// Cases long runs found that have since been fixed: each must stay a closed 2-manifold.
TEST(EditFuzz, FormerFailuresStayClosed) {
  int cases = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(CORBEL_SOURCE_DIR) + "/tests/data/edit-closed")) {
    if (entry.path().extension() != ".corbel") continue;
    ++cases;
    SCOPED_TRACE(entry.path().filename().string());
    const ExtrusionSpec s = std::get<ExtrusionSpec>(loadProject(entry.path().string()).document.objects[0].spec);
    ASSERT_FALSE(checkSpec(s).has_value());
    const ExtrusionResult r = extrude(s, nullptr, 5.0);
    ASSERT_EQ(unpairedEdges(r.shell), 0u);
    Scene scene;
    scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, s, "plaster"));
    const ValidityReport v = scene.validate(1);
    // Closed, manifold, consistently oriented, no zero-area face. (Not necessarily of genus 0:
    // two dormers grown into each other can leave a tunnel between them and the roof.)
    EXPECT_TRUE(v.problems().empty()) << (v.problems().empty() ? "" : v.problems()[0]);
    EXPECT_TRUE(v.closedManifold());
  }
  EXPECT_GE(cases, 1);
}

}  // namespace
}  // namespace corbel::extrude::test
