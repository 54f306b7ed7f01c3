// Non-convex blocks and contacts, and blocks read from the Scene (materials, nonstructural
// shapes, the ground plane): thresholds computed by hand from centroids and supports.
#include "statics/scene_blocks.h"
#include "core/error.h"
#include "core/scene.h"
#include "statics/analysis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace corbel::statics {
namespace {

using Poly = std::vector<std::array<double, 2>>;

// A prism over the counter-clockwise polygon `base` (x, y), from z0 up to z1.
Block prismXY(const std::string& name, const Poly& base, double z0, double z1, double density = 2400) {
  Block b;
  b.name = name;
  b.density = density;
  const int n = int(base.size());
  for (const auto& p : base) b.vertices.emplace_back(p[0], p[1], z0);
  for (const auto& p : base) b.vertices.emplace_back(p[0], p[1], z1);
  std::vector<int> bottom, top;
  for (int i = n - 1; i >= 0; --i) bottom.push_back(i);
  for (int i = 0; i < n; ++i) top.push_back(n + i);
  b.faces = {bottom, top};
  for (int i = 0; i < n; ++i) b.faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
  return b;
}

// The same prism with y and z exchanged: `base` in the (x, z) plane, from y0 to y1. The swap is
// a reflection, so every face loop is reversed to keep it outward.
Block prismXZ(const std::string& name, const Poly& base, double y0, double y1, double density = 2400) {
  Block b = prismXY(name, base, y0, y1, density);
  for (Vec3& v : b.vertices) std::swap(v[1], v[2]);
  for (auto& f : b.faces) std::reverse(f.begin(), f.end());
  return b;
}

Block ground() { return boxBlock("ground", Vec3(-10, -10, -1), Vec3(10, 10, 0), 1.0, true); }

bool stands(const Assembly& as) { return checkFeasibility(as).feasible; }

// An L in the (x, z) plane: a leg x ∈ [0, 1] from the ground to z = 3 and an arm at z ∈ [2, 3]
// reaching to x = a. Its centroid is at x = (1.5 + (a² − 1)/2)/(a + 2), over the leg's base
// while a ≤ 1 + √3.
Poly lShape(double a) { return {{0, 0}, {1, 0}, {1, 2}, {a, 2}, {a, 3}, {0, 3}}; }

TEST(NonConvexBlocks, AnLShapedBlockHasTheLsVolumeAndCentroid) {
  Assembly as;
  as.blocks = {ground(), prismXZ("L", lShape(2.5), 0, 1)};
  const std::vector<BlockProperties> p = validateAssembly(as, 1e-9);
  EXPECT_FALSE(p[1].convex);
  EXPECT_NEAR(p[1].volume, 2.5 + 2, 1e-12);  // area 3 + (a − 1)·1
  EXPECT_NEAR(p[1].centroid[0], (1.5 + (2.5 * 2.5 - 1) / 2) / 4.5, 1e-12);
  EXPECT_NEAR(p[1].centroid[1], 0.5, 1e-12);
}

TEST(NonConvexBlocks, AnLShapedBlockTipsWhereItsCentroidLeavesItsBase) {
  const double critical = 1 + std::sqrt(3.0);
  for (double a : {critical - 0.02, critical + 0.02}) {
    Assembly as;
    as.blocks = {ground(), prismXZ("L", lShape(a), 0, 1)};
    EXPECT_EQ(stands(as), a < critical) << "arm to x = " << a;
    const AnalysisResult r = analyse(as);
    EXPECT_EQ(r.feasible, a < critical) << "arm to x = " << a;
    EXPECT_LE(r.equilibriumResidual, 1e-8);
  }
}

// Two L-shaped prisms (plan: a 2 × 2 square less one unit corner), the upper one turned by a
// half turn: their faces overlap in two unit squares that touch at one corner.
TEST(NonConvexContacts, TwoLsMeetInTheirExactOverlapAndCarryLoadAcrossBoth) {
  const Poly lower = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};  // less [1,2]²
  const Poly upper = {{1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 1}, {1, 1}};  // less [0,1]²
  Assembly as;
  as.blocks = {ground(), prismXY("lower", lower, 0, 1), prismXY("upper", upper, 1, 2)};
  const std::vector<BlockProperties> props = validateAssembly(as, 1e-9);
  const Contacts c = findContacts(as, props, 1e-9, 0.0);
  double overlap = 0, onGround = 0;
  int pieces = 0;
  for (const Interface& itf : c.interfaces) {
    if (itf.a == 1 && itf.b == 2) overlap += itf.area, ++pieces;
    if (itf.a == 0 && itf.b == 1) onGround += itf.area;
  }
  EXPECT_NEAR(onGround, 3.0, 1e-12);  // the whole L on the ground
  EXPECT_NEAR(overlap, 2.0, 1e-12);   // [1,2]×[0,1] and [0,1]×[1,2]
  EXPECT_GE(pieces, 1);               // CGAL may give one boundary pinched at (1, 1): the same force points
  // The upper L's centroid (7/6, 7/6) lies in the convex hull of the two squares (x + y ≤ 3)
  // but inside neither: it stands only if both pieces carry force.
  const AnalysisResult r = analyse(as);
  EXPECT_TRUE(r.feasible);
  EXPECT_LE(r.equilibriumResidual, 1e-8);
  double carried = 0;
  for (const InterfaceForces& f : r.interfaces)
    if (f.a == 1 && f.b == 2) {
      carried += f.normalForce;
      EXPECT_GT(f.normalForce, 0);  // each piece in compression
      EXPECT_LE(f.pressureGauge, 1.0 + 1e-9);
    }
  EXPECT_NEAR(carried, 3.0 * 2400 * 9.81, 1e-6 * 3.0 * 2400 * 9.81);  // the upper L's weight
  EXPECT_TRUE(stands(as));
}

