// Randomized editing (issue 4's acceptance): seeded sequences of the panes' operations —
// corners dragged, inserted and deleted, profile points moved, overhangs added, anchors moved,
// undo and redo — applied to the Fig. 1 house. After every edit the spec is either refused by
// the kernel with a reason (the editor shows it and keeps the last good shell) or builds a
// closed 2-manifold shell; anything else is saved as a project file to reproduce it.
// By default it runs 400 sessions of 60 edits (deterministic, about 10 s); with
// CORBEL_EDIT_FUZZ_SECONDS it runs sessions for that long instead (the long run: 1800).
#include "core/error.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "extrude/edit.h"
#include "support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <limits>
#include <cstdlib>
#include <random>

namespace corbel::extrude::test {
namespace {

namespace ed = corbel::extrude::edit;

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
  std::size_t edits = 0, refusedByEdit = 0, refusedByKernel = 0, built = 0, failures = 0;
  for (int session = 0; session < sessions; ++session) {
    if (timed && std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count() >= seconds) break;
    std::vector<ExtrusionSpec> undo{start}, redo;
    for (int step = 0; step < 60; ++step) {
      ExtrusionSpec s = undo.back();
      const int kind = pick(10);
      try {
        PlanLoop& l = s.loops[0];
        switch (kind) {
          case 0:
          case 1:
          case 2: {  // drag a corner
            const int c = pick(l.points.size());
            s = ed::moveCorner(s, 0, c, l.points[c] + Vec2(uniform(-1.5, 1.5), uniform(-1.5, 1.5)));
            break;
          }
          case 3: {  // insert a corner near an edge's middle
            const int e = pick(l.points.size());
            const Vec2 mid = (l.points[e] + l.points[(e + 1) % l.points.size()]) * 0.5;
            s = ed::insertCorner(s, 0, e, mid + Vec2(uniform(-0.5, 0.5), uniform(-0.5, 0.5)));
            break;
          }
          case 4:
            s = ed::deleteCorner(s, 0, pick(l.points.size()));
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
      undo.push_back(s);
      redo.clear();
      if (checkSpec(s)) {
        ++refusedByKernel;
        continue;
      }
      std::string problem;
      try {
        const ExtrusionResult r = extrude(s, nullptr, 5.0);
        if (const std::size_t open = unpairedEdges(r.shell)) problem = std::to_string(open) + " open edges";
        else {
          Scene scene;
          scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, s, "plaster"));
          const ValidityReport v = scene.validate(1);
          if (!v.problems().empty()) problem = v.problems()[0];
        }
      } catch (const InputError&) {
        ++refusedByKernel;
        continue;
      } catch (const std::exception& e) {
        problem = e.what();
      }
      if (problem.empty()) {
        ++built;
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
            << refusedByEdit << " refused by the edit, " << failures << " failures (saved in " << dir << ")\n";
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
