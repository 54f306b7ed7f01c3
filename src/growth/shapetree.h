#pragma once
// The ShapeTree (Ch. 6): a tree per unit footprint on an integer grid.
//
// The four top-level nodes are the north, east, south and west edges of a canonical
// rectangle (labels a, b, c, d in the paper). The leaves, read left to right, are the
// footprint's edges in clockwise order (y up), each weighted by its length. Face Split
// turns a leaf into an internal node with three children: the two pieces and, between
// them, a virtual node of weight 0 (Fig. 6.5). Face Advance moves a leaf along its
// normal and changes the weights of the leaves before and after it; a virtual neighbour
// becomes a real step edge (Fig. 6.6). Internal nodes keep the history: which op made
// each node, and the boxes each advance swept. Undo pops the history (Sec. 6.5).
//
// Coordinates are whole grid cells (std::int64_t), so every test on a tree is exact.
#include <cstdint>
#include <string>
#include <vector>

namespace corbel::growth {

using GridCoord = std::int64_t;

struct GridPoint {
  GridCoord x = 0, y = 0;
  bool operator==(const GridPoint&) const = default;
  auto operator<=>(const GridPoint&) const = default;
};

// A closed rectangle [x0, x1] × [y0, y1] on the grid.
struct GridRect {
  GridCoord x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  GridCoord area() const { return (x1 - x0) * (y1 - y0); }
  bool operator==(const GridRect&) const = default;
  auto operator<=>(const GridRect&) const = default;
};

// Whether the interiors of two rectangles meet.
bool interiorsMeet(const GridRect& a, const GridRect& b);
// a − b as disjoint rectangles of positive area.
std::vector<GridRect> subtractRect(const GridRect& a, const GridRect& b);

// Outward normal of an edge; the order is the clockwise order of a rectangle's sides.
enum class Facing { North = 0, East = 1, South = 2, West = 3, None = 4 };
char facingLetter(Facing f);      // 'a' 'b' 'c' 'd' (the paper's labels), '?' for None
Facing oppositeFacing(Facing f);  // North <-> South, East <-> West
// The unit vector an edge of this facing runs along when the boundary is walked clockwise.
GridPoint travelOf(Facing f);
GridPoint normalOf(Facing f);

struct ShapeNode {
  Facing facing = Facing::None;  // None while virtual
  GridCoord weight = 0;          // the edge length (0 for a virtual node)
  int parent = -1;               // -1 for the four top-level nodes
  std::vector<int> children;     // empty for a leaf
  int createdBy = -1;            // history index of the op that made it (-1: the canonical unit)
  int splitLimit = -1;           // SplitCount(v) of Eq. 6.1: splits allowed in its subtree (-1: any)
  bool isVirtual() const { return weight == 0; }
  bool isLeaf() const { return children.empty(); }
};

// A real leaf with its endpoints (from → to, clockwise).
struct ShapeEdge {
  int node = -1;
  Facing facing = Facing::None;
  GridPoint from, to;
  // The fixed coordinate (y for north/south edges, x for east/west) and the interval along it.
  GridCoord line() const { return facing == Facing::North || facing == Facing::South ? from.y : from.x; }
  GridCoord lo() const;
  GridCoord hi() const;
};

struct SplitNodes {
  int first = -1, virtualNode = -1, second = -1;
};

// A component (Sec. 6.5): the real leaves of a subtree and the leaf after them, which
// closes the component's outline.
struct ShapeComponent {
  std::vector<int> leaves;
  int closing = -1;
};

class ShapeTree {
 public:
  ShapeTree() = default;
  // The canonical unit: a w × h rectangle with its south-west corner at `lo` (w, h ≥ 1).
  static ShapeTree canonical(GridPoint lo, GridCoord w, GridCoord h);

  const std::vector<ShapeNode>& nodes() const { return nodes_; }
  const ShapeNode& node(int i) const { return nodes_[std::size_t(i)]; }
  // Leaves in left-to-right order (= clockwise boundary order), with or without virtual ones.
  std::vector<int> leaves(bool withVirtual = false) const;
  std::vector<ShapeEdge> edges() const;  // the real leaves, clockwise
  int faceCount() const;                 // real leaves: |s| of Sec. 7.2
  // Corners of the outline, clockwise; collinear pieces of a split edge are merged.
  std::vector<GridPoint> outline() const;
  GridCoord area() const;  // of the outline (shoelace)
  GridRect bounds() const;
  // The decomposition into boxes (Sec. 6.5): the canonical rectangle and what each advance
  // swept; pairwise interior-disjoint, their union is the footprint.
  const std::vector<GridRect>& boxes() const { return boxes_; }
  // The geometry of a real leaf.
  ShapeEdge edgeOf(int leaf) const;
  ShapeComponent component(int node) const;

  // Face Split (Sec. 6.3): cuts real leaf `leaf` at distance `at` from its start (0 < at < weight).
  SplitNodes faceSplit(int leaf, GridCoord at, std::string* why = nullptr);
  // Face Advance (Sec. 6.2): moves real leaf `leaf` by `alpha` along its outward normal
  // (negative: inward). Refused, leaving the tree unchanged, when a neighbour would get a
  // negative length or the outline would stop being a simple rectilinear polygon.
  bool faceAdvance(int leaf, GridCoord alpha, std::string* why = nullptr);
  // Eq. 6.1: caps the splits in the subtree at `node` (-1 lifts the cap). Refused when the
  // subtree already has more, or when the caps of a node's children would add up to more
  // than the node's own (Σ SplitCount(v_i) ≤ SplitCount(v_x)).
  bool setSplitLimit(int node, int limit, std::string* why = nullptr);
  // Splits made so far in the subtree at `node` (its internal nodes).
  int splitCount(int node) const;

  // Undo the last op; false when there is none.
  bool undo();
  std::size_t historySize() const { return history_.size(); }

  // The outline is a simple, clockwise, rectilinear polygon whose edge labels agree with
  // the geometry and whose boxes tile it. For tests and asserts.
  bool valid(std::string* why = nullptr) const;

 private:
  struct Saved {
    std::vector<ShapeNode> nodes;
    GridPoint anchor;
    std::vector<GridRect> boxes;
    std::vector<int> boxOwner;
  };
  std::vector<ShapeNode> nodes_;
  std::vector<int> roots_;  // the four top-level nodes, north, east, south, west
  GridPoint anchor_;        // where the first leaf starts
  std::vector<GridRect> boxes_;
  std::vector<int> boxOwner_;  // the leaf whose advance made each box (-1: canonical)
  std::vector<Saved> history_;

  void collectLeaves(int n, bool withVirtual, std::vector<int>& out) const;
  Saved save() const { return {nodes_, anchor_, boxes_, boxOwner_}; }
  void restore(Saved s);
};

// A simple rectilinear polygon (clockwise, no repeated or collinear consecutive corners)?
bool simpleRectilinear(const std::vector<GridPoint>& corners, std::string* why = nullptr);
// Twice the signed area (negative for clockwise, y up).
GridCoord signedArea2(const std::vector<GridPoint>& corners);
// Drops repeated corners and merges collinear runs.
std::vector<GridPoint> cleanOutline(std::vector<GridPoint> corners);

}  // namespace corbel::growth
