#include "sim/hull_contact.h"

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

class ClippedHullContact : public btActivatingCollisionAlgorithm {
 public:
  ClippedHullContact(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* a,
                     const btCollisionObjectWrapper* b, bool fresh)
      : btActivatingCollisionAlgorithm(ci, a, b), fresh_(fresh) {}
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
    auto consider = [&](btVector3 n, btScalar bias) {
      if (n.dot(fromAtoB) < 0) n = -n;
      const btScalar g = gapAlong(a, ta, b, tb, n);
      if (g > best + bias) {
        best = g;
        axis = n;
      }
    };
    for (int f = 0; f < a.m_faces.size(); ++f)
      consider(ta.getBasis() * btVector3(a.m_faces[f].m_plane[0], a.m_faces[f].m_plane[1], a.m_faces[f].m_plane[2]), 0);
    for (int f = 0; f < b.m_faces.size(); ++f)
      consider(tb.getBasis() * btVector3(b.m_faces[f].m_plane[0], b.m_faces[f].m_plane[1], b.m_faces[f].m_plane[2]), 0);
    const btScalar threshold = manifold_->getContactBreakingThreshold();
    const btScalar edgeBias = 1e-3 * threshold;  // an edge axis must beat the faces clearly
    for (int i = 0; i < a.m_uniqueEdges.size(); ++i)
      for (int j = 0; j < b.m_uniqueEdges.size(); ++j) {
        btVector3 n = (ta.getBasis() * a.m_uniqueEdges[i]).cross(tb.getBasis() * b.m_uniqueEdges[j]);
        if (n.length2() < 1e-12) continue;
        consider(n.normalized(), edgeBias);
      }
    if (!fresh_) {
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
    ClippedPoints clipped;
    if (best <= threshold)
      btPolyhedralContactClipping::clipHullAgainstHull(-axis, a, b, ta, tb, best - threshold, threshold, vertsB1_,
                                                       vertsB2_, clipped);
    manifold_->clearManifold();
    for (const ClippedPoints::Point& p : clipped.points) out->addContactPoint(p.normal, p.onB, p.depth);
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override {
    if (manifold_) manifolds.push_back(manifold_);
  }

  struct CreateFunc : btCollisionAlgorithmCreateFunc {
    explicit CreateFunc(bool fresh) : fresh(fresh) {}
    bool fresh;
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                   const btCollisionObjectWrapper* a,
                                                   const btCollisionObjectWrapper* b) override {
      void* mem = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(ClippedHullContact));
      return new (mem) ClippedHullContact(ci, a, b, fresh);
    }
  };

 private:
  bool fresh_;
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

void useClippedHullContacts(btCollisionDispatcher& dispatcher, bool fresh) {
  static ClippedHullContact::CreateFunc kept(false), renewed(true);
  dispatcher.registerCollisionCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE,
                                         fresh ? &renewed : &kept);
}

}  // namespace corbel::sim
