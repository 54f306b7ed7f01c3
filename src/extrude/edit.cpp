#include "extrude/edit.h"

#include "core/polygon_area.h"
#include "core/error.h"
#include "extrude/plan_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>

namespace corbel::extrude::edit {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& why) { throw InputError(where, why); }

PlanLoop& loopAt(ExtrusionSpec& s, int loop) {
  if (loop < 0 || loop >= static_cast<int>(s.loops.size())) fail("loop", "no loop number " + std::to_string(loop));
  return s.loops[loop];
}

Profile& profileAt(ExtrusionSpec& s, int profile) {
  if (profile < 0 || profile >= static_cast<int>(s.profiles.size()))
    fail("profile", "no profile number " + std::to_string(profile));
  return s.profiles[profile];
}

bool finite(const Vec2& p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

bool inside(const Vec2& q, const std::vector<Vec2>& poly) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[i], &b = poly[j];
    if ((a[1] > q[1]) != (b[1] > q[1]) && q[0] < (b[0] - a[0]) * (q[1] - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
  }
  return in;
}

}  // namespace

namespace {

// Every anchored thing of a spec (steps, then mesh anchors) with a name for the log.
template <class F>
void forEachAnchor(ExtrusionSpec& s, F&& f) {
  for (std::size_t k = 0; k < s.steps.size(); ++k)
    f(s.steps[k].anchor, "steps[" + std::to_string(k) + "] \"" + s.steps[k].name + "\"");
  for (std::size_t k = 0; k < s.anchors.size(); ++k)
    f(s.anchors[k].anchor, "anchors[" + std::to_string(k) + "] \"" + s.anchors[k].name + "\"");
}

// Removes the anchored things `gone` marks (steps first, then mesh anchors, as forEachAnchor
// counts them), noting each.
void removeAnchored(ExtrusionSpec& s, const std::vector<char>& gone, const std::string& why, std::vector<std::string>* notes) {
  std::size_t k = 0;
  std::vector<PlanStep> steps;
  for (PlanStep& st : s.steps)
    if (gone[k++]) {
      if (notes) notes->push_back("removed step \"" + st.name + "\": " + why);
    } else {
      steps.push_back(std::move(st));
    }
  std::vector<MeshAnchor> anchors;
  for (MeshAnchor& m : s.anchors)
    if (gone[k++]) {
      if (notes) notes->push_back("removed feature \"" + m.name + "\": " + why);
    } else {
      anchors.push_back(std::move(m));
    }
  s.steps = std::move(steps);
  s.anchors = std::move(anchors);
}

double planScale(const ExtrusionSpec& s) {
  BBox box;
  for (const PlanLoop& l : s.loops)
    for (const Vec2& p : l.points) box.add(Vec3(p[0], p[1], 0));
  return std::max(box.diagonal(), 1.0);
}

}  // namespace

ExtrusionSpec insertCorner(ExtrusionSpec s, int loop, int edge, const Vec2& at, std::vector<std::string>*) {
  PlanLoop& l = loopAt(s, loop);
  if (edge < 0 || edge >= static_cast<int>(l.points.size())) fail("edge", "loop " + std::to_string(loop) + " has no edge " + std::to_string(edge));
  if (!finite(at)) fail("point", "coordinates must be finite");
  assignWalls(s);
  // Both halves belong to the edge's wall, so every anchor keeps its place along the wall.
  l.points.insert(l.points.begin() + edge + 1, at);
  l.profile.insert(l.profile.begin() + edge + 1, l.profile[edge]);
  l.walls.insert(l.walls.begin() + edge + 1, l.walls[edge]);
  forEachAnchor(s, [&](Anchor& a, const std::string&) {
    if (a.loop == loop && a.edge > edge) ++a.edge;
  });
  canonicalWalls(s);
  return s;
}

ExtrusionSpec deleteCorner(ExtrusionSpec s, int loop, int corner, std::vector<std::string>* notes) {
  PlanLoop& l = loopAt(s, loop);
  const int n = static_cast<int>(l.points.size());
  if (corner < 0 || corner >= n) fail("corner", "no corner " + std::to_string(corner));
  if (n <= 3) fail("corner", "a loop needs at least three corners (delete the loop instead)");
  assignWalls(s);
  // The edge arriving at the corner now runs on to the next one and keeps its profile and
  // wall; the wall of the edge leaving it, when another, merges into that one.
  const int prev = (corner + n - 1) % n;
  const int survive = l.walls[prev], absorbed = l.walls[corner];
  // Before the change: where each anchor on either wall lies.
  std::vector<std::optional<Vec2>> before;
  std::vector<int> wallBefore;
  forEachAnchor(s, [&](Anchor& a, const std::string&) {
    const bool mine = a.loop == loop && a.edge >= 0 && a.edge < n;
    wallBefore.push_back(mine ? l.walls[a.edge] : 0);
    before.push_back(mine ? anchorPoint(s, a) : std::nullopt);
  });
  l.points.erase(l.points.begin() + corner);
  l.profile.erase(l.profile.begin() + corner);
  l.walls.erase(l.walls.begin() + corner);
  for (int& w : l.walls)
    if (w == absorbed) w = survive;
  const int merged = prev < corner ? prev : prev - 1;
  forEachAnchor(s, [&](Anchor& a, const std::string&) {
    if (a.loop != loop) return;
    if (a.edge == corner) a.edge = merged;
    else if (a.edge > corner) --a.edge;
  });
  canonicalWalls(s);
  if (survive == absorbed) return s;  // a corner within one wall: fractions along it stay
  // Two walls become one: an anchor whose point lies on it keeps that point; one of the
  // surviving wall keeps its place along the edge that moved; one of the other wall is gone.
  const WallRun run = wallRun(s, loop, merged);
  const double near = 1e-9 * planScale(s);
  std::vector<char> gone;
  std::size_t k = 0;
  forEachAnchor(s, [&](Anchor& a, const std::string&) {
    const std::size_t i = k++;
    gone.push_back(0);
    if (!before[i] || (wallBefore[i] != survive && wallBefore[i] != absorbed)) return;
    const auto [q, t] = nearestOnWall(s, run, *before[i]);
    if ((q - *before[i]).norm() <= near) {
      a.along = a.absolute ? t : (run.length > 0 ? std::clamp(t / run.length, 0.0, 1.0) : 0.0);
      a.edge = merged;
    } else if (wallBefore[i] == absorbed) {
      gone.back() = 1;
    }
  });
  removeAnchored(s, gone, "its wall went with corner " + std::to_string(corner) + " of loop " + std::to_string(loop), notes);
  return s;
}

