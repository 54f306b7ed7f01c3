#pragma once
// KIFS buildings in the Document (core/kifs_spec.h): the spec's numbers turned into the kernel's
// KifsParams and back, and the SceneSync builder that registers KIFS objects with the Scene.
#include "core/kifs_spec.h"
#include "core/scene_sync.h"
#include "kifs/params.h"

#include <string>

namespace corbel::kifs {

// The parameters a spec holds, checked by validate(): a bad value throws corbel::Error naming
// the field as the project file does ("kifs.mass.shell: must be ..."). The trace's pixel
// angle is not part of a spec; the renderer sets it for its view (render::kifsForView).
KifsParams paramsOf(const KifsSpec& spec);
// The spec of a set of parameters (a preset), named after `preset`.
KifsSpec specOf(const KifsParams& params, std::string preset = {});

// A KIFS object's builder: the parameters are validated (a bad one is the object's error); with
// spec.meshResolution = 0 the object has no faces (it is ray-marched by render::KifsPass), else
// its building is meshed at that resolution (kifs/mesher.h, cancellable through the build's
// progress), faces of kind Ornament tagged "kifs" in the spec's material. A building that
// follows another object (footprint "object") is meshed on that object's shell, built from its
// spec by the same SceneSync, in world space (BuildResult::worldSpace); it is rebuilt whenever
// that object changes. A follower of one building of a town is refused (ray-marched only).
void registerKernel(SceneSync& sync);

}  // namespace corbel::kifs
