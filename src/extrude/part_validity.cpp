#include "extrude/part_validity.h"

#include "core/geometry.h"

#include <cmath>
#include <map>

namespace corbel::extrude {

namespace {

// What a Scene makes of a part's faces, whatever its points: the counts its validate gives
// that do not depend on geometry, and the faces in the order the Scene keeps them, each as it
// walks it (indices into the part's points).
struct PartShape {
  bool whole = false;  // every face and every point kept (else the part is not checked apart)
  std::size_t faces = 0, vertices = 0, edges = 0, components = 0, boundaryEdges = 0, nonManifoldVertices = 0;
  std::vector<std::vector<int>> loops;
};

PartShape shapeOf(const FeaturePart& part) {
  MeshData m;
  m.points = part.points;
  for (const auto& f : part.faces) m.addFace(f);
  Scene scene;
  scene.replaceObject(1, Kind::Shell, part.name, m);
  PartShape s;
  // Vertex handles are the points' indices while no point was dropped.
  s.whole = scene.objects().at(1).rejected_faces == 0 && scene.mesh().n_vertices() == part.points.size();
  if (!s.whole) return s;
  const ValidityReport v = scene.validate(1);
  s.faces = v.faces;
  s.vertices = v.vertices;
  s.edges = v.edges;
  s.components = v.components;
  s.boundaryEdges = v.boundary_edges;
  s.nonManifoldVertices = v.non_manifold_vertices;
  const PolyMesh& mesh = scene.mesh();
  for (auto f : scene.faces(1)) {
    std::vector<int>& loop = s.loops.emplace_back();
    for (auto vh : mesh.fv_range(f)) loop.push_back(vh.idx());
  }
  return s;
}

// Shapes by point count and faces, kept for the thread's life (a few kinds of part).
const PartShape& cachedShape(const FeaturePart& part) {
  thread_local std::map<std::size_t, std::map<std::vector<std::vector<int>>, PartShape>> shapes;
  auto& byFaces = shapes[part.points.size()];
  auto it = byFaces.find(part.faces);
  if (it == byFaces.end()) it = byFaces.emplace(part.faces, shapeOf(part)).first;
  return it->second;
}

bool finite(const Vec3& p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

}  // namespace

ValidityReport validateWithFeatures(const MeshData& shell, const std::vector<PlacedFeature>& features,
                                    const std::string& name) {
  std::vector<const PartShape*> shapes;
  BBox partsBox;
  bool apart = true;
  for (const PlacedFeature& f : features) {
    for (const FeaturePart& part : f.parts) {
      const PartShape& s = cachedShape(part);
      apart = s.whole;
      for (const Vec3& p : part.points) {
        apart = apart && finite(p);
        partsBox.add(p);
      }
      if (!apart) break;
      shapes.push_back(&s);
    }
    if (!apart) break;
  }
  auto whole = [&] {  // the whole mesh, as it is checked without parts
    MeshData all = shell;
    appendFeatures(all, features);
    Scene scene;
    scene.replaceObject(1, Kind::Shell, name, all);
    return scene.validate(1);
  };
  if (!apart) return whole();
  Scene scene;
  scene.replaceObject(1, Kind::Shell, name, shell);
  ValidityReport r = scene.validate(1);
  if (r.non_finite_points) return whole();  // (a box with NaN in it depends on the order points come in)
  // Faces are taken as collapsed relative to the whole mesh's box (Scene::validate): where the
  // parts reach out of the shell's box, its faces are counted again against that.
  const BBox shellBox = scene.bounds(1);
  BBox box = shellBox;
  box.add(partsBox);
  const double scale = std::max(box.diagonal(), 1e-300);
  const double areaEps = 1e-14 * scale * scale;
  std::vector<Vec3> poly;
  if (!(box.lo == shellBox.lo && box.hi == shellBox.hi)) {
    const PolyMesh& mesh = scene.mesh();
    r.degenerate_faces = 0;
    for (auto f : scene.faces(1)) {
      poly.clear();
      for (auto v : mesh.fv_range(f)) poly.push_back(mesh.point(v));
      if (!(0.5 * newellNormal(poly).norm() > areaEps)) ++r.degenerate_faces;
    }
  }
  // The parts' faces as Scene::validate takes them, in the order the whole mesh would have them
  // (the shell's, then each part's in turn), so that the sums come out the same.
  std::size_t k = 0;
  for (const PlacedFeature& f : features)
    for (const FeaturePart& part : f.parts) {
      const PartShape& s = *shapes[k++];
      r.faces += s.faces;
      r.vertices += s.vertices;
      r.edges += s.edges;
      r.components += s.components;
      r.boundary_edges += s.boundaryEdges;
      r.non_manifold_vertices += s.nonManifoldVertices;
      for (const std::vector<int>& loop : s.loops) {
        poly.clear();
        for (int v : loop) poly.push_back(part.points[v]);
        const double area = 0.5 * newellNormal(poly).norm();
        r.area += area;
        if (!(area > areaEps)) ++r.degenerate_faces;
        for (std::size_t i = 1; i + 1 < poly.size(); ++i)
          r.volume += OpenMesh::dot(poly[0], OpenMesh::cross(poly[i], poly[i + 1])) / 6.0;
      }
    }
  r.euler = static_cast<long>(r.vertices) - static_cast<long>(r.edges) + static_cast<long>(r.faces);
  return r;
}

}  // namespace corbel::extrude
