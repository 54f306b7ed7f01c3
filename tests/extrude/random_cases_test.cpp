// Every random plan that ever failed its first build in the random robustness run
// (RandomRobustness.HundredThousandFootprints, seed 0xC0B3E1) is kept as a case of its own,
// tests/data/extrude/random/randomN.corbel, and tested by name: RandomCases/Saved.Builds/randomN.
// docs/extrude.md ("Known limits") says how they were made and how to add new ones.
//
// A case the batch closes (at its first build or rebuilt with wider tolerances, as users get it:
// extrude/batch.h) must be a closed 2-manifold built through the kernel here, project its roof
// onto the footprint once (sum of area × n_z over the non-base faces = the plan's shoelace area,
// within 1e-7 × the tolerance factor, as the random test checks), and, where volume_oracle.h has
// an oracle (CGAL's skeleton under one profile; the unperturbed plan of a perturbed orthogonal
// one), hold its volume within 1e-6, and pass the shell checks (shell_checks.h: every face a
// simple polygon in its plane, no triangle crossing another) unless
// tests/data/extrude/shell_check_exemptions.txt names it. A rebuilt case must also be justified: three consecutive
// factors' rebuilds, made here, all close and agree within 1e-6 (10×, 100×, 1000×, or, where the
// 10× rebuild fails, 100×, 1000×, 10000×), and the kept one is the first of them. The
// exceptions are named in
// tests/data/extrude/random/oracle_disagreements.txt with the reason.
//
// A case named in tests/data/extrude/random/still_failing.txt (with its class, the first
// build's as scripts/extrude_failure_classes.py gives it) must be refused with a reason, and
// the batch must have left it the right way: the rebuilds made here stop at the same factor for
// the same reason (a rebuild that fails, or two that disagree), its error is the first build's
// followed by that reason, and no rebuild warning. A listed case that closes fails the test
// with a message to delete its line; a case not listed that fails is a regression. Both lists
// stay true this way, and a case leaves one by deleting one line.
#include "core/error.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "extrude/batch.h"
#include "shell_checks.h"
#include "support.h"
#include "volume_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace corbel::extrude::test {
namespace {

namespace fs = std::filesystem;

const fs::path& casesDir() {
  static const fs::path dir = fs::path(CORBEL_SOURCE_DIR) / "tests/data/extrude/random";
  return dir;
}

std::vector<std::string> savedCases() {
  std::vector<std::string> out;
  if (fs::is_directory(casesDir()))
    for (const auto& e : fs::directory_iterator(casesDir()))
      if (e.path().extension() == ".corbel") out.push_back(e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Lines "NAME  TEXT  # comment": NAME → TEXT (trimmed); blank lines and '#' lines skipped.
struct CaseList {
  std::map<std::string, std::string> entries;
  std::vector<std::string> problems;  // duplicates and malformed lines
};

CaseList readList(const std::string& file) {
  CaseList list;
  std::ifstream in(casesDir() / file);
  if (!in) list.problems.push_back("cannot read " + (casesDir() / file).string());
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    line = line.substr(0, line.find('#'));
    const auto b = line.find_first_not_of(" \t"), e = line.find_last_not_of(" \t\r");
    if (b == std::string::npos) continue;
    line = line.substr(b, e - b + 1);
    const auto gap = line.find_first_of(" \t");
    const std::string name = line.substr(0, gap);
    const std::string text = gap == std::string::npos ? "" : line.substr(line.find_first_not_of(" \t", gap));
    if (text.empty()) list.problems.push_back(file + ":" + std::to_string(n) + ": no text after the name");
    if (!list.entries.emplace(name, text).second) list.problems.push_back(file + ": " + name + " twice");
  }
  return list;
}

const CaseList& stillFailing() {
  static const CaseList l = readList("still_failing.txt");
  return l;
}
const CaseList& disagreements() {
  static const CaseList l = readList("oracle_disagreements.txt");
  return l;
}

// The classes of scripts/extrude_failure_classes.py (classify), in its order: first match wins.
std::string failureClass(const std::string& error, const std::vector<std::string>& warnings) {
  std::string w;
  for (const std::string& s : warnings) w += s + " ";
  auto has = [](const std::string& s, const char* t) { return s.find(t) != std::string::npos; };
  if (has(error, "the roof cannot close")) return "roof cannot close";
  if (has(error, "cascade") || has(error, "cycle")) return "event cycle";
  if (has(error, "time limit")) return "time limit";
  if (has(w, "diverged")) return "diverged";
  if (has(w, "did not close")) return "capped";
  if (has(w, "overlapped itself")) return "overlap-warned";
  if (has(w, "could not be placed")) return "face placement";
  if (has(error, "not closed")) return warnings.empty() ? "unclosed without warning" : "unclosed, other warning";
  if (has(error, "2-manifold")) return "non-manifold";
  if (has(error, "crosses itself")) return "face crossing itself";
  return "other: " + error.substr(0, 60);
}

const std::set<std::string> kClasses{"roof cannot close",
                                     "event cycle",
                                     "time limit",
                                     "diverged",
                                     "capped",
                                     "overlap-warned",
                                     "face placement",
                                     "unclosed without warning",
                                     "unclosed, other warning",
                                     "non-manifold",
                                     "face crossing itself"};

ExtrusionSpec load(const std::string& name) { return savedSpec(casesDir() / (name + ".corbel")); }

// The rebuild factors and agreement of the batch as users get it (BatchOptions' defaults).
const BatchOptions kUsers;

BatchResult batch(const ExtrusionSpec& spec, bool rebuilds) {
  BatchOptions o = kUsers;
  o.jobs = 1;
  if (!rebuilds) o.retryFactors.clear();
  return extrudeBatch({{"case", spec, ""}}, o)[0];
}

// One build made here, not through the batch: the kernel at a tolerance factor, its shell
// validated as a half-edge mesh by the Scene, its projection identity measured.
struct Build {
  bool closed = false;
  std::string why;                                  // when not closed
  double volume = 0, roofArea = 0, projection = 0;  // projection: relative error of the identity
  std::string geometry;                             // shellGeometryProblem, when asked for
};

Build buildAt(const ExtrusionSpec& spec, double factor, bool checkGeometry = false) {
  Build b;
  try {
    const ExtrusionResult er = extrude(spec, nullptr, ExtrudeOptions{kUsers.timeLimitSeconds, factor, false});
    const ShellMeasures m = measure(er.shell);
    b.volume = m.volume;
    b.roofArea = m.roofArea;
    if (const std::size_t open = unpairedEdges(er.shell)) {
      b.why = std::to_string(open) + " unpaired edges";
      return b;
    }
    Scene scene;
    scene.replaceObject(1, Kind::Shell, "case", toMeshData(er.shell, spec, spec.material));
    const ValidityReport v = scene.validate(1);
    if (!v.closedManifold()) {
      b.why = v.problems().empty() ? "not a closed 2-manifold" : v.problems()[0];
      return b;
    }
    // The batch refuses a face that crosses itself too (CGAL says so here, face by face).
    if (const std::string crossed = faceLoopProblem(er.shell); !crossed.empty()) {
      b.why = crossed;
      return b;
    }
    double projected = 0, footprint = 0;
    for (const ShellFace& f : er.shell.faces)
      if (!f.base) projected += faceArea(er.shell, f) * f.normal[2];
    for (const auto& l : spec.loops) footprint += shoelace(l.points);
    b.projection = std::abs(projected - footprint) / footprint;
    if (checkGeometry) b.geometry = shellGeometryProblem(er.shell, spec);
    b.closed = true;
  } catch (const InputError& e) {
    b.why = std::string("bad input: ") + e.what();
  } catch (const std::exception& e) {
    b.why = e.what();
  }
  return b;
}

double relative(double a, double b) {
  const double m = std::max(std::abs(a), std::abs(b));
  return m > 0 ? std::abs(a - b) / m : 0.0;
}

std::string times(double f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g×", f);
  return buf;
}

// The rule of docs/extrude.md ("Rebuilding with wider tolerances"), replayed on builds made
// here: a window of three consecutive factors, each rebuilt in turn, stopping at the first that
// fails or disagrees with the window's first; a window whose first rebuild fails moves one
// factor up while the list allows. builds counts the first build too.
struct Replay {
  bool accepted = false;
  int builds = 1;
  double factor = 0;   // the accepted rebuild's
  std::string reason;  // why none was kept: "the 100× rebuild failed too", "10× and 1000× disagree"
  double worst = 0;    // largest disagreement with the window's first rebuild (volume or roof area)
};

Replay replay(const ExtrusionSpec& spec) {
  Replay p;
  const std::vector<double>& f = kUsers.retryFactors;
  const std::size_t window = std::min<std::size_t>(kUsers.retryWindow, f.size());
  for (std::size_t start = 0; start + window <= f.size(); ++start) {
    const Build lead = buildAt(spec, f[start]);
    ++p.builds;
    if (!lead.closed) {
      p.reason = "the " + times(f[start]) + " rebuild failed too";
      continue;  // the window moves up (the loop ends where it cannot)
    }
    for (std::size_t i = 1; i < window; ++i) {
      const Build b = buildAt(spec, f[start + i]);
      ++p.builds;
      if (!b.closed) {
        p.reason = "the " + times(f[start + i]) + " rebuild failed too";
        return p;
      }
      p.worst = std::max({p.worst, relative(lead.volume, b.volume), relative(lead.roofArea, b.roofArea)});
      if (p.worst > kUsers.retryAgreement) {
        p.reason = times(f[start]) + " and " + times(f[start + i]) + " disagree";
        return p;
      }
    }
    p.accepted = true;
    p.factor = f[start];
    return p;
  }
  return p;
}

bool warnedRebuilt(const BatchResult& r) {
  for (const std::string& w : r.warnings)
    if (w.rfind("rebuilt with", 0) == 0) return true;
  return false;
}

// Refused, and left as the rule says (the case is on still_failing.txt with `listedClass`).
void expectRefusedTheRightWay(const std::string& name, const std::string& listedClass, const ExtrusionSpec& spec,
                              const BatchResult& first, const BatchResult& r) {
  ASSERT_FALSE(r.ok) << name << " closes now ("
                     << (r.toleranceFactor > 1 ? "rebuilt with " + times(r.toleranceFactor) + " tolerances"
                                               : std::string("at its first build"))
                     << "): move it off the list, i.e. delete its line from tests/data/extrude/random/"
                        "still_failing.txt; this test then holds it to a closed shell's properties";
  EXPECT_FALSE(r.error.empty()) << "refused without a reason";
  EXPECT_FALSE(first.error.empty()) << "first build refused without a reason";
  EXPECT_EQ(failureClass(first.error, first.warnings), listedClass)
      << "its first build is in another class now (error: " << first.error
      << "): change its class in still_failing.txt";
  if (listedClass == "roof cannot close") {
    // The spec's own fault (Sweeper::refuseStandingLoop): bad input, the same at any
    // tolerance, so built once and never rebuilt, and the loop named.
    const Build here = buildAt(spec, 1.0);
    EXPECT_EQ(here.why.rfind("bad input: loops[", 0), 0u) << here.why;
    EXPECT_EQ(r.builds, 1);
    EXPECT_EQ(r.error, first.error);
    EXPECT_TRUE(r.warnings.empty());
    return;
  }
  // The first build fails here too, through the kernel directly.
  const Build here = buildAt(spec, 1.0);
  EXPECT_FALSE(here.closed) << "the kernel's own first build closes, but the batch refused it: " << r.error;
  EXPECT_EQ(here.why.rfind("bad input", 0), std::string::npos) << here.why;
  // The exit path: no shell kept, the first build's error standing with the rule's reason.
  EXPECT_EQ(r.toleranceFactor, 1.0);
  EXPECT_FALSE(warnedRebuilt(r)) << "a refused building carries a rebuild warning";
  EXPECT_EQ(r.warnings, first.warnings) << "the first build's warnings stand";
  const Replay p = replay(spec);
  ASSERT_FALSE(p.accepted) << "the rebuilds made here close and agree within " << kUsers.retryAgreement << " (worst "
                           << p.worst << "), but the batch refused it: " << r.error;
  EXPECT_EQ(r.builds, p.builds) << "the batch stopped at another rebuild than the rule: " << r.error;
  const std::string prefix = first.error + " (rebuilt with wider tolerances: " + p.reason;
  EXPECT_EQ(r.error.rfind(prefix, 0), 0u) << "expected \"" << prefix << "…\", got \"" << r.error << "\"";
}

// The plan rounded to 1e-5 m has only axis-parallel edges: a perturbed orthogonal plan, as
// volume_oracle.cpp decides it (a uniform plan takes CGAL's oracle first).
bool roundsToOrthogonal(ExtrusionSpec spec) {
  for (auto& l : spec.loops) {
    for (Vec2& q : l.points) q = Vec2(std::round(q[0] * 1e5) / 1e5, std::round(q[1] * 1e5) / 1e5);
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      const Vec2 &a = l.points[i], &b = l.points[(i + 1) % l.points.size()];
      if (a[0] != b[0] && a[1] != b[1]) return false;
    }
  }
  return true;
}

class Saved : public ::testing::TestWithParam<std::string> {};

TEST_P(Saved, Builds) {
  const std::string name = GetParam();
  const ExtrusionSpec spec = load(name);
  const BatchResult first = batch(spec, false), r = batch(spec, true);
  if (const auto it = stillFailing().entries.find(name); it != stillFailing().entries.end()) {
    expectRefusedTheRightWay(name, it->second, spec, first, r);
    return;
  }
  ASSERT_TRUE(r.ok) << name << " is refused but not listed in still_failing.txt, so it must close: " << r.error
                    << "\n(a regression; if it has to be accepted, add the line \"" << name << "  "
                    << failureClass(first.error, first.warnings)
                    << "\" to tests/data/extrude/random/still_failing.txt)";
  EXPECT_TRUE(r.watertight && r.manifold);
  // The shell the batch kept, built here at its factor: closed, 2-manifold, the same volume.
  const double factor = r.toleranceFactor;
  const Build kept = buildAt(spec, factor, true);
  ASSERT_TRUE(kept.closed) << "built here at " << times(factor) << ": " << kept.why;
  EXPECT_EQ(kept.volume, r.measures.volume);
  if (shellCheckExemptions().exempt("random", name, "geometry"))
    EXPECT_NE(kept.geometry, "") << "passes the shell checks now: delete its line from "
                                    "tests/data/extrude/shell_check_exemptions.txt";
  else
    EXPECT_EQ(kept.geometry, "") << "(built at " << times(factor)
                                 << "; not in tests/data/extrude/shell_check_exemptions.txt)";
  EXPECT_LT(kept.projection, 1e-7 * factor) << "the roof does not project onto the footprint once";
  if (factor == 1.0) {
    EXPECT_TRUE(first.ok) << first.error;
    EXPECT_EQ(r.builds, 1);
    EXPECT_FALSE(warnedRebuilt(r));
  } else {
    EXPECT_FALSE(first.ok) << "the first build closes, yet it was rebuilt";
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_EQ(r.warnings[0].rfind(
                  "rebuilt with " + times(factor) + " tolerances (the first build failed: " + first.error + ")", 0),
              0u)
        << r.warnings[0];
    const Replay p = replay(spec);
    EXPECT_TRUE(p.accepted) << "kept, but the rebuilds made here say: " << p.reason << " (by " << p.worst << ")";
    EXPECT_EQ(factor, p.factor) << "kept another rebuild than the rule's";
    EXPECT_EQ(r.builds, p.builds);
  }
  const VolumeOracle o = independentVolume(spec);
  const auto listed = disagreements().entries.find(name);
  if (o.kind == VolumeOracle::None) {
    // Mixed profiles on a plan that is not a perturbed orthogonal one: the topology and the
    // projection identity above are all there is to check. A perturbed orthogonal plan always
    // has its oracle: losing it means the exact axis-parallel plan no longer builds cleanly.
    // (Unless oracle_disagreements.txt lists it, saying why its unperturbed plan cannot close.)
    if (listed == disagreements().entries.end())
      EXPECT_FALSE(roundsToOrthogonal(spec)) << "its unperturbed plan no longer closes without warnings, or differs "
                                                "from its quarter turn or moved copy (volume_oracle.h)";
    else
      EXPECT_TRUE(roundsToOrthogonal(spec)) << "listed in oracle_disagreements.txt, but has no oracle";
    return;
  }
  const double off = std::abs(r.measures.volume - o.volume) / o.volume;
  const char* oracle = o.kind == VolumeOracle::Cgal ? "CGAL's skeleton under its one profile" : "its unperturbed plan";
  if (listed != disagreements().entries.end()) {
    EXPECT_GT(off, 1e-6) << name << " agrees with " << oracle << " now (within " << off
                         << "): delete its line from tests/data/extrude/random/oracle_disagreements.txt";
    return;
  }
  EXPECT_LT(off, 1e-6) << "volume " << r.measures.volume << " (" << times(factor) << ") against " << oracle << "'s "
                       << o.volume;
  if (o.kind == VolumeOracle::Unperturbed) {
    EXPECT_NEAR(r.measures.roofArea, o.roofArea, 1e-6 * o.roofArea) << "roof area against " << oracle << "'s";
  }
}

INSTANTIATE_TEST_SUITE_P(RandomCases, Saved, ::testing::ValuesIn(savedCases()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// The lists name saved cases only, once each, with a known class.
TEST(RandomCases, ListsNameSavedCases) {
  const std::vector<std::string> cases = savedCases();
  ASSERT_FALSE(cases.empty()) << "no cases in " << casesDir();
  const std::set<std::string> saved(cases.begin(), cases.end());
  for (const CaseList* l : {&stillFailing(), &disagreements()}) {
    for (const std::string& p : l->problems) ADD_FAILURE() << p;
    for (const auto& [name, text] : l->entries) EXPECT_TRUE(saved.count(name)) << name << " is listed but not saved";
  }
  for (const auto& [name, cls] : stillFailing().entries)
    EXPECT_TRUE(kClasses.count(cls)) << name << ": unknown class \"" << cls << "\"";
  for (const auto& [name, reason] : disagreements().entries)
    EXPECT_FALSE(stillFailing().entries.count(name)) << name << " is on both lists";
  for (const std::string& p : shellCheckExemptions().problems) ADD_FAILURE() << p;
  // A refused case has no shell to check.
  for (const auto& [name, cls] : stillFailing().entries)
    for (const char* check : {"geometry", "above-skeleton"})
      EXPECT_FALSE(shellCheckExemptions().exempt("random", name, check))
          << name << " is refused and exempt from a shell check";
}

}  // namespace
}  // namespace corbel::extrude::test
