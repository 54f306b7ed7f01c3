#include "core/extrusion_spec.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace corbel {

const char* featureName(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::None: return "none";
    case FeatureKind::Door: return "door";
    case FeatureKind::Window: return "window";
    case FeatureKind::RoofWindow: return "roof_window";
    case FeatureKind::ChimneyPot: return "chimney_pot";
  }
  return "none";
}

std::optional<FeatureKind> featureFromName(std::string_view name) {
  for (FeatureKind k : {FeatureKind::None, FeatureKind::Door, FeatureKind::Window, FeatureKind::RoofWindow, FeatureKind::ChimneyPot})
    if (name == featureName(k)) return k;
  return std::nullopt;
}

FeatureSize defaultFeatureSize(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::Door: return {1.0, 2.2, 0.15};
    case FeatureKind::Window: return {1.2, 1.4, 0.12};
    case FeatureKind::RoofWindow: return {0.8, 1.1, 0.12};
    case FeatureKind::ChimneyPot: return {0.3, 0.6, 0.3};
    case FeatureKind::None: break;
  }
  return {};
}

namespace {

// How many elements fit between two places `span` metres apart with at least `spacing`
// between neighbours; both ends are used when more than one fits.
std::size_t fitting(double span, double spacing) {
  if (!std::isfinite(span) || !std::isfinite(spacing) || spacing <= 0) return 1;
  const double n = std::floor(std::abs(span) / spacing + 1e-9) + 1;
  return static_cast<std::size_t>(std::min(n, 1e9));
}

double inputEdgeLength(const ExtrusionSpec& spec, const Anchor& a) { return wallRun(spec, a.loop, a.edge).length; }

Vec2 edgeVector(const PlanLoop& l, int e) { return l.points[(e + 1) % l.points.size()] - l.points[e]; }

// The edge of the run holding `along` and how far into it the point lies, m.
std::optional<std::pair<int, double>> placeOnRun(const ExtrusionSpec& spec, const Anchor& a) {
  const WallRun run = wallRun(spec, a.loop, a.edge);
  if (run.edges.empty()) return std::nullopt;
  double s = a.absolute ? a.along : a.along * run.length;
  if (!std::isfinite(s)) s = 0;
  const PlanLoop& l = spec.loops[a.loop];
  for (std::size_t k = 0; k < run.edges.size(); ++k) {
    const double len = edgeVector(l, run.edges[k]).norm();
    if (s <= len || k + 1 == run.edges.size()) return std::make_pair(run.edges[k], std::clamp(s, 0.0, len));
    s -= len;
  }
  return std::nullopt;
}

}  // namespace

int wallOf(const PlanLoop& loop, int edge) {
  if (edge < 0 || edge >= static_cast<int>(loop.points.size())) return 0;
  return loop.walls.size() == loop.points.size() ? loop.walls[edge] : -(edge + 1);  // own, distinct, negative
}

WallRun wallRun(const ExtrusionSpec& spec, int loop, int edge) {
  WallRun run;
  if (loop < 0 || loop >= static_cast<int>(spec.loops.size())) return run;
  const PlanLoop& l = spec.loops[loop];
  const int n = static_cast<int>(l.points.size());
  if (edge < 0 || edge >= n) return run;
  run.loop = loop;
  const int id = wallOf(l, edge);
  int first = edge, count = 1;
  // Back to the run's first edge (a loop that is all one wall starts at edge 0), then forward.
  while (count < n && wallOf(l, (first + n - 1) % n) == id) first = (first + n - 1) % n, ++count;
  if (count == n) first = 0;
  for (int k = 0; k < n; ++k) {
    const int e = (first + k) % n;
    if (wallOf(l, e) != id) break;
    run.edges.push_back(e);
    run.length += edgeVector(l, e).norm();
  }
  return run;
}

std::optional<Vec2> anchorPoint(const ExtrusionSpec& spec, const Anchor& a) {
  const auto at = placeOnRun(spec, a);
  if (!at) return std::nullopt;
  const PlanLoop& l = spec.loops[a.loop];
  const Vec2 d = edgeVector(l, at->first);
  const double len = d.norm();
  return len > 0 ? l.points[at->first] + d * (at->second / len) : l.points[at->first];
}

