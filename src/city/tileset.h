#pragma once
// A town as a 3D Tiles 1.1 tileset (docs/city.md, "Tilesets"): a quadtree of square cells over
// the buildings, each leaf cell a tile of plain blocks (city/blocks.h) refined by a tile of the
// full buildings, and the root placed on the globe by an east-north-up frame in Earth-centred,
// Earth-fixed (ECEF) coordinates.
#include "core/geometry.h"

#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <vector>

namespace corbel::city {

// A square cell of the quadtree: its level (0: the root) and position (x, y) among the 2^level
// cells a side of that level, its corner and side in metres.
struct QuadCell {
  int level = 0;
  long x = 0, y = 0;
  double x0 = 0, y0 = 0, size = 0;
  std::vector<int> children;  // into Quadtree::cells; none for a leaf
  int leaf = -1;              // the leaf's number (leaves in depth-first order), -1 for an inner cell
};

struct Quadtree {
  std::vector<QuadCell> cells;  // [0] the root; empty when there are no points
  std::vector<int> leafOf;      // per point: its leaf's number
  std::vector<int> leafCells;   // per leaf: its cell
};

// Splits the square around `points` into quadrants until a cell holds at most `capacity` points
// and is at most `maxSide` m across (or is under 1 m across, for points that coincide). A point on a cell's edge goes to the cell
// east or north of it. An inner cell with only one quadrant in use is that quadrant (no cell
// has a single child).
Quadtree buildQuadtree(const std::vector<Vec2>& points, std::size_t capacity, double maxSide = 1e300);

// What one leaf's two tiles hold (boxes of their content in the town's frame: x east, y north,
// z up, metres) and the block tile's geometric error. A leaf whose buildings all failed has
// empty boxes and is left out of the tileset.
struct LeafContent {
  std::string blocksUri, detailUri;  // relative to the tileset.json
  BBox blocks, detail;               // in the leaf's frame (LeafFrame)
  double blockError = 0;
  std::array<double, 16> transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // LeafFrame::toRoot
};

// The frame a leaf's content is written in: east-north-up at the leaf's centre, so that no
// building is farther than the leaf's half-diagonal from the tangent point it is placed by.
// A town point p (the local frame, metres) is at
// Rz(-gamma) (p - centre) in it, where gamma is the grid convergence at the centre (the angle
// from true north to the local frame's +y, clockwise); toRoot takes the leaf's frame to the
// root's (the east-north-up frame at the town's origin).
struct LeafFrame {
  Vec2 centre{0, 0};
  double lon = 0, lat = 0;  // the centre's, degrees (WGS 84)
  double gamma = 0;         // radians
  std::array<double, 16> toRoot{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  Vec3 operator()(const Vec3& p) const;        // a point into the leaf's frame
  Vec3 direction(const Vec3& v) const;         // a direction (rotated only)
};
// The leaf frame's PROJ definition: the topocentric conversion from ECEF at the centre.
std::string leafFrameDefinition(const LeafFrame& frame, double height);
// `proj` is the town's local frame (PROJ definition), `root` = enuToEcef at its origin,
// `height` the ground's ellipsoidal height. Throws corbel::Error or InputError.
LeafFrame leafFrame(const std::string& proj, const Vec2& centre, const std::array<double, 16>& root, double height);

// The column-major 4x4 matrix that takes east-north-up metres about (lon, lat, height) (degrees,
// WGS 84 ellipsoidal metres) to ECEF metres (EPSG:4978), by PROJ's topocentric conversion.
// Throws corbel::Error when PROJ cannot make it.
std::array<double, 16> enuToEcef(double lon, double lat, double height);

// The tileset.json: version 1.1, the root's transform (none when null), a leaf's transform its
// LeafContent::transform, every tile's bounding volume a box (in its own frame) around its
// content and its children's grown by `pad` metres on each side, every refinement REPLACE. The root's and each inner tile's geometric error is the diagonal of its
// box, a block tile's its blockError, a building tile's 0.
nlohmann::json tilesetJson(const Quadtree& tree, const std::vector<LeafContent>& leaves,
                           const std::array<double, 16>* transform, double pad);

}  // namespace corbel::city
