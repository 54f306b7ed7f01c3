#pragma once
// Many buildings at once on all cores: each is extruded, measured and checked on its own, and
// a bad building never stops the batch.
#include "core/mesh_data.h"
#include "core/progress.h"
#include "extrude/extrude.h"
#include "extrude/features.h"

#include <string>
#include <vector>

namespace corbel::extrude {

struct BatchItem {
  std::string id;
  ExtrusionSpec spec;
  std::string problem;  // known before extrusion (e.g. a bad GeoJSON ring): reported, skipped
};

struct BatchResult {
  std::string id;
  bool ok = false;
  std::string error;             // why it failed
  std::vector<std::string> warnings;
  ShellMeasures measures;
  std::size_t meshFaces = 0, meshVertices = 0;
  bool watertight = false, manifold = false;
  double ms = 0.0;  // all attempts together
  // 1: the first build passed. Larger: the first build failed validation and this is the
  // accepted rebuild with that many times the tolerances (a warning says so).
  double toleranceFactor = 1.0;
  int builds = 0;                    // extrusions run for it: 1 for a building that passed (or was refused) at once
  std::vector<AnchorFrame> anchors;  // the spec's mesh anchors, placed on the shell
  MeshData mesh;                 // kept when requested (for export)
  std::vector<FeaturePlacement> features;  // BatchOptions::featuresApart: the features left out of `mesh`
};

struct BatchOptions {
  unsigned jobs = 0;             // 0 = all cores
  bool keepMeshes = false;
  bool mergeCoplanar = false;    // kept meshes only: coplanar neighbours merged (export option)
  bool featuresApart = false;    // kept meshes only: without their features, placed in BatchResult::features
  double timeLimitSeconds = 10.0;  // per building and attempt
  // A building whose first build fails validation (not closed, not a 2-manifold, a face crossing
  // itself, or an error of the sweep; never bad input or the time limit) is rebuilt with tolerance factors
  // (Tolerances::forScale) from a window of `retryWindow` consecutive entries, in turn. The
  // window's first rebuild is accepted only when the others pass too and all agree on volume
  // and roof area within `retryAgreement` (relative): wider tolerances can close a shell around
  // the wrong roof, and several of them rarely make the same wrong one. Where the window's
  // first rebuild fails outright, the window moves one entry up while the list allows (a
  // disagreement never moves it). Empty: no rebuilds. docs/extrude.md has the measurements.
  std::vector<double> retryFactors{10.0, 100.0, 1000.0, 10000.0};
  std::size_t retryWindow = 3;
  double retryAgreement = 1e-6;
  // Every build with ExtrudeOptions::windingRule (corbel-cli extrude --winding-rule): off by
  // default, see docs/extrude.md, "Rebuilding by the winding rule".
  bool windingRule = false;
};

std::vector<BatchResult> extrudeBatch(const std::vector<BatchItem>& items, const BatchOptions& options,
                                      Progress* progress = nullptr);

}  // namespace corbel::extrude
