#pragma once
// The rectangular cartogram of a form (Sec. 7.3.2-7.3.3): its sub-units (ShapeTree boxes),
// the sea region around them cut into rectangles, the relations ≺x / ≺z between corners,
// and realization of corner correspondences that keeps them.
//
// - Boundary paths (Alg. 1): the outline of the union of units, walked clockwise through the
//   trees' leaves and jumping from unit to unit along their incidence links.
// - Sea decomposition (Alg. 2): each pocket between that outline and the bounding box is cut
//   into rectangles by collapsing its steps; enclosed sea (courtyards) by rectangle
//   subtraction.
// - The cartogram keeps every rectangle as indices into sorted coordinate lines xs, ys;
//   realization and sizing move lines, never past a neighbour, so no rectangle inverts and
//   the arrangement (and so ≺x and ≺z) is kept.
#include "growth/floorplan.h"

#include <array>
#include <string>
#include <vector>

namespace corbel::growth {

// The four cases of Fig. 7.13 as Alg. 1 meets them.
enum class TraceCase {
  NoIncidence = 0,     // the edge has no links: all of it is boundary
  StartCovered = 1,    // the edge's start lies in a linked edge's interval: jump to it
  ContactAhead = 2,    // a linked edge begins further on: boundary up to there, then jump
  ContactsBehind = 3,  // links, but none ahead: the rest of the edge is boundary
};

struct BoundaryTrace {
  std::vector<GridPoint> corners;  // clockwise, cleaned
  std::array<int, 4> cases{};      // how often each TraceCase arose
  // The four paths e_t → e_r → e_b → e_l → e_t between the extremal edges (Fig. 7.12), as
  // runs of `corners` (inclusive index ranges, cyclic).
  std::array<std::pair<int, int>, 4> paths{};
};

// Alg. 1 over the whole outer boundary, starting at the top extremal edge.
BoundaryTrace traceBoundary(const Floorplan& plan);

// Alg. 2: the sea between the units and their bounding box as disjoint rectangles;
// `bySubtraction` (if given) counts those that came from the fallback, not from collapsing.
std::vector<GridRect> seaRectangles(const Floorplan& plan, const BoundaryTrace& trace,
                                    std::size_t* bySubtraction = nullptr);

struct PlanRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double area() const { return (x1 - x0) * (y1 - y0); }
};

class Cartogram {
 public:
  struct Rect {
    int x0, y0, x1, y1;  // indices into xs, ys
    int unit;            // -1: sea
  };
  static Cartogram of(const Floorplan& plan);
  std::vector<double> xs, ys;
  std::vector<Rect> rects;
  PlanRect geometry(int i) const;
  std::vector<PlanRect> geometry() const;
  int subUnits() const;
};

// A corner of a cartogram rectangle: 0 south-west, 1 south-east, 2 north-east, 3 north-west.
struct CornerRef {
  int rect = 0, corner = 0;
};
// The corner's place.
std::array<double, 2> cornerAt(const std::vector<PlanRect>& rects, CornerRef c);

// ≺x and ≺z (Sec. 7.3.3) for all corners of all rectangles, from geometry: p ≺x q when a
// path along rectangle edges leads from p to q with no horizontal step toward −x and at
// least one toward +x (and likewise in y). Indexed [4·rect + corner].
struct Relations {
  std::vector<std::vector<char>> x, z;
  bool operator==(const Relations&) const = default;
};
Relations relationsOf(const std::vector<PlanRect>& rects);

struct Correspondence {
  CornerRef corner;
  double x = 0, y = 0;
};
// Whether the targets respect ≺x and ≺z pairwise (the paper's realizable correspondence).
bool respectsRelations(const std::vector<PlanRect>& rects, const std::vector<Correspondence>& targets,
                       std::string* why = nullptr);
bool realizable(const Cartogram& c, const std::vector<Correspondence>& targets, std::string* why = nullptr);
// Moves coordinate lines so each corresponded corner lands on its target; lines between
// follow proportionally. Refuses (unchanged) when the targets are not realizable or would
// need two lines to swap.
bool realize(Cartogram& c, const std::vector<Correspondence>& targets, std::string* why = nullptr);

}  // namespace corbel::growth
