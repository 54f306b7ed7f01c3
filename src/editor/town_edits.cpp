#include "editor/town_edits.h"

#include "core/error.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>

namespace corbel::editor {

namespace {

TownSpec& townOf(Document& doc, ObjectId id) {
  DocObject* o = doc.find(id);
  TownSpec* t = o ? std::get_if<TownSpec>(&o->spec) : nullptr;
  if (!t) throw Error("object " + std::to_string(id) + " is not a town");
  return *t;
}

// Möller–Trumbore: the ray parameter of a hit on triangle (a, b, c), or nullopt.
std::optional<double> hitTriangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = d % e2;
  const double det = e1 | p;
  if (std::abs(det) < 1e-12) return std::nullopt;
  const Vec3 s = o - a;
  const double u = (s | p) / det;
  if (u < 0 || u > 1) return std::nullopt;
  const Vec3 q = s % e1;
  const double v = (d | q) / det;
  if (v < 0 || u + v > 1) return std::nullopt;
  const double t = (e2 | q) / det;
  return t > 0 ? std::optional<double>(t) : std::nullopt;
}

// Whether the ray meets the box (slab test).
bool hitsBox(const Vec3& o, const Vec3& d, const BBox& box) {
  double lo = 0, hi = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (o[k] < box.lo[k] || o[k] > box.hi[k]) return false;
      continue;
    }
    double t0 = (box.lo[k] - o[k]) / d[k], t1 = (box.hi[k] - o[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
  }
  return lo <= hi;
}

}  // namespace

void setTownOverride(Document& doc, ObjectId id, const std::string& building, const TownOverride& o) {
  TownSpec& t = townOf(doc, id);
  if (o.empty())
    t.overrides.erase(building);
  else
    t.overrides[building] = o;
}

void setTownEdgeProfile(Document& doc, ObjectId id, const std::string& building, int loop, int edge,
                        const std::string& profile) {
  TownSpec& t = townOf(doc, id);
  TownOverride o;
  if (auto it = t.overrides.find(building); it != t.overrides.end()) o = it->second;
  if (profile.empty())
    o.edges.erase(townEdgeKey(loop, edge));
  else
    o.edges[townEdgeKey(loop, edge)] = profile;
  setTownOverride(doc, id, building, o);
}

std::optional<std::pair<int, int>> nearestEdge(const std::vector<std::vector<Vec2>>& loops, const Vec2& p,
                                               double maxDistance) {
  std::optional<std::pair<int, int>> best;
  double bestDistance = maxDistance;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& ring = loops[l];
    for (std::size_t e = 0; e < ring.size(); ++e) {
      const Vec2 a = ring[e], b = ring[(e + 1) % ring.size()], ab = b - a;
      const double len2 = ab | ab;
      const double t = len2 > 0 ? std::clamp(((p - a) | ab) / len2, 0.0, 1.0) : 0.0;
      const double d = (a + t * ab - p).norm();
      if (d < bestDistance || (!best && d <= bestDistance)) {
        bestDistance = d;
        best = std::pair{static_cast<int>(l), static_cast<int>(e)};
      }
    }
  }
  return best;
}

namespace {

void checked(Document& doc, ObjectId id, const TownSpec& changed) {
  if (auto problem = checkTownSpec(changed)) throw Error("town." + *problem);
  townOf(doc, id) = changed;
}

TownStreet& streetOf(TownSpec& t, std::size_t street) {
  if (street >= t.streets.size()) throw Error("the town has no street " + std::to_string(street + 1));
  return t.streets[street];
}

}  // namespace

TownStreet defaultStreet(const city::TownCache& cache, ObjectId object) {
  BBox box;
  for (const city::BuiltBuilding& b : cache.buildings(object))
    if (!b.bounds.empty()) box.lo = box.lo.minimize(b.bounds.lo), box.hi = box.hi.maximize(b.bounds.hi);
  TownStreet st;
  // Its plots reach width/2 + setback + depth = 19 m from the centreline: 20 m keeps them clear.
  const double reach = st.width / 2 + st.setback + st.depth + 1;
  double x0 = 0, x1 = 70, y = -reach;
  if (!box.empty()) {
    x0 = box.lo[0];
    x1 = std::max(box.hi[0], x0 + 30);
    y = box.lo[1] - reach;
  }
  st.points = {{x0, y}, {(x0 + x1) / 2, y}, {x1, y}};
  return st;
}

std::size_t addStreet(Document& doc, ObjectId id, const TownStreet& street) {
  TownSpec t = townOf(doc, id);
  t.streets.push_back(street);
  checked(doc, id, t);
  return t.streets.size() - 1;
}

void setStreet(Document& doc, ObjectId id, std::size_t street, const TownStreet& value) {
  TownSpec t = townOf(doc, id);
  streetOf(t, street) = value;
  checked(doc, id, t);
}

void moveStreetPoint(Document& doc, ObjectId id, std::size_t street, std::size_t point, const Vec2& to) {
  TownSpec t = townOf(doc, id);
  TownStreet& st = streetOf(t, street);
  if (point >= st.points.size())
    throw Error("street " + std::to_string(street + 1) + " has no point " + std::to_string(point + 1));
  st.points[point] = {to[0], to[1]};
  checked(doc, id, t);
}

void removeStreet(Document& doc, ObjectId id, std::size_t street) {
  TownSpec t = townOf(doc, id);
  streetOf(t, street);
  t.streets.erase(t.streets.begin() + std::ptrdiff_t(street));
  // Overrides of its plots, and the numbers of the streets after it, would now mean other plots.
  const std::string prefix = "street ";
  std::map<std::string, TownOverride> kept;
  for (auto& [building, o] : t.overrides) {
    if (building.rfind(prefix, 0) != 0) {
      kept[building] = o;
      continue;
    }
    const std::size_t slash = building.find('/');
    const std::size_t k = std::size_t(std::stoul(building.substr(prefix.size(), slash - prefix.size()))) - 1;
    if (k == street) continue;
    kept[k > street ? prefix + std::to_string(k) + building.substr(slash) : building] = o;
  }
  t.overrides = std::move(kept);
  checked(doc, id, t);
}

std::optional<Vec2> groundPoint(const Vec3& origin, const Vec3& dir) {
  if (!(dir[2] < -1e-9) || !(origin[2] > 0)) return std::nullopt;
  const double t = -origin[2] / dir[2];
  return Vec2(origin[0] + t * dir[0], origin[1] + t * dir[1]);
}

void setTownSpec(Document& doc, ObjectId id, const TownSpec& spec) {
  if (auto problem = checkTownSpec(spec)) throw Error(*problem);
  townOf(doc, id) = spec;
}

std::optional<std::string> pickBuilding(const city::TownCache& cache, ObjectId object, const Vec3& origin,
                                        const Vec3& dir) {
  std::optional<std::string> best;
  double bestT = std::numeric_limits<double>::infinity();
  for (const city::BuiltBuilding& b : cache.buildings(object)) {
    if (b.bounds.empty() || !hitsBox(origin, dir, b.bounds)) continue;
    const MeshData m = cache.mesh(object, b.id);
    for (const auto& f : m.faces)
      for (std::size_t k = 1; k + 1 < f.size(); ++k)  // a fan: faces of a shell are near convex
        if (auto t = hitTriangle(origin, dir, m.points[f[0]], m.points[f[k]], m.points[f[k + 1]]); t && *t < bestT) {
          bestT = *t;
          best = b.id;
        }
  }
  return best;
}

std::vector<std::string> stylesIn(const std::string& folder) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec))
    if (e.path().extension() == ".json") out.push_back(e.path().lexically_normal().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace corbel::editor
