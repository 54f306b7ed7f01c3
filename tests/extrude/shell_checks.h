#pragma once
// Geometric checks of a shell beyond closure (the Scene checks that): each face a simple
// polygon in its own plane, and the triangulated shell free of self-intersections. A face
// that runs up a hip past the roof's apex and back (a needle of no area) is closed and a
// 2-manifold, and only these see it.
#include "extrude/extrude.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace corbel::extrude::test {

// "" or the first problem: a face loop (outer or hole) that is not simple when projected onto
// the coordinate plane its normal is most across (CGAL's is_simple_2), or two triangles of the
// shell's mesh (toMeshData, every face cut by triangulatePolygon as the exports and the renderer
// cut it) that intersect (CGAL's exact predicates), except triangles that only touch at one
// point where the mesh has two vertices (a vertex of two fans split in two, as toMeshData does
// where a shell touches itself).
std::string shellGeometryProblem(const SweepOutput& shell, const ExtrusionSpec& spec);

// The first half of shellGeometryProblem: "" or the first face loop that is not simple in the
// coordinate plane its normal is most across.
std::string faceLoopProblem(const SweepOutput& shell);

// How far above CGAL's skeleton the top of a one-profile shell may be and still count as the
// skeleton's top: the kernel's event height tolerance δ1 (events that close in height are one),
// plus δ2 (events that close in plan are one, so an edge meets the last event up to δ2 from
// where it would) times the profile's slope dz/dw at that height (a horizontal error moves the
// top by that much). `height` is the shell's top; the profile's last segment goes on past its
// end, and a vertical segment, which moves no edge, adds nothing.
double skeletonTopTolerance(const Profile& profile, double height, double delta1, double delta2);

// The shells the random, real-footprint and saved-case runs may build although a check flags
// them, each named with the reason (tests/data/extrude/shell_check_exemptions.txt): lines
// "RUN  ID  CHECK  REASON" ('#' starts a comment line), RUN one of random (the random run and its saved cases), hip45
// or mixed (the real footprints' runs), CHECK geometry (shellGeometryProblem) or above-skeleton (with one profile, the
// top above CGAL's skeleton by more than skeletonTopTolerance). The runs fail on a flagged shell the list does not
// name, and on a named one that passes (its line is to go).
struct ShellCheckExemptions {
  std::map<std::string, std::string> reasons;  // "RUN ID CHECK" -> reason
  std::vector<std::string> problems;           // malformed or repeated lines
  bool exempt(const std::string& run, const std::string& id, const std::string& check) const {
    return reasons.count(run + " " + id + " " + check) > 0;
  }
};
const ShellCheckExemptions& shellCheckExemptions();

}  // namespace corbel::extrude::test
