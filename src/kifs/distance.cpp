#include "kifs/distance.h"

#include "core/error.h"
#include "kifs/mass_field.h"
#include "kifs/tolerances.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace corbel::kifs {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;

glm::dmat3 rotation(const Rotation& r) {
  glm::dmat4 m(1.0);
  m = glm::rotate(m, glm::radians(r.zDeg), glm::dvec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(r.yDeg), glm::dvec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(r.xDeg), glm::dvec3(1, 0, 0));
  return glm::dmat3(m);
}

// The exact distance to a box (negative inside); Eq. 1 is its inside part.
double boxDistance(const glm::dvec3& p, const glm::dvec3& centre, const glm::dvec3& half) {
  const glm::dvec3 q = glm::abs(p - centre) - half;
  return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

}  // namespace

FacadeFold facadeFold(double x, const Facade& fc) {
  double f = std::abs(2.0 * glslMod(x, fc.period) / fc.period - 1.0);
  int id = 0;
  double gap = kInf;
  for (int i = 0; i < 3; ++i) {
    f = std::abs(f - fc.r[i]) - fc.r[i];
    if (f > 0) ++id;
    gap = std::min(gap, std::abs(f));
    f = std::abs(f);
  }
  return {f, id, gap};
}

double massModelDistance(const MassModel& m, const glm::dvec3& b, double inset) {
  const double top = m.height - inset;
  auto box = [&](double cx, double cz, double hx, double hz) {
    return boxDistance(b, glm::dvec3(cx, 0.5 * top, cz), glm::dvec3(hx - inset, 0.5 * top, hz - inset));
  };
  const double hx = m.halfWidth, hz = m.halfDepth, w = m.wing;
  switch (m.footprint) {
    case Footprint::Box: return box(0, 0, hx, hz);
    case Footprint::T: return std::min(box(0, hz - w, hx, w), box(0, 0, w, hz));
    case Footprint::H:
      return std::min({box(-(hx - w), 0, w, hz), box(hx - w, 0, w, hz), box(0, 0, hx, w)});
    case Footprint::Object: break;  // Building::evaluate reads its mass field
  }
  return kInf;
}

Building::Building(const KifsParams& params, std::shared_ptr<const MassField> mass) : p_(params) {
  validate(p_);
  if (p_.mass.footprint == Footprint::Object) {
    if (!mass) throw Error("kifs.mass.object: the building follows a mass object, but no mass was given");
    mass_ = std::move(mass);
  }
  r1_ = rotation(p_.r1);
  r2_ = rotation(p_.r2);
  r1Identity_ = r1_ == glm::dmat3(1.0);  // skipping them changes nothing (I·p = p exactly)
  r2Identity_ = r2_ == glm::dmat3(1.0);
  rho_ = escapeRadius(p_);
  const Facade& fc = p_.facade;
  double maxScale = 0;
  for (int id = 0; id <= 3; ++id) maxScale = std::max(maxScale, std::abs(fc.a1 * id + fc.a2));
  stretch_ = std::max(2.0 * maxScale / fc.period, p_.floors.sy / p_.floors.height);
  idsCut_ = fc.a1 != 0.0 || fc.b1 != 0.0;

  const MassModel& m = p_.mass;
  glm::dvec3 lo(-m.halfWidth, -m.halfDepth, 0.0), hi(m.halfWidth, m.halfDepth, m.height);  // world x, y, z
  if (p_.curvilinear.enabled) {
    const Curvilinear& c = p_.curvilinear;
    ringOuter_ = m.halfDepth / c.sR - c.cR;
    ringInner_ = std::max(0.0, -m.halfDepth / c.sR - c.cR);
    // A ring that closes on itself (docs/kifs.md) has no seam where the angle jumps.
    const double periods = 2.0 * kPi * c.sTheta / fc.period;
    closedRing_ = m.halfWidth - m.shell >= c.sTheta * (kPi + std::abs(c.cTheta)) &&
                  std::abs(periods - std::round(periods)) < 1e-9 * periods;
    lo = glm::dvec3(-ringOuter_, c.z0 - ringOuter_, 0.0);
    hi = glm::dvec3(ringOuter_, c.z0 + ringOuter_, m.height);
    // An arc short of a whole turn: the box of its annular sector (ends and axis crossings).
    const double a0 = -m.halfWidth / c.sTheta - c.cTheta, a1 = m.halfWidth / c.sTheta - c.cTheta;
    if (a1 - a0 < 2 * kPi) {
      lo = glm::dvec3(1e300, 1e300, 0.0);
      hi = glm::dvec3(-1e300, -1e300, m.height);
      std::vector<double> angles = {a0, a1};
      const double first = std::ceil(a0 / (0.5 * kPi)) * 0.5 * kPi;
      for (int q = 0; q < 4; ++q)  // counted, so huge angles (no progress in a += π/2) cannot hang
        if (first + q * 0.5 * kPi < a1) angles.push_back(first + q * 0.5 * kPi);
      for (double a : angles)
        for (double r : {ringInner_, ringOuter_}) {
          const glm::dvec2 q(r * std::cos(a), c.z0 + r * std::sin(a));  // world x, y (building x, z)
          lo = glm::dvec3(std::min(lo.x, q.x), std::min(lo.y, q.y), 0.0);
          hi = glm::dvec3(std::max(hi.x, q.x), std::max(hi.y, q.y), m.height);
        }
    }
  }
  if (mass_) lo = mass_->shell.lo, hi = mass_->shell.hi;  // world x, y, z already
  const double margin = kBoundsMargin * glm::length(hi - lo);
  bounds_ = {lo - margin, hi + margin};
}

