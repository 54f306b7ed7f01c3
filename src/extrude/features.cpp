// Feature meshes (Fig. 28): closed polyhedra built from a few control outlines in the anchor's
// frame. Every part is either a prism over a convex outline or a ring between two outlines
// (a frame round an opening), so each is closed and its faces are planar and convex.
#include "extrude/features.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace corbel::extrude {

const FeatureDimensions& featureDimensions() {
  static const FeatureDimensions d;
  return d;
}

namespace {

// A right-handed frame: world = origin + x ex + y ey + z ez.
struct Local {
  Vec3 origin, ex, ey, ez;
  Vec3 at(double x, double y, double z) const { return origin + ex * x + ey * y + ez * z; }
};

std::vector<Vec2> rect(double x0, double x1, double y0, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

// A prism over a counter-clockwise convex outline in (x, y), from z0 to z1 (> z0).
FeaturePart prism(std::string name, std::string material, const Local& l, const std::vector<Vec2>& outline, double z0,
                  double z1) {
  FeaturePart p{std::move(name), std::move(material), {}, {}};
  const int n = static_cast<int>(outline.size());
  for (const Vec2& q : outline) p.points.push_back(l.at(q[0], q[1], z0));
  for (const Vec2& q : outline) p.points.push_back(l.at(q[0], q[1], z1));
  std::vector<int> top, bottom;
  for (int i = 0; i < n; ++i) top.push_back(n + i);
  for (int i = n - 1; i >= 0; --i) bottom.push_back(i);
  p.faces.push_back(top);
  p.faces.push_back(bottom);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    p.faces.push_back({i, j, n + j, n + i});
  }
  return p;
}

// The ring between two counter-clockwise outlines of as many corners (`inner` inside `outer`,
// corner i of one facing corner i of the other), from z0 to z1: a frame round an opening.
FeaturePart ring(std::string name, std::string material, const Local& l, const std::vector<Vec2>& outer,
                 const std::vector<Vec2>& inner, double z0, double z1) {
  FeaturePart p{std::move(name), std::move(material), {}, {}};
  const int n = static_cast<int>(outer.size());
  auto add = [&](const std::vector<Vec2>& o, double z) {
    for (const Vec2& q : o) p.points.push_back(l.at(q[0], q[1], z));
  };
  add(outer, z0);  // ob: 0 .. n-1
  add(outer, z1);  // ot: n .. 2n-1
  add(inner, z0);  // ib: 2n .. 3n-1
  add(inner, z1);  // it: 3n .. 4n-1
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const int ob = 0, ot = n, ib = 2 * n, it = 3 * n;
    p.faces.push_back({ot + i, ot + j, it + j, it + i});  // front
    p.faces.push_back({ob + i, ib + i, ib + j, ob + j});  // back
    p.faces.push_back({ob + i, ob + j, ot + j, ot + i});  // outside
    p.faces.push_back({ib + j, ib + i, it + i, it + j});  // inside, facing the opening
  }
  return p;
}

// A frame ring from (−W/2, y0) to (W/2, y1), `t` thick, `depth` out of the face, and the pane
// (or leaf) filling its opening half as deep.
void framed(std::vector<FeaturePart>& parts, const Local& l, double W, double y0, double y1, double t, double depth,
            const char* pane, const char* paneMaterial, const char* frameMaterial) {
  const std::vector<Vec2> outer = rect(-W / 2, W / 2, y0, y1);
  const std::vector<Vec2> inner = rect(-W / 2 + t, W / 2 - t, y0 + t, y1 - t);
  parts.push_back(ring("frame", frameMaterial, l, outer, inner, 0, depth));
  parts.push_back(prism(pane, paneMaterial, l, inner, 0, depth / 2));
}

std::vector<Vec2> ellipseOutline(int n, double a, double b) {
  std::vector<Vec2> o;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * (i + 0.5) / n;
    o.emplace_back(a * std::cos(t), b * std::sin(t));
  }
  return o;
}

}  // namespace

std::string featureTag(FeatureKind kind) { return featureName(kind); }

FeaturePlacement featurePlacement(FeatureKind kind, const FeatureSize& size, const AnchorFrame& frame) {
  FeaturePlacement p;
  p.kind = kind;
  p.size = size;
  p.origin = frame.position;
  if (kind != FeatureKind::ChimneyPot) {  // x along the edge, y up the face, z out of it
    p.ex = frame.along;
    p.ey = frame.up;
    p.ez = frame.normal;
    return p;
  }
  // Straight up, whatever the face's slope: x along the edge, z world up.
  Vec3 ex(frame.along[0], frame.along[1], 0);
  if (ex.norm() < 1e-12) ex = Vec3(1, 0, 0);
  ex.normalize();
  p.ex = ex;
  p.ez = Vec3(0, 0, 1);
  p.ey = OpenMesh::cross(p.ez, p.ex);
  // Reach down to the face under the whole footprint (rim included): on a face rising inward at
  // dz/dw, the footprint's far side lies R dz/dw below the anchor's height. Rounded up to the
  // millimetre, so pots on roofs of one pitch are alike.
  const FeatureDimensions& dim = featureDimensions();
  const double R = std::max(size.width, size.depth) / 2 + dim.potRim;
  const double horizontal = std::hypot(frame.normal[0], frame.normal[1]);
  const double sink = R * horizontal / std::max(std::abs(frame.normal[2]), 1e-9);
  p.sink = std::min(size.height, std::ceil(sink * 1000 - 1e-6) / 1000);  // 1e-6: not 0.191 for 0.19 + ε
  return p;
}