TEST(NonConvexBlocks, AFaceWhoseEdgesCrossIsRefusedByName) {
  Assembly as;
  Block bow = prismXY("bow tie", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0, 1);
  std::swap(bow.vertices[6], bow.vertices[7]);  // the top face's loop now crosses itself
  as.blocks = {ground(), bow};
  try {
    validateAssembly(as, 1e-9);
    FAIL() << "accepted a self-crossing face";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bow tie"), std::string::npos) << e.what();
  }
}

// ---- Blocks from the Scene ----

MeshData meshOf(const std::vector<Block>& blocks, const std::string& material, const std::string& tag = "") {
  MeshData m;
  const int mat = m.addMaterial(material), t = tag.empty() ? 0 : m.addTag(tag);
  for (const Block& b : blocks) {
    const int first = int(m.points.size());
    for (const Vec3& v : b.vertices) m.addPoint(v);
    for (const auto& f : b.faces) {
      std::vector<int> loop;
      for (int v : f) loop.push_back(first + v);
      m.addFace(loop, t, mat);
    }
  }
  return m;
}

TEST(SceneBlocks, EachPieceOfABlockObjectIsABlockAndTheMeasureMatchesTheModel) {
  // A stack of three unit cubes, each shifted by s further: the top cube stands on the middle
  // one while s ≤ 1/2, the upper pair (centroid at 0.5 + 1.5 s) on the bottom one while
  // s ≤ 1/3. Scene and model must agree on the QP's y to rounding.
  for (double shift : {0.3, 0.55}) {
    std::vector<Block> cubes;
    for (int k = 0; k < 3; ++k) cubes.push_back(boxBlock("c", Vec3(k * shift, 0, k), Vec3(k * shift + 1, 1, k + 1)));
    Scene scene;
    scene.replaceObject(1, Kind::Block, "stack", meshOf(cubes, "stone"));
    const SceneAssembly s = assemblyFromScene(scene);
    ASSERT_EQ(s.assembly.blocks.size(), 4u);  // three pieces and the ground plane
    EXPECT_TRUE(s.groundPlaneAdded);
    EXPECT_EQ(s.assembly.blocks[1].name, "stack piece 1");
    Assembly model;
    model.blocks = cubes;
    model.blocks.push_back(ground());
    const AnalysisResult fromScene = analyse(s.assembly), fromModel = analyse(model);
    EXPECT_EQ(fromScene.feasible, shift < 1.0 / 3) << shift;
    EXPECT_EQ(fromModel.feasible, shift < 1.0 / 3) << shift;
    EXPECT_NEAR(fromScene.yNormalised, fromModel.yNormalised, 1e-9 + 1e-6 * fromModel.yNormalised);
    EXPECT_NEAR(fromScene.totalWeight, 3 * 2400 * 9.81, 1e-9);
  }
}

