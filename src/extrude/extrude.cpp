#include "extrude/extrude.h"

#include "core/error.h"
#include "extrude/plan_check.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <sstream>

namespace corbel::extrude {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

// Segment angle θ of a profile: the clockwise angle from the vertical to the segment (Sec. 4.1).
double segmentAngle(const Vec2& a, const Vec2& b) { return std::atan2(b[0] - a[0], b[1] - a[1]); }

bool finite(const Vec2& p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

}  // namespace

std::optional<std::string> checkSpec(const ExtrusionSpec& spec) {
  // Every extrusion (each building of a batch) passes here, so the messages' paths are only
  // spelled out once something is wrong.
  if (spec.loops.empty()) return "loops: a plan needs at least one loop";
  if (spec.profiles.empty()) return "profiles: at least one profile is needed";
  for (std::size_t pi = 0; pi < spec.profiles.size(); ++pi) {
    const Profile& p = spec.profiles[pi];
    const auto at = [pi] { return "profiles[" + std::to_string(pi) + "]"; };
    if (p.points.size() < 2) return at() + ".points: a profile needs at least two points";
    for (std::size_t i = 0; i < p.points.size(); ++i)
      if (!finite(p.points[i])) return at() + ".points[" + std::to_string(i) + "]: coordinates must be finite";
    for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
      const Vec2 &a = p.points[i], &b = p.points[i + 1];
      const auto seg = [&at, i] { return at() + ".points[" + std::to_string(i + 1) + "]"; };
      if (b[1] < a[1]) return seg() + ": profiles must be vertically monotone (z may not decrease)";
      if (b[1] == a[1] && b[0] == a[0]) return seg() + ": repeats the previous point";
      if (b[1] == a[1]) {
        if (i == 0) return seg() + ": a profile may not start with a horizontal segment (move the plan instead)";
        if (i + 2 == p.points.size()) return seg() + ": a profile may not end with a horizontal segment";
        if (std::abs(b[0] - a[0]) > 1e6) return seg() + ": the horizontal segment is longer than 1e6 m";
        continue;
      }
      const double theta = segmentAngle(a, b);
      if (std::abs(theta) > kHalfPi - 1e-6)
        return seg() + ": the segment is too close to horizontal (" + std::to_string(theta * 180 / std::numbers::pi) +
               "°)";
    }
    // The last segment may stand vertical (a gable end, closed by its neighbours) but not
    // lean outward: such an edge would grow for ever.
    const double last = segmentAngle(p.points[p.points.size() - 2], p.points.back());
    if (last < 0) return at() + ": the last segment leans outward (angle < 0), so the roof could never close";
  }
  std::vector<std::vector<Vec2>> loops;
  double scale = 0;
  BBox box;
  for (std::size_t li = 0; li < spec.loops.size(); ++li) {
    const PlanLoop& l = spec.loops[li];
    const auto at = [li] { return "loops[" + std::to_string(li) + "]"; };
    if (l.points.size() < 3) return at() + ".points: a loop needs at least three corners";
    if (l.profile.size() != l.points.size())
      return at() + ".profile: one profile per edge is needed (" + std::to_string(l.points.size()) + " edges, " +
             std::to_string(l.profile.size()) + " profiles)";
    if (!l.walls.empty() && l.walls.size() != l.points.size())
      return at() + ".walls: one wall per edge is needed (" + std::to_string(l.points.size()) + " edges, " +
             std::to_string(l.walls.size()) + " walls)";
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      if (!finite(l.points[i])) return at() + ".points[" + std::to_string(i) + "]: coordinates must be finite";
      if (std::abs(l.points[i][0]) > 1e7 || std::abs(l.points[i][1]) > 1e7)
        return at() + ".points[" + std::to_string(i) + "]: coordinates must be within 1e7 m";
      box.add(Vec3(l.points[i][0], l.points[i][1], 0));
      if (l.profile[i] < 0 || static_cast<std::size_t>(l.profile[i]) >= spec.profiles.size())
        return at() + ".profile[" + std::to_string(i) + "]: no profile number " + std::to_string(l.profile[i]);
    }
    loops.push_back(l.points);
  }
  scale = box.diagonal();
  for (std::size_t li = 0; li < spec.loops.size(); ++li) {
    bool closes = false;
    for (int pi : spec.loops[li].profile) {
      const auto& pts = spec.profiles[pi].points;
      closes = closes || segmentAngle(pts[pts.size() - 2], pts.back()) > 1e-9;
    }
    if (!closes)
      return "loops[" + std::to_string(li) + "]: no edge's profile ends leaning inward, so the roof cannot close";
  }
  const Tolerances tol = Tolerances::forScale(scale);
  for (std::size_t li = 0; li < loops.size(); ++li)
    for (std::size_t i = 0; i < loops[li].size(); ++i)
      if ((loops[li][(i + 1) % loops[li].size()] - loops[li][i]).norm() <= tol.minEdge) {
        std::ostringstream m;
        m << "loops[" << li << "].points[" << (i + 1) % loops[li].size() << "]: zero-length edge (repeats points[" << i
          << "])";
        return m.str();
      }
  if (auto bad = checkPlanTopology(loops)) return bad;
  auto checkAnchor = [&](const Anchor& a, const std::string& at) -> std::optional<std::string> {
    if (a.loop < 0 || a.loop >= static_cast<int>(spec.loops.size()))
      return at + ".loop: no loop number " + std::to_string(a.loop);
    if (a.edge < 0 || a.edge >= static_cast<int>(spec.loops[a.loop].points.size()))
      return at + ".edge: loop " + std::to_string(a.loop) + " has no edge number " + std::to_string(a.edge);
    if (!std::isfinite(a.along) || (!a.absolute && (a.along < 0 || a.along > 1)))
      return at + ".along: a relative anchor needs a fraction within [0, 1]";
    if (!std::isfinite(a.height) || a.height < 0 || a.height > 1e5)
      return at + ".height: must be within [0, 1e5] m above the base";
    return std::nullopt;
  };
  for (std::size_t si = 0; si < spec.steps.size(); ++si) {
    const PlanStep& st = spec.steps[si];
    const std::string at = "steps[" + std::to_string(si) + "]";
    if (auto bad = checkAnchor(st.anchor, at + ".anchor")) return bad;
    if (st.shape == StepShape::Forced) {
      if (st.points.size() < 3) return at + ".points: a forced step needs a polygon of at least three points";
      for (std::size_t i = 0; i < st.points.size(); ++i)
        if (!finite(st.points[i]) || std::abs(st.points[i][0]) > 1e5 || std::abs(st.points[i][1]) > 1e5)
          return at + ".points[" + std::to_string(i) + "]: coordinates must be finite and within 1e5 m";
      std::vector<Vec2> poly = st.points;
      double area = 0;
      for (std::size_t i = 0; i < poly.size(); ++i)
        area += poly[i][0] * poly[(i + 1) % poly.size()][1] - poly[(i + 1) % poly.size()][0] * poly[i][1];
      if (area < 0) std::reverse(poly.begin(), poly.end());
      if (auto bad = checkPlanTopology({poly})) {
        const auto colon = bad->find(": ");
        return at + ".points: " + (colon == std::string::npos ? *bad : bad->substr(colon + 2));
      }
      for (int p : {st.frontProfile})
        if (p < 0 || p >= static_cast<int>(spec.profiles.size()))
          return at + ": no profile number " + std::to_string(p);
      continue;
    }
    if (!std::isfinite(st.width) || st.width <= tol.minEdge * 1e3) return at + ".width: must be positive";
    if (!std::isfinite(st.depth) || std::abs(st.depth) <= tol.minEdge * 1e3)
      return at + ".depth: must be non-zero (negative for a recess)";
    if (std::abs(st.width) > 1e5 || std::abs(st.depth) > 1e5) return at + ": larger than 1e5 m";
    if (st.shape == StepShape::Bay && (!std::isfinite(st.cant) || st.cant < 0 || 2 * st.cant >= st.width))
      return at + ".cant: a bay's cant must be at least 0 and less than half its width";
    for (int p : {st.frontProfile, st.sideProfile})
      if (p < 0 || p >= static_cast<int>(spec.profiles.size())) return at + ": no profile number " + std::to_string(p);
  }
  for (std::size_t k = 0; k < spec.offsets.size(); ++k) {
    const OffsetEvent& o = spec.offsets[k];
    const std::string at = "offsets[" + std::to_string(k) + "]";
    if (!std::isfinite(o.height) || o.height <= 0 || o.height > 1e5)
      return at + ".height: must be within (0, 1e5] m above the base";
    auto badProfile = [&](int p) { return p < 0 || p >= static_cast<int>(spec.profiles.size()); };
    if (badProfile(o.sideProfile)) return at + ".side_profile: no profile number " + std::to_string(o.sideProfile);
    if (o.edges.empty()) return at + ".edges: an offset event needs at least one edge";
    for (std::size_t j = 0; j < o.edges.size(); ++j) {
      const OffsetEdge& e = o.edges[j];
      const std::string ej = at + ".edges[" + std::to_string(j) + "]";
      for (int p : {e.profile, e.insideProfile, e.outsideProfile})
        if (badProfile(p)) return ej + ": no profile number " + std::to_string(p);
      if (!std::isfinite(e.inside) || !std::isfinite(e.outside) || std::abs(e.outside) > 1e5)
        return ej + ": offsets must be finite and within 1e5 m";
      if (e.inside * e.outside < 0 || std::abs(e.outside) <= std::abs(e.inside))
        return ej + ": the outside offset must lie beyond the inside one, on the same side of the edge";
      if ((e.outside > 0) != (o.edges[0].outside > 0))
        return ej + ": all offsets of one event must go the same way (all out, or all in)";
    }
  }
  for (std::size_t k = 0; k < spec.anchors.size(); ++k) {
    const MeshAnchor& a = spec.anchors[k];
    const std::string at = "anchors[" + std::to_string(k) + "]";
    if (auto bad = checkAnchor(a.anchor, at + ".anchor")) return bad;
    if (a.feature != FeatureKind::None)
      if (auto bad = checkFeatureSize(a.size)) return at + "." + *bad;
    if (auto bad = checkRepeat(a.anchor, a.repeat)) return at + ".repeat." + *bad;
  }
  for (std::size_t k = 0; k < spec.steps.size(); ++k)
    if (auto bad = checkRepeat(spec.steps[k].anchor, spec.steps[k].repeat))
      return "steps[" + std::to_string(k) + "].repeat." + *bad;
  if (auto bad = checkInstanceCounts(spec)) return bad;
  return std::nullopt;
}

