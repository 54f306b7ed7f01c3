// Real footprints (../shared/data/footprints: 10,524 OpenStreetMap buildings from Kathmandu
// and Moosburg). Every building must give a closed 2-manifold shell whose roof projects onto
// the footprint exactly once: Σ_faces area·cos φ = footprint area (for one pitch φ this is
// roof area = footprint area / cos φ). Buildings known to fail are listed, with the reason,
// in tests/data/extrude/known_failures.txt: the test fails when any other building fails,
// and when a listed one starts to pass (so the list only shrinks). Every closed shell passes
// the shell checks (shell_checks.h) and, at 45°, stays under CGAL's skeleton within δ1 + δ2, unless
// tests/data/extrude/shell_check_exemptions.txt names it.
#include "extrude/footprints.h"
#include "core/project_io.h"
#include "extrude/batch.h"
#include "shell_checks.h"
#include "skeleton_oracle.h"
#include "support.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <set>
#include <sstream>
#include <thread>

namespace corbel::extrude::test {
namespace {

std::vector<Footprint> allFootprints() {
  std::vector<Footprint> all;
  for (const char* name : {"kathmandu_np.geojson", "moosburg_de.geojson"}) {
    const std::string path = std::string(CORBEL_FOOTPRINTS) + "/" + name;
    if (!std::filesystem::exists(path)) throw std::runtime_error("missing test data: " + path);
    auto fps = readGeoJsonFile(path);
    all.insert(all.end(), fps.begin(), fps.end());
  }
  return all;
}

std::set<std::string> knownFailures(const std::string& label) {
  std::set<std::string> out;
  std::ifstream in(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/known_failures.txt");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    std::string l, id;
    ss >> l >> id;
    if (l == label) out.insert(id);
  }
  return out;
}

double projectedRoofArea(const SweepOutput& s) {
  double sum = 0;
  for (const ShellFace& f : s.faces)
    if (!f.base) sum += faceArea(s, f) * f.normal[2];  // area × cos φ
  return sum;
}

// Per building, after the batch: the shell rebuilt (as the batch kept it: its first build
// passed) and checked, on every core.
struct Checked {
  double identity = 0;   // relative error of the projection identity
  std::string geometry;  // shellGeometryProblem
  double height = 0, volume = 0;
  bool cgal = false;  // CGAL answered (equal angles only)
  double cgalHeight = 0, cgalVolume = 0;
  double delta1 = 0;        // the kernel's event height tolerance for it
  double delta2 = 0;        // and its event position tolerance
  double topTolerance = 0;  // skeletonTopTolerance (equal angles only)
  double footprint = 0;     // the plan's area
};

template <class F>
void onEveryCore(std::size_t n, F f) {
  const unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> pool;
  for (unsigned j = 0; j < jobs; ++j)
    pool.emplace_back([&] {
      for (std::size_t i; (i = next++) < n;) f(i);
    });
  for (auto& t : pool) t.join();
}

// profile: when every edge has it, CGAL's skeleton under it is the oracle of the height and
// volume (skeleton_oracle.h).
void runAll(const std::string& label, const std::function<ExtrusionSpec(const Footprint&)>& specFor,
            const std::vector<Vec2>* profile = nullptr) {
  const auto fps = allFootprints();
  ASSERT_EQ(fps.size(), 10524u);
  std::vector<BatchItem> items;
  for (const auto& fp : fps) items.push_back({fp.id, specFor(fp), fp.problem});
  BatchOptions options;
  const auto results = extrudeBatch(items, options);
  const auto known = knownFailures(label);
  std::vector<Checked> checked(results.size());
  onEveryCore(results.size(), [&](std::size_t i) {
    if (!results[i].ok) return;
    const ExtrusionSpec& spec = items[i].spec;
    const ExtrusionResult er = extrude(spec);
    Checked& c = checked[i];
    double footprint = 0;
    for (const auto& l : spec.loops) footprint += shoelace(l.points);
    c.identity = std::abs(projectedRoofArea(er.shell) - footprint) / footprint;
    c.geometry = shellGeometryProblem(er.shell, spec);
    c.height = er.shell.maxHeight;
    c.delta1 = Tolerances::forScale(er.scale).height;
    c.delta2 = Tolerances::forScale(er.scale).cluster;
    c.footprint = footprint;
    c.volume = measure(er.shell).volume;
    if (profile) c.topTolerance = skeletonTopTolerance(Profile{"", *profile, {}}, c.height, c.delta1, c.delta2);
  });
  // CGAL's skeleton under the profile, in child processes after the threads have ended.
  if (profile) {
    std::vector<std::size_t> asked;
    std::vector<SkeletonQuery> queries;
    for (std::size_t i = 0; i < results.size(); ++i)
      if (results[i].ok) {
        SkeletonQuery q;
        for (const auto& l : items[i].spec.loops) q.loops.push_back(l.points);
        q.profile = *profile;
        asked.push_back(i);
        queries.push_back(std::move(q));
      }
    const auto answers = cgalUnderProfileIsolated(queries);
    for (std::size_t k = 0; k < asked.size(); ++k) {
      Checked& c = checked[asked[k]];
      if (!answers[k]) {
        ADD_FAILURE() << label << ": " << results[asked[k]].id << ": CGAL's skeleton gave no answer";
        continue;
      }
      c.cgal = true;
      c.cgalHeight = answers[k]->height;
      c.cgalVolume = answers[k]->volume;
    }
  }
  const ShellCheckExemptions& exemptions = shellCheckExemptions();
  for (const std::string& p : exemptions.problems) ADD_FAILURE() << p;
  std::size_t failed = 0, identityChecked = 0;
  double worst = 0, worstVolume = 0, worstHeight = 0;
  std::size_t badGeometry = 0, aboveSkeleton = 0;
  std::string firstBadGeometry, firstAbove;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    if (!r.ok) {
      ++failed;
      if (!known.count(r.id)) ADD_FAILURE() << label << ": " << r.id << " failed: " << r.error;
      continue;
    }
    if (known.count(r.id)) ADD_FAILURE() << label << ": " << r.id << " now passes: remove it from known_failures.txt";
    // The post inter-chain check (Sec. 4.4) never cries wolf on a building that closes.
    for (const std::string& w : r.warnings)
      EXPECT_EQ(w.find("overlapped itself"), std::string::npos) << label << ": " << r.id << ": " << w;
    const Checked& c = checked[i];
    worst = std::max(worst, c.identity);
    ++identityChecked;
    EXPECT_LT(c.identity, 1e-9) << label << ": " << r.id;
    EXPECT_GT(r.measures.volume, 0) << label << ": " << r.id;
    // Issue 28, "no needle faces": every face simple in its plane and no shell intersecting
    // itself, and no top above CGAL's skeleton beyond the kernel's tolerances
    // (skeletonTopTolerance: δ1 and δ2 times the roof's slope), unless
    // shell_check_exemptions.txt names it.
    auto expectListed = [&](const char* check, bool flagged, const std::string& problem) {
      const bool listed = exemptions.exempt(label, r.id, check);
      if (flagged && !listed)
        ADD_FAILURE() << label << ": " << r.id << ": " << problem
                      << " (tests/data/extrude/shell_check_exemptions.txt does not list \"" << label << " " << r.id
                      << " " << check << "\")";
      if (!flagged && listed)
        ADD_FAILURE() << label << ": " << r.id << " passes the " << check
                      << " check now: delete its line from tests/data/extrude/shell_check_exemptions.txt";
    };
    if (!c.geometry.empty() && badGeometry++ == 0) firstBadGeometry = r.id + ": " + c.geometry;
    expectListed("geometry", !c.geometry.empty(), c.geometry);
    if (c.cgal) {
      worstHeight = std::max(worstHeight, c.height - c.cgalHeight);
      if (c.height > c.cgalHeight + c.topTolerance && aboveSkeleton++ == 0) firstAbove = r.id;
      expectListed("above-skeleton", c.height > c.cgalHeight + c.topTolerance,
                   "top " + std::to_string(c.height) + " m, CGAL's skeleton " + std::to_string(c.cgalHeight) + " m");
      // The volume: the kernel places each event within δ2 of where it is (one point to it), so
      // under a 45° roof each point of the roof lies within δ2 of CGAL's height, and the volume
      // within the footprint's area times δ2.
      const double off = std::abs(c.volume - c.cgalVolume);
      worstVolume = std::max(worstVolume, off / (c.footprint * c.delta2));
      EXPECT_LE(off, c.footprint * c.delta2) << label << ": " << r.id << ": volume " << c.volume << ", CGAL's "
                                             << c.cgalVolume << ", footprint " << c.footprint << " m², δ2 " << c.delta2;
    }
  }
  std::cout << label << ": " << results.size() << " buildings, " << failed << " failed (" << known.size()
            << " known), projection identity worst relative error " << worst << " over " << identityChecked;
  std::cout << "; " << badGeometry << " with a face not simple or intersecting itself (first: " << firstBadGeometry
            << ")";
  if (profile)
    std::cout << "; against CGAL's skeleton: volume off by at most " << worstVolume
              << " footprint × δ2, top above it at most " << worstHeight << " m, " << aboveSkeleton
              << " above it beyond the tolerance (first: " << firstAbove << ")";
  std::cout << "\n";
}

ExtrusionSpec hipSpec(const Footprint& fp) {
  ExtrusionSpec s;
  s.profiles = {hipProfile(45 * kDeg)};
  for (const auto& l : fp.loops) s.loops.push_back({l, std::vector<int>(l.size(), 0)});
  return s;
}

// 3 m walls under roofs of 20°–70°, one per edge, drawn from a generator seeded by the id.
ExtrusionSpec mixedSpec(const Footprint& fp) {
  ExtrusionSpec s;
  for (int a = 20; a <= 70; a += 10) s.profiles.push_back(wallAndRoofProfile(3.0, a * kDeg));
  std::seed_seq seq(fp.id.begin(), fp.id.end());
  std::mt19937 rng(seq);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(s.profiles.size()) - 1);
  for (const auto& l : fp.loops) {
    PlanLoop pl{l, {}};
    for (std::size_t i = 0; i < l.size(); ++i) pl.profile.push_back(pick(rng));
    s.loops.push_back(pl);
  }
  return s;
}

