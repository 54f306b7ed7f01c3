#pragma once
// The kernel's view of the extrusion spec (core/extrusion_spec.h): angle steps, standard
// profiles and validation.
#include "core/extrusion_spec.h"
#include "core/geometry.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel::extrude {

using corbel::Anchor;
using corbel::ExtrusionSpec;
using corbel::FeatureKind;
using corbel::FeatureSize;
using corbel::Repeat;
using corbel::RepeatKind;
using corbel::MeshAnchor;
using corbel::OffsetEdge;
using corbel::OffsetEvent;
using corbel::PlanStep;
using corbel::StepShape;
using corbel::PlanLoop;
using corbel::Priority;
using corbel::Profile;

// Standard profiles used by the CLI and tests.
Profile hipProfile(double pitchRadians);                             // one inward segment
Profile wallAndRoofProfile(double wallHeight, double pitchRadians);  // wall, then roof

// Checks a spec and returns the first fault as "loops[1].points[3]: ...", or nullopt.
std::optional<std::string> checkSpec(const ExtrusionSpec& spec);

}  // namespace corbel::extrude
