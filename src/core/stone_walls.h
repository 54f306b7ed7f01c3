#pragma once
// An extrusion built in stone (the `masonry` section of an extrusion object): its walls
// coursed into blocks for the statics kernel, openings at its door and window anchors, and
// its roof carried as loads on the wall heads (src/compose/stone_extrusion.h builds it).
#include <string>
#include <vector>

namespace corbel {

// What spans an opening: one lintel stone, a flat arch of voussoirs (a jack arch), or a
// semicircular arch of voussoirs springing from the opening's top corners.
enum class OpeningHead { Lintel, FlatArch, SemicircularArch };

// The head over the opening of one mesh anchor, by the anchor's name.
struct StoneOpening {
  std::string anchor;
  OpeningHead head = OpeningHead::Lintel;
  bool operator==(const StoneOpening&) const = default;
};

struct StoneWalls {
  double courseHeight = 0.4;     // m; the wall height is cut into whole courses near this
  double blockLength = 0.8;      // m; the running bond's period along a course
  double thickness = 0.5;        // m, measured inward from the plan edge
  double density = 2400.0;       // kg/m³ of the wall stone
  double coveringWeight = 600.0; // N per m² of roof surface (slates, battens, rafters)
  bool ties = false;             // tie beams: the roof pushes no thrust onto the wall heads
  double windPressure = 0.0;     // N/m² on the walls' outer faces that meet the wind; 0: no wind
  double windDirection = 0.0;    // degrees, the way the wind blows, counter-clockwise from +x
  std::vector<StoneOpening> openings;  // heads other than a lintel, per anchor name
  bool operator==(const StoneWalls&) const = default;
};

// "lintel", "flat_arch", "semicircular_arch"; openingHeadFromName is false for any other name.
const char* openingHeadName(OpeningHead head);
bool openingHeadFromName(const std::string& name, OpeningHead& head);

}  // namespace corbel