// Algorithm 1 (after Knighty): the fold count n, not the loop index, scales the result, and
// line 13 is the continuous fold z ← h − |z − h| (docs/kifs.md).
double Building::kifs(glm::dvec3 p) const {
  const double s = p_.scale, h = 0.5 * p_.centre.z * (s - 1.0);
  const glm::dvec3 c = p_.centre;
  double scl = 1.0;
  for (int i = 0; i <= p_.iterations; ++i) {
    p = glm::abs(r1Identity_ ? p : r1_ * p);
    if (p.x < p.y) std::swap(p.x, p.y);
    if (p.x < p.z) std::swap(p.x, p.z);
    if (p.y < p.z) std::swap(p.y, p.z);
    if (!r2Identity_) p = r2_ * p;
    p.x = s * (p.x - c.x) + c.x;
    p.y = s * (p.y - c.y) + c.y;
    p.z = h - std::abs(s * p.z - h);
    scl *= s;
    if (glm::dot(p, p) > p_.bailout) break;
  }
  return (glm::length(p) - rho_) / scl;
}

namespace {

// Algorithm 1 on the folds of mass-model coordinates m (Algorithm 2, Eq. 4): d_KIFS, and the
// cell the bound may step in. Eq. 4 is a sawtooth, so the storeys are cells. The nearer
// neighbouring storey starts gapNear away, and its own fold (this one shifted by a storey,
// continuous everywhere) bounds the distance to its solid; every other storey is at least
// gapFar away. Facade ids are cells too when they change the transform; they cap the bound at
// their distance. Where d0 ≥ the cell, max(d0, cell) is d0 whatever the neighbour gives, so it
// is not evaluated. `ids` (may be null) receives the ids and the storey.
struct FoldCell {
  double dk, cell;
};
FoldCell foldCell(const Building& building, const glm::dvec3& m, double d0, Sample* ids) {
  const KifsParams& p = building.params();
  const FacadeFold fx = facadeFold(m.x, p.facade), fz = facadeFold(m.z, p.facade);
  const Floors& fl = p.floors;
  const double my = glslMod(m.y - fl.y0, fl.height);  // Eq. 4
  if (ids) {
    ids->idX = fx.id;
    ids->idZ = fz.id;
    ids->floor = static_cast<int>(std::floor((m.y - fl.y0) / fl.height));
  }
  const Facade& fc = p.facade;
  const glm::dvec3 q((fc.a1 * fx.id + fc.a2) * fx.f + fc.b1 * fx.id + fc.b2, fl.sy * my / fl.height,
                     (fc.a1 * fz.id + fc.a2) * fz.f + fc.b1 * fz.id + fc.b2);
  const double stretch = building.fractalStretch();
  const double dk = building.kifs(q) / stretch;
  const bool below = my < 0.5 * fl.height;
  const double gapNear = below ? my : fl.height - my, gapFar = fl.height - gapNear;
  double cell = std::min(dk, gapFar);
  if (gapNear < cell && d0 < cell) {
    glm::dvec3 qn = q;
    qn.y = fl.sy * (below ? my + fl.height : my - fl.height) / fl.height;
    cell = std::min(cell, std::max(gapNear, building.kifs(qn) / stretch));
  }
  if (building.idsCut()) cell = std::min({cell, 0.5 * fx.gap * fc.period, 0.5 * fz.gap * fc.period});
  return {dk, cell};
}

}  // namespace

