#include "editor/tape_measure.h"

#include "core/scene_pick.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace corbel::editor {

namespace {

// The point of segment [a, b] nearest to p.
Vec3 nearestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = OpenMesh::dot(ab, ab);
  if (!(len2 > 0)) return a;
  const double s = std::clamp(OpenMesh::dot(p - a, ab) / len2, 0.0, 1.0);
  return a + ab * s;
}

}  // namespace

std::optional<TapePoint> tapePoint(const Scene& scene, const Ray& ray, const std::function<double(const Vec3&)>& tolerance,
                                   const std::function<bool(ObjectId)>& visible) {
  const Vec3 d = ray.direction.normalized();
  if (const auto pick = pickScene(scene, ray.origin, d, visible)) {
    const PolyMesh& mesh = scene.mesh();
    const Vec3 hit = ray.origin + d * pick->t;
    const double tol = tolerance ? tolerance(hit) : 0.0;
    std::vector<Vec3> corners;
    for (auto v : mesh.fv_range(pick->face)) corners.push_back(mesh.point(v));
    // The best candidate of each kind, nearest first; kinds in order of preference.
    auto nearest = [&](const std::vector<Vec3>& candidates) -> std::optional<Vec3> {
      std::optional<Vec3> best;
      double bestDistance = tol;
      for (const Vec3& c : candidates) {
        const double dist = (c - hit).norm();
        if (dist <= bestDistance) bestDistance = dist, best = c;
      }
      return best;
    };
    const std::size_t n = corners.size();
    std::vector<Vec3> midpoints, onEdges;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& a = corners[i];
      const Vec3& b = corners[(i + 1) % n];
      midpoints.push_back((a + b) * 0.5);
      onEdges.push_back(nearestOnSegment(hit, a, b));
    }
    if (const auto c = nearest(corners)) return TapePoint{*c, TapePoint::Snap::Corner, pick->object};
    if (const auto c = nearest(midpoints)) return TapePoint{*c, TapePoint::Snap::Midpoint, pick->object};
    if (const auto c = nearest(onEdges)) return TapePoint{*c, TapePoint::Snap::Edge, pick->object};
    return TapePoint{hit, TapePoint::Snap::Face, pick->object};
  }
  // The ground: z = 0 in front of the ray's origin.
  if (std::abs(d[2]) < 1e-12) return std::nullopt;
  const double t = -ray.origin[2] / d[2];
  if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
  Vec3 ground = ray.origin + d * t;
  ground[2] = 0.0;
  return TapePoint{ground, TapePoint::Snap::Ground, 0};
}

const char* snapName(TapePoint::Snap s) {
  switch (s) {
    case TapePoint::Snap::Corner: return "corner";
    case TapePoint::Snap::Midpoint: return "midpoint";
    case TapePoint::Snap::Edge: return "on edge";
    case TapePoint::Snap::Face: return "on face";
    case TapePoint::Snap::Ground: return "on ground";
  }
  return "";
}

void TapeMeasure::click(const TapePoint& p) {
  if (!start_ || end_) {
    start_ = p;
    end_.reset();
  } else {
    end_ = p;
  }
}

void TapeMeasure::clear() {
  start_.reset();
  end_.reset();
}

std::optional<Vec3> TapeMeasure::span() const {
  const auto& e = end();
  if (!start_ || !e) return std::nullopt;
  return e->at - start_->at;
}

std::string TapeMeasure::describe() const {
  const auto s = span();
  if (!s) return "";
  char text[160];
  std::snprintf(text, sizeof text, "%.3f m  (x %.3f, y %.3f, z %.3f)", s->norm(), std::abs((*s)[0]), std::abs((*s)[1]),
                std::abs((*s)[2]));
  return text;
}

int TapeMeasure::axis() const {
  const auto s = span();
  if (!s) return -1;
  const double len = s->norm();
  if (!(len > 0)) return -1;
  const double cosLimit = std::cos(0.01 * M_PI / 180.0);
  for (int k = 0; k < 3; ++k)
    if (std::abs((*s)[k]) / len >= cosLimit) return k;
  return -1;
}

}  // namespace corbel::editor
