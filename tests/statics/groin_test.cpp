// The groin-vault template against independent oracles: the analytic volume of the shell (and
// a numerical integration of it), hand-counted contacts and their areas, the vault's mirror
// and diagonal symmetries, and its statics (it stands thick, fails thin, and its least
// thickness falls as friction grows).
#include "core/error.h"
#include "statics/analysis.h"
#include "statics/equilibrium.h"
#include "statics/examples.h"
#include "statics/groin.h"
#include "statics/thresholds.h"
#include "statics/tolerances.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

namespace corbel::statics {
namespace {

BBox bounds(const Assembly& as) {
  BBox box;
  for (const Block& b : as.blocks)
    for (const Vec3& v : b.vertices) box.add(v);
  return box;
}

double vaultVolume(const Assembly& as) {
  const std::vector<BlockProperties> props = validateAssembly(as, lengthTolerance(bounds(as)));  // every block validates
  double v = 0;
  for (std::size_t i = 0; i < as.blocks.size(); ++i) {
    if (as.blocks[i].fixed) continue;
    EXPECT_GT(props[i].volume, 0) << as.blocks[i].name;
    v += props[i].volume;
  }
  return v;
}

// The true shell by the midpoint rule over one eighth of the square bay (0 ≤ y ≤ x ≤ ro,
// where the web of +x is the cylinder y² + z² ∈ [ri², ro²]), each cell's height integrated
// exactly: an oracle for the closed form that shares nothing with it.
double integratedShell(double ri, double ro, int cells) {
  double v = 0;
  const double h = ro / cells;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const double x = (i + 0.5) * h, y = (j + 0.5) * h;
      if (y > x) continue;
      const double w = y == x ? 0.5 : 1.0;  // the diagonal cells are half inside
      const double top = std::sqrt(std::max(0.0, ro * ro - y * y)), bottom = std::sqrt(std::max(0.0, ri * ri - y * y));
      v += w * (top - bottom) * h * h;
    }
  return 8 * v;
}

Assembly onGround(const GroinVaultSpec& s) {
  GroinVaultSpec g = s;
  g.pierHeight = 0;
  return groinVault(g);
}

TEST(GroinVault, ShellVolumeClosedFormMatchesAnIntegration) {
  GroinVaultSpec s;
  s.radius = 2.0;
  s.thickness = 0.3;
  const double ri = s.radius - s.thickness / 2, ro = s.radius + s.thickness / 2;
  EXPECT_NEAR(integratedShell(ri, ro, 4000) / groinVaultShellVolume(s), 1.0, 1e-4);
}

// Faceted blocks (chords for intrados and extrados) differ from the shell by O(1/N²): the
// error falls about fourfold each time the voussoirs double.
TEST(GroinVault, VolumeConvergesToTheShellAsTheTessellationIsRefined) {
  GroinVaultSpec s;
  s.radius = 2.0;
  s.thickness = 0.3;
  const double shell = groinVaultShellVolume(s);
  double previous = 0;
  for (int n : {8, 16, 32, 64}) {
    s.voussoirs = n;
    s.courses = n / 4;
    const double err = std::abs(vaultVolume(onGround(s)) - shell) / shell;
    std::printf("voussoirs %d courses %d: relative volume error %.3e\n", n, s.courses, err);
    EXPECT_LT(err, 2.0 / (n * n));
    if (previous > 0) {
      EXPECT_GT(previous / err, 3.5);
      EXPECT_LT(previous / err, 4.5);
    }
    previous = err;
  }
  // A rectangular bay is the square one stretched along x: its volume scales with it.
  s.voussoirs = 16;
  s.courses = 4;
  const double square = vaultVolume(onGround(s));
  s.stretch = 1.5;
  EXPECT_NEAR(vaultVolume(onGround(s)), 1.5 * square, 1e-9 * square);
}

std::vector<double> sortedAreas(const Assembly& as) {
  std::vector<double> a;
  for (const Interface& itf : prepareEquilibrium(as, {}).contacts.interfaces) a.push_back(itf.area);
  std::sort(a.begin(), a.end());
  return a;
}

// 4 voussoirs, 1 course: each web is 4 groin blocks (16). Per web: radial joints at 45°, 90°,
// 135° (3), two springings on the ground; per half-diagonal the 2 rows of one web against the
// 2 of the next (8). 12 + 8 + 8 = 28. Areas: the joint at 45° is {r ∈ [ri, ro], x ∈ [r/√2, ro]},
// ro t − (ro² − ri²)/(2√2); at 90° the rectangle ro × t; a springing the triangle t²/2; a
// diagonal contact the section R t sin(π/4) stretched by √2.
TEST(GroinVault, SmallVaultHasTheHandCountedContactsAndAreas) {
  GroinVaultSpec s;
  s.voussoirs = 4;
  s.courses = 1;
  s.radius = 1.0;
  s.thickness = 0.2;
  const double t = s.thickness, R = s.radius, ri = R - t / 2, ro = R + t / 2;
  const Assembly as = onGround(s);
  EXPECT_EQ(as.blocks.size(), 16u + 1);
  std::vector<double> expected;
  for (int i = 0; i < 8; ++i) expected.push_back(ro * t - (ro * ro - ri * ri) / (2 * std::sqrt(2.0)));
  for (int i = 0; i < 4; ++i) expected.push_back(ro * t);
  for (int i = 0; i < 8; ++i) expected.push_back(t * t / 2);
  for (int i = 0; i < 8; ++i) expected.push_back(std::sqrt(2.0) * R * t * std::sin(std::numbers::pi / 4));
  std::sort(expected.begin(), expected.end());
  const std::vector<double> found = sortedAreas(as);
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) EXPECT_NEAR(found[i], expected[i], 1e-9) << i;
}