std::optional<Vec2> anchorDirection(const ExtrusionSpec& spec, const Anchor& a) {
  const auto at = placeOnRun(spec, a);
  if (!at) return std::nullopt;
  Vec2 d = edgeVector(spec.loops[a.loop], at->first);
  const double len = d.norm();
  return len > 0 ? d / len : Vec2(1, 0);
}

double alongWall(const ExtrusionSpec& spec, int loop, int edge, double metres) {
  const WallRun run = wallRun(spec, loop, edge);
  double before = 0;
  for (int e : run.edges) {
    if (e == edge) break;
    before += edgeVector(spec.loops[loop], e).norm();
  }
  return before + metres;
}

WallPoint nearestOnWall(const ExtrusionSpec& spec, const WallRun& run, const Vec2& p) {
  WallPoint best;
  if (run.edges.empty()) return best;
  const PlanLoop& l = spec.loops[run.loop];
  best.point = l.points[run.edges.front()];
  double bestDistance = std::numeric_limits<double>::infinity(), before = 0;
  for (int e : run.edges) {
    const Vec2 a = l.points[e], d = edgeVector(l, e);
    const double len = d.norm();
    const double t = len > 0 ? std::clamp(OpenMesh::dot(p - a, d) / len, 0.0, len) : 0.0;
    const Vec2 q = len > 0 ? a + d * (t / len) : a;
    if ((q - p).norm() < bestDistance) bestDistance = (q - p).norm(), best = {q, before + t};
    before += len;
  }
  return best;
}

int nextWallId(const ExtrusionSpec& spec) {
  int next = 1;
  for (const PlanLoop& l : spec.loops)
    for (int w : l.walls) next = std::max(next, w + 1);
  return next;
}

void assignWalls(ExtrusionSpec& spec) {
  int next = nextWallId(spec);
  for (PlanLoop& l : spec.loops)
    if (l.walls.size() != l.points.size()) {
      l.walls.resize(l.points.size());
      for (int& w : l.walls) w = next++;
    }
}

bool wallsAreEdges(const ExtrusionSpec& spec) {
  std::set<int> seen;
  for (const PlanLoop& l : spec.loops)
    for (int w : l.walls)
      if (!seen.insert(w).second) return false;
  return true;
}

void canonicalWalls(ExtrusionSpec& spec) {
  if (!wallsAreEdges(spec)) return;
  for (PlanLoop& l : spec.loops) l.walls.clear();
}

std::vector<std::vector<int>> numberedWalls(const ExtrusionSpec& spec) {
  ExtrusionSpec s = spec;
  assignWalls(s);
  std::map<int, int> number;
  std::vector<std::vector<int>> out;
  for (const PlanLoop& l : s.loops) {
    out.emplace_back();
    for (int w : l.walls) out.back().push_back(number.emplace(w, static_cast<int>(number.size()) + 1).first->second);
  }
  return out;
}

RepeatGrid repeatGrid(const ExtrusionSpec& spec, const Anchor& anchor, const Repeat& repeat) {
  RepeatGrid g;
  if (repeat.kind == RepeatKind::None) return g;
  const double span = (repeat.along - anchor.along) * (anchor.absolute ? 1.0 : inputEdgeLength(spec, anchor));
  g.columns = fitting(span, repeat.spacing);
  if (repeat.kind == RepeatKind::Grid) g.rows = fitting(repeat.height - anchor.height, repeat.rowSpacing);
  return g;
}

std::vector<Anchor> repeatAnchors(const ExtrusionSpec& spec, const Anchor& anchor, const Repeat& repeat) {
  const RepeatGrid g = repeatGrid(spec, anchor, repeat);
  std::vector<Anchor> out;
  out.reserve(std::min<std::size_t>(g.count(), kMaxFeatureInstances + 1));
  auto at = [](double first, double last, std::size_t i, std::size_t n) {
    return n <= 1 ? first : first + (last - first) * static_cast<double>(i) / static_cast<double>(n - 1);
  };
  for (std::size_t r = 0; r < g.rows && out.size() <= kMaxFeatureInstances; ++r)
    for (std::size_t c = 0; c < g.columns && out.size() <= kMaxFeatureInstances; ++c) {
      Anchor a = anchor;
      a.along = at(anchor.along, repeat.along, c, g.columns);
      if (repeat.kind == RepeatKind::Grid) a.height = at(anchor.height, repeat.height, r, g.rows);
      out.push_back(a);
    }
  return out;
}

