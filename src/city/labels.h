#pragma once
// Edge labels of a footprint (Kelly & Wonka Sec. 3.7): a length class, the orientation to the
// street and the angle of the edge's normal once the building is turned to face its street.
#include "city/import.h"

#include <optional>
#include <string_view>
#include <vector>

namespace corbel::city {

enum class LengthClass { Short, Medium, Long };
enum class Orientation { Street, Side, Back };
std::string_view lengthName(LengthClass c);
std::string_view orientationName(Orientation o);
std::optional<LengthClass> lengthFromName(std::string_view name);
std::optional<Orientation> orientationFromName(std::string_view name);

struct EdgeLabel {
  int loop = 0, edge = 0;  // edge i of a loop runs from point i to point i + 1
  double length = 0;
  LengthClass length_class = LengthClass::Medium;
  Orientation orientation = Orientation::Side;
  // The outward normal on the unit disk turned so the building's front points up (+y): disk =
  // (sin angle, cos angle); angle in degrees in (-180, 180], 0 facing the street, positive
  // clockwise from it (to the right, seen from above looking at the street).
  double angle = 0;
  Vec2 disk{0, 1};
};

struct BuildingLabels {
  Vec2 front{0, 1};         // unit, from the building towards its street
  bool fromStreet = false;  // true: a street centreline; false: the widest gap to neighbours
  std::vector<EdgeLabel> edges;
  std::size_t longestStreetEdge = 0;  // index into edges (the building's main front)
};

struct LabelOptions {
  double shortBelow = 4.0;    // m
  double longFrom = 12.0;     // m
  double streetDegrees = 45;  // |angle| up to this: street; from 180 - this: back; else side
  double gapReach = 40.0;     // m: how far the gap search looks for neighbours
  double streetReach = 200;   // m: farther streets are ignored (then the gap decides)
};

// Labels every usable building of the town (unusable ones get empty labels), on `jobs`
// threads (0 = all cores). Given `only`, just those buildings (the others get empty labels): a
// building's labels depend on the other buildings' outlines and the streets, not on their
// labels, so they are the ones labelling the whole town gives.
std::vector<BuildingLabels> labelTown(const Town& town, const LabelOptions& options = {}, unsigned jobs = 0,
                                      const std::vector<std::size_t>* only = nullptr);

// Labels of one footprint facing `front` (unit vector).
std::vector<EdgeLabel> labelEdges(const std::vector<std::vector<Vec2>>& loops, const Vec2& front,
                                  const LabelOptions& options = {});

}  // namespace corbel::city
