#include "extrude/extrude.h"

#include "core/error.h"
#include "extrude/plan_check.h"

#include <cmath>
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
  std::ostringstream m;
  if (spec.loops.empty()) return "loops: a plan needs at least one loop";
  if (spec.profiles.empty()) return "profiles: at least one profile is needed";
  for (std::size_t pi = 0; pi < spec.profiles.size(); ++pi) {
    const Profile& p = spec.profiles[pi];
    const std::string at = "profiles[" + std::to_string(pi) + "]";
    if (p.points.size() < 2) return at + ".points: a profile needs at least two points";
    for (std::size_t i = 0; i < p.points.size(); ++i)
      if (!finite(p.points[i])) return at + ".points[" + std::to_string(i) + "]: coordinates must be finite";
    for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
      const Vec2 &a = p.points[i], &b = p.points[i + 1];
      const std::string seg = at + ".points[" + std::to_string(i + 1) + "]";
      if (b[1] < a[1]) return seg + ": profiles must be vertically monotone (z may not decrease)";
      if (b[1] == a[1] && b[0] == a[0]) return seg + ": repeats the previous point";
      if (b[1] == a[1])
        return seg + ": horizontal profile segments (near-horizontal direction events, Sec. 4.5.2) are not supported yet";
      const double theta = segmentAngle(a, b);
      if (std::abs(theta) > kHalfPi - 1e-6)
        return seg + ": the segment is too close to horizontal (" + std::to_string(theta * 180 / std::numbers::pi) +
               "°)";
    }
    // The last segment may stand vertical (a gable end, closed by its neighbours) but not
    // lean outward: such an edge would grow for ever.
    const double last = segmentAngle(p.points[p.points.size() - 2], p.points.back());
    if (last < 0) return at + ": the last segment leans outward (angle < 0), so the roof could never close";
  }
  std::vector<std::vector<Vec2>> loops;
  double scale = 0;
  BBox box;
  for (std::size_t li = 0; li < spec.loops.size(); ++li) {
    const PlanLoop& l = spec.loops[li];
    const std::string at = "loops[" + std::to_string(li) + "]";
    if (l.points.size() < 3) return at + ".points: a loop needs at least three corners";
    if (l.profile.size() != l.points.size())
      return at + ".profile: one profile per edge is needed (" + std::to_string(l.points.size()) + " edges, " +
             std::to_string(l.profile.size()) + " profiles)";
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      if (!finite(l.points[i])) return at + ".points[" + std::to_string(i) + "]: coordinates must be finite";
      if (std::abs(l.points[i][0]) > 1e7 || std::abs(l.points[i][1]) > 1e7)
        return at + ".points[" + std::to_string(i) + "]: coordinates must be within 1e7 m";
      box.add(Vec3(l.points[i][0], l.points[i][1], 0));
      if (l.profile[i] < 0 || static_cast<std::size_t>(l.profile[i]) >= spec.profiles.size())
        return at + ".profile[" + std::to_string(i) + "]: no profile number " + std::to_string(l.profile[i]);
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
        m << "loops[" << li << "].points[" << (i + 1) % loops[li].size() << "]: zero-length edge (repeats points["
          << i << "])";
        return m.str();
      }
  return checkPlanTopology(loops);
}

ExtrusionResult extrude(const ExtrusionSpec& spec, Progress* progress, double timeLimitSeconds) {
  if (auto problem = checkSpec(spec)) {
    const auto colon = problem->find(": ");
    throw InputError(problem->substr(0, colon), colon == std::string::npos ? *problem : problem->substr(colon + 2));
  }
  BBox box;
  for (const auto& l : spec.loops)
    for (const Vec2& p : l.points) box.add(Vec3(p[0], p[1], 0));
  ExtrusionResult result;
  result.scale = box.diagonal();

  SweepInput in;
  in.baseZ = spec.baseZ;
  in.timeLimitSeconds = timeLimitSeconds;
  for (std::size_t li = 0; li < spec.loops.size(); ++li) {
    const PlanLoop& l = spec.loops[li];
    std::vector<SweepEdge> loop;
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      SweepEdge e;
      e.start = l.points[i];
      e.sourceLoop = static_cast<int>(li);
      e.sourceEdge = static_cast<int>(i);
      const Profile& p = spec.profiles[l.profile[i]];
      for (std::size_t s = 0; s + 1 < p.points.size(); ++s)
        e.steps.push_back({spec.baseZ + p.points[s][1] - p.points[0][1], segmentAngle(p.points[s], p.points[s + 1]), static_cast<int>(s)});
      // Sec. 4.8: by default the edge with the lowest angle wins (volume maximising).
      const double first = e.steps.front().angle;
      e.priority = spec.priority == Priority::MaximiseVolume ? -first : first;
      loop.push_back(std::move(e));
    }
    in.loops.push_back(std::move(loop));
  }
  result.shell = sweep(in, Tolerances::forScale(result.scale), progress);
  return result;
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
  for (const ShellFace& f : shell.faces) {
    const double a = faceArea(shell, f);
    // Divergence theorem: V = 1/3 Σ (n·p) A over planar faces.
    m.volume += OpenMesh::dot(f.normal, shell.points[f.loops[0][0]]) * a / 3.0;
    if (f.base) m.baseArea += a;
    else if (f.segment == -2 || f.angle > 1e-9) m.roofArea += a;
    else if (f.angle < -1e-9) m.soffitArea += a;
    else m.wallArea += a;
  }
  return m;
}

}  // namespace corbel::extrude
