#pragma once
// A street from a spline of a few points and the plots along it (Kelly & Wonka Fig. 26). The
// paper grows the plots from seed points by a second application of the skeleton; we offer both
// that (PlotMethod::Skeleton: the frontage strip extruded with vertical walls and a small square
// seed hole per plot whose edges rise at 45°, so each seed's roof faces are the region the
// seed reaches first) and cuts along the street's normals (PlotMethod::Normals, the default),
// which tile the frontage exactly as well and let every plot follow a reshaped street (see
// docs/city.md).
#include "city/import.h"
#include "core/town_spec.h"

#include <vector>

namespace corbel::city {

// A Catmull-Rom spline (uniform) through the control points, sampled `perSpan` times between
// each two of them; the ends are held by repeating the first and last points.
std::vector<Vec2> catmullRom(const std::vector<Vec2>& control, int perSpan = 16);

enum class PlotMethod { Normals, Skeleton };

struct PlotOptions {
  double streetWidth = 10;  // m, kerb to kerb
  double setback = 2;       // m, from the kerb to the plot's front
  double depth = 12;        // m, front to back
  double plotWidth = 7;     // m, wanted frontage of one plot (the frontage is cut evenly)
  bool bothSides = true;
  PlotMethod method = PlotMethod::Normals;
};

// The street as a Town: the centreline as its street and one building per plot (ids
// "left/0", "left/1", …, "right/0", …; properties: side, index).
Town streetTown(const std::vector<Vec2>& control, const PlotOptions& options = {});

// The streets of a town object (core/town_spec.h) added to a town read from footprints: each
// street's centreline joins town.streets (id "street K", K from 1), and its plots join the
// buildings (ids "street K/left/I", "street K/right/I"). A plot that overlaps a footprint, a plot
// of an earlier street, or another street's centreline is kept with a problem naming what it
// overlaps, so the town reports it instead of building one house into another. Bad control
// points throw InputError at "streets[k].points[i]".
void addStreets(Town& town, const std::vector<TownStreet>& streets);

}  // namespace corbel::city
