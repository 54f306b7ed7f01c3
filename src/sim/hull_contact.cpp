#include "sim/hull_contact.h"

#include "core/error.h"
#include "statics/interfaces.h"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>
#include <BulletCollision/NarrowPhaseCollision/btPolyhedralContactClipping.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::sim {
namespace {

// The extent of `hull` (placed by `t`) along `axis`.
void project(const btConvexPolyhedron& hull, const btTransform& t, const btVector3& axis, btScalar& lo, btScalar& hi) {
  const btVector3 local = t.getBasis().transpose() * axis;
  const btScalar offset = axis.dot(t.getOrigin());
  lo = std::numeric_limits<btScalar>::infinity();
  hi = -lo;
  for (int i = 0; i < hull.m_vertices.size(); ++i) {
    const btScalar d = local.dot(hull.m_vertices[i]) + offset;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
}

// The gap between A and B along `axis` oriented from A to B: positive when they stand apart
// along it, negative by the overlap.
btScalar gapAlong(const btConvexPolyhedron& a, const btTransform& ta, const btConvexPolyhedron& b,
                  const btTransform& tb, const btVector3& axis) {
  btScalar loA, hiA, loB, hiB;
  project(a, ta, axis, loA, hiA);
  project(b, tb, axis, loB, hiB);
  return loB - hiA;
}

// The clipped points of one pair, before they go into the manifold.
struct ClippedPoints : btDiscreteCollisionDetectorInterface::Result {
  struct Point {
    btVector3 normal, onB;
    btScalar depth;
  };
  std::vector<Point> points;
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3& normal, const btVector3& onB, btScalar depth) override {
    points.push_back({normal, onB, depth});
  }
};

// The corners of the clipped contact polygon, in order: points inside it, on one of its edges
// or repeated are dropped. A manifold holds four points; the clipping may give a fifth on an
// edge (where the other face has a vertex), and Bullet's reduction would then drop a corner and
// shrink the joint a force may act on (an arch at its least thickness fell).
std::vector<ClippedPoints::Point> corners(const std::vector<ClippedPoints::Point>& points) {
  if (points.size() <= 2) return points;
  btVector3 u, w;
  btPlaneSpace1(points[0].normal, u, w);
  struct P2 {
    double x, y;
    std::size_t i;
  };
  std::vector<P2> p;
  double extent = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    p.push_back({double(points[i].onB.dot(u)), double(points[i].onB.dot(w)), i});
    extent = std::max({extent, std::abs(p.back().x - p[0].x), std::abs(p.back().y - p[0].y)});
  }
  std::sort(p.begin(), p.end(), [](const P2& a, const P2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  // Andrew's monotone chain; a turn smaller than this (relative to the extent²) is straight.
  const double straight = 1e-9 * extent * extent;
  auto cross = [](const P2& o, const P2& a, const P2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<P2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= straight) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= straight) --k;
    hull[k++] = p[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
  std::vector<ClippedPoints::Point> out;
  for (const P2& q : hull) out.push_back(points[q.i]);
  return out;
}

class ClippedHullContact : public btActivatingCollisionAlgorithm {
 public:
  // `tolerance` > 0: each step's contacts are the clipped faces of the blocks as they are, with
  // the statics kernel's tolerance (see useFaceContacts); 0: Bullet's clipping merged into its
  // manifold (useClippedHullContacts).
  ClippedHullContact(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* a,
                     const btCollisionObjectWrapper* b, double tolerance)
      : btActivatingCollisionAlgorithm(ci, a, b), tolerance_(tolerance) {}
  ~ClippedHullContact() override {
    if (manifold_) m_dispatcher->releaseManifold(manifold_);
  }

  void processCollision(const btCollisionObjectWrapper* wa, const btCollisionObjectWrapper* wb, const btDispatcherInfo&,
                        btManifoldResult* out) override {
    if (!manifold_) manifold_ = m_dispatcher->getNewManifold(wa->getCollisionObject(), wb->getCollisionObject());
    out->setPersistentManifold(manifold_);
    const auto* sa = static_cast<const btPolyhedralConvexShape*>(wa->getCollisionShape());
    const auto* sb = static_cast<const btPolyhedralConvexShape*>(wb->getCollisionShape());
    const btConvexPolyhedron& a = *sa->getConvexPolyhedron();
    const btConvexPolyhedron& b = *sb->getConvexPolyhedron();
    const btTransform& ta = wa->getWorldTransform();
    const btTransform& tb = wb->getWorldTransform();
    const btVector3 fromAtoB = tb * b.m_localCenter - ta * a.m_localCenter;

    // The axis along which A and B are farthest apart (least overlapping). Face normals win
    // ties with edge-edge directions, so two blocks sharing a joint get its plane's normal.
    btScalar best = -std::numeric_limits<btScalar>::infinity();
    btVector3 axis(0, 0, 1);
    bool faceAxis = false;
    auto consider = [&](btVector3 n, btScalar bias, bool face) {
      if (n.dot(fromAtoB) < 0) n = -n;
      const btScalar g = gapAlong(a, ta, b, tb, n);
      if (g > best + bias) {
        best = g;
        axis = n;
        faceAxis = face;
      }
    };
    for (int f = 0; f < a.m_faces.size(); ++f)
      consider(ta.getBasis() * btVector3(a.m_faces[f].m_plane[0], a.m_faces[f].m_plane[1], a.m_faces[f].m_plane[2]), 0,
               true);
    for (int f = 0; f < b.m_faces.size(); ++f)
      consider(tb.getBasis() * btVector3(b.m_faces[f].m_plane[0], b.m_faces[f].m_plane[1], b.m_faces[f].m_plane[2]), 0,
               true);
    const btScalar threshold = manifold_->getContactBreakingThreshold();
    const btScalar edgeBias = 1e-3 * threshold;  // an edge axis must beat the faces clearly
    for (int i = 0; i < a.m_uniqueEdges.size(); ++i)
      for (int j = 0; j < b.m_uniqueEdges.size(); ++j) {
        btVector3 n = (ta.getBasis() * a.m_uniqueEdges[i]).cross(tb.getBasis() * b.m_uniqueEdges[j]);
        if (n.length2() < 1e-12) continue;
        consider(n.normalized(), edgeBias, false);
      }
    if (tolerance_ == 0) {
      if (best <= threshold) {
        // Bullet's clipping takes the normal from B towards A and reports points on B.
        btPolyhedralContactClipping::clipHullAgainstHull(-axis, a, b, ta, tb, best - threshold, threshold, vertsB1_,
                                                         vertsB2_, *out);
      }
      out->refreshContactPoints();
      return;
    }
    // Fresh points every step, the contact polygon of the blocks as they are: Bullet's manifold
    // would match each new point to the nearest of its old ones and keep old points that the
    // clipping no longer finds (its solver warm-starts from them).
    manifold_->clearManifold();
    if (best > threshold) return;
    if (faceAxis) {
      clipFaces(a, ta, b, tb, axis, threshold, *out);
      return;
    }
    // Edge against edge: Bullet's clipping, its points reduced to the polygon's corners.
    ClippedPoints clipped;
    btPolyhedralContactClipping::clipHullAgainstHull(-axis, a, b, ta, tb, best - threshold, threshold, vertsB1_,
                                                     vertsB2_, clipped);
    for (const ClippedPoints::Point& p : corners(clipped.points)) out->addContactPoint(p.normal, p.onB, p.depth);
  }

  // The contact of two faces across `axis` (from A to B): A's face that faces B most and B's that
  // faces A most, clipped against each other in the plane across the axis with the statics
  // kernel's clip and tolerance (statics::clipConvex: faces that match within it clip to
  // themselves, corners and all). Each corner of the result is a contact point, its depth the
  // distance between the two faces' planes there along the axis.
  void clipFaces(const btConvexPolyhedron& a, const btTransform& ta, const btConvexPolyhedron& b, const btTransform& tb,
                 const btVector3& axis, btScalar threshold, btManifoldResult& out) const {
    auto facing = [&](const btConvexPolyhedron& hull, const btTransform& t, const btVector3& dir) {
      int best = 0;
      btScalar most = -2;
      for (int f = 0; f < hull.m_faces.size(); ++f) {
        const btScalar d = (t.getBasis() * btVector3(hull.m_faces[f].m_plane[0], hull.m_faces[f].m_plane[1],
                                                     hull.m_faces[f].m_plane[2]))
                               .dot(dir);
        if (d > most) {
          most = d;
          best = f;
        }
      }
      return best;
    };
    const btFace& fa = a.m_faces[facing(a, ta, axis)];
    const btFace& fb = b.m_faces[facing(b, tb, -axis)];
    btVector3 u, w;
    btPlaneSpace1(axis, u, w);  // u × w = axis
    std::vector<Vec2> pa, pb;
    for (int i = 0; i < fa.m_indices.size(); ++i) {
      const btVector3 p = ta * a.m_vertices[fa.m_indices[i]];
      pa.emplace_back(p.dot(u), p.dot(w));
    }
    // B's face runs counter-clockwise about B's outward normal, against the axis: reversed.
    for (int i = fb.m_indices.size(); i-- > 0;) {
      const btVector3 p = tb * b.m_vertices[fb.m_indices[i]];
      pb.emplace_back(p.dot(u), p.dot(w));
    }
    const std::vector<Vec2> polygon = statics::clipConvex(pb, pa, tolerance_);
    const btVector3 na = ta.getBasis() * btVector3(fa.m_plane[0], fa.m_plane[1], fa.m_plane[2]);
    const btVector3 nb = tb.getBasis() * btVector3(fb.m_plane[0], fb.m_plane[1], fb.m_plane[2]);
    const btVector3 onFaceA = ta * a.m_vertices[fa.m_indices[0]], onFaceB = tb * b.m_vertices[fb.m_indices[0]];
    for (const Vec2& q : polygon) {
      const btVector3 x = u * q[0] + w * q[1];
      // x + s·axis on each face's plane.
      const btScalar sa = (onFaceA - x).dot(na) / axis.dot(na), sb = (onFaceB - x).dot(nb) / axis.dot(nb);
      const btScalar depth = sb - sa;
      if (depth <= threshold) out.addContactPoint(-axis, x + axis * sb, depth);
    }
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override {
    if (manifold_) manifolds.push_back(manifold_);
  }

  struct CreateFunc : btCollisionAlgorithmCreateFunc {
    explicit CreateFunc(double tolerance) : tolerance(tolerance) {}
    double tolerance;
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                   const btCollisionObjectWrapper* a,
                                                   const btCollisionObjectWrapper* b) override {
      void* mem = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(ClippedHullContact));
      return new (mem) ClippedHullContact(ci, a, b, tolerance);
    }
  };

 private:
  double tolerance_;
  btPersistentManifold* manifold_ = nullptr;
  btVertexArray vertsB1_, vertsB2_;
};

}  // namespace

