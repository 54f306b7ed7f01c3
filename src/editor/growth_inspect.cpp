#include "editor/growth_inspect.h"

#include "growth/tolerances.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace corbel::editor {

std::vector<growth::ViewBox> viewBoxesOf(const growth::Site& site, const std::vector<growth::Unit>& units) {
  std::vector<growth::ViewBox> boxes;
  for (const growth::Unit& u : units)
    for (const growth::Box& p : u.parts) boxes.push_back({p, std::uint32_t(u.id)});
  for (std::size_t i = 0; i < site.cores.size(); ++i) boxes.push_back({site.coreBox(i), growth::kObstacleId});
  for (const growth::Box& c : site.circulation) boxes.push_back({c, growth::kObstacleId});
  return boxes;
}

GrowthInspection inspectGrowth(const growth::GrowthInput& input, Progress* progress, growth::ViewMapper* mapper,
                               const std::string& maps) {
  GrowthInspection out;
  out.of = input;
  out.maps = maps;
  out.grown = growth::grow(input, progress, mapper);
  growth::ExactViewMapper exact;
  growth::ViewMapper& m = mapper ? *mapper : exact;
  out.views = m.render(viewBoxesOf(out.grown.site, out.grown.units), out.grown.site.bounds());
  out.stats = growth::computeStatistics(out.grown.site, out.grown.units, out.views);
  return out;
}

std::vector<std::pair<std::string, std::string>> statisticsRows(const growth::Statistics& s) {
  auto num = [](const char* format, double v) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return std::string(text);
  };
  auto n = [](int v) { return std::to_string(v); };
  std::string types = n(s.typeA) + " / " + n(s.typeB) + " / " + n(s.typeC);
  if (s.unclassified) types += " (" + n(s.unclassified) + " under 30 m²)";
  std::string views = n(s.twoViews) + " / " + n(s.threeViews);
  if (s.fourViews) views += " (" + n(s.fourViews) + " with four)";
  return {{"site area", num("%.0f m²", s.siteArea) + ", " + n(s.storeys) + (s.storeys == 1 ? " storey" : " storeys")},
          {"units", n(s.units)},
          {"occupants", n(s.occupants)},
          {"occupancy ratio", num("%.4f", s.occupancyRatio)},
          {"type A / B / C", types},
          {"average view", num("%.1f m²", s.averageView)},
          {"two / three views", views},
          {"average floor area", num("%.1f m²", s.averageFloorArea)},
          {"double volume", n(s.doubleVolume)},
          {"outdoor space", n(s.outdoorSpace)}};
}

std::array<std::uint8_t, 3> idColour(std::uint32_t id) {
  if (id == growth::kEmptyId) return {24, 26, 30};
  if (id == growth::kObstacleId) return {128, 128, 132};
  // Hues spaced by the golden angle, so consecutive ids differ clearly; two lightness levels.
  const double h = std::fmod(id * 0.61803398875, 1.0) * 6.0;
  const double v = id % 2 ? 0.95 : 0.75, s = 0.7;
  const int k = int(h);
  const double f = h - k, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r = v, g = t, b = p;
  switch (k % 6) {
    case 0:
      r = v, g = t, b = p;
      break;
    case 1:
      r = q, g = v, b = p;
      break;
    case 2:
      r = p, g = v, b = t;
      break;
    case 3:
      r = p, g = q, b = v;
      break;
    case 4:
      r = t, g = p, b = v;
      break;
    default:
      r = v, g = p, b = q;
      break;
  }
  return {std::uint8_t(std::lround(r * 255)), std::uint8_t(std::lround(g * 255)), std::uint8_t(std::lround(b * 255))};
}

const char* viewDirectionName(growth::ViewDirection d) {
  switch (d) {
    case growth::ViewDirection::PosX:
      return "+x";
    case growth::ViewDirection::NegX:
      return "-x";
    case growth::ViewDirection::PosY:
      return "+y";
    case growth::ViewDirection::NegY:
      return "-y";
  }
  return "";
}