// 6 voussoirs, 2 courses (planes x = 0, ro/2, ro): rows 2 and 3 (max |y| = ro cos 60° = ro/2)
// have a groin block to ro/2 and one straight course, the other rows a groin block to ro: 8
// blocks a web (32). Per web: 2 course joints; radial joints 1 + 2 + 2 + 2 + 1 = 8; 2
// springings. Per half-diagonal 3 rows against 3 (12). 4 × 12 + 12 = 60.
TEST(GroinVault, CoursesSplitTheRowsNearTheCrown) {
  GroinVaultSpec s;
  s.voussoirs = 6;
  s.courses = 2;
  const Assembly as = onGround(s);
  EXPECT_EQ(as.blocks.size(), 32u + 1);
  EXPECT_EQ(sortedAreas(as).size(), 60u);
}

// Mirror images: the image of a point under x ↦ −x, y ↦ −y and (x, y) ↦ (y, x).
const std::vector<std::function<Vec3(const Vec3&)>>& mirrors() {
  static const std::vector<std::function<Vec3(const Vec3&)>> m = {
      [](const Vec3& p) { return Vec3(-p[0], p[1], p[2]); }, [](const Vec3& p) { return Vec3(p[0], -p[1], p[2]); },
      [](const Vec3& p) { return Vec3(p[1], p[0], p[2]); }};
  return m;
}

