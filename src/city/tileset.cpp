// 3D Tiles: the quadtree, the globe frame and tileset.json (city/tileset.h).
#include "city/tileset.h"

#include "city/local_frame.h"
#include "core/error.h"

#include <proj.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

namespace corbel::city {

namespace {

using json = nlohmann::json;

// Cells under this side are not split (points that coincide would split forever).
constexpr double kSmallestCell = 1.0;

}  // namespace

Quadtree buildQuadtree(const std::vector<Vec2>& points, std::size_t capacity, double maxSide) {
  Quadtree tree;
  tree.leafOf.assign(points.size(), -1);
  if (points.empty()) return tree;
  capacity = std::max<std::size_t>(capacity, 1);
  Vec2 lo = points[0], hi = points[0];
  for (const Vec2& p : points) {
    lo.minimize(p);
    hi.maximize(p);
  }
  // A little over the extent, so the largest coordinates fall inside the root's last cell.
  const double side = std::max({hi[0] - lo[0], hi[1] - lo[1], kSmallestCell}) * (1 + 1e-9) + 1e-6;
  std::vector<int> all(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) all[i] = static_cast<int>(i);
  std::function<int(QuadCell, std::vector<int>)> grow = [&](QuadCell cell, std::vector<int> members) -> int {
    for (;;) {
      if ((members.size() <= capacity && cell.size <= maxSide) || cell.size < kSmallestCell) break;
      std::vector<int> quadrant[4];
      const double half = cell.size / 2;
      for (int i : members) {
        const int qx = points[i][0] >= cell.x0 + half, qy = points[i][1] >= cell.y0 + half;
        quadrant[qx + 2 * qy].push_back(i);
      }
      const int used = static_cast<int>(std::count_if(quadrant, quadrant + 4, [](const auto& q) { return !q.empty(); }));
      const int index = static_cast<int>(tree.cells.size());
      if (used > 1) {
        tree.cells.push_back(cell);
        for (int q = 0; q < 4; ++q) {
          if (quadrant[q].empty()) continue;
          QuadCell child;
          child.level = cell.level + 1;
          child.x = 2 * cell.x + (q & 1);
          child.y = 2 * cell.y + (q >> 1);
          child.size = half;
          child.x0 = cell.x0 + (q & 1) * half;
          child.y0 = cell.y0 + (q >> 1) * half;
          const int c = grow(child, std::move(quadrant[q]));
          tree.cells[index].children.push_back(c);
        }
        return index;
      }
      // One quadrant in use: this cell is that quadrant.
      const int q = static_cast<int>(std::find_if(quadrant, quadrant + 4, [](const auto& v) { return !v.empty(); }) - quadrant);
      cell.level += 1;
      cell.x = 2 * cell.x + (q & 1);
      cell.y = 2 * cell.y + (q >> 1);
      cell.x0 += (q & 1) * half;
      cell.y0 += (q >> 1) * half;
      cell.size = half;
      members = std::move(quadrant[q]);
    }
    const int index = static_cast<int>(tree.cells.size());
    cell.leaf = static_cast<int>(tree.leafCells.size());
    tree.leafCells.push_back(index);
    for (int i : members) tree.leafOf[i] = cell.leaf;
    tree.cells.push_back(cell);
    return index;
  };
  QuadCell root;
  root.x0 = (lo[0] + hi[0]) / 2 - side / 2;
  root.y0 = (lo[1] + hi[1]) / 2 - side / 2;
  root.size = side;
  grow(root, std::move(all));
  return tree;
}

std::array<double, 16> enuToEcef(double lon, double lat, double height) {
  std::unique_ptr<PJ_CONTEXT, decltype(&proj_context_destroy)> context(proj_context_create(), proj_context_destroy);
  char definition[256];
  std::snprintf(definition, sizeof definition, "+proj=topocentric +ellps=WGS84 +lon_0=%.17g +lat_0=%.17g +h_0=%.17g",
                lon, lat, height);
  std::unique_ptr<PJ, decltype(&proj_destroy)> topocentric(proj_create(context.get(), definition), proj_destroy);
  if (!topocentric) throw Error(std::string("PROJ cannot make the east-north-up frame: ") + definition);
  // The conversion is ECEF -> ENU; its inverse places ENU points. It is an exact rotation and
  // translation, so the images of the origin and of the unit vectors give the matrix.
  auto place = [&](double e, double n, double u) {
    PJ_COORD c = proj_coord(e, n, u, 0);
    c = proj_trans(topocentric.get(), PJ_INV, c);
    if (!std::isfinite(c.xyz.x)) throw Error(std::string("PROJ cannot place the east-north-up frame: ") + definition);
    return Vec3(c.xyz.x, c.xyz.y, c.xyz.z);
  };
  const Vec3 o = place(0, 0, 0);
  std::array<double, 16> m{};
  const Vec3 axes[3] = {place(1, 0, 0) - o, place(0, 1, 0) - o, place(0, 0, 1) - o};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[4 * c + r] = axes[c][r];
  for (int r = 0; r < 3; ++r) m[12 + r] = o[r];
  m[15] = 1;
  return m;
}

namespace {

using Matrix = std::array<double, 16>;  // column-major

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
  return m;
}

// The inverse of a rotation and translation.
Matrix rigidInverse(const Matrix& m) {
  Matrix out{};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) out[4 * c + r] = m[4 * r + c];
  for (int r = 0; r < 3; ++r) out[12 + r] = -(m[4 * r] * m[12] + m[4 * r + 1] * m[13] + m[4 * r + 2] * m[14]);
  out[15] = 1;
  return out;
}