std::size_t unpairedEdges(const SweepOutput& shell) {
  std::vector<std::pair<int, int>> edges;
  for (const ShellFace& f : shell.faces)
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) edges.emplace_back(loop[i], loop[(i + 1) % loop.size()]);
  std::sort(edges.begin(), edges.end());
  std::size_t bad = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const bool repeated = (i > 0 && edges[i - 1] == edges[i]) || (i + 1 < edges.size() && edges[i + 1] == edges[i]);
    const auto rev = std::equal_range(edges.begin(), edges.end(), std::make_pair(edges[i].second, edges[i].first));
    if (repeated || rev.second - rev.first != 1) {
      ++bad;
      if (const char* t = std::getenv("CORBEL_SWEEP_TRACE"); t && *t == '1') {
        const Vec3& a = shell.points[edges[i].first];
        const Vec3& b = shell.points[edges[i].second];
        std::fprintf(stderr, "unpaired edge v%d (%.9g, %.9g, %.9g) -> v%d (%.9g, %.9g, %.9g)\n", edges[i].first, a[0],
                     a[1], a[2], edges[i].second, b[0], b[1], b[2]);
      }
    }
  }
  return bad;
}

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

// CGAL::is_simple_2's answer for a few corners, by testing every pair of sides with the same
// exact predicates: CGAL's sweep allocates a tree per call, which costs more than the pairs
// below a few dozen corners (most faces have 3 to 6). Sides that share a corner may only meet
// there: they overlap where the far ends lie on one line on the same side of it. Other sides
// may not meet at all (a corner twice is two sides touching).
bool simpleByPairs(const std::vector<Epick::Point_2>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Epick::Point_2 &a = p[i], &b = p[(i + 1) % n];
    if (a == b) return false;
    // The next side, from b: it turns back along this one?
    const Epick::Point_2& c = p[(i + 2) % n];
    if (CGAL::collinear(a, b, c) && !CGAL::collinear_are_strictly_ordered_along_line(a, b, c)) return false;
    const Epick::Segment_2 s(a, b);
    // Sides not sharing a corner with this one, each pair once.
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) break;
      if (CGAL::do_intersect(s, Epick::Segment_2(p[j], p[(j + 1) % n]))) return false;
    }
  }
  return true;
}

}  // namespace

