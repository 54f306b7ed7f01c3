// massing.h: buildBoxes against the analytic measures of a (rotated, repeated) box.
#include "core/massing.h"

#include "core/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <set>

namespace {

using corbel::BoxSpec;
using corbel::Kind;
using corbel::MeshData;
using corbel::Scene;
using corbel::Vec3;

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

Vec3 centroid(const MeshData& m, const std::vector<int>& loop) {
  Vec3 c(0.0);
  for (int i : loop) c += m.points[i];
  return c / static_cast<double>(loop.size());
}

Vec3 unitNormal(const MeshData& m, const std::vector<int>& loop) {
  std::vector<Vec3> poly;
  for (int i : loop) poly.push_back(m.points[i]);
  return corbel::newellNormal(poly).normalized();
}

// Splits a soup into pieces connected through shared point indices (union-find).
std::vector<MeshData> components(const MeshData& m) {
  std::vector<int> parent(m.points.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& f : m.faces)
    for (int i : f) parent[find(i)] = find(f[0]);
  std::map<int, MeshData> pieces;
  std::map<int, std::map<int, int>> remap;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const int root = find(m.faces[f][0]);
    MeshData& piece = pieces[root];
    std::vector<int> loop;
    for (int i : m.faces[f]) {
      auto [it, fresh] = remap[root].try_emplace(i, 0);
      if (fresh) it->second = piece.addPoint(m.points[i]);
      loop.push_back(it->second);
    }
    piece.addFace(loop, piece.addTag(m.tags[m.faceTag[f]]), piece.addMaterial(m.materials[m.faceMaterial[f]]));
  }
  std::vector<MeshData> out;
  for (auto& [root, piece] : pieces) out.push_back(std::move(piece));
  return out;
}

TEST(Massing, RotatedBoxHasAnalyticVolumeAreaAndExtents) {
  for (double deg : {0.0, 30.0, 90.0, -45.0}) {
    SCOPED_TRACE("rotation " + std::to_string(deg));
    BoxSpec spec;
    spec.origin = Vec3(4, -3, 1.5);
    spec.size = Vec3(10, 6, 4);
    spec.rotation_deg = deg;
    const MeshData m = buildBoxes(spec);
    EXPECT_EQ(m.points.size(), 8u);
    EXPECT_EQ(m.faces.size(), 6u);
    Scene s;
    s.replaceObject(1, Kind::Mass, "box", m);
    const auto r = s.validate(1);
    EXPECT_TRUE(r.closedManifold());
    EXPECT_EQ(r.euler, 2);
    EXPECT_NEAR(r.volume, 10.0 * 6 * 4, 1e-9 * 240);
    EXPECT_NEAR(r.area, 2.0 * (60 + 24 + 40), 1e-9 * 248);

    // Half extents of a rectangle rotated by a: |cos a| hx + |sin a| hy, |sin a| hx + |cos a| hy.
    const double c = std::abs(std::cos(rad(deg))), sn = std::abs(std::sin(rad(deg)));
    const double ex = c * 5 + sn * 3, ey = sn * 5 + c * 3;
    const corbel::BBox b = s.bounds(1);
    EXPECT_NEAR(b.lo[0], 4 - ex, 1e-12 * 10);
    EXPECT_NEAR(b.hi[0], 4 + ex, 1e-12 * 10);
    EXPECT_NEAR(b.lo[1], -3 - ey, 1e-12 * 10);
    EXPECT_NEAR(b.hi[1], -3 + ey, 1e-12 * 10);
    EXPECT_DOUBLE_EQ(b.lo[2], 1.5);
    EXPECT_DOUBLE_EQ(b.hi[2], 5.5);
  }
}

TEST(Massing, CornersAreTheRotatedLocalCorners) {
  // Every point is origin + R(a) (±hx, ±hy) at z0 or z0 + h, and all eight appear.
  BoxSpec spec;
  spec.origin = Vec3(-2, 7, 0);
  spec.size = Vec3(3, 1, 2);
  spec.rotation_deg = 30;
  const MeshData m = buildBoxes(spec);
  const double a = rad(30), c = std::cos(a), sn = std::sin(a);
  int matched = 0;
  for (double lx : {-1.5, 1.5})
    for (double ly : {-0.5, 0.5})
      for (double z : {0.0, 2.0}) {
        const Vec3 expected(-2 + c * lx - sn * ly, 7 + sn * lx + c * ly, z);
        for (const Vec3& p : m.points)
          if ((p - expected).norm() < 1e-12) ++matched;
      }
  EXPECT_EQ(matched, 8);
}