ExtrusionSpec moveCorner(ExtrusionSpec s, int loop, int corner, const Vec2& to) {
  PlanLoop& l = loopAt(s, loop);
  if (corner < 0 || corner >= static_cast<int>(l.points.size())) fail("corner", "no corner " + std::to_string(corner));
  if (!finite(to)) fail("point", "coordinates must be finite");
  l.points[corner] = to;  // anchors keep their fractions along their walls
  return s;
}

ExtrusionSpec addLoop(ExtrusionSpec s, std::vector<Vec2> points, int profile) {
  if (points.size() < 3) fail("points", "a loop needs at least three corners");
  for (const Vec2& p : points)
    if (!finite(p)) fail("points", "coordinates must be finite");
  profileAt(s, profile);
  int depth = 0;
  for (const PlanLoop& l : s.loops) depth += inside(points[0], l.points);
  const bool hole = depth % 2 == 1;
  if ((signedArea(points) > 0) == hole) std::reverse(points.begin(), points.end());
  assignWalls(s);
  PlanLoop l;
  l.profile.assign(points.size(), profile);
  for (int next = nextWallId(s); l.walls.size() < points.size();) l.walls.push_back(next++);
  l.points = std::move(points);
  s.loops.push_back(std::move(l));
  canonicalWalls(s);
  return s;
}

ExtrusionSpec deleteLoop(ExtrusionSpec s, int loop, std::vector<std::string>* notes) {
  loopAt(s, loop);
  if (s.loops.size() == 1) fail("loop", "the plan's last loop cannot be deleted (delete the object instead)");
  s.loops.erase(s.loops.begin() + loop);
  std::vector<char> gone;
  forEachAnchor(s, [&](Anchor& a, const std::string&) {
    gone.push_back(a.loop == loop);
    if (a.loop > loop) --a.loop;
  });
  removeAnchored(s, gone, "its loop " + std::to_string(loop) + " was deleted", notes);
  canonicalWalls(s);
  return s;
}

ExtrusionSpec setEdgeProfile(ExtrusionSpec s, const std::vector<EdgeRef>& edges, int profile) {
  profileAt(s, profile);
  for (auto [loop, edge] : edges) {
    PlanLoop& l = loopAt(s, loop);
    if (edge < 0 || edge >= static_cast<int>(l.profile.size())) fail("edge", "no edge " + std::to_string(edge));
    l.profile[edge] = profile;
  }
  return s;
}

Vec2 clampProfilePoint(const Profile& p, int point, const Vec2& wz) {
  if (point == 0) return Vec2(0, 0);
  Vec2 q = wz;
  const double lo = p.points[point - 1][1];
  const double hi = point + 1 < static_cast<int>(p.points.size()) ? p.points[point + 1][1] : 1e5;
  q[1] = std::clamp(q[1], lo, hi);
  q[0] = std::clamp(q[0], -1e5, 1e5);
  return q;
}