bool simpleInItsPlane(const SweepOutput& shell, const ShellFace& f, const std::vector<int>& loop) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(f.normal[k]) > std::abs(f.normal[axis])) axis = k;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  std::vector<Epick::Point_2> flat;
  flat.reserve(loop.size());
  for (int i : loop) flat.emplace_back(shell.points[i][u], shell.points[i][v]);
  if (flat.size() < 3) return false;
  if (flat.size() <= 24) return simpleByPairs(flat);
  return CGAL::is_simple_2(flat.begin(), flat.end(), Epick());
}

std::size_t loopsNotSimple(const SweepOutput& shell) {
  std::size_t n = 0;
  for (const ShellFace& f : shell.faces)
    for (const auto& loop : f.loops) n += simpleInItsPlane(shell, f, loop) ? 0 : 1;
  return n;
}

std::string crossedFace(const SweepOutput& shell) {
  for (std::size_t fi = 0; fi < shell.faces.size(); ++fi) {
    const ShellFace& f = shell.faces[fi];
    for (const auto& loop : f.loops) {
      if (simpleInItsPlane(shell, f, loop)) continue;
      Vec3 top(0, 0, -std::numeric_limits<double>::infinity());
      for (int i : loop)
        if (shell.points[i][2] > top[2]) top = shell.points[i];
      std::ostringstream s;
      s.precision(6);
      s << "face " << fi << " (" << (f.base ? "base" : "plan edge " + std::to_string(f.sourceEdge)) << ", segment "
        << f.segment << ") crosses itself in its plane, its top at (" << top[0] << ", " << top[1] << ", " << top[2]
        << ")";
      return s.str();
    }
  }
  return "";
}

