#include "editor/unit_edits.h"

#include "core/error.h"
#include "growth/collide.h"
#include "growth/site.h"
#include "growth/tolerances.h"
#include "growth/unit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::editor {

namespace {

// A box of the frame `from` in the frame `to`, when a quarter turn and no change of scale lie
// between them (then it stays axis-aligned).
std::optional<growth::Box> boxInto(const Placement& from, const Placement& to, const growth::Box& b) {
  if (std::abs(std::remainder(from.rotation_deg - to.rotation_deg, 90.0)) > 1e-9 || from.scale != to.scale)
    return std::nullopt;
  if (from == to) return b;  // one frame: no rounding
  const Vec3 a = to.unapply(from.apply(b.lo)), c = to.unapply(from.apply(b.hi));
  growth::Box out;
  for (int k = 0; k < 3; ++k) {
    out.lo[k] = std::min(a[k], c[k]);
    out.hi[k] = std::max(a[k], c[k]);
  }
  return out;
}

const UnitSpec& unitOf(const Document& doc, ObjectId id, const char* what) {
  const DocObject* o = doc.find(id);
  const auto* u = o ? std::get_if<UnitSpec>(&o->spec) : nullptr;
  if (!u) throw InputError(what, "the object is not a unit");
  return *u;
}

growth::Unit toUnit(const UnitSpec& spec) {
  growth::Unit u;
  u.id = 1;
  for (const UnitPart& p : spec.parts) u.parts.push_back({p.lo, p.hi});
  return u;
}

std::vector<UnitPart> toParts(const growth::Unit& u) {
  std::vector<UnitPart> parts;
  for (const growth::Box& b : u.parts) parts.push_back({b.lo, b.hi});
  return parts;
}

// The storeys a unit's floors and ceilings move by, and the ground: those of the growth site it
// was frozen from or grows beside (a growth object with around_units first, then any whose site
// parses), else its lowest part's height (parts are one or two storeys) over z = 0.
struct Storeys {
  double height = 3.0, ground = 0.0;
};
Storeys storeysOf(const Document& doc, const UnitSpec& spec) {
  for (const bool around : {true, false})
    for (const DocObject& o : doc.objects)
      if (const auto* g = std::get_if<GrowthSpec>(&o.spec); g && g->aroundUnits == around) {
        try {
          const growth::Site site = growth::parseSite(g->site);
          return {site.storeyHeight, site.base};
        } catch (const std::exception&) {
          // a site that does not parse has its own error
        }
      }
  Storeys out;
  out.height = INFINITY;
  for (const UnitPart& p : spec.parts) out.height = std::min(out.height, p.hi[2] - p.lo[2]);
  return out;
}

}  // namespace

std::vector<growth::Box> obstaclesAround(const Document& doc, ObjectId id) {
  std::vector<growth::Box> out;
  const DocObject* self = doc.find(id);
  if (!self) return out;
  auto add = [&](const Placement& from, const growth::Box& b) {
    if (auto into = boxInto(from, self->placement, b)) out.push_back(*into);
  };
  for (const DocObject& o : doc.objects) {
    if (o.id == id) continue;
    if (const auto* u = std::get_if<UnitSpec>(&o.spec)) {
      for (const UnitPart& p : u->parts) add(o.placement, {p.lo, p.hi});
    } else if (const auto* g = std::get_if<GrowthSpec>(&o.spec)) {
      try {
        const growth::Site site = growth::parseSite(g->site);
        for (std::size_t i = 0; i < site.cores.size(); ++i) add(o.placement, site.coreBox(i));
        for (const growth::Box& c : site.circulation) add(o.placement, c);
      } catch (const std::exception&) {
        // a site that does not parse has its own error; it stands in nothing's way
      }
    }
  }
  return out;
}

Document pushUnitFace(const Document& doc, ObjectId id, int part, growth::Side side, double distance) {
  const UnitSpec& spec = unitOf(doc, id, "push");
  if (!std::isfinite(distance)) throw InputError("push", "the distance must be a number");
  std::string why;
  std::optional<growth::Extruded> e;
  if (growth::sideAxis(side) == 2) {
    const Storeys storeys = storeysOf(doc, spec);
    const double n = std::round(distance / storeys.height);
    if (std::abs(n) > 2) throw InputError("push", "a floor or ceiling moves by one or two storeys");
    e = growth::moveFloorOrCeiling(toUnit(spec), part, side, int(n), storeys.height, obstaclesAround(doc, id), storeys.ground, &why);
  } else {
    e = growth::collideAndExtrude(toUnit(spec), part, side, distance, obstaclesAround(doc, id), kUnitLeast, &why);
  }
  if (!e) throw InputError("push", why);
  Document out = doc;
  std::get<UnitSpec>(out.find(id)->spec).parts = toParts(e->unit);
  return out;
}