// The blocks are symmetric: each has a mirror image of the same volume. The forces the solver
// returns need not be (a standing vault is statically indeterminate: many force fields hold
// it), but the set of fields in equilibrium is: the mirror image of the solution (each
// interface's vertex forces reflected onto its image interface) must balance every block's
// weight as the solution does. That checks the contacts, their frames and areas, and the
// weights against the symmetry without trusting the solver to pick a symmetric field.
TEST(GroinVault, BlocksAndForcesAreSymmetric) {
  GroinVaultSpec s;
  s.voussoirs = 8;
  s.courses = 2;
  s.radius = 1.0;
  s.thickness = 0.25;
  const Assembly as = onGround(s);
  const std::size_t nb = as.blocks.size();
  const std::vector<BlockProperties> props = validateAssembly(as, lengthTolerance(bounds(as)));
  const EquilibriumSystem sys = prepareEquilibrium(as, {});
  const AnalysisResult r = analyse(as);
  ASSERT_TRUE(r.feasible);
  ASSERT_EQ(r.interfaces.size(), sys.contacts.interfaces.size());
  const double W = r.totalWeight;
  // The largest force and moment imbalance over the free blocks of a field given as vertex
  // forces on b (a gets the opposite) at points, per interface.
  struct Load {
    int a, b;
    Vec3 point, force;
  };
  auto imbalance = [&](const std::vector<Load>& loads) {
    std::vector<Vec3> f(nb, Vec3(0.0)), m(nb, Vec3(0.0));
    for (std::size_t i = 0; i < nb; ++i) f[i] = as.gravity * (as.g * as.blocks[i].density * props[i].volume);
    for (const Load& l : loads) {
      f[std::size_t(l.b)] += l.force;
      m[std::size_t(l.b)] += cross(l.point - props[std::size_t(l.b)].centroid, l.force);
      f[std::size_t(l.a)] -= l.force;
      m[std::size_t(l.a)] -= cross(l.point - props[std::size_t(l.a)].centroid, l.force);
    }
    double worst = 0;
    for (std::size_t i = 0; i < nb; ++i)
      if (!as.blocks[i].fixed) worst = std::max({worst, f[i].norm() / W, m[i].norm() / (W * s.radius)});
    return worst;
  };
  std::vector<Load> solution;
  for (std::size_t k = 0; k < r.interfaces.size(); ++k) {
    const Interface& itf = sys.contacts.interfaces[k];
    ASSERT_EQ(itf.a, r.interfaces[k].a);
    ASSERT_EQ(itf.b, r.interfaces[k].b);
    for (const VertexForce& v : r.interfaces[k].vertices)
      solution.push_back({itf.a, itf.b, v.point, itf.normal * v.normal() + itf.t1 * v.t1 + itf.t2 * v.t2});
  }
  EXPECT_LT(imbalance(solution), 1e-7);
  for (const auto& mirror : mirrors()) {
    // Every block has a mirror image of the same volume.
    std::vector<int> image(nb, -1);
    for (std::size_t i = 0; i < nb; ++i) {
      if (as.blocks[i].fixed) {
        image[i] = int(i);
        continue;
      }
      const Vec3 c = mirror(props[i].centroid);
      for (std::size_t j = 0; j < nb; ++j)
        if (!as.blocks[j].fixed && (props[j].centroid - c).norm() < 1e-9 && std::abs(props[j].volume - props[i].volume) < 1e-12)
          image[i] = int(j);
      EXPECT_GE(image[i], 0) << as.blocks[i].name;
    }
    if (std::count(image.begin(), image.end(), -1)) continue;
    std::vector<Load> mirrored;
    for (const Load& l : solution) {
      const Vec3 o = mirror(Vec3(0.0));
      mirrored.push_back({image[std::size_t(l.a)], image[std::size_t(l.b)], mirror(l.point), mirror(l.force) - o});
    }
    EXPECT_LT(imbalance(mirrored), 1e-7);
    // And every interface has a mirror image of the same area.
    for (const Interface& itf : sys.contacts.interfaces) {
      bool found = false;
      for (const Interface& other : sys.contacts.interfaces)
        found = found || ((other.centroid - mirror(itf.centroid)).norm() < 1e-9 && std::abs(other.area - itf.area) < 1e-12);
      EXPECT_TRUE(found);
    }
  }
}

bool stands(double t, double friction, int n = 8) {
  GroinVaultSpec s;
  s.voussoirs = n;
  s.courses = 2;
  s.radius = 1.0;
  s.thickness = t;
  AnalysisOptions o;
  o.friction = friction;
  return checkFeasibility(onGround(s), o).feasible;
}

TEST(GroinVault, StandsThickFailsThin) {
  GroinVaultSpec s;
  s.voussoirs = 8;
  s.courses = 2;
  s.radius = 1.0;
  s.thickness = 0.3;
  const AnalysisResult r = analyse(onGround(s));
  EXPECT_TRUE(r.feasible);
  EXPECT_LE(r.yNormalised, 1e-10);
  EXPECT_LE(r.equilibriumResidual, 1e-8);
  EXPECT_TRUE(stands(0.3, 0.7));
  s.thickness = 0.01;
  const AnalysisResult thin = analyse(onGround(s));
  EXPECT_FALSE(thin.feasible);
  EXPECT_GT(thin.yNormalised, 1e-6);
  EXPECT_FALSE(stands(0.01, 0.7));
}

TEST(GroinVault, LeastThicknessIsSaneAndFallsWithFriction) {
  double previous = 1.0;
  for (double mu : {0.4, 0.7, 1.0}) {
    const double least = bisectThreshold([&](double t) { return stands(t, mu); }, 0.4, 0.005, 1e-4, "thickness");
    std::printf("friction %.1f: least t/R %.4f\n", mu, least);
    EXPECT_LE(least, previous + 1e-4);
    previous = least;
  }
  ArchSpec arch;
  arch.blocks = 8;
  std::printf("the 8-voussoir semicircular arch: least t/R %.4f\n", minimumArchThickness(arch, {}, 1e-4));
}