Vec3 applyMatrix(const Matrix& m, const Vec3& p) {
  return Vec3(m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12], m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
              m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]);
}

}  // namespace

Vec3 LeafFrame::direction(const Vec3& v) const {
  const double c = std::cos(gamma), s = std::sin(gamma);
  return Vec3(c * v[0] + s * v[1], -s * v[0] + c * v[1], v[2]);
}

Vec3 LeafFrame::operator()(const Vec3& p) const { return direction(p - Vec3(centre[0], centre[1], 0)); }

std::string leafFrameDefinition(const LeafFrame& frame, double height) {
  char definition[256];
  std::snprintf(definition, sizeof definition, "+proj=topocentric +ellps=WGS84 +lon_0=%.17g +lat_0=%.17g +h_0=%.17g",
                frame.lon, frame.lat, height);
  return definition;
}

LeafFrame leafFrame(const std::string& proj, const Vec2& centre, const std::array<double, 16>& root, double height) {
  LeafFrame f;
  f.centre = centre;
  const Vec2 here = toLonLat(proj, centre), north = toLonLat(proj, centre + Vec2(0, 100));
  const Matrix at = enuToEcef(here[0], here[1], height);
  // The local frame's +y at the centre, in the east-north-up frame there.
  const Matrix there = enuToEcef(north[0], north[1], height);
  const Vec3 d = applyMatrix(rigidInverse(at), Vec3(there[12], there[13], there[14]));
  f.gamma = std::atan2(d[0], d[1]);
  f.lon = here[0];
  f.lat = here[1];
  f.toRoot = multiply(rigidInverse(root), at);
  return f;
}

nlohmann::json tilesetJson(const Quadtree& tree, const std::vector<LeafContent>& leaves,
                           const std::array<double, 16>* transform, double pad) {
  auto boxOf = [&](const BBox& b) {
    const Vec3 c = b.center(), h = (b.hi - b.lo) / 2 + Vec3(pad, pad, pad);
    return json{{"box", {c[0], c[1], c[2], h[0], 0, 0, 0, h[1], 0, 0, 0, h[2]}}};
  };
  auto diagonal = [&](const BBox& b) { return (b.hi - b.lo + Vec3(2 * pad, 2 * pad, 2 * pad)).norm(); };
  // A tile per cell (null when its content is empty) and the box it covers.
  std::function<std::pair<json, BBox>(int)> tile = [&](int index) -> std::pair<json, BBox> {
    const QuadCell& cell = tree.cells[index];
    if (cell.leaf >= 0) {
      const LeafContent& c = leaves[cell.leaf];
      if (c.detail.empty()) return {nullptr, BBox()};
      BBox both = c.detail;
      both.add(c.blocks);
      // The box the parent sees: the padded box's corners in the root's frame.
      BBox seen;
      for (int m = 0; m < 8; ++m)
        seen.add(applyMatrix(c.transform, Vec3(m & 1 ? both.hi[0] + pad : both.lo[0] - pad,
                                               m & 2 ? both.hi[1] + pad : both.lo[1] - pad,
                                               m & 4 ? both.hi[2] + pad : both.lo[2] - pad)));
      json detail{{"boundingVolume", boxOf(c.detail)}, {"geometricError", 0}, {"content", {{"uri", c.detailUri}}}};
      json blocks{{"boundingVolume", boxOf(both)},
                  {"geometricError", c.blockError},
                  {"refine", "REPLACE"},
                  {"content", {{"uri", c.blocksUri}}},
                  {"children", json::array({std::move(detail)})}};
      if (c.transform != Matrix{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}) blocks["transform"] = c.transform;
      return {std::move(blocks), seen};
    }
    json children = json::array();
    BBox box;
    for (int child : cell.children) {
      auto [t, b] = tile(child);
      if (t.is_null()) continue;
      children.push_back(std::move(t));
      box.add(b);
    }
    if (children.empty()) return {nullptr, BBox()};
    if (children.size() == 1) return {std::move(children[0]), box};  // no tile with a single child
    return {json{{"boundingVolume", boxOf(box)},
                 {"geometricError", diagonal(box)},
                 {"refine", "REPLACE"},
                 {"children", std::move(children)}},
            box};
  };
  json root = nullptr;
  if (!tree.cells.empty()) root = tile(0).first;
  if (root.is_null())  // nothing was built: an empty tile, which the format allows
    root = json{{"boundingVolume", {{"box", {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}}}}, {"geometricError", 0}};
  if (transform)  // a root that is a leaf has its frame in the root's already
    root["transform"] = root.contains("transform") ? multiply(*transform, root["transform"].get<Matrix>()) : *transform;
  root["refine"] = "REPLACE";
  json out;
  out["asset"] = {{"version", "1.1"}, {"generator", "corbel"}};
  out["geometricError"] = root["geometricError"];
  out["root"] = std::move(root);
  return out;
}

}  // namespace corbel::city
