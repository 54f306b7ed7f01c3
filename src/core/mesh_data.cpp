#include "core/mesh_data.h"

#include <algorithm>

namespace corbel {

namespace {
int intern(std::vector<std::string>& table, const std::string& name) {
  auto it = std::find(table.begin(), table.end(), name);
  if (it != table.end()) return static_cast<int>(it - table.begin());
  table.push_back(name);
  return static_cast<int>(table.size()) - 1;
}
}  // namespace

int MeshData::addTag(const std::string& name) { return intern(tags, name); }
int MeshData::addMaterial(const std::string& name) { return intern(materials, name); }

void MeshData::append(const MeshData& other) {
  const int base = static_cast<int>(points.size());
  points.insert(points.end(), other.points.begin(), other.points.end());
  for (size_t f = 0; f < other.faces.size(); ++f) {
    std::vector<int> loop = other.faces[f];
    for (int& i : loop) i += base;
    const int tag = f < other.faceTag.size() ? addTag(other.tags[other.faceTag[f]]) : 0;
    const int mat =
        f < other.faceMaterial.size() ? addMaterial(other.materials[other.faceMaterial[f]]) : 0;
    addFace(std::move(loop), tag, mat);
  }
}

}  // namespace corbel