// A seesaw: a plank x ∈ [−2, 2] (0.2 thick) on a column x ∈ [−0.5, 0.5], a unit cube on each
// end. It stands while the centroid of plank and cubes, X = 1.5 (ρR − ρL) / (ρL + ρR + 0.8 ρP),
// lies over the column: |X| ≤ 0.5.
Scene seesaw(const std::string& left, const std::string& right) {
  Scene scene;
  scene.replaceObject(1, Kind::Block, "column", meshOf({boxBlock("", Vec3(-0.5, 0, 0), Vec3(0.5, 1, 1))}, "stone"));
  scene.replaceObject(2, Kind::Block, "plank", meshOf({boxBlock("", Vec3(-2, 0, 1), Vec3(2, 1, 1.2))}, "timber"));
  scene.replaceObject(3, Kind::Block, "left", meshOf({boxBlock("", Vec3(-2, 0, 1.2), Vec3(-1, 1, 2.2))}, left));
  scene.replaceObject(4, Kind::Block, "right", meshOf({boxBlock("", Vec3(1, 0, 1.2), Vec3(2, 1, 2.2))}, right));
  return scene;
}

TEST(SceneBlocks, DensityByMaterialDecidesWhetherASeesawStands) {
  auto centroid = [](double l, double r) { return 1.5 * (r - l) / (l + r + 0.8 * 600); };
  // Stone against timber: X = −0.78, it tips; stone on both ends: X = 0; with timber given
  // stone's density, stands again.
  ASSERT_GT(std::abs(centroid(2400, 600)), 0.5);
  const SceneAssembly mixed = assemblyFromScene(seesaw("stone", "timber"));
  EXPECT_DOUBLE_EQ(mixed.assembly.blocks[2].density, 2400);
  EXPECT_DOUBLE_EQ(mixed.assembly.blocks[3].density, 600);
  EXPECT_FALSE(stands(mixed.assembly));
  EXPECT_NEAR(analyse(mixed.assembly).totalWeight, (2400 * 1 + 600 * 0.8 + 2400 + 600) * 9.81, 1e-6);
  EXPECT_TRUE(stands(assemblyFromScene(seesaw("stone", "stone")).assembly));
  SceneBlockOptions heavyTimber;
  heavyTimber.densities["timber"] = 2400;
  EXPECT_TRUE(stands(assemblyFromScene(seesaw("stone", "timber"), heavyTimber).assembly));
  // Brick (1,900) against stone: X = −0.17, within the column.
  ASSERT_LT(std::abs(centroid(2400, 1900)), 0.5);
  EXPECT_TRUE(stands(assemblyFromScene(seesaw("stone", "brick")).assembly));
}

// A column x ∈ [0, 1] on the ground and a statue x ∈ [0.8, 2.8] (0.4 deep, 0.5 high) on it.
// As a block the statue tips (its centroid 1.8 is past the column's edge). Carried as a load
// it cannot tip by itself; column and statue stand while their centroid
// X = (0.5 ρc + 1.8 · 0.4 ρs) / (ρc + 0.4 ρs) is over the column: stone 0.87, metal 1.24.
Scene statue(const std::string& material, bool tagged) {
  Scene scene;
  scene.replaceObject(1, Kind::Block, "column", meshOf({boxBlock("", Vec3(0, 0, 0), Vec3(1, 1, 1))}, "stone"));
  scene.replaceObject(
      2, Kind::Block, "statue",
      meshOf({boxBlock("", Vec3(0.8, 0.3, 1), Vec3(2.8, 0.7, 1.5))}, material, tagged ? "nonstructural" : ""));
  return scene;
}