std::vector<FeaturePart> featureParts(const FeaturePlacement& placement, bool own) {
  const FeatureDimensions& dim = featureDimensions();
  const double W = placement.size.width, H = placement.size.height, D = placement.size.depth;
  std::vector<FeaturePart> parts;
  const Local l = own ? Local{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}
                      : Local{placement.origin, placement.ex, placement.ey, placement.ez};
  switch (placement.kind) {
    case FeatureKind::None: break;
    case FeatureKind::Door: {
      const double s = std::min(dim.doorStepHeight, H / 4);
      const double t = std::min({dim.doorFrame, W / 4, (H - s) / 4});
      const double o = dim.doorStepOverhang;
      parts.push_back(prism("step", "stone", l, rect(-W / 2 - o, W / 2 + o, 0, s), 0, dim.doorStepDepth));
      framed(parts, l, W, s, H, t, D, "leaf", "timber", "timber");
      break;
    }
    case FeatureKind::Window: {
      const double t = std::min({dim.windowFrame, W / 4, H / 4});
      const double sh = std::min(dim.sillHeight, H / 4), so = dim.sillOverhang;
      framed(parts, l, W, 0, H, t, D, "pane", "glass", "timber");
      parts.push_back(prism("sill", "stone", l, rect(-W / 2 - so, W / 2 + so, -sh, 0), 0, D + so));
      break;
    }
    case FeatureKind::RoofWindow: {
      const double t = std::min({dim.roofWindowFrame, W / 4, H / 4});
      framed(parts, l, W, 0, H, t, D, "pane", "glass", "metal");
      break;
    }
    case FeatureKind::ChimneyPot: {
      const double a = W / 2, b = D / 2, rim = dim.potRim;
      const double rh = std::min(dim.potRimHeight, H / 4);
      const std::vector<Vec2> body = ellipseOutline(dim.potSides, a, b);
      parts.push_back(prism("pot", "brick", l, body, -placement.sink, H));
      parts.push_back(ring("rim", "concrete", l, ellipseOutline(dim.potSides, a + rim, b + rim), body, H - rh, H));
      break;
    }
  }
  return parts;
}

std::vector<FeaturePart> featureParts(FeatureKind kind, const FeatureSize& size, const AnchorFrame& frame) {
  return featureParts(featurePlacement(kind, size, frame));
}

namespace {

// The instanced features of the extrusion in anchor order, each handed to `use` with its mesh
// anchor; a warning for each instance whose anchor was not placed.
template <class Use>
void forEachFeature(const ExtrusionSpec& spec, const ExtrusionResult& result, std::vector<std::string>& warnings,
                    Use use) {
  for (const AnchorFrame& f : result.anchors) {
    if (f.source < 0 || f.source >= static_cast<int>(spec.anchors.size())) continue;
    const MeshAnchor& m = spec.anchors[f.source];
    if (m.feature == FeatureKind::None) continue;
    std::string what = featureName(m.feature);
    std::replace(what.begin(), what.end(), '_', ' ');
    if (!f.instanced) {
      warnings.push_back("anchors[" + std::to_string(f.source) + "] (" + f.name + "): the " + what +
                         " is not placed: its edge is not in the active plan at " +
                         (m.repeat.kind == RepeatKind::Grid ? std::string("that height")
                                                            : "height " + std::to_string(spec.baseZ + m.anchor.height)));
      continue;
    }
    use(featurePlacement(m.feature, m.size, f));
  }
}

}  // namespace

void appendParts(MeshData& mesh, FeatureKind kind, const std::vector<FeaturePart>& parts) {
  const int tag = mesh.addTag(featureTag(kind));
  for (const FeaturePart& part : parts) {
    const int base = static_cast<int>(mesh.points.size());
    const int material = mesh.addMaterial(part.material);
    for (const Vec3& q : part.points) mesh.addPoint(q);
    for (std::vector<int> loop : part.faces) {
      for (int& v : loop) v += base;
      mesh.addFace(std::move(loop), tag, material);
    }
  }
}

void appendFeatures(MeshData& mesh, const ExtrusionSpec& spec, const ExtrusionResult& result,
                    std::vector<std::string>& warnings, std::vector<FeaturePlacement>* apart) {
  forEachFeature(spec, result, warnings, [&](const FeaturePlacement& p) {
    if (apart)
      apart->push_back(p);
    else
      appendParts(mesh, p.kind, featureParts(p));
  });
}

std::vector<PlacedFeature> placeFeatures(const ExtrusionSpec& spec, const ExtrusionResult& result,
                                         std::vector<std::string>& warnings) {
  std::vector<PlacedFeature> placed;
  forEachFeature(spec, result, warnings, [&](const FeaturePlacement& p) { placed.push_back({p, featureParts(p)}); });
  return placed;
}

void appendFeatures(MeshData& mesh, const std::vector<PlacedFeature>& features) {
  for (const PlacedFeature& f : features) appendParts(mesh, f.placement.kind, f.parts);
}

}  // namespace corbel::extrude
