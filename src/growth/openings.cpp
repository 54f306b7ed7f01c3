#include "growth/openings.h"

#include "extrude/features.h"
#include "growth/tolerances.h"

#include <algorithm>
#include <cmath>

namespace corbel::growth {

namespace {

ViewDirection facing(Side s) {
  switch (s) {
    case Side::PosX: return ViewDirection::PosX;
    case Side::NegX: return ViewDirection::NegX;
    case Side::PosY: return ViewDirection::PosY;
    default: return ViewDirection::NegY;
  }
}

Vec3 normalOf(Side s) {
  Vec3 n(0.0);
  n[sideAxis(s)] = sideSign(s);
  return n;
}

// [lo, hi] less the intervals, as sorted disjoint intervals longer than the tolerance.
std::vector<std::pair<double, double>> freeIntervals(double lo, double hi, std::vector<std::pair<double, double>> cut) {
  std::sort(cut.begin(), cut.end());
  std::vector<std::pair<double, double>> out;
  double at = lo;
  for (const auto& [a, b] : cut) {
    if (a > at + kEps) out.emplace_back(at, std::min(a, hi));
    at = std::max(at, b);
    if (at >= hi) break;
  }
  if (hi > at + kEps) out.emplace_back(at, hi);
  return out;
}

}  // namespace

double stretchView(const ViewMaps& views, std::uint32_t id, Side side, double at, double u0, double u1, double z0,
                   double z1) {
  const int a = sideAxis(side), b = 1 - a;
  Box face;
  face.lo[a] = face.hi[a] = at;
  face.lo[b] = u0;
  face.hi[b] = u1;
  face.lo[2] = z0;
  face.hi[2] = z1;
  const ViewDirection d = facing(side);
  const Rect r = projectBox(face, d);
  const double depth = frontDepth(face, d);
  const ViewMap& m = views[d];
  const auto& us = m.uEdges();
  const auto& vs = m.vEdges();
  double seen = 0;
  for (int j = 0; j < m.rows(); ++j) {
    const double h = overlapLength(vs[j], vs[j + 1], r.v0, r.v1);
    if (h <= 0) continue;
    for (int i = 0; i < m.columns(); ++i) {
      const double w = overlapLength(us[i], us[i + 1], r.u0, r.u1);
      if (w <= 0) continue;
      if (m.id(i, j) == id && std::abs(m.depth(i, j) - depth) < 1e-6) seen += w * h;
    }
  }
  return seen;
}

std::vector<Opening> placeOpenings(const Site& site, const std::vector<Unit>& units, const ViewMaps& views,
                                   const OpeningSettings& settings) {
  std::vector<Box> everything;
  for (const Unit& u : units) everything.insert(everything.end(), u.parts.begin(), u.parts.end());
  for (std::size_t i = 0; i < site.cores.size(); ++i) everything.push_back(site.coreBox(i));
  everything.insert(everything.end(), site.circulation.begin(), site.circulation.end());
  const double storey = site.storeyHeight;

  // What touches side s of part p (from outside) over heights [z0, z1]: intervals along the side.
  const auto touching = [&](const Box& p, Side s, double z0, double z1, const std::vector<Box>& boxes) {
    const int a = sideAxis(s), b = 1 - a;
    const double at = sideCoord(p, s);
    std::vector<std::pair<double, double>> cut;
    for (const Box& o : boxes) {
      if (&o == &p || o == p) continue;
      if (std::abs(sideCoord(o, opposite(s)) - at) > kEps) continue;
      if (overlapLength(o.lo[2], o.hi[2], z0, z1) <= kEps) continue;
      const double lo = std::max(o.lo[b], p.lo[b]), hi = std::min(o.hi[b], p.hi[b]);
      if (hi > lo + kEps) cut.emplace_back(lo, hi);
    }
    return cut;
  };
  const auto place = [&](FeatureKind kind, const Unit& u, Side s, const Box& p, double along, double z,
                         const FeatureSize& size) {
    Opening o;
    o.kind = kind;
    o.unit = u.id;
    o.side = s;
    o.size = size;
    const int a = sideAxis(s);
    o.position[a] = sideCoord(p, s);
    o.position[1 - a] = along;
    o.position[2] = z;
    return o;
  };

  std::vector<Opening> out;
  for (const Unit& u : units) {
    if (u.parts.empty()) continue;
    // The door: the longest contact with circulation on the unit's lowest storey.
    double floor = u.parts[0].lo[2];
    for (const Box& p : u.parts) floor = std::min(floor, p.lo[2]);
    double best = settings.door.width - kEps;
    std::optional<Opening> door;
    for (const Box& p : u.parts) {
      if (std::abs(p.lo[2] - floor) > kEps) continue;
      for (Side s : kVerticalSides)
        for (const auto& [lo, hi] : touching(p, s, floor, floor + storey, site.circulation))
          if (hi - lo > best) {
            best = hi - lo;
            door = place(FeatureKind::Door, u, s, p, (lo + hi) / 2, floor, settings.door);
          }
    }
    if (door) out.push_back(*door);
    // Windows on each storey of each part side with a view.
    for (const Box& p : u.parts)
      for (Side s : kVerticalSides) {
        const int b = 1 - sideAxis(s);
        for (double z0 = p.lo[2]; z0 + storey <= p.hi[2] + kEps; z0 += storey) {
          const double z1 = z0 + storey;
          for (const auto& [lo, hi] : freeIntervals(p.lo[b], p.hi[b], touching(p, s, z0, z1, everything))) {
            const int n = static_cast<int>(std::floor((hi - lo) / settings.spacing + 1e-9));
            if (n < 1) continue;
            if (stretchView(views, std::uint32_t(u.id), s, sideCoord(p, s), lo, hi, z0, z1) <= kEps) continue;
            const double share = (hi - lo) / n;
            for (int k = 0; k < n; ++k)
              out.push_back(place(FeatureKind::Window, u, s, p, lo + (k + 0.5) * share, z0 + settings.sill,
                                  settings.window));
          }
        }
      }
  }
  return out;
}

std::vector<Opening> placeOpenings(const Site& site, const std::vector<Unit>& units, const OpeningSettings& settings) {
  std::vector<ViewBox> boxes;
  for (const Unit& u : units)
    for (const Box& p : u.parts) boxes.push_back({p, std::uint32_t(u.id)});
  for (std::size_t i = 0; i < site.cores.size(); ++i) boxes.push_back({site.coreBox(i), kObstacleId});
  for (const Box& c : site.circulation) boxes.push_back({c, kObstacleId});
  ExactViewMapper mapper;
  return placeOpenings(site, units, mapper.render(boxes, site.bounds()), settings);
}

MeshData openingsMesh(const std::vector<Opening>& openings) {
  MeshData mesh;
  for (const Opening& o : openings) {
    extrude::AnchorFrame frame;
    frame.position = o.position;
    frame.normal = normalOf(o.side);
    frame.up = Vec3(0, 0, 1);
    frame.along = Vec3(-frame.normal[1], frame.normal[0], 0);  // normal × along = up
    frame.instanced = true;
    extrude::appendParts(mesh, o.kind, extrude::featureParts(o.kind, o.size, frame));
  }
  return mesh;
}

}  // namespace corbel::growth
