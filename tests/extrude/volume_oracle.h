#pragma once
// An independent volume for a shell that was rebuilt with wider tolerances (extrude/batch.h):
// - Cgal: every edge has one profile rising inward (a wall, one or more roof slopes), so the
//   active plan at each height is an offset of the unweighted straight skeleton: CGAL's
//   skeleton integrated under the profile (skeleton_oracle.h).
// - Unperturbed: an orthogonal plan perturbed by less than 1e-5 m (the random plans'
//   near-degenerate cases), rounded back to its exact axis-parallel plan and built with the
//   normal tolerances, closing without warnings and unchanged by a quarter turn and a move
//   (else the unperturbed plan is itself ambiguous: None). The volume is continuous in such small moves
//   wherever colinear edges meet by the priority rule (Sec. 4.8), as the wider merge sine
//   makes them.
// - None: neither applies (mixed profiles on a plan with slanted edges).
#include "extrude/extrude.h"

namespace corbel::extrude::test {

struct VolumeOracle {
  enum Kind { None, Cgal, Unperturbed } kind = None;
  double volume = 0;
  double roofArea = 0;  // Unperturbed only
};

VolumeOracle independentVolume(const ExtrusionSpec& spec);

}  // namespace corbel::extrude::test