TEST(RealFootprints, HipRoofsAt45Degrees) {
  const std::vector<Vec2> hip = hipProfile(45 * kDeg).points;
  runAll("hip45", hipSpec, &hip);
}

TEST(RealFootprints, MixedPerEdgeAnglesOverWalls) { runAll("mixed", mixedSpec); }

// Footprints that once failed (tests/data/extrude): two chains that are nearly antiparallel
// must still cross over at a split, not reconnect each chain to itself (w387700951,
// w180878574); sliver ridges between near-antiparallel edges must leave no face overlapping
// its neighbour once every edge is split at the vertices on it (w177600540, w574863504).
TEST(RegressionCases, OnceFailingFootprintsGiveClosedShells) {
  for (const char* name : {"moosburg_w387700951.geojson", "moosburg_w180878574.geojson", "moosburg_w177600540.geojson",
                           "moosburg_w574863504.geojson"}) {
    SCOPED_TRACE(name);
    const auto fps = readGeoJsonFile(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/" + name);
    ASSERT_EQ(fps.size(), 1u);
    const ExtrusionSpec s = hipSpec(fps[0]);
    const auto results = extrudeBatch({{fps[0].id, s, ""}}, {});
    EXPECT_TRUE(results[0].ok) << results[0].error;
    // w180878574 still ends in a sliver loop capped flat at the ridge (closed, with a warning).
    for (const auto& w : results[0].warnings) std::cout << name << ": " << w << "\n";
    const ExtrusionResult er = extrude(s);
    const double footprint = shoelace(fps[0].loops[0]);
    EXPECT_NEAR(projectedRoofArea(er.shell), footprint, 1e-9 * footprint);
  }
}

// The last two real footprints that did not close (2026-12-01). Both are nearly orthogonal
// plans whose opposite walls differ in direction by a few hundredths of a degree, so a ridge
// corner races along a near-flat ridge at thousands of metres per metre of rise, and two
// predictions of one event differ in height by more than δ1 / speed: w224304505 (an L whose
// arm closes in a hip end and a ridge as the arm's wall bends by 0.02° at its midpoint) under
// the hip profile, w177178374 under the mixed walls and pitches. They must close without
// a warning and satisfy the projection identity.
TEST(RegressionCases, RacingRidgeCornersJoinTheirEvents) {
  const std::pair<const char*, ExtrusionSpec (*)(const Footprint&)> cases[] = {
      {"moosburg_w224304505.geojson", hipSpec}, {"moosburg_w177178374.geojson", mixedSpec}};
  for (const auto& [name, specFor] : cases) {
    SCOPED_TRACE(name);
    const auto fps = readGeoJsonFile(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/" + name);
    ASSERT_EQ(fps.size(), 1u);
    const ExtrusionSpec s = specFor(fps[0]);
    const auto results = extrudeBatch({{fps[0].id, s, ""}}, {});
    ASSERT_TRUE(results[0].ok) << results[0].error;
    for (const auto& w : results[0].warnings) ADD_FAILURE() << "warning: " << w;
    const ExtrusionResult er = extrude(s);
    const double footprint = shoelace(fps[0].loops[0]);
    EXPECT_NEAR(projectedRoofArea(er.shell), footprint, 1e-9 * footprint);
  }
}

// Plans of the random robustness run, perturbed by up to 5e-7 m, that ended in open shells
// with no warning (2026-12-02). The oracle is the same plan unperturbed (coordinates rounded
// to 1e-5 m, so colinear walls are exactly colinear), which the sweep closes without racing
// corners: the perturbed shell must close without a warning, with the same faces, and match
// its volume, areas and height to 1e-7 relative (the random test's bar), and its roof must
// project onto the footprint once.
// - racing_corner_sweeps_its_edge (random83162): an initial corner between a shallow roof and
//   a wall 2.5e-7 rad off it races at 1.3e7 m per m of rise and sweeps its 0.33 m edge in
//   2.4e-8 m, under δ1: predictions within δ1 of a corner's making were dropped, the edge's
//   end was missed and the corner ran on through the next wall.
// - two_edge_ridge_loop (random40587): two almost antiparallel edges left as a loop of their
//   own raced their two corners along one ridge instead of closing it (the sliver bound saw
//   metres between the corners where the lines give them one point), and the zips that
//   followed laid that ridge twice; the zips also took corners made at this height from their
//   lines, decimetres along the ridge from where the event made them.
TEST(RegressionCases, PerturbedRacingCornersCloseAsTheUnperturbedPlan) {
  for (const char* name : {"racing_corner_sweeps_its_edge.corbel", "two_edge_ridge_loop.corbel"}) {
    SCOPED_TRACE(name);
    const Document doc = loadProject(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/" + name).document;
    const auto& spec = std::get<ExtrusionSpec>(doc.objects.at(0).spec);
    ExtrusionSpec plain = spec;
    for (auto& l : plain.loops)
      for (Vec2& p : l.points) p = Vec2(std::round(p[0] * 1e5) / 1e5, std::round(p[1] * 1e5) / 1e5);
    const ExtrusionResult o = extrude(plain);
    ASSERT_EQ(unpairedEdges(o.shell), 0u) << "the oracle must close";
    const auto results = extrudeBatch({{name, spec, ""}}, {});
    ASSERT_TRUE(results[0].ok) << results[0].error;
    for (const auto& w : results[0].warnings) ADD_FAILURE() << "warning: " << w;
    const ExtrusionResult r = extrude(spec);
    const ShellMeasures m = measure(r.shell), mo = measure(o.shell);
    EXPECT_EQ(m.faces, mo.faces);
    const double rel = 1e-7;
    EXPECT_NEAR(m.volume, mo.volume, rel * mo.volume);
    EXPECT_NEAR(m.roofArea, mo.roofArea, rel * mo.roofArea);
    EXPECT_NEAR(m.wallArea, mo.wallArea, rel * mo.wallArea);
    EXPECT_NEAR(m.maxHeight, mo.maxHeight, rel * mo.maxHeight);
    double footprint = 0;
    for (const auto& l : spec.loops) footprint += shoelace(l.points);
    EXPECT_NEAR(projectedRoofArea(r.shell), footprint, rel * footprint);
  }
}

}  // namespace
}  // namespace corbel::extrude::test
