#include "extrude/spec.h"

#include <cmath>

namespace corbel::extrude {

Profile hipProfile(double pitch) {
  Profile p;
  p.name = "hip";
  // A segment of unit height leaning inward at `pitch` from horizontal: θ = π/2 − pitch.
  p.points = {Vec2(0, 0), Vec2(1.0 / std::tan(pitch), 1.0)};
  p.tags = {"roof"};
  return p;
}

Profile wallAndRoofProfile(double wallHeight, double pitch) {
  if (wallHeight <= 0) return hipProfile(pitch);
  Profile p;
  p.name = "wall+roof";
  p.points = {Vec2(0, 0), Vec2(0, wallHeight), Vec2(1.0 / std::tan(pitch), wallHeight + 1.0)};
  p.tags = {"wall", "roof"};
  return p;
}

}  // namespace corbel::extrude