ViewMapImage viewMapImage(const growth::ViewMap& map, growth::ViewDirection d, int width) {
  ViewMapImage img;
  if (map.columns() < 1 || map.rows() < 1 || width < 1) return img;
  const auto& ue = map.uEdges();
  const auto& ve = map.vEdges();
  const double u0 = ue.front(), u1 = ue.back(), v0 = ve.front(), v1 = ve.back();
  const double pixel = (u1 - u0) / width;
  img.width = width;
  img.height = std::max(1, int(std::lround((v1 - v0) / pixel)));
  const double pv = (v1 - v0) / img.height;
  const bool mirrored = d == growth::ViewDirection::NegX || d == growth::ViewDirection::PosY;
  // The cell holding coordinate c: the last edge ≤ c.
  auto cellOf = [](const std::vector<double>& edges, double c) {
    const auto it = std::upper_bound(edges.begin(), edges.end(), c);
    return std::clamp(int(it - edges.begin()) - 1, 0, int(edges.size()) - 2);
  };
  std::vector<int> column(width);
  for (int x = 0; x < width; ++x) {
    const int i = mirrored ? width - 1 - x : x;
    column[x] = cellOf(ue, u0 + (i + 0.5) * pixel);
  }
  img.ids.resize(std::size_t(img.width) * img.height);
  img.depths.assign(img.ids.size(), -std::numeric_limits<double>::infinity());
  img.rgba.resize(img.ids.size() * 4);
  img.depthRgba.resize(img.ids.size() * 4);
  double nearest = -std::numeric_limits<double>::infinity(), farthest = std::numeric_limits<double>::infinity();
  for (int y = 0; y < img.height; ++y) {
    const int j = cellOf(ve, v1 - (y + 0.5) * pv);
    for (int x = 0; x < width; ++x) {
      const std::uint32_t id = map.id(column[x], j);
      const std::size_t k = std::size_t(y) * width + x;
      img.ids[k] = id;
      const auto c = idColour(id);
      img.rgba[4 * k] = c[0];
      img.rgba[4 * k + 1] = c[1];
      img.rgba[4 * k + 2] = c[2];
      img.rgba[4 * k + 3] = 255;
      if (id == growth::kEmptyId) continue;
      img.depths[k] = map.depth(column[x], j);
      nearest = std::max(nearest, img.depths[k]);
      farthest = std::min(farthest, img.depths[k]);
    }
  }
  const auto empty = idColour(growth::kEmptyId);
  for (std::size_t k = 0; k < img.ids.size(); ++k) {
    std::uint8_t grey[3] = {empty[0], empty[1], empty[2]};
    if (img.ids[k] != growth::kEmptyId) {
      // One depth only (everything seen at one depth) is all nearest: white.
      const double t = nearest > farthest ? (img.depths[k] - farthest) / (nearest - farthest) : 1.0;
      grey[0] = grey[1] = grey[2] = std::uint8_t(std::lround(kFarthestGrey + t * (255 - kFarthestGrey)));
    }
    img.depthRgba[4 * k] = grey[0];
    img.depthRgba[4 * k + 1] = grey[1];
    img.depthRgba[4 * k + 2] = grey[2];
    img.depthRgba[4 * k + 3] = 255;
  }
  return img;
}

MeshData objectMesh(const Scene& scene, ObjectId id) {
  MeshData out;
  const PolyMesh& mesh = scene.mesh();
  std::map<int, int> vertexIndex;
  std::map<int, int> materialIndex, tagIndex;
  for (PolyMesh::FaceHandle f : scene.faces(id)) {
    std::vector<int> loop;
    for (PolyMesh::VertexHandle v : mesh.fv_range(f)) {
      auto [it, added] = vertexIndex.try_emplace(v.idx(), 0);
      if (added) it->second = out.addPoint(mesh.point(v));
      loop.push_back(it->second);
    }
    const int m = scene.faceMaterialIndex(f);
    auto [mi, mAdded] = materialIndex.try_emplace(m, 0);
    if (mAdded) mi->second = out.addMaterial(scene.faceMaterial(f));
    const std::string& tag = scene.faceTag(f);
    out.addFace(std::move(loop), tag.empty() ? 0 : out.addTag(tag), mi->second);
  }
  return out;
}

MeshData sliceBelow(const MeshData& mesh, double z) {
  MeshData out;
  out.tags = mesh.tags;
  out.materials = mesh.materials;
  constexpr double eps = growth::kEps;
  // Points kept whole are shared as in the input; points made by a cut are shared per edge.
  std::vector<int> kept(mesh.points.size(), -1);
  std::map<std::pair<int, int>, int> cuts;
  auto keep = [&](int i) {
    if (kept[i] < 0) kept[i] = out.addPoint(mesh.points[i]);
    return kept[i];
  };
  auto cut = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto [it, added] = cuts.try_emplace({key.first, key.second}, 0);
    if (added) {
      const Vec3& p = mesh.points[key.first];
      const Vec3& q = mesh.points[key.second];
      const double t = (z - p[2]) / (q[2] - p[2]);
      Vec3 c = p + (q - p) * t;
      c[2] = z;
      it->second = out.addPoint(c);
    }
    return it->second;
  };
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& loop = mesh.faces[f];
    std::vector<int> clipped;
    bool anyBelow = false;
    for (int i : loop) anyBelow = anyBelow || mesh.points[i][2] < z - eps;
    if (!anyBelow) continue;  // wholly at or above the cut
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      const bool aIn = mesh.points[a][2] <= z + eps, bIn = mesh.points[b][2] <= z + eps;
      if (aIn) clipped.push_back(keep(a));
      if (aIn != bIn && std::abs(mesh.points[a][2] - z) > eps && std::abs(mesh.points[b][2] - z) > eps)
        clipped.push_back(cut(a, b));
    }
    if (clipped.size() >= 3) out.addFace(std::move(clipped), mesh.faceTag[f], mesh.faceMaterial[f]);
  }
  return out;
}

std::vector<std::size_t> unitsBelow(const std::vector<growth::Unit>& units, double z) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < units.size(); ++i) {
    double floor = std::numeric_limits<double>::infinity();
    for (const growth::Box& p : units[i].parts) floor = std::min(floor, p.lo[2]);
    if (floor < z - growth::kEps) out.push_back(i);
  }
  return out;
}

}  // namespace corbel::editor
