#include "editor/dimensions.h"

#include "core/error.h"
#include "extrude/edit.h"

#include <cmath>
#include <numbers>
#include <string>

namespace corbel::editor {

namespace {

const PlanLoop& loopAt(const ExtrusionSpec& spec, int loop) {
  if (loop < 0 || loop >= static_cast<int>(spec.loops.size())) throw InputError("loop", "no loop " + std::to_string(loop));
  return spec.loops[loop];
}

const Profile& profileAt(const ExtrusionSpec& spec, int profile, int segment) {
  if (profile < 0 || profile >= static_cast<int>(spec.profiles.size()))
    throw InputError("profile", "no profile " + std::to_string(profile));
  const Profile& p = spec.profiles[profile];
  if (segment < 0 || segment + 1 >= static_cast<int>(p.points.size()))
    throw InputError("segment", "profile \"" + p.name + "\" has no segment " + std::to_string(segment));
  return p;
}

void checkLength(double length) {
  if (!std::isfinite(length) || length <= 0)
    throw InputError("length", "a length must be a positive number of metres (got " + std::to_string(length) + ")");
}

// The unit direction from a to b; throws where they coincide.
Vec2 direction(const Vec2& a, const Vec2& b, const std::string& what) {
  const Vec2 d = b - a;
  const double n = d.norm();
  if (!(n > 1e-12)) throw InputError(what, "it has no length, so no direction to measure along");
  return d / n;
}

}  // namespace

double planEdgeLength(const ExtrusionSpec& spec, int loop, int edge) {
  const PlanLoop& l = loopAt(spec, loop);
  const int n = static_cast<int>(l.points.size());
  if (edge < 0 || edge >= n) throw InputError("edge", "loop " + std::to_string(loop) + " has no edge " + std::to_string(edge));
  return (l.points[(edge + 1) % n] - l.points[edge]).norm();
}

ExtrusionSpec setPlanEdgeLength(const ExtrusionSpec& spec, int loop, int edge, double length) {
  planEdgeLength(spec, loop, edge);  // checks the edge exists
  checkLength(length);
  const PlanLoop& l = spec.loops[loop];
  const int end = (edge + 1) % static_cast<int>(l.points.size());
  const Vec2 d = direction(l.points[edge], l.points[end], "edge");
  return extrude::edit::moveCorner(spec, loop, end, l.points[edge] + d * length);
}

double profileSegmentLength(const ExtrusionSpec& spec, int profile, int segment) {
  const Profile& p = profileAt(spec, profile, segment);
  return (p.points[segment + 1] - p.points[segment]).norm();
}

double profileSegmentPitch(const ExtrusionSpec& spec, int profile, int segment) {
  const Profile& p = profileAt(spec, profile, segment);
  const Vec2 d = p.points[segment + 1] - p.points[segment];
  return std::atan2(d[1], d[0]) * 180 / std::numbers::pi;
}

ExtrusionSpec setProfileSegmentLength(const ExtrusionSpec& spec, int profile, int segment, double length) {
  const Profile& p = profileAt(spec, profile, segment);
  checkLength(length);
  const Vec2 a = p.points[segment], b = p.points[segment + 1];
  const Vec2 shift = a + direction(a, b, "segment") * length - b;
  // Each point is moved next to a neighbour already moved by the same shift, never past an
  // unmoved one (moveProfilePoint keeps z between the neighbours' heights): from the top down
  // when the shift raises them, from the bottom up when it lowers them.
  ExtrusionSpec s = spec;
  const int last = static_cast<int>(p.points.size()) - 1;
  for (int k = 0; k < last - segment; ++k) {
    const int i = shift[1] > 0 ? last - k : segment + 1 + k;
    s = extrude::edit::moveProfilePoint(s, profile, i, p.points[i] + shift);
  }
  return s;
}

}  // namespace corbel::editor
