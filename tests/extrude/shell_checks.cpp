#include "shell_checks.h"

#include "core/geometry.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace corbel::extrude::test {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;
using P3 = K::Point_3;

std::string where(const P3& p) {
  std::ostringstream s;
  s.precision(10);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// The projection of a face onto the coordinate plane its normal is most across.
std::array<int, 2> planeOf(const Vec3& n) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
  return {(axis + 1) % 3, (axis + 2) % 3};
}

// Whether two triangles of the shell meet other than where they must: along their shared side,
// at their shared corner, or at one point both have as a corner (a vertex split in two fans).
bool improper(const std::array<int, 3>& s, const std::array<int, 3>& t, const std::vector<P3>& p) {
  std::array<int, 3> si{-1, -1, -1}, ti{-1, -1, -1};  // the corner of t each corner of s shares
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s[i] == t[j] || p[s[i]] == p[t[j]]) {
        si[i] = j;
        ti[j] = i;
        ++shared;
      }
  const K::Triangle_3 A(p[s[0]], p[s[1]], p[s[2]]), B(p[t[0]], p[t[1]], p[t[2]]);
  if (shared == 0) return CGAL::do_intersect(A, B);
  if (shared == 1) {
    int i = 0, j = 0;
    while (si[i] < 0) ++i;
    while (ti[j] < 0) ++j;
    if (CGAL::do_intersect(K::Segment_3(p[s[(i + 1) % 3]], p[s[(i + 2) % 3]]), B)) return true;
    if (CGAL::do_intersect(K::Segment_3(p[t[(j + 1) % 3]], p[t[(j + 2) % 3]]), A)) return true;
    if (CGAL::coplanar(p[s[0]], p[s[1]], p[s[2]], p[t[(j + 1) % 3]]) &&
        CGAL::coplanar(p[s[0]], p[s[1]], p[s[2]], p[t[(j + 2) % 3]])) {
      // In one plane: neither reaches into the other's corner at the shared point.
      auto inward = [&](const std::array<int, 3>& u, int k) {
        const P3 c = CGAL::centroid(p[u[0]], p[u[1]], p[u[2]]);
        return p[u[k]] + (c - p[u[k]]) * 1e-6;
      };
      if (CGAL::do_intersect(B, inward(s, i)) || CGAL::do_intersect(A, inward(t, j))) return true;
    }
    return false;
  }
  if (shared == 2) {
    // Along a shared side they overlap only when in one plane with their third corners on one
    // side of it.
    int i = 0, j = 0;
    while (si[i] >= 0) ++i;
    while (ti[j] >= 0) ++j;
    int e0 = (i + 1) % 3, e1 = (i + 2) % 3;
    if (!CGAL::coplanar(p[s[e0]], p[s[e1]], p[s[i]], p[t[j]])) return false;
    // Same side of the shared line, within the plane: the third corners' orientations about it
    // agree.
    const K::Vector_3 n = CGAL::cross_product(p[s[e1]] - p[s[e0]], p[s[i]] - p[s[e0]]);
    const K::Vector_3 m = CGAL::cross_product(p[s[e1]] - p[s[e0]], p[t[j]] - p[s[e0]]);
    return n * m > 0;
  }
  return true;  // three corners in common: the same triangle twice
}

}  // namespace

std::string faceLoopProblem(const SweepOutput& shell) {
  for (std::size_t fi = 0; fi < shell.faces.size(); ++fi) {
    const ShellFace& f = shell.faces[fi];
    const auto [u, v] = planeOf(f.normal);
    for (const auto& loop : f.loops) {
      CGAL::Polygon_2<K> p;
      for (int i : loop) p.push_back(P2(shell.points[i][u], shell.points[i][v]));
      if (p.size() < 3 || !p.is_simple()) {
        double top = -1e300;
        P3 at;
        for (int i : loop)
          if (shell.points[i][2] > top) top = shell.points[i][2], at = P3(shell.points[i][0], shell.points[i][1], top);
        // The longest run of the loop that goes out and straight back (a needle): at a corner
        // where the boundary turns back on itself, the shorter of its two sides.
        double needle = 0;
        for (std::size_t k = 0; k < loop.size(); ++k) {
          const Vec3& a = shell.points[loop[(k + loop.size() - 1) % loop.size()]];
          const Vec3& b = shell.points[loop[k]];
          const Vec3& c = shell.points[loop[(k + 1) % loop.size()]];
          const double ab = (b - a).norm(), bc = (c - b).norm();
          if (ab > 0 && bc > 0 && OpenMesh::dot(b - a, c - b) < -0.999 * ab * bc)
            needle = std::max(needle, std::min(ab, bc));
        }
        std::ostringstream s;
        s << "face " << fi << " (edge " << f.sourceEdge << ", segment " << f.segment << ", step " << f.step
          << ") has a loop of " << loop.size() << " corners that is not a simple polygon in its plane; its top "
          << where(at);
        if (needle > 0) s << "; it runs out and back along a line for " << needle << " m";
        return s.str();
      }
    }
  }
  return "";
}

