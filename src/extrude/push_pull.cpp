#include "extrude/push_pull.h"

#include "core/error.h"
#include "extrude/edit.h"
#include "extrude/features.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace corbel::extrude::pushpull {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& why) { throw InputError(where, why); }

const PlanLoop& loopAt(const ExtrusionSpec& s, int loop, int edge) {
  if (loop < 0 || loop >= static_cast<int>(s.loops.size())) fail("loop", "no loop number " + std::to_string(loop));
  const PlanLoop& l = s.loops[loop];
  if (edge < 0 || edge >= static_cast<int>(l.points.size()))
    fail("edge", "loop " + std::to_string(loop) + " has no edge " + std::to_string(edge));
  return l;
}

const Profile& profileAt(const ExtrusionSpec& s, int profile) {
  if (profile < 0 || profile >= static_cast<int>(s.profiles.size()))
    fail("profile", "no profile number " + std::to_string(profile));
  return s.profiles[profile];
}

// Where the ray meets the planar polygon (loops[0] outer, the rest holes; even-odd inside), if
// it does in front of its origin.
std::optional<double> rayPolygon(const std::vector<Vec3>& pts, const std::vector<std::vector<int>>& loops, const Vec3& normal,
                                 const Vec3& origin, const Vec3& direction) {
  if (loops.empty() || loops[0].empty()) return std::nullopt;
  const double denom = OpenMesh::dot(normal, direction);
  if (std::abs(denom) < 1e-12) return std::nullopt;
  const double t = OpenMesh::dot(normal, pts[loops[0][0]] - origin) / denom;
  if (!(t > 0)) return std::nullopt;
  const Vec3 hit = origin + direction * t;
  Vec3 u = std::abs(normal[2]) < 0.9 ? OpenMesh::cross(Vec3(0, 0, 1), normal) : Vec3(1, 0, 0);
  u.normalize();
  const Vec3 v = OpenMesh::cross(normal, u);
  const double hx = OpenMesh::dot(hit, u), hy = OpenMesh::dot(hit, v);
  bool in = false;
  for (const auto& loop : loops)
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
      const double ax = OpenMesh::dot(pts[loop[i]], u), ay = OpenMesh::dot(pts[loop[i]], v);
      const double bx = OpenMesh::dot(pts[loop[j]], u), by = OpenMesh::dot(pts[loop[j]], v);
      if ((ay > hy) != (by > hy) && hx < (bx - ax) * (hy - ay) / (by - ay) + ax) in = !in;
    }
  return in ? std::optional<double>(t) : std::nullopt;
}

// Newell's normal of a polygon of points.
Vec3 polygonNormal(const std::vector<Vec3>& pts, const std::vector<int>& loop) {
  Vec3 n(0, 0, 0);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 &a = pts[loop[i]], &b = pts[loop[(i + 1) % loop.size()]];
    n += Vec3((a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]), (a[0] - b[0]) * (a[1] + b[1]));
  }
  const double len = n.norm();
  return len > 0 ? n / len : Vec3(0, 0, 1);
}

double cross2(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

}  // namespace