Document splitUnit(const Document& doc, ObjectId id, int axis, double at, ObjectId* added) {
  const UnitSpec& spec = unitOf(doc, id, "split");
  if (axis != 0 && axis != 1) throw InputError("split", "the plane is x or y");
  if (!std::isfinite(at)) throw InputError("split", "the plane's position must be a number");
  UnitSpec low = spec, high = spec;
  low.parts.clear();
  high.parts.clear();
  for (const UnitPart& p : spec.parts) {
    if (p.hi[axis] <= at + growth::kEps) {
      low.parts.push_back(p);
    } else if (p.lo[axis] >= at - growth::kEps) {
      high.parts.push_back(p);
    } else {
      UnitPart a = p, b = p;
      a.hi[axis] = at;
      b.lo[axis] = at;
      low.parts.push_back(a);
      high.parts.push_back(b);
    }
  }
  if (low.parts.empty() || high.parts.empty()) throw InputError("split", "the plane misses the unit: nothing to split");
  Document out = doc;
  DocObject& o = *out.find(id);
  std::get<UnitSpec>(o.spec) = std::move(low);
  const Placement placement = o.placement;
  const std::string name = o.name;
  const ObjectId other = out.add(name + " (split)", std::move(high));
  out.find(other)->placement = placement;
  if (added) *added = other;
  return out;
}

Document mergeUnits(const Document& doc, ObjectId a, ObjectId b) {
  if (a == b) throw InputError("merge", "a unit merges with another unit");
  const UnitSpec& ua = unitOf(doc, a, "merge");
  const UnitSpec& ub = unitOf(doc, b, "merge");
  const Placement& pa = doc.find(a)->placement;
  std::vector<UnitPart> moved;
  for (const UnitPart& p : ub.parts) {
    const auto box = boxInto(doc.find(b)->placement, pa, {p.lo, p.hi});
    if (!box) throw InputError("merge", "the units are turned against each other");
    moved.push_back({box->lo, box->hi});
  }
  bool touch = false;
  for (const UnitPart& p : ua.parts)
    for (const UnitPart& q : moved) {
      const growth::Box x{p.lo, p.hi}, y{q.lo, q.hi};
      if (growth::interiorsOverlap(x, y, growth::kEps)) throw InputError("merge", "the units share volume");
      int shared = 0, flush = 0;
      for (int k = 0; k < 3; ++k) {
        if (growth::overlapLength(x.lo[k], x.hi[k], y.lo[k], y.hi[k]) > growth::kEps) ++shared;
        else if (std::abs(x.hi[k] - y.lo[k]) <= growth::kEps || std::abs(y.hi[k] - x.lo[k]) <= growth::kEps) ++flush;
      }
      touch = touch || (shared == 2 && flush == 1);
    }
  if (!touch) throw InputError("merge", "the units do not touch over a face");
  Document out = doc;
  auto& parts = std::get<UnitSpec>(out.find(a)->spec).parts;
  parts.insert(parts.end(), moved.begin(), moved.end());
  out.remove(b);
  return out;
}

std::optional<UnitFace> pickUnitFace(const UnitSpec& unit, const Vec3& origin, const Vec3& direction) {
  const growth::Unit u = toUnit(unit);
  std::optional<UnitFace> best;
  for (std::size_t i = 0; i < u.parts.size(); ++i) {
    const growth::Box& b = u.parts[i];
    for (growth::Side s : growth::kAllSides) {
      const int a = growth::sideAxis(s);
      const double sign = growth::sideSign(s);
      if (direction[a] * sign >= 0) continue;  // seen from inside or edge-on
      const double c = growth::sideCoord(b, s);
      const double t = (c - origin[a]) / direction[a];
      if (t < 0 || (best && t >= best->t)) continue;
      const Vec3 hit = origin + direction * t;
      bool inside = true;
      for (int k = 0; k < 3; ++k)
        if (k != a && (hit[k] < b.lo[k] - growth::kEps || hit[k] > b.hi[k] + growth::kEps)) inside = false;
      if (!inside) continue;
      UnitFace f;
      f.part = int(i);
      f.side = s;
      f.hit = hit;
      f.t = t;
      // The side's rectangle, its corners in order round the outward normal.
      const int p = (a + 1) % 3, q = (a + 2) % 3;
      Vec3 corner(0, 0, 0);
      corner[a] = c;
      const double us[4] = {b.lo[p], b.hi[p], b.hi[p], b.lo[p]}, vs[4] = {b.lo[q], b.lo[q], b.hi[q], b.hi[q]};
      for (int k = 0; k < 4; ++k) {
        corner[p] = us[k];
        corner[q] = vs[k];
        f.outline.push_back(corner);
      }
      if (sign < 0) std::reverse(f.outline.begin(), f.outline.end());
      best = f;
    }
  }
  return best;
}

}  // namespace corbel::editor
