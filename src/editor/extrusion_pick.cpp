// A click in the 3D view on an extrusion: the face under the ray, by its provenance, selects
// its plan edge and profile segment in the panes.
#include "editor/extrusion_panes.h"

#include "extrude/extrude.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace corbel::editor {

std::string ExtrusionPanes::pick(const ExtrusionSpec& spec, const Vec3& origin, const Vec3& direction) {
  extrude::ExtrusionResult r;
  try {
    r = extrude::extrude(spec);
  } catch (const std::exception&) {
    return "";
  }
  const auto& pts = r.shell.points;
  double bestT = std::numeric_limits<double>::infinity();
  const extrude::ShellFace* best = nullptr;
  for (const extrude::ShellFace& f : r.shell.faces) {
    const double denom = OpenMesh::dot(f.normal, direction);
    if (std::abs(denom) < 1e-12) continue;
    const double t = OpenMesh::dot(f.normal, pts[f.loops[0][0]] - origin) / denom;
    if (!(t > 0) || t >= bestT) continue;
    const Vec3 hit = origin + direction * t;
    // Inside the face: even-odd over its loops, in the face's plane.
    Vec3 u = std::abs(f.normal[2]) < 0.9 ? OpenMesh::cross(Vec3(0, 0, 1), f.normal) : Vec3(1, 0, 0);
    u.normalize();
    const Vec3 v = OpenMesh::cross(f.normal, u);
    const double hx = OpenMesh::dot(hit, u), hy = OpenMesh::dot(hit, v);
    bool in = false;
    for (const auto& loop : f.loops)
      for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const double ax = OpenMesh::dot(pts[loop[i]], u), ay = OpenMesh::dot(pts[loop[i]], v);
        const double bx = OpenMesh::dot(pts[loop[j]], u), by = OpenMesh::dot(pts[loop[j]], v);
        if ((ay > hy) != (by > hy) && hx < (bx - ax) * (hy - ay) / (by - ay) + ax) in = !in;
      }
    if (in) {
      bestT = t;
      best = &f;
    }
  }
  if (!best) return "";
  char text[256];
  if (best->base) {
    std::snprintf(text, sizeof text, "the base");
    return text;
  }
  if (best->profile >= 0 && best->profile < static_cast<int>(spec.profiles.size())) {
    profile_ = best->profile;
    pickedSegment_ = best->segment >= 0 ? std::optional<int>(best->segment) : std::nullopt;
  }
  const std::string profileName = best->profile >= 0 ? spec.profiles[best->profile].name : "-";
  if (best->sourceLoop >= 0) {
    selectedEdges_ = {{best->sourceLoop, best->sourceEdge}};
    std::snprintf(text, sizeof text, "loop %d edge %d, profile \"%s\" segment %d", best->sourceLoop, best->sourceEdge,
                  profileName.c_str(), best->segment);
  } else if (best->step >= 0) {
    selectedEdges_.clear();
    std::snprintf(text, sizeof text, "step %d (%s), profile \"%s\" segment %d", best->step,
                  spec.steps[best->step].name.c_str(), profileName.c_str(), best->segment);
  } else {
    std::snprintf(text, sizeof text, "a horizontal face made at a plan change");
  }
  return text;
}

void ExtrusionPanes::showEdge(const ExtrusionSpec& spec, int loop, int edge, std::optional<int> segment) {
  if (loop < 0 || loop >= static_cast<int>(spec.loops.size())) return;
  const PlanLoop& l = spec.loops[loop];
  if (edge < 0 || edge >= static_cast<int>(l.profile.size())) return;
  selectedEdges_ = {{loop, edge}};
  profile_ = l.profile[edge];
  pickedSegment_ = segment;
}

}  // namespace corbel::editor