ExpandedSpec expandRepeats(const ExtrusionSpec& spec) {
  ExpandedSpec e;
  e.spec = spec;
  e.spec.steps.clear();
  e.spec.anchors.clear();
  auto numbered = [](const std::string& name, std::size_t i, std::size_t n) {
    if (n <= 1) return name;
    return (name.empty() ? std::string() : name + " ") + "(" + std::to_string(i + 1) + " of " + std::to_string(n) + ")";
  };
  // Steps and mesh anchors repeat alike: one instance per place, numbered, pointing back.
  auto expand = [&](const auto& items, auto& out, std::vector<int>& source) {
    for (std::size_t k = 0; k < items.size(); ++k) {
      const std::vector<Anchor> places = repeatAnchors(spec, items[k].anchor, items[k].repeat);
      for (std::size_t i = 0; i < places.size(); ++i) {
        auto one = items[k];
        one.anchor = places[i];
        one.repeat = Repeat();
        one.name = numbered(items[k].name, i, places.size());
        out.push_back(std::move(one));
        source.push_back(static_cast<int>(k));
      }
    }
  };
  expand(spec.steps, e.spec.steps, e.stepSource);
  expand(spec.anchors, e.spec.anchors, e.anchorSource);
  return e;
}

std::optional<std::string> checkRepeat(const Anchor& anchor, const Repeat& repeat) {
  if (repeat.kind == RepeatKind::None) return std::nullopt;
  if (!std::isfinite(repeat.along) || std::abs(repeat.along) > 1e7)
    return std::string("along: the last element's place must be a finite number");
  if (!anchor.absolute && (repeat.along < 0 || repeat.along > 1))
    return std::string("along: a relative anchor's repeat ends at a fraction within [0, 1]");
  if (!std::isfinite(repeat.spacing) || repeat.spacing <= 0)
    return std::string("spacing: must be greater than 0 m");
  if (repeat.kind == RepeatKind::Grid) {
    if (!std::isfinite(repeat.height) || repeat.height < 0 || repeat.height > 1e5)
      return std::string("height: the last row must be within [0, 1e5] m above the base");
    if (!std::isfinite(repeat.rowSpacing) || repeat.rowSpacing <= 0)
      return std::string("row_spacing: must be greater than 0 m");
  }
  return std::nullopt;
}

std::optional<std::string> checkFeatureSize(const FeatureSize& size) {
  const double v[3] = {size.width, size.height, size.depth};
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(v[i]) || v[i] <= 0 || v[i] > 1e3)
      return "size[" + std::to_string(i) + "]: must be greater than 0 and at most 1000 m";
  return std::nullopt;
}

std::optional<std::string> checkInstanceCounts(const ExtrusionSpec& spec) {
  std::size_t steps = 0, anchors = 0;
  auto over = [](const std::string& at, const RepeatGrid& g, std::size_t total, std::size_t limit) {
    return at + ".repeat: " + std::to_string(g.columns) + " x " + std::to_string(g.rows) + " instances make " +
           std::to_string(total) + ", more than the limit of " + std::to_string(limit) + " per extrusion";
  };
  for (std::size_t k = 0; k < spec.steps.size(); ++k) {
    const RepeatGrid g = repeatGrid(spec, spec.steps[k].anchor, spec.steps[k].repeat);
    const double total = static_cast<double>(steps) + static_cast<double>(g.columns) * static_cast<double>(g.rows);
    if (total > static_cast<double>(kMaxStepInstances))
      return over("steps[" + std::to_string(k) + "]", g, static_cast<std::size_t>(std::min(total, 1e18)), kMaxStepInstances);
    steps = static_cast<std::size_t>(total);
  }
  for (std::size_t k = 0; k < spec.anchors.size(); ++k) {
    const RepeatGrid g = repeatGrid(spec, spec.anchors[k].anchor, spec.anchors[k].repeat);
    const double total = static_cast<double>(anchors) + static_cast<double>(g.columns) * static_cast<double>(g.rows);
    if (total > static_cast<double>(kMaxFeatureInstances))
      return over("anchors[" + std::to_string(k) + "]", g, static_cast<std::size_t>(std::min(total, 1e18)), kMaxFeatureInstances);
    anchors = static_cast<std::size_t>(total);
  }
  return std::nullopt;
}

}  // namespace corbel