TEST(SceneBlocks, ANonstructuralShapeIsCarriedAsALoadWithoutContactsOfItsOwn) {
  EXPECT_FALSE(stands(assemblyFromScene(statue("stone", false)).assembly));
  const SceneAssembly carried = assemblyFromScene(statue("stone", true));
  ASSERT_EQ(carried.assembly.blocks.size(), 2u);  // the column and the ground plane
  EXPECT_EQ(carried.nonstructuralPieces, 1);
  EXPECT_NEAR(carried.nonstructuralWeight, 2400 * 0.4 * 9.81, 1e-9);
  ASSERT_EQ(carried.assembly.blocks[0].pointLoads.size(), 1u);
  EXPECT_NEAR(carried.assembly.blocks[0].pointLoads[0].at[0], 1.8, 1e-12);
  EXPECT_TRUE(stands(carried.assembly));
  const AnalysisResult r = analyse(carried.assembly);
  EXPECT_TRUE(r.feasible);
  ASSERT_EQ(r.interfaces.size(), 1u);  // column on the ground only
  // The ground carries column and statue; their centre of pressure is their centroid.
  EXPECT_NEAR(r.interfaces[0].normalForce, (2400 + 2400 * 0.4) * 9.81, 1e-6);
  EXPECT_NEAR(r.interfaces[0].centreOfPressure[0], (0.5 + 1.8 * 0.4) / 1.4, 1e-6);
  // A metal statue moves the centroid past the column's edge.
  EXPECT_FALSE(stands(assemblyFromScene(statue("metal", true)).assembly));
  // Listed by object instead of tagged: the same.
  SceneBlockOptions o;
  o.nonstructural = {2};
  o.objects = {1};
  EXPECT_TRUE(stands(assemblyFromScene(statue("stone", false), o).assembly));
}

TEST(SceneBlocks, ANonstructuralBeamOnTwoColumnsIsSharedByContactArea) {
  Scene scene;
  scene.replaceObject(
      1, Kind::Block, "columns",
      meshOf({boxBlock("", Vec3(0, 0, 0), Vec3(1, 1, 2)), boxBlock("", Vec3(3, 0, 0), Vec3(3.5, 1, 2))}, "stone"));
  scene.replaceObject(2, Kind::Block, "beam",
                      meshOf({boxBlock("", Vec3(0, 0, 2), Vec3(3.5, 1, 2.5))}, "timber", "nonstructural"));
  const SceneAssembly s = assemblyFromScene(scene);
  const double w = 600 * 3.5 * 0.5 * 9.81;
  ASSERT_EQ(s.assembly.blocks[0].pointLoads.size(), 1u);
  ASSERT_EQ(s.assembly.blocks[1].pointLoads.size(), 1u);
  EXPECT_NEAR(-s.assembly.blocks[0].pointLoads[0].force[2], w * 1.0 / 1.5, 1e-9);  // contact areas 1 and 0.5
  EXPECT_NEAR(-s.assembly.blocks[1].pointLoads[0].force[2], w * 0.5 / 1.5, 1e-9);
  EXPECT_NEAR(s.assembly.blocks[1].pointLoads[0].at[0], 3.25, 1e-12);
  EXPECT_TRUE(stands(s.assembly));
}

std::string errorOf(const Scene& scene, const SceneBlockOptions& o = {}) {
  try {
    assemblyFromScene(scene, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SceneBlocks, BadScenesAreRefusedNamingTheObject) {
  Scene open;
  MeshData m = meshOf({boxBlock("", Vec3(0, 0, 0), Vec3(1, 1, 1))}, "stone");
  m.faces.pop_back(), m.faceTag.pop_back(), m.faceMaterial.pop_back();
  open.replaceObject(1, Kind::Block, "lidless", m);
  EXPECT_NE(errorOf(open).find("lidless\": the surface is not closed"), std::string::npos) << errorOf(open);
  Scene lawn;
  lawn.replaceObject(1, Kind::Block, "lawn", meshOf({boxBlock("", Vec3(0, 0, 0), Vec3(1, 1, 1))}, "grass"));
  EXPECT_NE(errorOf(lawn).find("\"grass\" has no density"), std::string::npos) << errorOf(lawn);
  Scene floating = statue("stone", true);
  floating.replaceObject(2, Kind::Block, "kite",
                         meshOf({boxBlock("", Vec3(0, 0, 3), Vec3(1, 1, 4))}, "timber", "nonstructural"));
  EXPECT_NE(errorOf(floating).find("kite\" rests on no structural block"), std::string::npos) << errorOf(floating);
  Scene empty;
  EXPECT_NE(errorOf(empty).find("no blocks"), std::string::npos) << errorOf(empty);
  SceneBlockOptions o;
  o.densities["stone"] = std::nan("");
  EXPECT_NE(errorOf(statue("stone", false), o).find("positive"), std::string::npos);
}

}  // namespace
}  // namespace corbel::statics