Sample Building::evaluate(const glm::dvec3& world) const {
  const glm::dvec3 local = mass_ ? mass_->toFrame(world) : world;  // a followed object's frame
  const Curvilinear& cv = p_.curvilinear;
  // Walls that face several ways (kifs/facings.h): the point's facing turns the folds' axes.
  const bool faced = mass_ && !mass_->walls.empty() && !cv.enabled;
  const MassField::FacingAt at = faced ? mass_->facingAt({local.x, local.y}) : MassField::FacingAt{};
  auto building = [&](int facing) {  // building coordinates, y up, in a facing's turn
    if (!faced) return glm::dvec3(local.x, local.z, local.y);
    const glm::dvec2 t = mass_->facings[facing];
    const glm::dvec3 d = world - mass_->frameOrigin;
    return glm::dvec3(t.x * d.x + t.y * d.y, d.z, -t.y * d.x + t.x * d.y);
  };
  const glm::dvec3 b = building(at.facing);
  glm::dvec3 m = b;  // mass-model coordinates
  double radius = 0, ring = -kInf, cut = kInf;
  if (cv.enabled) {  // Eq. 5-6
    const double dx = b.x, dz = b.z - cv.z0;
    radius = std::sqrt(dx * dx + dz * dz);
    m.x = cv.sTheta * (std::atan2(dz, dx) + cv.cTheta);
    m.z = cv.sR * (radius + cv.cR);
    ring = std::max({ringInner_ - radius, radius - ringOuter_, -b.y, b.y - p_.mass.height});
    if (!closedRing_) cut = dx < 0 ? std::abs(dz) : radius;  // the angle jumps on this half-plane
  }
  // A mass object's shell: its baked distance (a lower bound, mass_field.h) is d_o, and d_o +
  // shell bounds the distance to the shell offset inward by `shell` from below (a point of the
  // inner solid has the ball of radius `shell` about it in the outer one), so d_i = d_o + shell.
  const double d0 = mass_ ? mass_->distance(world) : massModelDistance(p_.mass, m, 0.0);
  const double di = mass_ ? d0 + p_.mass.shell : massModelDistance(p_.mass, m, p_.mass.shell);
  Sample out;
  const FoldCell own = foldCell(*this, m, d0, &out);
  double cell = own.cell;
  // Facings are cells as storeys are: the nearest other facing's region starts at.gap away and
  // its own fractal bounds the distance to its solid; every further facing's is at.beyond away.
  if (faced && at.gap < cell && d0 < cell)
    cell = std::min({cell, std::max(at.gap, foldCell(*this, building(at.other), d0, nullptr).cell), at.beyond});
  const double surface = std::min(di, std::max(d0, own.dk));  // g(d_KIFS, d_i, d_o), Sec. 3
  const double bound = std::min(di, std::max(d0, cell));
  if (!cv.enabled) {
    out.surface = surface;
    out.bound = bound;
    return out;
  }
  // Warped distances to world ones: the map stretches by at most max(1, s_r, s_θ / radius).
  auto stretch = [&](double r) { return std::max({1.0, cv.sR, cv.sTheta / std::max(r, kMinRadius)}); };
  const double first = bound / stretch(radius);
  const double safe = bound > 0 ? bound / stretch(radius - first) : first;
  // Outside the annulus holding the building, its distance is a bound of its own.
  out.surface = std::max(ring, surface / stretch(radius));
  out.bound = std::max(ring, std::min(safe, cut));
  return out;
}

}  // namespace corbel::kifs
