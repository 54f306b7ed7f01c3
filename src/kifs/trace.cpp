#include "kifs/trace.h"

#include "kifs/tolerances.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace corbel::kifs {

Ray pixelRay(const glm::dmat4& inverseViewProj, const glm::dvec3& eye, int px, int py, int width, int height) {
  const glm::dvec2 ndc(2.0 * (px + 0.5) / width - 1.0, 2.0 * (py + 0.5) / height - 1.0);
  const glm::dvec4 far = inverseViewProj * glm::dvec4(ndc, 1.0, 1.0);
  return {eye, glm::normalize(glm::dvec3(far) / far.w - eye)};
}

double pixelAngle(double fovDeg, int height) { return 2.0 * std::tan(0.5 * glm::radians(fovDeg)) / height; }

bool rayBox(const Ray& ray, const Aabb& box, double& t0, double& t1) {
  t0 = -1e300;
  t1 = 1e300;
  for (int a = 0; a < 3; ++a) {
    const double inv = 1.0 / ray.dir[a];
    double ta = (box.lo[a] - ray.origin[a]) * inv, tb = (box.hi[a] - ray.origin[a]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t1 >= std::max(t0, 0.0);
}

Hit trace(const Building& building, const Ray& ray, double probe) {
  const Trace& tr = building.params().trace;
  Hit hit;
  auto threshold = [&](double t) { return std::max(tr.hitFactor * tr.pixelAngle * t, kMinHitDistance); };
  double t0 = 0, t1 = 0;
  const bool inBox = rayBox(ray, building.worldBounds(), t0, t1);
  hit.margin = std::abs(t1 - std::max(t0, 0.0)) / threshold(std::max(t0, 0.0));
  if (!inBox) return hit;
  double t = std::max(t0, 0.0), tPrev = t, rPrev = 0.0, omega = tr.overRelax;
  double lastRatio = std::numeric_limits<double>::infinity();
  for (int i = 0; i < tr.maxSteps; ++i) {
    hit.steps = i + 1;
    const Sample s = building.evaluate(ray.origin + t * ray.dir);
    const double r = tr.lipschitz * s.bound;
    const double eps = threshold(t);
    if (probe > 0)
      for (int a = 0; a < 6; ++a) {
        glm::dvec3 d(0.0);
        d[a / 2] = a % 2 ? probe : -probe;
        const Sample n = building.evaluate(ray.origin + t * ray.dir + d);
        hit.wobble = std::max(hit.wobble, std::max(std::abs(n.surface - s.surface), std::abs(n.bound - s.bound)) / eps);
      }
    if (omega > 1.0 && t > tPrev) hit.margin = std::min(hit.margin, std::abs(r + rPrev - (t - tPrev)) / eps);
    if (omega > 1.0 && r + rPrev < t - tPrev) {
      // The spheres before and after the relaxed step do not overlap, so it may have jumped a
      // surface: step plainly from the previous point and relax no more.
      t = tPrev + rPrev;
      omega = 1.0;
      continue;
    }
    hit.margin = std::min(hit.margin, std::abs(s.surface - eps) / eps);
    if (s.surface < eps) {
      hit.hit = true;
      hit.t = t;
      hit.sample = s;
      return hit;
    }
    const double ratio = s.surface / eps;
    if (ratio > lastRatio) hit.closest = std::min(hit.closest, lastRatio);
    lastRatio = ratio;
    tPrev = t;
    rPrev = r;
    t += std::max(omega * r, eps);  // at least eps: cell boundaries make the bound vanish
    hit.margin = std::min(hit.margin, std::abs(t - t1) / eps);
    if (t > t1) return hit;
  }
  return hit;
}

glm::dvec3 normalAt(const Building& building, const glm::dvec3& p, double h) {
  const glm::dvec3 k[4] = {{1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {1, 1, 1}};
  glm::dvec3 n(0.0);
  for (const auto& e : k) n += e * building.evaluate(p + h * e).surface;
  return glm::normalize(n);
}

}  // namespace corbel::kifs
