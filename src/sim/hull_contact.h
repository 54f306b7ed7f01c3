#pragma once
// Contacts between two blocks (convex hulls) for the collapse simulation: the faces of the
// hulls clipped against each other along the axis of least penetration, found by testing
// every face normal and edge-edge direction of both hulls (the separating-axis test), and
// made whether the hulls overlap, touch or stand apart by less than the contact threshold.
//
// Bullet's own convex-convex algorithm clips the faces only when GJK finds the hulls
// overlapping; blocks that touch exactly, as masonry is built, get one GJK point a step with a
// normal GJK cannot determine (docs/sim.md, "Contacts").
#include <memory>
#include <vector>

class btCollisionDispatcher;
struct btCollisionAlgorithmCreateFunc;
class btConvexHullShape;
class btVector3;

namespace corbel::sim {

// Gives `shape` the faces clipping uses from the block's own vertices and faces (outward,
// counter-clockwise), coplanar faces merged. Bullet's initializePolyhedralFeatures() rebuilds
// them with its hull computer, which rounds every vertex to 1/10216 of the block's extent on
// each axis: 50 µm on a 0.5 m block, enough to tilt a joint's faces against each other.
void setExactFaces(btConvexHullShape& shape, const std::vector<btVector3>& vertices,
                   const std::vector<std::vector<int>>& faces);

// Makes `dispatcher` use the clipped contacts for every pair of convex hull shapes, merged into
// Bullet's manifold (its sequential-impulse solver warm-starts from the old points' impulses).
void useClippedHullContacts(btCollisionDispatcher& dispatcher);

// Makes `dispatcher` use, for every pair of convex hull shapes, the contacts of the blocks as
// they are, renewed every step (the contact QP's, contact_qp.h): where the axis is a face's, the
// two facing faces clipped against each other by the statics kernel's clip, points within
// `tolerance` (m) of a face's edge counting as inside, so blocks built to touch meet over their
// whole joint, corners and all; edge against edge, Bullet's clipping reduced to its corners.
// Bullet's manifold holds at most four points: a joint of more corners keeps four of them.
// The returned object is the dispatcher's and must outlive it.
std::unique_ptr<btCollisionAlgorithmCreateFunc> useFaceContacts(btCollisionDispatcher& dispatcher, double tolerance);

}  // namespace corbel::sim
