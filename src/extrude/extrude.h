#pragma once
// Procedural extrusions (Kelly & Wonka 2011): ExtrusionSpec → a closed 2-manifold shell.
#include "core/mesh_data.h"
#include "core/progress.h"
#include "extrude/spec.h"
#include "extrude/sweep.h"

#include <string>
#include <vector>

namespace corbel::extrude {

struct ExtrusionResult {
  SweepOutput shell;
  double scale = 0.0;  // plan bounding-box diagonal the tolerances were scaled by
};

// Validates the spec (throws InputError naming the loop/edge/point) and runs the sweep.
ExtrusionResult extrude(const ExtrusionSpec& spec, Progress* progress = nullptr, double timeLimitSeconds = 0.0);

// Areas and volume of a shell, from its planar faces (holes included).
struct ShellMeasures {
  double volume = 0.0;
  double roofArea = 0.0;   // faces leaning inward (θ > 0) or flat caps
  double wallArea = 0.0;   // vertical faces (θ = 0)
  double soffitArea = 0.0; // faces leaning outward (θ < 0)
  double baseArea = 0.0;
  double maxHeight = 0.0;
  std::size_t faces = 0;
};
ShellMeasures measure(const SweepOutput& shell);

// The shell as Scene geometry: faces without holes stay one polygon; faces with holes are
// triangulated (CGAL constrained Delaunay), every piece keeping the face's provenance. Tags:
// the profile segment's tag, else "wall", "roof", "soffit" or "base".
MeshData toMeshData(const SweepOutput& shell, const ExtrusionSpec& spec, const std::string& material);

// Area of a planar polygon with holes (outer minus holes), in its own plane.
double faceArea(const SweepOutput& shell, const ShellFace& face);

}  // namespace corbel::extrude