// Ribs: 4 voussoirs, so each half-diagonal carries a rib of 2, split into halves a (under the
// web of x) and b (its mirror): 16 blocks. Per quadrant: a_k against b_k on the diagonal (2),
// a_0 | a_1 and b_0 | b_1 on the joint at 45° (2), each half under its web's groin block (4),
// the springing halves on the ground (2); and at the crown the quadrants' halves meet on the
// four half-planes x = 0, y = 0 (4): 4 × 10 + 4 = 44 contacts more than the 28 without ribs.
// Their volume is the trapezoids' swept volume (groinVaultRibVolume), checked here against
// the difference of the block volumes.
TEST(GroinVault, RibsAddTheirVolumeAndContactsAndStand) {
  GroinVaultSpec s;
  s.voussoirs = 4;
  s.courses = 1;
  s.radius = 1.0;
  s.thickness = 0.2;
  const double plain = vaultVolume(onGround(s));
  s.ribs = true;
  s.ribWidth = 0.12;
  s.ribDepth = 0.1;
  const Assembly ribbed = onGround(s);
  EXPECT_EQ(ribbed.blocks.size(), 16u + 16u + 1);
  const double ri = s.radius - s.thickness / 2, c = std::cos(std::numbers::pi / 8), h1 = ri * c, h0 = h1 - s.ribDepth;
  const double ribs = 4 * 4 * (s.ribWidth / std::sqrt(2.0)) * std::tan(std::numbers::pi / 8) * (h1 * h1 - h0 * h0);
  EXPECT_NEAR(groinVaultRibVolume(s), ribs, 1e-14);
  EXPECT_NEAR(vaultVolume(ribbed) - plain, ribs, 1e-12);
  EXPECT_EQ(sortedAreas(ribbed).size(), 28u + 44u);
  s.voussoirs = 8;
  s.courses = 2;
  s.thickness = 0.3;
  s.ribWidth = 0.2;
  const AnalysisResult r = analyse(onGround(s));
  EXPECT_TRUE(r.feasible);
  EXPECT_LE(r.equilibriumResidual, 1e-8);
  s.voussoirs = 7;
  EXPECT_THROW(groinVaultBlocks(s), Error);
}

// The example (12 voussoirs, 3 courses): rows 4 and 7 have one straight course, rows 5 and 6
// two, so a web is 12 + 2 (1 + 2) = 18 blocks; 4 webs and 4 piers of 2 drums make 80. On its
// 2 m piers it stands with piers 1.2 m wide (assets/examples/masonry-groin.corbel) and not
// with 0.5 m ones: the webs' thrust at the corners overturns them.
TEST(GroinVault, ExampleCountsAndStandsOnWidePiers) {
  ParametricModel m = exampleByName("groin-vault");
  EXPECT_EQ(m.build(m.parameters).blocks.size(), 80u + 1);
  m.parameters.set("pierWidth", 1.2);
  EXPECT_TRUE(checkFeasibility(m.build(m.parameters)).feasible);
  m.parameters.set("pierWidth", 0.5);
  EXPECT_FALSE(checkFeasibility(m.build(m.parameters)).feasible);
  // With ribs (masonry-groin.corbel): 4 ribs of 6 voussoirs in halves, 48 blocks more. The
  // ribs bear on the piers' inner halves, and 0.8 m piers, which fail without them, stand.
  m.parameters.set("ribs", 1);
  m.parameters.set("pierWidth", 1.2);
  EXPECT_EQ(m.build(m.parameters).blocks.size(), 128u + 1);
  EXPECT_TRUE(checkFeasibility(m.build(m.parameters)).feasible);
  m.parameters.set("pierWidth", 0.8);
  EXPECT_TRUE(checkFeasibility(m.build(m.parameters)).feasible);
  m.parameters.set("ribs", 0);
  EXPECT_FALSE(checkFeasibility(m.build(m.parameters)).feasible);
  GroinVaultSpec bad;
  bad.thickness = -1;
  EXPECT_THROW(groinVaultBlocks(bad), Error);
  bad.thickness = 0.3;
  bad.pierHeight = 1.0;
  bad.pierWidth = 0.1;  // narrower than the vault is thick
  EXPECT_THROW(groinVault(bad), Error);
}

}  // namespace
}  // namespace corbel::statics
