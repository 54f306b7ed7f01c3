#include "core/export.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/materials.h"

#include <OpenMesh/Core/IO/MeshIO.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

namespace corbel {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool included(const ExportOptions& o, ObjectId id) { return !o.include || o.include(id); }

// Material name as written to files: the scene's name, or "<kind>" for faces without one.
std::string materialLabel(const Scene& scene, PolyMesh::FaceHandle f) {
  const std::string& m = scene.faceMaterial(f);
  return m.empty() ? std::string(kindName(scene.faceKind(f))) : m;
}

Rgb faceColor(const Scene& scene, PolyMesh::FaceHandle f) {
  return materialColor(scene.faceMaterial(f), scene.faceKind(f));
}

// OBJ has object names ("o") and materials ("usemtl" + .mtl); OpenMesh's OBJ writer knows
// neither, so this one is ours (a few lines of a plain text format).
void writeObj(const Scene& scene, const std::string& path, const ExportOptions& options) {
  const std::filesystem::path p(path);
  const std::string mtlName = p.stem().string() + ".mtl";
  const std::string mtlPath = (p.parent_path() / mtlName).string();
  const PolyMesh& mesh = scene.mesh();

  std::ostringstream obj;
  obj.precision(17);
  obj << "# corbel export: meters, Z up\nmtllib " << mtlName << "\n";
  std::map<std::string, Rgb> usedMaterials;
  std::vector<int> index(mesh.n_vertices(), 0);
  int next = 1;
  const auto byObject = scene.facesByObject();
  for (const auto& [id, info] : scene.objects()) {
    if (!included(options, id)) continue;
    static const std::vector<PolyMesh::FaceHandle> none;
    const auto found = byObject.find(id);
    const auto& faces = found == byObject.end() ? none : found->second;
    obj << "o " << info.name << "\n";
    for (auto f : faces)
      for (auto v : mesh.fv_range(f))
        if (!index[v.idx()]) {
          index[v.idx()] = next++;
          const auto& q = mesh.point(v);
          obj << "v " << q[0] << ' ' << q[1] << ' ' << q[2] << "\n";
        }
    std::string current;
    for (auto f : faces) {
      const std::string m = materialLabel(scene, f);
      usedMaterials.emplace(m, faceColor(scene, f));
      if (m != current) {
        obj << "usemtl " << m << "\n";
        current = m;
      }
      obj << "f";
      for (auto v : mesh.fv_range(f)) obj << ' ' << index[v.idx()];
      obj << "\n";
    }
  }
  std::ostringstream mtl;
  mtl << "# corbel materials\n";
  for (const auto& [name, c] : usedMaterials)
    mtl << "newmtl " << name << "\nKd " << c[0] << ' ' << c[1] << ' ' << c[2] << "\nKa 0 0 0\nKs 0 0 0\nd 1\n\n";
  writeFileAtomic(mtlPath, mtl.str());
  writeFileAtomic(path, obj.str());
}

// PLY and OFF through OpenMesh IO: a copy of the included faces with face colors and, for
// PLY, the object id, kind and material index as persistent custom face properties.
void writeWithOpenMesh(const Scene& scene, const std::string& path, ExportFormat format,
                       const ExportOptions& options) {
  PolyMesh out;
  out.request_face_colors();
  OpenMesh::FPropHandleT<int> objectProp, materialProp;
  OpenMesh::FPropHandleT<unsigned char> kindProp;
  if (format == ExportFormat::Ply) {
    out.add_property(objectProp, "object_id");
    out.add_property(kindProp, "kind");
    out.add_property(materialProp, "material_id");
    out.property(objectProp).set_persistent(true);
    out.property(kindProp).set_persistent(true);
    out.property(materialProp).set_persistent(true);
  }
  const PolyMesh& mesh = scene.mesh();
  std::vector<PolyMesh::VertexHandle> map(mesh.n_vertices());
  std::vector<PolyMesh::VertexHandle> loop;
  for (auto f : mesh.faces()) {
    const ObjectId id = scene.faceObject(f);
    if (!included(options, id)) continue;
    loop.clear();
    for (auto v : mesh.fv_range(f)) {
      if (!map[v.idx()].is_valid()) map[v.idx()] = out.add_vertex(mesh.point(v));
      loop.push_back(map[v.idx()]);
    }
    auto nf = out.add_face(loop);
    if (!nf.is_valid()) continue;  // cannot happen: the scene is already a valid half-edge mesh
    const Rgb c = faceColor(scene, f);
    // PolyMesh::Color is 8-bit (0..255); the writer turns it into floats for ColorFloat.
    auto byte = [](float x) { return static_cast<unsigned char>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); };
    out.set_color(nf, PolyMesh::Color(byte(c[0]), byte(c[1]), byte(c[2])));
    if (format == ExportFormat::Ply) {
      out.property(objectProp, nf) = static_cast<int>(id);
      out.property(kindProp, nf) = static_cast<unsigned char>(scene.faceKind(f));
      out.property(materialProp, nf) = scene.faceMaterialIndex(f);
    }
  }
  OpenMesh::IO::Options opt = OpenMesh::IO::Options::FaceColor | OpenMesh::IO::Options::ColorFloat;
  if (format == ExportFormat::Ply) opt += OpenMesh::IO::Options::Custom;
  const std::string temp = makeTempSibling(path);
  if (!OpenMesh::IO::write_mesh(out, temp, opt, 17)) {
    std::remove(temp.c_str());
    throw Error("cannot write '" + path + "' (OpenMesh writer failed)");
  }
  commitTempFile(temp, path);
}

}  // namespace

void writeGlb(const Scene& scene, const std::string& path, const ExportOptions& options);  // gltf_export.cpp

ExportFormat exportFormatFor(const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (ext == ".obj") return ExportFormat::Obj;
  if (ext == ".ply") return ExportFormat::Ply;
  if (ext == ".off") return ExportFormat::Off;
  if (ext == ".glb") return ExportFormat::Glb;
  throw Error("cannot export to '" + path + "': unknown extension (use .obj, .ply, .off or .glb)");
}

void exportScene(const Scene& scene, const std::string& path, const ExportOptions& options) {
  switch (exportFormatFor(path)) {
    case ExportFormat::Obj: writeObj(scene, path, options); break;
    case ExportFormat::Ply: writeWithOpenMesh(scene, path, ExportFormat::Ply, options); break;
    case ExportFormat::Off: writeWithOpenMesh(scene, path, ExportFormat::Off, options); break;
    case ExportFormat::Glb: writeGlb(scene, path, options); break;
  }
}

}  // namespace corbel
