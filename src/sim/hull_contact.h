#pragma once
// Contacts between two blocks (convex hulls) for the collapse simulation: the faces of the
// hulls clipped against each other along the axis of least penetration, found by testing
// every face normal and edge-edge direction of both hulls (the separating-axis test), and
// made whether the hulls overlap, touch or stand apart by less than the contact threshold.
//
// Bullet's own convex-convex algorithm clips the faces only when GJK finds the hulls
// overlapping; blocks that touch exactly, as masonry is built, get one GJK point a step with a
// normal GJK cannot determine (docs/sim.md, "Contacts").
#include <vector>

class btCollisionDispatcher;
class btConvexHullShape;
class btVector3;

namespace corbel::sim {

// Gives `shape` the faces clipping uses from the block's own vertices and faces (outward,
// counter-clockwise), coplanar faces merged. Bullet's initializePolyhedralFeatures() rebuilds
// them with its hull computer, which rounds every vertex to 1/10216 of the block's extent on
// each axis: 50 µm on a 0.5 m block, enough to tilt a joint's faces against each other.
void setExactFaces(btConvexHullShape& shape, const std::vector<btVector3>& vertices,
                   const std::vector<std::vector<int>>& faces);

// Makes `dispatcher` use the clipped contacts for every pair of convex hull shapes. `fresh`:
// each step's points replace the manifold's (the contact QP wants the contacts as they are);
// otherwise Bullet's manifold merges them with its own, as its sequential-impulse solver, which
// warm-starts from the old points' impulses, expects.
void useClippedHullContacts(btCollisionDispatcher& dispatcher, bool fresh = false);

}  // namespace corbel::sim
