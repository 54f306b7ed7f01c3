#pragma once
// Every tolerance of the statics kernel, in one place.
#include "core/geometry.h"

#include <algorithm>

namespace corbel::statics {

// Geometric tolerance: kLengthTolerance × the model's bounding-box diagonal. Points closer
// than this are one point, faces whose planes are closer are coplanar, and a contact polygon
// thinner than this (area below tolerance × diagonal) is a zero-area contact. Model
// coordinates are doubles, so 1e-9 of the model size leaves six orders of magnitude above
// rounding noise and is far below any gap a modeller would mean.
inline constexpr double kLengthTolerance = 1e-9;

// Two faces are opposite when their unit normals satisfy n_a · n_b ≤ −(1 − kOppositeCosine).
// 1e-9 is an angle of about 4.5e-5 rad: looser than rounding, tighter than any cut.
inline constexpr double kOppositeCosine = 1e-9;

// Loads are normalised by the total weight W before solving, so forces are O(1) and the
// measure y is y/W². The QP calls a structure feasible when y/W² ≤ kFeasibleMeasure: past
// the threshold y/W² grows roughly with the square of the distance (1.7e-7 at 0.5 % below
// the arch's minimum thickness), so exact thresholds use the LP test instead.
inline constexpr double kFeasibleMeasure = 1e-10;

// The LP phase-1 test calls a structure feasible when the least total equilibrium violation
// (sum of |artificial| over all rows, in units of W) is at most kFeasibleViolation. It grows
// linearly past the threshold, so this places thresholds to about 1e-8 relative.
inline constexpr double kFeasibleViolation = 1e-9;

// A contact vertex is reported as a tension site when f_n⁻ exceeds kTensionSite × W. A
// structure the QP calls feasible (y/W² ≤ 1e-10) has every f_n⁻ ≤ 1e-5 W, so feasible
// structures report none; solver noise in standing ones is far below.
inline constexpr double kTensionSite = 1e-5;

inline double lengthTolerance(const BBox& model) { return kLengthTolerance * std::max(model.diagonal(), 1e-300); }

}  // namespace corbel::statics