std::string shellGeometryProblem(const SweepOutput& shell, const ExtrusionSpec& spec) {
  if (std::string loop = faceLoopProblem(shell); !loop.empty()) return loop;

  // The shell's mesh, every polygon cut into triangles as the exports and the renderer cut it.
  const MeshData m = toMeshData(shell, spec, "plaster");
  std::vector<P3> pts;
  for (const Vec3& q : m.points) pts.emplace_back(q[0], q[1], q[2]);
  // (Triangles of one polygon tile it: only triangles of different polygons are tested.)
  std::vector<std::array<int, 3>> tris;
  std::vector<std::size_t> polygonOf;
  for (std::size_t fi = 0; fi < m.faces.size(); ++fi) {
    std::vector<Vec3> corners;
    for (int i : m.faces[fi]) corners.push_back(m.points[i]);
    for (auto t : triangulatePolygon(corners)) {
      for (int& i : t) i = m.faces[fi][i];
      tris.push_back(t);
    }
    polygonOf.resize(tris.size(), fi);
  }
  using Box =
      CGAL::Box_intersection_d::Box_with_handle_d<double, 3, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;
  std::vector<Box> boxes;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const auto& t = tris[k];
    boxes.emplace_back(pts[t[0]].bbox() + pts[t[1]].bbox() + pts[t[2]].bbox(), k);
  }
  std::string problem;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    if (!problem.empty() || polygonOf[a.handle()] == polygonOf[b.handle()] ||
        !improper(tris[a.handle()], tris[b.handle()], pts))
      return;
    const auto &s = tris[a.handle()], &t = tris[b.handle()];
    problem = "the shell intersects itself: triangles " + where(pts[s[0]]) + ", " + where(pts[s[1]]) + ", " +
              where(pts[s[2]]) + " and " + where(pts[t[0]]) + ", " + where(pts[t[1]]) + ", " + where(pts[t[2]]);
  });
  return problem;
}

const ShellCheckExemptions& shellCheckExemptions() {
  static const ShellCheckExemptions list = [] {
    ShellCheckExemptions l;
    const std::string file = std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/shell_check_exemptions.txt";
    std::ifstream in(file);
    if (!in) l.problems.push_back("cannot read " + file);
    const std::set<std::string> runs{"random", "hip45", "mixed"}, checks{"geometry", "above-skeleton"};
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      std::istringstream ss(line);  // (ids may hold '#': only whole lines are comments)
      std::string run, id, check, reason;
      if (!(ss >> run) || run[0] == '#') continue;
      ss >> id >> check;
      std::getline(ss >> std::ws, reason);
      const std::string at = "shell_check_exemptions.txt:" + std::to_string(n) + ": ";
      if (!runs.count(run) || !checks.count(check) || id.empty() || reason.empty())
        l.problems.push_back(
            at + "expected \"RUN ID CHECK REASON\" (RUN random, hip45 or mixed; CHECK geometry or above-skeleton)");
      else if (!l.reasons.emplace(run + " " + id + " " + check, reason).second)
        l.problems.push_back(at + run + " " + id + " " + check + " twice");
    }
    return l;
  }();
  return list;
}

double skeletonTopTolerance(const Profile& profile, double height, double delta1, double delta2) {
  const auto& pts = profile.points;
  double slope = 0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const double dw = pts[k + 1][0] - pts[k][0], dz = pts[k + 1][1] - pts[k][1];
    const bool last = k + 2 == pts.size();
    if (height >= pts[k][1] && (height <= pts[k + 1][1] || last)) {
      slope = dw > 0 ? dz / dw : 0.0;
      break;
    }
  }
  return delta1 + delta2 * slope;
}

}  // namespace corbel::extrude::test
