#pragma once
// Many buildings at once on all cores: each is extruded, measured and checked on its own, and
// a bad building never stops the batch.
#include "core/mesh_data.h"
#include "core/progress.h"
#include "extrude/extrude.h"

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
  double ms = 0.0;
  std::vector<AnchorFrame> anchors;  // the spec's mesh anchors, placed on the shell
  MeshData mesh;                 // kept when requested (for export)
};

struct BatchOptions {
  unsigned jobs = 0;             // 0 = all cores
  bool keepMeshes = false;
  bool mergeCoplanar = false;    // kept meshes only: coplanar neighbours merged (export option)
  double timeLimitSeconds = 10.0;  // per building
};

std::vector<BatchResult> extrudeBatch(const std::vector<BatchItem>& items, const BatchOptions& options,
                                      Progress* progress = nullptr);

}  // namespace corbel::extrude