TEST(Massing, TagsAndOutwardNormals) {
  BoxSpec spec;
  spec.size = Vec3(8, 5, 3);
  spec.rotation_deg = 30;
  spec.material = "brick";
  const MeshData m = buildBoxes(spec);
  std::map<std::string, int> count;
  const Vec3 centre(0, 0, 1.5);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const std::string& tag = m.tags[m.faceTag[f]];
    ++count[tag];
    EXPECT_EQ(m.materials[m.faceMaterial[f]], "brick");
    const Vec3 n = unitNormal(m, m.faces[f]);
    if (tag == "roof") {
      EXPECT_NEAR(n[2], 1.0, 1e-12);
      EXPECT_NEAR(centroid(m, m.faces[f])[2], 3.0, 1e-12);
    } else if (tag == "base") {
      EXPECT_NEAR(n[2], -1.0, 1e-12);
      EXPECT_NEAR(centroid(m, m.faces[f])[2], 0.0, 1e-12);
    } else {
      EXPECT_EQ(tag, "wall");
      EXPECT_NEAR(n[2], 0.0, 1e-12);
      // Outward: the normal points away from the box's centre.
      EXPECT_GT(OpenMesh::dot(n, centroid(m, m.faces[f]) - centre), 0.0);
    }
  }
  EXPECT_EQ(count["wall"], 4);
  EXPECT_EQ(count["roof"], 1);
  EXPECT_EQ(count["base"], 1);
}

TEST(Massing, RepeatMakesOneClosedComponentPerCopy) {
  BoxSpec spec;
  spec.origin = Vec3(100, 50, 2);
  spec.size = Vec3(6, 8, 5);
  spec.rotation_deg = 30;
  spec.repeat_x = 3;
  spec.repeat_y = 2;
  spec.spacing_x = 7;
  spec.spacing_y = 10;
  const MeshData m = buildBoxes(spec);
  EXPECT_EQ(m.faces.size(), 36u);

  std::map<std::string, int> tags;
  for (int t : m.faceTag) ++tags[m.tags[t]];
  EXPECT_EQ(tags["wall"], 24);
  EXPECT_EQ(tags["roof"], 6);
  EXPECT_EQ(tags["base"], 6);

  Scene whole;
  whole.replaceObject(1, Kind::Mass, "row", m);
  const auto all = whole.validate(1);
  EXPECT_EQ(all.components, 6u);
  EXPECT_EQ(all.euler, 12);
  EXPECT_TRUE(all.closedManifold());
  EXPECT_NEAR(all.volume, 6 * 240.0, 1e-9 * 1440);

  // Expected copy centres: the grid (i - 1) * 7, (j - 0.5) * 10 rotated by 30 degrees.
  const double c = std::cos(rad(30)), sn = std::sin(rad(30));
  std::vector<Vec3> expectedCentres;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const double lx = (i - 1) * 7.0, ly = (j - 0.5) * 10.0;
      expectedCentres.emplace_back(100 + c * lx - sn * ly, 50 + sn * lx + c * ly, 2 + 2.5);
    }

  const auto pieces = components(m);
  ASSERT_EQ(pieces.size(), 6u);
  std::set<int> matchedCentres;
  for (const MeshData& piece : pieces) {
    EXPECT_EQ(piece.points.size(), 8u);
    EXPECT_EQ(piece.faces.size(), 6u);
    Scene s;
    s.replaceObject(1, Kind::Mass, "copy", piece);
    const auto r = s.validate(1);
    EXPECT_TRUE(r.closedManifold());
    EXPECT_EQ(r.components, 1u);
    EXPECT_EQ(r.euler, 2);
    EXPECT_NEAR(r.volume, 240.0, 1e-9 * 240);
    Vec3 centre(0.0);
    for (const Vec3& p : piece.points) centre += p / 8.0;
    for (std::size_t k = 0; k < expectedCentres.size(); ++k)
      if ((centre - expectedCentres[k]).norm() < 1e-9) matchedCentres.insert(static_cast<int>(k));
  }
  EXPECT_EQ(matchedCentres.size(), 6u);
}

TEST(Massing, TouchingCopiesStaySeparateComponents) {
  // Spacing equal to the width: neighbours touch but share no points.
  BoxSpec spec;
  spec.size = Vec3(2, 2, 2);
  spec.repeat_x = 4;
  spec.spacing_x = 2;
  const MeshData m = buildBoxes(spec);
  EXPECT_EQ(components(m).size(), 4u);
  Scene s;
  s.replaceObject(1, Kind::Mass, "row", m);
  EXPECT_EQ(s.validate(1).components, 4u);
  EXPECT_TRUE(s.validate(1).closedManifold());
  EXPECT_NEAR(s.bounds(1).lo[0], -4.0, 1e-12);
  EXPECT_NEAR(s.bounds(1).hi[0], 4.0, 1e-12);
}

}  // namespace