double faceArea(const SweepOutput& shell, const ShellFace& face) {
  double a = 0;
  for (std::size_t k = 0; k < face.loops.size(); ++k) {
    std::vector<Vec3> poly;
    for (int v : face.loops[k]) poly.push_back(shell.points[v]);
    a += OpenMesh::dot(newellNormal(poly), face.normal) * 0.5;  // holes run the other way: negative
  }
  return a;
}

ShellMeasures measure(const SweepOutput& shell) {
  ShellMeasures m;
  m.maxHeight = shell.maxHeight;
  m.faces = shell.faces.size();
  // Divergence theorem: V = 1/3 Σ (n·(p − o)) A over planar faces, any o. Each face is planar
  // only to the kernel's tolerances (a corner within δ2 of its profile's plane), so Σ n A is
  // not exactly zero and V moves with o by (Σ n A)·o / 3: with o at the origin, a plan 1.4 km
  // from it came out 1.85e-5 m³ (2.4 footprint × δ2) over its mesh's own volume. o at the
  // middle of the shell's box keeps that term within the shell's size.
  Vec3 lo(INFINITY, INFINITY, INFINITY), hi(-INFINITY, -INFINITY, -INFINITY);
  for (const Vec3& p : shell.points) {
    lo.minimize(p);
    hi.maximize(p);
  }
  const Vec3 o = shell.points.empty() ? Vec3(0, 0, 0) : (lo + hi) / 2;
  for (const ShellFace& f : shell.faces) {
    const double a = faceArea(shell, f);
    m.volume += OpenMesh::dot(f.normal, shell.points[f.loops[0][0]] - o) * a / 3.0;
    if (f.base)
      m.baseArea += a;
    else if (f.segment == -2 || f.angle > 1e-9)
      m.roofArea += a;
    else if (f.angle < -1e-9)
      m.soffitArea += a;
    else
      m.wallArea += a;
  }
  return m;
}

}  // namespace corbel::extrude
