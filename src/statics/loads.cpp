#include "statics/loads.h"

#include "core/error.h"

#include <cmath>
#include <map>
#include <string>

namespace corbel::statics {
namespace {

bool finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// The area vector (Newell: outward normal times area) and the area centroid of a planar
// polygon, from a fan of triangles about its first corner, each weighted by its area signed
// along the face's normal (so a non-convex face's fan sums right).
void faceAreaAndCentroid(const Block& b, const std::vector<int>& f, Vec3& areaVector, Vec3& centroid) {
  const auto corner = [&](std::size_t k) -> const Vec3& { return b.vertices[std::size_t(f[k])]; };
  areaVector = Vec3(0.0);
  for (std::size_t k = 1; k + 1 < f.size(); ++k)
    areaVector += OpenMesh::cross(corner(k) - corner(0), corner(k + 1) - corner(0)) * 0.5;
  const double area = areaVector.norm();
  centroid = Vec3(0.0);
  if (!(area > 0)) return;
  const Vec3 n = areaVector / area;
  for (std::size_t k = 1; k + 1 < f.size(); ++k) {
    const double a = OpenMesh::dot(OpenMesh::cross(corner(k) - corner(0), corner(k + 1) - corner(0)) * 0.5, n);
    centroid += (corner(0) + corner(k) + corner(k + 1)) * (a / 3.0);
  }
  centroid /= area;
}

}  // namespace

std::vector<ResolvedLoad> resolveLoads(const Assembly& assembly, const std::vector<MasonryLoad>& loads) {
  std::vector<ResolvedLoad> out;
  if (loads.empty()) return out;
  std::map<std::string, int> byName;
  for (std::size_t i = 0; i < assembly.blocks.size(); ++i) byName.emplace(assembly.blocks[i].name, int(i));
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const MasonryLoad& l = loads[k];
    const std::string where = "masonry.loads[" + std::to_string(k) + "]";
    const std::string what = l.name.empty() ? "the load" : "the load \"" + l.name + "\"";
    const auto it = byName.find(l.block);
    if (it == byName.end())
      throw InputError(where, what + " is on block \"" + l.block + "\", which this model does not have");
    const Block& b = assembly.blocks[std::size_t(it->second)];
    if (b.fixed) throw InputError(where, what + " is on \"" + l.block + "\", a fixed block (the ground takes any load)");
    ResolvedLoad r;
    r.block = it->second;
    if (l.face >= 0) {
      if (std::size_t(l.face) >= b.faces.size())
        throw InputError(where, what + " is on face " + std::to_string(l.face) + " of \"" + l.block + "\", which has " +
                                    std::to_string(b.faces.size()) + " faces");
      if (!std::isfinite(l.pressure)) throw InputError(where, what + ": the pressure is not a finite number");
      Vec3 area, centroid;
      faceAreaAndCentroid(b, b.faces[std::size_t(l.face)], area, centroid);
      r.load.at = centroid;
      r.load.force = -area * l.pressure;  // pushes into the face: against its outward normal
    } else {
      if (!finite(l.force) || !finite(l.offset)) throw InputError(where, what + ": its force or offset is not finite");
      Vec3 c(0.0);
      for (const Vec3& v : b.vertices) c += v;
      // The block's volume centroid would need its mass properties; the offset is from the mean
      // of its corners, which is what the editor measures it from too (masonryLoadOffset).
      r.load.at = c / double(b.vertices.size()) + l.offset;
      r.load.force = l.force;
    }
    out.push_back(r);
  }
  return out;
}

void applyLoads(Assembly& assembly, const std::vector<MasonryLoad>& loads) {
  for (const ResolvedLoad& r : resolveLoads(assembly, loads))
    assembly.blocks[std::size_t(r.block)].pointLoads.push_back(r.load);
}

}  // namespace corbel::statics