Target pick(const ExtrusionSpec& spec, const ExtrusionResult& built, const Vec3& origin, const Vec3& direction) {
  Target best;
  best.t = std::numeric_limits<double>::infinity();
  const auto& pts = built.shell.points;
  for (const ShellFace& f : built.shell.faces) {
    const auto t = rayPolygon(pts, f.loops, f.normal, origin, direction);
    if (!t || *t >= best.t) continue;
    Target c;
    c.t = *t;
    c.hit = origin + direction * *t;
    c.normal = f.normal;
    for (int i : f.loops[0]) c.outline.push_back(pts[i]);
    c.profile = f.profile;
    c.segment = f.segment;
    if (f.step >= 0 && f.step < static_cast<int>(spec.steps.size())) {
      c.kind = Kind::Step;
      c.step = f.step;
    } else if (!f.base && f.sourceLoop >= 0 && f.segment >= 0 && f.profile >= 0 &&
               f.profile < static_cast<int>(spec.profiles.size())) {
      c.kind = f.segment == 0 ? Kind::Wall : Kind::Roof;
      c.loop = f.sourceLoop;
      c.edge = f.sourceEdge;
    }
    best = std::move(c);
  }
  // Feature meshes stand out of the faces they sit on: the nearest of their polygons wins.
  for (const AnchorFrame& a : built.anchors) {
    if (!a.instanced || a.source < 0 || a.source >= static_cast<int>(spec.anchors.size())) continue;
    const MeshAnchor& m = spec.anchors[a.source];
    for (const FeaturePart& part : featureParts(m.feature, m.size, a))
      for (const auto& face : part.faces) {
        const Vec3 n = polygonNormal(part.points, face);
        const auto t = rayPolygon(part.points, {face}, n, origin, direction);
        if (!t || *t >= best.t) continue;
        Target c;
        c.kind = Kind::Feature;
        c.feature = a.source;
        c.t = *t;
        c.hit = origin + direction * *t;
        c.normal = n;
        for (int i : face) c.outline.push_back(part.points[i]);
        best = std::move(c);
      }
  }
  if (!std::isfinite(best.t)) return Target{};
  return best;
}

Vec2 edgeNormal(const ExtrusionSpec& spec, int loop, int edge) {
  const PlanLoop& l = loopAt(spec, loop, edge);
  const Vec2 d = l.points[(edge + 1) % l.points.size()] - l.points[edge];
  const double len = d.norm();
  if (!(len > 0)) fail("edge", "loop " + std::to_string(loop) + " edge " + std::to_string(edge) + " has no length");
  return Vec2(d[1], -d[0]) / len;
}

double edgeLength(const ExtrusionSpec& spec, int loop, int edge) {
  const PlanLoop& l = loopAt(spec, loop, edge);
  return (l.points[(edge + 1) % l.points.size()] - l.points[edge]).norm();
}

ExtrusionSpec pushEdge(ExtrusionSpec s, int loop, int edge, double distance) {
  if (!std::isfinite(distance) || std::abs(distance) > 1e5) fail("distance", "must be a finite number of metres");
  const Vec2 n = edgeNormal(s, loop, edge);
  const PlanLoop& l = s.loops[loop];
  const int count = static_cast<int>(l.points.size());
  const int a = edge, b = (edge + 1) % count;
  const Vec2 along(-n[1], n[0]);  // the edge's direction
  // Corner `c` of the edge, moved onto the pushed edge's line along the neighbour edge that
  // runs from `other` to it.
  auto moved = [&](int c, int other) {
    const Vec2 p = l.points[c], q = l.points[other];
    const Vec2 d = p - q;
    const double len = d.norm(), across = OpenMesh::dot(d, n);
    // The neighbour must cross the edge's direction: within about 1° of parallel it does not.
    if (len > 0 && std::abs(cross2(along, d)) > std::sin(std::numbers::pi / 180) * len && std::abs(across) > 1e-12)
      return p + d * (distance / across);
    return p + n * distance;
  };
  const Vec2 pa = moved(a, (a + count - 1) % count), pb = moved(b, (b + 1) % count);
  s = edit::moveCorner(std::move(s), loop, a, pa);
  return edit::moveCorner(std::move(s), loop, b, pb);
}

double segmentPitch(const Profile& p, int segment) {
  if (segment < 0 || segment + 1 >= static_cast<int>(p.points.size()))
    fail("segment", "profile \"" + p.name + "\" has no segment " + std::to_string(segment));
  const Vec2 d = p.points[segment + 1] - p.points[segment];
  return std::atan2(d[1], d[0]) * 180 / std::numbers::pi;
}

std::pair<double, double> pitchRange(const Profile& p, int segment) {
  const bool last = segment + 2 == static_cast<int>(p.points.size());
  return last ? std::pair(0.0, 90.0) : std::pair(0.0, 180.0);
}

