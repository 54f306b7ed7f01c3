#pragma once
// Procedural extrusions (Kelly & Wonka 2011): ExtrusionSpec → a closed 2-manifold shell.
#include "core/mesh_data.h"
#include "core/progress.h"
#include "extrude/spec.h"
#include "extrude/sweep.h"

#include <string>
#include <vector>

namespace corbel::extrude {

// A mesh anchor's place on the shell (Sec. 3.4): where it is and the frame of the face there.
struct AnchorFrame {
  std::string name;
  int source = -1;         // the spec.anchors entry it is an instance of (repeats expanded)
  bool instanced = false;  // false: its edge is not in the active plan at that height
  Vec3 position;
  Vec3 along;   // unit, along the active edge (the input edge's direction)
  Vec3 normal;  // unit, outward normal of the face the edge traces there
  Vec3 up;      // unit, normal × along: up the face
};

struct ExtrusionResult {
  SweepOutput shell;
  // One per instance of spec.anchors, in order (an anchor that repeats gives one per element).
  std::vector<AnchorFrame> anchors;
  double scale = 0.0;  // plan bounding-box diagonal the tolerances were scaled by
  double toleranceFactor = 1.0;  // ExtrudeOptions::toleranceFactor it was built with
};

struct ExtrudeOptions {
  double timeLimitSeconds = 0.0;  // > 0: give up with an Error after this long
  // Multiplies the sweep's tolerances (Tolerances::forScale). 1 is the kernel as documented;
  // larger factors are for rebuilding a shell that failed validation (extrude/batch.cpp), and
  // their results need checking (docs/extrude.md, "Rebuilding with wider tolerances").
  double toleranceFactor = 1.0;
  // Where the post inter-chain check (Sec. 4.4) finds the active plan overlapping itself,
  // rebuild it there by the winding rule (extrude/winding.h) instead of sweeping on with a
  // warning. Off in a first build: the overlap comes from an earlier degenerate event, and the
  // rule makes a valid plan of what is there, not always the right one; the batch uses it as
  // a last rebuild, checked by agreement (docs/extrude.md, "Rebuilding by the winding rule").
  bool windingRule = false;
};

// Validates the spec (throws InputError naming the loop/edge/point), expands its repeats
// (core/extrusion_spec.h) and runs the sweep. Shell faces of a repeated step name the step's
// index in `spec`.
ExtrusionResult extrude(const ExtrusionSpec& spec, Progress* progress, const ExtrudeOptions& options);
inline ExtrusionResult extrude(const ExtrusionSpec& spec, Progress* progress = nullptr, double timeLimitSeconds = 0.0) {
  return extrude(spec, progress, ExtrudeOptions{timeLimitSeconds, 1.0, false});
}

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
// mergeCoplanar (an export option): neighbouring faces in one plane with the same tag and
// material become one face, as campskeleton outputs them; provenance is then the first's.
MeshData toMeshData(const SweepOutput& shell, const ExtrusionSpec& spec, const std::string& material,
                    bool mergeCoplanar = false);

// Directed boundary edges of the shell without exactly one reverse partner (0 for a closed,
// consistently oriented shell). Linear-logarithmic: a cheap test before building a mesh.
std::size_t unpairedEdges(const SweepOutput& shell);

// "" where every loop of every face is a simple polygon in its plane (simpleInItsPlane), else
// the first that is not: "face F (plan edge E, segment S) crosses itself in its plane, its top
// at (x, y, z)". A shell can be closed and a 2-manifold and still have such a face (a roof's
// boundary running past its ridge and back): the batch and the editor's builder reject it as
// they reject a shell that is not closed, and rebuild it with wider tolerances.
std::string crossedFace(const SweepOutput& shell);

// Area of a planar polygon with holes (outer minus holes), in its own plane.
double faceArea(const SweepOutput& shell, const ShellFace& face);

}  // namespace corbel::extrude
