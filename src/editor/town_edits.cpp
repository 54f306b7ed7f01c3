#include "editor/town_edits.h"

#include "core/error.h"

#include <algorithm>
#include <filesystem>
#include <limits>

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
  if (o.empty()) t.overrides.erase(building);
  else t.overrides[building] = o;
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