void setExactFaces(btConvexHullShape& shape, const std::vector<btVector3>& vertices,
                   const std::vector<std::vector<int>>& faces) {
  btConvexPolyhedron poly;
  for (const btVector3& v : vertices) poly.m_vertices.push_back(v);
  // Each face's outward normal (Newell's method), then faces grouped by plane.
  std::vector<btVector3> normals;
  for (const auto& f : faces) {
    btVector3 n(0, 0, 0);
    for (std::size_t i = 0; i < f.size(); ++i) {
      const btVector3& a = vertices[f[i]];
      const btVector3& b = vertices[f[(i + 1) % f.size()]];
      n += btVector3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                     (a.x() - b.x()) * (a.y() + b.y()));
    }
    normals.push_back(n.normalized());
  }
  std::vector<bool> done(faces.size(), false);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (done[i]) continue;
    const btVector3 n = normals[i];
    std::vector<int> ids;
    for (std::size_t j = i; j < faces.size(); ++j)
      if (!done[j] && normals[j].dot(n) > 1 - 1e-9) {
        done[j] = true;
        for (int k : faces[j])
          if (std::find(ids.begin(), ids.end(), k) == ids.end()) ids.push_back(k);
      }
    // The merged face's boundary: its vertices in counter-clockwise order about n (a convex
    // face, so by angle about their centre), points inside the boundary dropped.
    btVector3 u, w;
    btPlaneSpace1(n, u, w);
    btVector3 c(0, 0, 0);
    for (int k : ids) c += vertices[k];
    c /= btScalar(ids.size());
    std::sort(ids.begin(), ids.end(), [&](int a, int b) {
      const btVector3 da = vertices[a] - c, db = vertices[b] - c;
      return std::atan2(da.dot(w), da.dot(u)) < std::atan2(db.dot(w), db.dot(u));
    });
    // u × w = n (btPlaneSpace1), so increasing angle is counter-clockwise about n.
    btFace face;
    btScalar lowest = std::numeric_limits<btScalar>::infinity();
    for (int k : ids) lowest = std::min(lowest, vertices[k].dot(n));
    for (int k : ids) face.m_indices.push_back(k);
    face.m_plane[0] = n.x();
    face.m_plane[1] = n.y();
    face.m_plane[2] = n.z();
    face.m_plane[3] = -lowest;
    poly.m_faces.push_back(face);
  }
  poly.initialize();
  shape.setPolyhedralFeatures(poly);
}

void useClippedHullContacts(btCollisionDispatcher& dispatcher) {
  static ClippedHullContact::CreateFunc create(0.0);
  dispatcher.registerCollisionCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE, &create);
}

std::unique_ptr<btCollisionAlgorithmCreateFunc> useFaceContacts(btCollisionDispatcher& dispatcher, double tolerance) {
  if (!(tolerance > 0)) throw Error("simulation: the contact tolerance must be positive");
  auto create = std::make_unique<ClippedHullContact::CreateFunc>(tolerance);
  dispatcher.registerCollisionCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE, create.get());
  return create;
}

}  // namespace corbel::sim