ExtrusionSpec turnSegment(ExtrusionSpec s, int profile, int segment, double pitchDeg) {
  profileAt(s, profile);
  Profile& p = s.profiles[profile];
  segmentPitch(p, segment);  // checks the segment
  const auto [lo, hi] = pitchRange(p, segment);
  const bool last = segment + 2 == static_cast<int>(p.points.size());
  if (!std::isfinite(pitchDeg) || pitchDeg < lo || pitchDeg > hi || (last && pitchDeg <= 0))
    fail("pitch", last ? "the last segment of a profile takes a pitch above 0° and at most 90° (it must not lean outward)"
                       : "a segment's pitch must lie within [0°, 180°] (z never decreases along a profile)");
  const Vec2 start = p.points[segment], end = p.points[segment + 1];
  const double length = (end - start).norm();
  if (!(length > 0)) fail("segment", "segment " + std::to_string(segment) + " of \"" + p.name + "\" has no length");
  const double r = pitchDeg * std::numbers::pi / 180;
  Vec2 d(std::cos(r), std::sin(r));
  if (std::abs(d[1]) < 1e-15) d[1] = 0;  // 0° and 180° stay exactly level
  const Vec2 shift = start + d * length - end;
  for (std::size_t i = segment + 1; i < p.points.size(); ++i) p.points[i] += shift;
  return s;
}

int profileUsers(const ExtrusionSpec& s, int profile) {
  int n = 0;
  for (const PlanLoop& l : s.loops) n += static_cast<int>(std::count(l.profile.begin(), l.profile.end(), profile));
  return n;
}

ExtrusionSpec ownProfile(ExtrusionSpec s, int loop, int edge, int* index) {
  const PlanLoop& l = loopAt(s, loop, edge);
  Profile copy = profileAt(s, l.profile.at(edge));
  int k = -1;
  s = edit::addProfile(std::move(s), std::move(copy), &k);
  s = edit::setEdgeProfile(std::move(s), {{loop, edge}}, k);
  if (index) *index = k;
  return s;
}

Anchor slideAnchor(const ExtrusionSpec& s, Anchor a, double metres) {
  if (!std::isfinite(metres)) fail("distance", "must be a finite number of metres");
  const WallRun run = wallRun(s, a.loop, a.edge);
  if (run.edges.empty()) fail("anchor", "names no edge of the plan");
  if (a.absolute)
    a.along = std::clamp(a.along + metres, 0.0, run.length);
  else
    a.along = std::clamp(a.along + metres / std::max(run.length, 1e-9), 0.0, 1.0);
  return a;
}

std::pair<Anchor, Repeat> slideRow(const ExtrusionSpec& s, Anchor a, Repeat r, double metres) {
  if (r.kind == RepeatKind::None) return {slideAnchor(s, a, metres), r};
  if (!std::isfinite(metres)) fail("distance", "must be a finite number of metres");
  const WallRun run = wallRun(s, a.loop, a.edge);
  if (run.edges.empty()) fail("anchor", "names no edge of the plan");
  // Both ends in metres along the wall; the row moves as one and stops where either end meets
  // an end of the wall (a row already past an end may still move back onto it).
  const double scale = a.absolute ? 1.0 : std::max(run.length, 1e-9);
  const double first = a.along * scale, last = r.along * scale;
  const double lo = std::min(0.0, -std::min(first, last));
  const double hi = std::max(0.0, run.length - std::max(first, last));
  const double d = std::clamp(metres, lo, hi);
  a.along += d / scale;
  r.along += d / scale;
  return {a, r};
}

ExtrusionSpec slideStep(ExtrusionSpec s, int step, double metres) {
  if (step < 0 || step >= static_cast<int>(s.steps.size())) fail("step", "no step " + std::to_string(step));
  const auto [a, r] = slideRow(s, s.steps[step].anchor, s.steps[step].repeat, metres);
  s.steps[step].repeat = r;
  return edit::moveAnchor(std::move(s), step, a);
}

ExtrusionSpec slideFeature(ExtrusionSpec s, int feature, double metres) {
  if (feature < 0 || feature >= static_cast<int>(s.anchors.size())) fail("feature", "no feature " + std::to_string(feature));
  const auto [a, r] = slideRow(s, s.anchors[feature].anchor, s.anchors[feature].repeat, metres);
  s.anchors[feature].repeat = r;
  return edit::moveMeshAnchor(std::move(s), feature, a);
}

}  // namespace corbel::extrude::pushpull
