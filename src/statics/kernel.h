#pragma once
// Registers the masonry-statics kernel with a SceneSync, so masonry objects of a Document
// (core/masonry_spec.h) become blocks in the Scene, and turns a MasonrySpec into the statics
// model it names.
#include "core/masonry_spec.h"
#include "core/scene_sync.h"
#include "statics/parameters.h"

namespace corbel::statics {

// The parametric model `spec.model` names, with the spec's parameter values set. A model or
// parameter that does not exist, or a value the model refuses, throws InputError at
// "masonry.model" or "masonry.parameters.NAME" with the model's own reason. Its build() adds
// the spec's loads (statics/loads.h) to every assembly it makes, and leaves out the model's
// fixed blocks when the spec has no ground (MasonrySpec::ground).
ParametricModel modelOf(const MasonrySpec& spec);

// Every block of the model one closed polyhedron of kind Block, tagged "block" (or "ground"
// for the fixed ones), in the spec's material.
void registerKernel(SceneSync& sync);

}  // namespace corbel::statics