namespace {

double cross2(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

// The direction `stepDeg * k` from the x axis; exact on the axes so snapped corners stay
// on round coordinates.
Vec2 axisDirection(long k, double stepDeg) {
  const double deg = std::remainder(static_cast<double>(k) * stepDeg, 360.0);
  if (std::abs(deg) < 1e-9) return Vec2(1, 0);
  if (std::abs(deg - 90) < 1e-9) return Vec2(0, 1);
  if (std::abs(std::abs(deg) - 180) < 1e-9) return Vec2(-1, 0);
  if (std::abs(deg + 90) < 1e-9) return Vec2(0, -1);
  const double r = deg * std::numbers::pi / 180;
  return Vec2(std::cos(r), std::sin(r));
}

// The allowed direction nearest to d (unit), with its kind and its angle from d in degrees.
struct Candidate {
  Vec2 direction;
  SnapKind kind = SnapKind::Axis;
  double deviation = 0;
};

double angleBetween(const Vec2& a, const Vec2& b) {
  return std::abs(std::atan2(cross2(a, b), OpenMesh::dot(a, b))) * 180 / std::numbers::pi;
}

std::optional<Candidate> nearestDirection(const Vec2& d, double stepDeg, const std::vector<Vec2>& references) {
  if (!(stepDeg > 0 && stepDeg <= 90)) return std::nullopt;
  std::optional<Candidate> best;
  for (const Vec2& ref : references) {
    const double len = ref.norm();
    if (!(len > 0) || !std::isfinite(len)) continue;
    const Vec2 u = ref / len;
    const Vec2 rotated[4] = {u, Vec2(-u[1], u[0]), -u, Vec2(u[1], -u[0])};
    for (int k = 0; k < 4; ++k) {
      const double dev = angleBetween(d, rotated[k]);
      if (dev <= stepDeg / 2 && (!best || dev < best->deviation))
        best = Candidate{rotated[k], k % 2 == 0 ? SnapKind::Parallel : SnapKind::Perpendicular, dev};
    }
  }
  if (best) return best;
  const double a = std::atan2(d[1], d[0]) * 180 / std::numbers::pi;
  const Vec2 dir = axisDirection(std::lround(a / stepDeg), stepDeg);
  return Candidate{dir, SnapKind::Axis, angleBetween(d, dir)};
}

}  // namespace

AngleSnap snapEdgeAngle(const Vec2& from, const Vec2& to, double stepDeg, const std::vector<Vec2>& references,
                        double lengthStep) {
  const Vec2 d = to - from;
  const double r = d.norm();
  if (!(r > 0) || !std::isfinite(r)) return {to, {}};
  const auto c = nearestDirection(d / r, stepDeg, references);
  if (!c) return {to, {}};
  double len = OpenMesh::dot(d, c->direction);  // > 0: the deviation is at most 45 degrees
  if (lengthStep > 0 && std::isfinite(lengthStep)) len = std::max(1.0, std::round(len / lengthStep)) * lengthStep;
  return {from + c->direction * len, {SnapGuide{from, c->direction, c->kind}}};
}

AngleSnap snapCornerAngles(const Vec2& prev, const Vec2& next, const Vec2& to, double stepDeg,
                           const std::vector<Vec2>& prevReferences, const std::vector<Vec2>& nextReferences) {
  const AngleSnap a = snapEdgeAngle(prev, to, stepDeg, prevReferences);
  const AngleSnap b = snapEdgeAngle(next, to, stepDeg, nextReferences);
  if (a.guides.empty() || b.guides.empty()) return a.guides.empty() ? b : a;
  const Vec2 da = a.guides[0].direction, db = b.guides[0].direction;
  const double det = cross2(da, db);
  auto single = [&] { return (a.point - to).sqrnorm() <= (b.point - to).sqrnorm() ? a : b; };
  if (std::abs(det) < std::sin(std::numbers::pi / 360)) return single();  // within half a degree
  // prev + t da = next + u db.
  const Vec2 w = next - prev;
  const double t = cross2(w, db) / det, u = cross2(w, da) / det;
  if (!(t > 0) || !(u > 0)) return single();
  const Vec2 meet = prev + da * t;
  const double reach = 0.5 * std::min((to - prev).norm(), (to - next).norm());
  if ((meet - to).norm() > reach) return single();
  return {meet, {a.guides[0], b.guides[0]}};
}

ExtrusionSpec insertProfilePoint(ExtrusionSpec s, int profile, int after, const Vec2& wz) {
  Profile& p = profileAt(s, profile);
  if (after < 0 || after >= static_cast<int>(p.points.size())) fail("point", "no profile point " + std::to_string(after));
  if (!finite(wz)) fail("point", "coordinates must be finite");
  p.points.insert(p.points.begin() + after + 1, wz);
  p.points[after + 1] = clampProfilePoint(p, after + 1, wz);
  if (static_cast<int>(p.tags.size()) > after) p.tags.insert(p.tags.begin() + after + 1, p.tags[after]);
  return s;
}

ExtrusionSpec deleteProfilePoint(ExtrusionSpec s, int profile, int point) {
  Profile& p = profileAt(s, profile);
  if (point <= 0 || point >= static_cast<int>(p.points.size())) fail("point", "the first point cannot be deleted");
  if (p.points.size() <= 2) fail("point", "a profile needs at least two points");
  p.points.erase(p.points.begin() + point);
  if (static_cast<int>(p.tags.size()) >= point) p.tags.erase(p.tags.begin() + point - 1);
  return s;
}

ExtrusionSpec moveProfilePoint(ExtrusionSpec s, int profile, int point, const Vec2& wz) {
  Profile& p = profileAt(s, profile);
  if (point < 0 || point >= static_cast<int>(p.points.size())) fail("point", "no profile point " + std::to_string(point));
  if (!finite(wz)) fail("point", "coordinates must be finite");
  p.points[point] = clampProfilePoint(p, point, wz);
  return s;
}

namespace {

// The overhang on one profile at `height` above the profile's own start.
void overhangOn(Profile& p, const std::string& field, double height, double depth) {
  const std::size_t n = p.points.size();
  if (n < 2) fail(field, "a profile needs at least two points");
  const Vec2 lastDir = p.points[n - 1] - p.points[n - 2];
  if (!(lastDir[1] > 0)) fail(field, "the profile ends with a horizontal segment: fix it before adding an overhang");
  if (height > p.points.back()[1]) {
    // Above the last point the last segment carries on: put a point on it at the height.
    const Vec2 a = p.points[n - 2], b = p.points[n - 1];
    p.points.push_back(a + (b - a) * ((height - a[1]) / (b[1] - a[1])));
  }
  // Where the profile reaches the height.
  std::size_t i = 1;
  while (i < p.points.size() && p.points[i][1] < height) ++i;
  if (i >= p.points.size()) fail(field, "the profile does not reach the height");
  Vec2 at = p.points[i];
  if (p.points[i][1] > height) {
    const Vec2 a = p.points[i - 1], b = p.points[i];
    at = a + (b - a) * ((height - a[1]) / (b[1] - a[1]));
    p.points.insert(p.points.begin() + i, at);
    if (p.tags.size() >= i) p.tags.insert(p.tags.begin() + i, p.tags[i - 1]);
  }
  // A horizontal segment outward; everything above moves out with it.
  for (std::size_t k = i + 1; k < p.points.size(); ++k) p.points[k][0] -= depth;
  p.points.insert(p.points.begin() + i + 1, Vec2(at[0] - depth, height));
  if (p.tags.size() >= i) p.tags.insert(p.tags.begin() + i, "soffit");
  // A profile may not end on the horizontal segment: carry on as its last segment did.
  if (i + 2 == p.points.size()) p.points.push_back(p.points.back() + lastDir);
}

}  // namespace

ExtrusionSpec addOverhang(ExtrusionSpec s, double height, double depth) {
  if (!std::isfinite(height) || height <= 0) fail("height", "an overhang starts above the base (height > 0)");
  if (!std::isfinite(depth) || depth == 0 || std::abs(depth) > 1e3) fail("depth", "the overhang's depth must be non-zero");
  // Where each profile starts above the base: main edges at the base, a step's profiles at its
  // anchor's height, an offset event's at the event's height. A profile nothing uses is
  // treated as a main edge's. Every user of a profile points at its slot in `users`.
  const std::size_t count = s.profiles.size();
  std::vector<std::vector<std::pair<double, int*>>> users(count);
  for (auto& l : s.loops)
    for (int& k : l.profile)
      if (k >= 0 && static_cast<std::size_t>(k) < count) users[k].push_back({0.0, &k});
  for (auto& st : s.steps)
    for (int* k : {&st.frontProfile, &st.sideProfile})
      if (*k >= 0 && static_cast<std::size_t>(*k) < count) users[*k].push_back({st.anchor.height, k});
  for (auto& o : s.offsets) {
    for (auto& e : o.edges)
      for (int* k : {&e.insideProfile, &e.outsideProfile})
        if (*k >= 0 && static_cast<std::size_t>(*k) < count) users[*k].push_back({o.height, k});
    if (o.sideProfile >= 0 && static_cast<std::size_t>(o.sideProfile) < count)
      users[o.sideProfile].push_back({o.height, &o.sideProfile});
  }
  // One start height per profile: a profile used from several gets a copy for each start but
  // the lowest (Sec. 3.3: the overhang's height stays one absolute height on every profile).
  std::vector<double> start(count, 0.0);
  std::vector<Profile> copies;
  std::vector<double> copyStart;
  for (std::size_t pi = 0; pi < count; ++pi) {
    if (users[pi].empty()) continue;
    std::map<double, std::vector<int*>> byStart;
    for (auto [a, slot] : users[pi]) byStart[a].push_back(slot);
    start[pi] = byStart.begin()->first;
    for (auto it = std::next(byStart.begin()); it != byStart.end(); ++it) {
      const int index = static_cast<int>(count + copies.size());
      for (int* slot : it->second) *slot = index;
      copies.push_back(s.profiles[pi]);
      copyStart.push_back(it->first);
    }
  }
  // The copies get free names, as addProfile gives them.
  for (std::size_t c = 0; c < copies.size(); ++c) s = addProfile(std::move(s), std::move(copies[c]));
  start.insert(start.end(), copyStart.begin(), copyStart.end());
  for (std::size_t pi = 0; pi < s.profiles.size(); ++pi) {
    // None on a profile that starts at or above the overhang.
    if (height - start[pi] <= 0) continue;
    overhangOn(s.profiles[pi], "profiles[" + std::to_string(pi) + "]", height - start[pi], depth);
  }
  return s;
}

ExtrusionSpec setSegmentTag(ExtrusionSpec s, int profile, int segment, const std::string& tag) {
  Profile& p = profileAt(s, profile);
  if (segment < 0 || segment + 1 >= static_cast<int>(p.points.size())) fail("segment", "no segment " + std::to_string(segment));
  if (static_cast<int>(p.tags.size()) <= segment) p.tags.resize(segment + 1);
  p.tags[segment] = tag;
  return s;
}

ExtrusionSpec addProfile(ExtrusionSpec s, Profile p, int* index) {
  const std::string base = p.name.empty() ? "profile" : p.name;
  auto taken = [&](const std::string& n) {
    return std::any_of(s.profiles.begin(), s.profiles.end(), [&](const Profile& q) { return q.name == n; });
  };
  std::string name = base;
  for (int k = 2; taken(name); ++k) name = base + " " + std::to_string(k);
  p.name = name;
  s.profiles.push_back(std::move(p));
  if (index) *index = static_cast<int>(s.profiles.size()) - 1;
  return s;
}

ExtrusionSpec addStep(ExtrusionSpec s, const PlanStep& step) {
  s.steps.push_back(step);
  return s;
}

ForcedStepFrame forcedStepFrame(const ExtrusionSpec& s, int loop, int edge, const std::vector<Vec2>& world, double height) {
  if (loop < 0 || loop >= static_cast<int>(s.loops.size())) fail("loop", "no loop number " + std::to_string(loop));
  const auto& pts = s.loops[loop].points;
  if (edge < 0 || edge >= static_cast<int>(pts.size()))
    fail("edge", "loop " + std::to_string(loop) + " has no edge " + std::to_string(edge));
  if (!std::isfinite(height) || height < 0 || height > 1e5) fail("height", "must be within [0, 1e5] m above the base");
  if (world.size() < 3) fail("points", "a forced step needs a polygon of at least three corners");
  double extent = 0;
  for (std::size_t i = 0; i < world.size(); ++i) {
    if (!finite(world[i]) || std::abs(world[i][0]) > 1e7 || std::abs(world[i][1]) > 1e7)
      fail("points[" + std::to_string(i) + "]", "coordinates must be finite and within 1e7 m");
    extent = std::max(extent, (world[i] - world[0]).norm());
  }
  for (std::size_t i = 0; i < world.size(); ++i)
    if ((world[(i + 1) % world.size()] - world[i]).norm() <= 1e-6 * std::max(extent, 1.0))
      fail("points[" + std::to_string(i) + "]", "repeats the next corner (the polygon has a zero-length edge)");
  if (std::abs(signedArea(world)) <= 1e-9 * extent * extent) fail("points", "the polygon encloses no area");
  std::vector<Vec2> ccw = world;
  if (signedArea(ccw) < 0) std::reverse(ccw.begin(), ccw.end());
  if (auto bad = checkPlanTopology({ccw})) {
    const auto colon = bad->find(": ");
    fail("points", "the polygon is not simple: " + (colon == std::string::npos ? *bad : bad->substr(colon + 2)));
  }
  const Vec2 p = pts[edge], q = pts[(edge + 1) % pts.size()];
  const double len = (q - p).norm();
  if (!(len > 0)) fail("edge", "the edge has no length");
  const Vec2 d = (q - p) / len, out(d[1], -d[0]);  // the plan's inside is left of every edge
  // Where the polygon covers the edge: the crossings of its boundary with the edge, and the
  // edge's ends where they lie inside it; the anchor is the middle of that stretch.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto cover = [&](double t) { lo = std::min(lo, t), hi = std::max(hi, t); };
  if (inside(p, ccw)) cover(0);
  if (inside(q, ccw)) cover(len);
  for (std::size_t i = 0; i < ccw.size(); ++i) {
    const Vec2 a = ccw[i], b = ccw[(i + 1) % ccw.size()];
    const double va = OpenMesh::dot(a - p, out), vb = OpenMesh::dot(b - p, out);
    if ((va > 0) == (vb > 0) && va != 0 && vb != 0) continue;
    const double ua = OpenMesh::dot(a - p, d), ub = OpenMesh::dot(b - p, d);
    const double t = va == vb ? std::clamp(ua, 0.0, len) : ua + (ub - ua) * (va / (va - vb));
    if (va == vb) {  // along the edge's line: the part of it on the edge
      const double t0 = std::clamp(std::min(ua, ub), 0.0, len), t1 = std::clamp(std::max(ua, ub), 0.0, len);
      if (std::max(ua, ub) >= 0 && std::min(ua, ub) <= len) cover(t0), cover(t1);
      continue;
    }
    if (t >= 0 && t <= len) cover(t);
  }
  double at;
  if (lo <= hi) {
    at = (lo + hi) / 2;
  } else {
    // Apart from the edge: the closest pair of a corner and the other's boundary.
    double best = std::numeric_limits<double>::infinity();
    at = 0;
    for (const Vec2& c : ccw) {
      const double t = std::clamp(OpenMesh::dot(c - p, d), 0.0, len);
      const double dd = (p + d * t - c).norm();
      if (dd < best) best = dd, at = t;
    }
    for (double t : {0.0, len}) {
      const Vec2 e = p + d * t;
      for (std::size_t i = 0; i < ccw.size(); ++i) {
        const Vec2 a = ccw[i], b = ccw[(i + 1) % ccw.size()], ab = b - a;
        const double k = std::clamp(OpenMesh::dot(e - a, ab) / std::max(ab.sqrnorm(), 1e-300), 0.0, 1.0);
        const double dd = (a + ab * k - e).norm();
        if (dd < best) best = dd, at = t;
      }
    }
  }
  ForcedStepFrame f;
  const double run = wallRun(s, loop, edge).length;  // the anchor measures the whole wall
  f.anchor = Anchor{loop, edge, false, run > 0 ? std::clamp(alongWall(s, loop, edge, at) / run, 0.0, 1.0) : at / len, height};
  const Vec2 origin = p + d * at;
  for (const Vec2& w : world) f.points.emplace_back(OpenMesh::dot(w - origin, d), OpenMesh::dot(w - origin, out));
  return f;
}

ExtrusionSpec addForcedStep(ExtrusionSpec s, int loop, int edge, const std::vector<Vec2>& world, double height,
                            int frontProfile, const std::string& name) {
  profileAt(s, frontProfile);
  ForcedStepFrame f = forcedStepFrame(s, loop, edge, world, height);
  PlanStep st;
  st.name = name;
  st.shape = StepShape::Forced;
  st.anchor = f.anchor;
  st.points = std::move(f.points);
  st.frontProfile = st.sideProfile = frontProfile;
  if (s.steps.size() >= limits::kMaxSteps) fail("steps", "an extrusion holds at most " + std::to_string(limits::kMaxSteps) + " steps");
  s.steps.push_back(std::move(st));
  return s;
}

ExtrusionSpec moveAnchor(ExtrusionSpec s, int step, const Anchor& anchor) {
  if (step < 0 || step >= static_cast<int>(s.steps.size())) fail("step", "no step " + std::to_string(step));
  s.steps[step].anchor = anchor;
  return s;
}

ExtrusionSpec deleteStep(ExtrusionSpec s, int step) {
  if (step < 0 || step >= static_cast<int>(s.steps.size())) fail("step", "no step " + std::to_string(step));
  s.steps.erase(s.steps.begin() + step);
  return s;
}

namespace {

// Throws when the anchor names no edge of the plan or its place is not a valid number.
void checkAnchorOn(const ExtrusionSpec& s, const Anchor& a) {
  if (a.loop < 0 || a.loop >= static_cast<int>(s.loops.size())) fail("anchor.loop", "no loop number " + std::to_string(a.loop));
  if (a.edge < 0 || a.edge >= static_cast<int>(s.loops[a.loop].points.size()))
    fail("anchor.edge", "loop " + std::to_string(a.loop) + " has no edge " + std::to_string(a.edge));
  if (!std::isfinite(a.along) || (!a.absolute && (a.along < 0 || a.along > 1)) || std::abs(a.along) > 1e7)
    fail("anchor.along", a.absolute ? "an absolute anchor needs a finite distance" : "a relative anchor needs a fraction within [0, 1]");
  if (!std::isfinite(a.height) || a.height < 0 || a.height > 1e5) fail("anchor.height", "must be within [0, 1e5] m above the base");
}

void checkRepeatOf(const ExtrusionSpec& s, const Anchor& a, const Repeat& r) {
  if (auto bad = checkRepeat(a, r)) {
    const auto colon = bad->find(": ");
    fail("repeat." + bad->substr(0, colon), bad->substr(colon + 2));
  }
  if (auto bad = checkInstanceCounts(s)) {
    const auto colon = bad->find(": ");
    fail("repeat", bad->substr(colon + 2));
  }
}

MeshAnchor& meshAnchorAt(ExtrusionSpec& s, int index) {
  if (index < 0 || index >= static_cast<int>(s.anchors.size())) fail("index", "no mesh anchor " + std::to_string(index));
  return s.anchors[index];
}

}  // namespace

ExtrusionSpec setStepRepeat(ExtrusionSpec s, int step, const Repeat& repeat) {
  if (step < 0 || step >= static_cast<int>(s.steps.size())) fail("step", "no step " + std::to_string(step));
  s.steps[step].repeat = repeat;
  checkRepeatOf(s, s.steps[step].anchor, repeat);
  return s;
}

ExtrusionSpec addMeshAnchor(ExtrusionSpec s, const MeshAnchor& anchor) {
  checkAnchorOn(s, anchor.anchor);
  if (anchor.feature != FeatureKind::None)
    if (auto bad = checkFeatureSize(anchor.size)) {
      const auto colon = bad->find(": ");
      fail(bad->substr(0, colon), bad->substr(colon + 2));
    }
  s.anchors.push_back(anchor);
  if (anchor.feature == FeatureKind::None) s.anchors.back().size = FeatureSize();  // not saved without a feature
  checkRepeatOf(s, anchor.anchor, anchor.repeat);
  return s;
}

ExtrusionSpec moveMeshAnchor(ExtrusionSpec s, int index, const Anchor& anchor) {
  MeshAnchor& m = meshAnchorAt(s, index);
  checkAnchorOn(s, anchor);
  m.anchor = anchor;
  checkRepeatOf(s, m.anchor, m.repeat);
  return s;
}

ExtrusionSpec deleteMeshAnchor(ExtrusionSpec s, int index) {
  meshAnchorAt(s, index);
  s.anchors.erase(s.anchors.begin() + index);
  return s;
}

ExtrusionSpec setFeatureSize(ExtrusionSpec s, int index, const FeatureSize& size) {
  if (auto bad = checkFeatureSize(size)) {
    const auto colon = bad->find(": ");
    fail(bad->substr(0, colon), bad->substr(colon + 2));
  }
  MeshAnchor& m = meshAnchorAt(s, index);
  if (m.feature == FeatureKind::None) fail("index", "mesh anchor " + std::to_string(index) + " has no feature to resize");
  m.size = size;
  return s;
}

ExtrusionSpec setFeatureRepeat(ExtrusionSpec s, int index, const Repeat& repeat) {
  MeshAnchor& m = meshAnchorAt(s, index);
  m.repeat = repeat;
  checkRepeatOf(s, m.anchor, repeat);
  return s;
}

std::vector<Profile> profileLibrary() {
  auto make = [](std::string name, std::vector<Vec2> pts, std::vector<std::string> tags) {
    Profile p;
    p.name = std::move(name);
    p.points = std::move(pts);
    p.tags = std::move(tags);
    return p;
  };
  return {
      make("vertical wall", {{0, 0}, {0, 1}}, {"wall"}),
      make("hip", {{0, 0}, {0, 3}, {3, 6}}, {"wall", "roof"}),
      make("gable", {{0, 0}, {0, 3}, {0, 4}}, {"wall", "gable"}),
      make("mansard", {{0, 0}, {0, 3}, {0.8, 5.5}, {3.5, 6.8}}, {"wall", "mansard", "roof"}),
      make("gambrel", {{0, 0}, {0, 3}, {0.9, 5}, {0.9, 6}}, {"wall", "gambrel", "gable"}),
      make("shed", {{0, 0}, {0, 3}, {4, 5}}, {"wall", "roof"}),
      make("overhanging eave", {{0, 0}, {0, 3}, {-0.4, 3}, {3.1, 6}}, {"wall", "soffit", "roof"}),
      make("dormer front", {{0, 0}, {0, 1}}, {"dormer"}),
      make("dormer side", {{0, 0}, {0, 1.2}, {1, 2.2}}, {"dormer", "dormer roof"}),
      make("bay", {{0, 0}, {0, 2.6}, {1, 3.6}}, {"bay", "bay roof"}),
      make("buttress", {{0, 0}, {0, 2}, {1, 3.5}}, {"buttress", "buttress slope"}),
      make("cornice", {{0, 0}, {0, 6}, {-0.3, 6}, {-0.3, 6.4}, {0.2, 6.4}, {0.2, 7}, {3.2, 9}},
           {"wall", "cornice soffit", "cornice", "cornice top", "attic", "roof"}),
  };
}

namespace {

Vec2 vec2(const nlohmann::json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number())
    fail(what, "expected [x, y] numbers");
  return Vec2(j[0].get<double>(), j[1].get<double>());
}

int integer(const nlohmann::json& op, const std::string& key) {
  if (!op.contains(key) || !op[key].is_number_integer()) fail(key, "expected an integer");
  return op[key].get<int>();
}

double number(const nlohmann::json& op, const std::string& key) {
  if (!op.contains(key) || !op[key].is_number()) fail(key, "expected a number");
  return op[key].get<double>();
}

std::string text(const nlohmann::json& op, const std::string& key) {
  if (!op.contains(key) || !op[key].is_string()) fail(key, "expected a string");
  return op[key].get<std::string>();
}

int profileNamed(const ExtrusionSpec& s, const std::string& name) {
  for (std::size_t i = 0; i < s.profiles.size(); ++i)
    if (s.profiles[i].name == name) return static_cast<int>(i);
  fail("profile", "no profile named \"" + name + "\"");
}

Profile libraryProfile(const std::string& name) {
  for (const Profile& p : profileLibrary())
    if (p.name == name) return p;
  fail("profile", "no library profile named \"" + name + "\"");
}

Anchor anchorFrom(const nlohmann::json& j) {
  if (!j.is_object()) fail("anchor", "expected an object");
  Anchor a;
  a.loop = integer(j, "loop");
  a.edge = integer(j, "edge");
  if (j.contains("at")) {
    a.absolute = true;
    a.along = number(j, "at");
  } else if (j.contains("fraction")) {
    a.along = number(j, "fraction");
  }
  if (j.contains("height")) a.height = number(j, "height");
  return a;
}

Repeat repeatFrom(const nlohmann::json& j) {
  if (!j.is_object()) fail("repeat", "expected an object");
  Repeat r;
  const std::string kind = text(j, "kind");
  if (kind == "none") return r;
  if (kind == "row") r.kind = RepeatKind::Row;
  else if (kind == "grid") r.kind = RepeatKind::Grid;
  else fail("repeat.kind", "expected \"row\", \"grid\" or \"none\"");
  r.along = number(j, "along");
  r.spacing = number(j, "spacing");
  if (r.kind == RepeatKind::Grid) {
    r.height = number(j, "height");
    r.rowSpacing = number(j, "row_spacing");
  }
  return r;
}

FeatureSize sizeFrom(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
    fail("size", "expected [width, height, depth] numbers");
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

}  // namespace

std::string applyEdit(Document& doc, const nlohmann::json& op, std::vector<std::string>* notes) {
  if (!op.is_object()) fail("op", "an edit is a JSON object");
  const std::string kind = text(op, "op");
  if (kind == "new_extrusion") {
    ExtrusionSpec s;
    Profile p = libraryProfile(text(op, "profile"));
    s.profiles.push_back(p);
    std::vector<Vec2> pts;
    if (!op.contains("points") || !op["points"].is_array()) fail("points", "expected a list of [x, y]");
    for (const auto& q : op["points"]) pts.push_back(vec2(q, "points"));
    s = addLoop(std::move(s), std::move(pts), 0);
    const std::string name = text(op, "name");
    if (doc.findByName(name)) fail("name", "an object called \"" + name + "\" exists already");
    doc.add(name, s);
    return "New extrusion " + name;
  }
  const std::string name = text(op, "object");
  const DocObject* found = doc.findByName(name);
  if (!found) fail("object", "no object called \"" + name + "\"");
  DocObject* o = doc.find(found->id);
  if (kind == "set_background") {
    PlanBackground b = o->background.value_or(PlanBackground());
    b.image = text(op, "image");
    if (op.contains("scale")) b.scale = number(op, "scale");
    if (op.contains("origin")) b.origin = vec2(op["origin"], "origin");
    if (op.contains("opacity")) b.opacity = number(op, "opacity");
    if (auto bad = checkPlanBackground(b)) {
      const auto colon = bad->find(": ");
      fail(bad->substr(0, colon), bad->substr(colon + 2));
    }
    o->background = b;
    return "Set background (" + name + ")";
  }
  if (kind == "clear_background") {
    o->background.reset();
    return "Remove background (" + name + ")";
  }
  auto* sp = std::get_if<ExtrusionSpec>(&o->spec);
  if (!sp) fail("object", "\"" + name + "\" is not an extrusion");
  ExtrusionSpec& s = *sp;
  std::string label;
  if (kind == "insert_corner") {
    s = insertCorner(s, integer(op, "loop"), integer(op, "edge"), vec2(op["at"], "at"), notes);
    label = "Insert corner";
  } else if (kind == "delete_corner") {
    s = deleteCorner(s, integer(op, "loop"), integer(op, "corner"), notes);
    label = "Delete corner";
  } else if (kind == "delete_loop") {
    s = deleteLoop(s, integer(op, "loop"), notes);
    label = "Delete loop";
  } else if (kind == "move_corner") {
    s = moveCorner(s, integer(op, "loop"), integer(op, "corner"), vec2(op["to"], "to"));
    label = "Move corner";
  } else if (kind == "add_loop") {
    std::vector<Vec2> pts;
    if (!op.contains("points") || !op["points"].is_array()) fail("points", "expected a list of [x, y]");
    for (const auto& q : op["points"]) pts.push_back(vec2(q, "points"));
    s = addLoop(s, std::move(pts), profileNamed(s, text(op, "profile")));
    label = "Add loop";
  } else if (kind == "set_edge_profile") {
    std::vector<EdgeRef> edges;
    if (!op.contains("edges") || !op["edges"].is_array()) fail("edges", "expected a list of [loop, edge]");
    for (const auto& e : op["edges"]) {
      const Vec2 v = vec2(e, "edges");
      edges.emplace_back(static_cast<int>(v[0]), static_cast<int>(v[1]));
    }
    s = setEdgeProfile(s, edges, profileNamed(s, text(op, "profile")));
    label = "Assign profile";
  } else if (kind == "add_profile") {
    Profile p = libraryProfile(text(op, "from"));
    if (op.contains("as")) p.name = text(op, "as");
    s = addProfile(s, p);
    label = "Add profile";
  } else if (kind == "insert_profile_point") {
    s = insertProfilePoint(s, profileNamed(s, text(op, "profile")), integer(op, "after"), vec2(op["at"], "at"));
    label = "Insert profile point";
  } else if (kind == "move_profile_point") {
    s = moveProfilePoint(s, profileNamed(s, text(op, "profile")), integer(op, "point"), vec2(op["to"], "to"));
    label = "Move profile point";
  } else if (kind == "delete_profile_point") {
    s = deleteProfilePoint(s, profileNamed(s, text(op, "profile")), integer(op, "point"));
    label = "Delete profile point";
  } else if (kind == "add_overhang") {
    s = addOverhang(s, number(op, "height"), number(op, "depth"));
    label = "Add overhang";
  } else if (kind == "set_tag") {
    s = setSegmentTag(s, profileNamed(s, text(op, "profile")), integer(op, "segment"), text(op, "tag"));
    label = "Set tag";
  } else if (kind == "add_step") {
    const nlohmann::json& j = op.contains("step") ? op["step"] : nlohmann::json();
    if (!j.is_object()) fail("step", "expected an object");
    PlanStep st;
    if (j.contains("name")) st.name = text(j, "name");
    st.anchor = anchorFrom(j.contains("anchor") ? j["anchor"] : nlohmann::json());
    const std::string shape = j.contains("shape") ? text(j, "shape") : "rectangle";
    if (shape == "bay") st.shape = StepShape::Bay;
    else if (shape == "forced") st.shape = StepShape::Forced;
    else if (shape != "rectangle") fail("shape", "expected \"rectangle\", \"bay\" or \"forced\"");
    if (st.shape == StepShape::Forced) {
      for (const auto& q : j.value("points", nlohmann::json::array())) st.points.push_back(vec2(q, "points"));
    } else {
      st.width = number(j, "width");
      st.depth = number(j, "depth");
      if (j.contains("cant")) st.cant = number(j, "cant");
    }
    st.frontProfile = profileNamed(s, text(j, "front_profile"));
    st.sideProfile = j.contains("side_profile") ? profileNamed(s, text(j, "side_profile")) : st.frontProfile;
    s = addStep(s, st);
    label = "Add step";
  } else if (kind == "add_forced_step") {
    std::vector<Vec2> pts;
    if (!op.contains("points") || !op["points"].is_array()) fail("points", "expected a list of [x, y]");
    for (const auto& q : op["points"]) pts.push_back(vec2(q, "points"));
    const double height = op.contains("height") ? number(op, "height") : 0.0;
    s = addForcedStep(s, integer(op, "loop"), integer(op, "edge"), pts, height, profileNamed(s, text(op, "profile")),
                      op.contains("name") ? text(op, "name") : "forced step");
    label = "Add forced step";
  } else if (kind == "move_anchor") {
    s = moveAnchor(s, integer(op, "step"), anchorFrom(op.contains("anchor") ? op["anchor"] : nlohmann::json()));
    label = "Move anchor";
  } else if (kind == "delete_step") {
    s = deleteStep(s, integer(op, "step"));
    label = "Delete step";
  } else if (kind == "set_step_repeat") {
    s = setStepRepeat(s, integer(op, "step"), repeatFrom(op.contains("repeat") ? op["repeat"] : nlohmann::json()));
    label = "Repeat step";
  } else if (kind == "add_feature") {
    MeshAnchor m;
    m.name = op.contains("name") ? text(op, "name") : text(op, "feature");
    const auto feature = featureFromName(text(op, "feature"));
    if (!feature) fail("feature", "expected \"none\", \"door\", \"window\", \"roof_window\" or \"chimney_pot\"");
    m.feature = *feature;
    m.size = op.contains("size") ? sizeFrom(op["size"]) : defaultFeatureSize(m.feature);
    m.anchor = anchorFrom(op.contains("anchor") ? op["anchor"] : nlohmann::json());
    if (op.contains("repeat")) m.repeat = repeatFrom(op["repeat"]);
    s = addMeshAnchor(s, m);
    label = "Add " + m.name;
  } else if (kind == "move_feature") {
    s = moveMeshAnchor(s, integer(op, "index"), anchorFrom(op.contains("anchor") ? op["anchor"] : nlohmann::json()));
    label = "Move feature";
  } else if (kind == "set_feature_size") {
    s = setFeatureSize(s, integer(op, "index"), sizeFrom(op.contains("size") ? op["size"] : nlohmann::json()));
    label = "Resize feature";
  } else if (kind == "set_feature_repeat") {
    s = setFeatureRepeat(s, integer(op, "index"), repeatFrom(op.contains("repeat") ? op["repeat"] : nlohmann::json()));
    label = "Repeat feature";
  } else if (kind == "delete_feature") {
    s = deleteMeshAnchor(s, integer(op, "index"));
    label = "Delete feature";
  } else {
    fail("op", "unknown edit \"" + kind + "\"");
  }
  return label + " (" + name + ")";
}

}  // namespace corbel::extrude::edit
