#include "core/export.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/materials.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
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

// The faces to write, object by object (in id order), each object's grouped by material so a
// reader makes one draw per material; their vertices in the order first used.
struct Written {
  struct Object {
    ObjectId id;
    std::string name;
    std::vector<PolyMesh::FaceHandle> faces;
  };
  std::vector<Object> objects;
  std::vector<PolyMesh::VertexHandle> vertices;
  std::vector<int> index;  // per scene vertex: its number in `vertices` (from 0), or -1
  std::size_t faceCount() const {
    std::size_t n = 0;
    for (const Object& o : objects) n += o.faces.size();
    return n;
  }
};

Written collect(const Scene& scene, const ExportOptions& options) {
  Written w;
  const PolyMesh& mesh = scene.mesh();
  w.index.assign(mesh.n_vertices(), -1);
  const auto byObject = scene.facesByObject();
  for (const auto& [id, info] : scene.objects()) {
    if (!included(options, id)) continue;
    const auto found = byObject.find(id);
    if (found == byObject.end()) continue;
    Written::Object o{id, info.name, found->second};
    std::stable_sort(o.faces.begin(), o.faces.end(), [&](auto a, auto b) {
      return materialLabel(scene, a) < materialLabel(scene, b);
    });
    for (auto f : o.faces)
      for (auto v : mesh.fv_range(f))
        if (w.index[v.idx()] < 0) {
          w.index[v.idx()] = static_cast<int>(w.vertices.size());
          w.vertices.push_back(v);
        }
    w.objects.push_back(std::move(o));
  }
  return w;
}

// A point in the file's frame: corbel's Z up, or Y up as (x, z, -y).
Vec3 framed(const Vec3& p, bool yUp) { return yUp ? Vec3(p[0], p[2], -p[1]) : p; }

// Names made unique after objToken (two objects "A B" and "A:B" would both be "A_B").
class UniqueTokens {
 public:
  std::string operator()(const std::string& name) {
    std::string t = objToken(name);
    for (int k = 2; !used_.insert(t).second; ++k) t = objToken(name) + "_" + std::to_string(k);
    return t;
  }

 private:
  std::set<std::string> used_;
};

// OBJ has object names ("o") and materials ("usemtl" + .mtl); OpenMesh's OBJ writer knows
// neither, so this one is ours (a few lines of a plain text format).
void writeObj(const Scene& scene, const std::string& path, const ExportOptions& options) {
  const std::filesystem::path p(path);
  const std::string mtlName = objToken(p.stem().string()) + ".mtl";  // mtllib takes one token
  const std::string mtlPath = (p.parent_path() / mtlName).string();
  const PolyMesh& mesh = scene.mesh();
  const bool yUp = options.up != UpAxis::Z;
  const Written w = collect(scene, options);

  std::ostringstream obj;
  obj.precision(17);
  obj << "# corbel export: meters, " << (yUp ? "Y" : "Z") << " up\nmtllib " << objToken(mtlName) << "\n";
  for (auto v : w.vertices) {
    const Vec3 q = framed(mesh.point(v), yUp);
    obj << "v " << q[0] << ' ' << q[1] << ' ' << q[2] << "\n";
  }
  std::map<std::string, Rgb> usedMaterials;  // by token
  std::map<std::string, std::string> materialToken;
  UniqueTokens objectTokens, materialTokens;
  for (const Written::Object& o : w.objects) {
    obj << "o " << objectTokens(o.name) << "\n";
    std::string current;
    for (auto f : o.faces) {
      const std::string m = materialLabel(scene, f);
      auto [it, fresh] = materialToken.emplace(m, "");
      if (fresh) it->second = materialTokens(m);
      usedMaterials.emplace(it->second, faceColor(scene, f));
      if (m != current || current.empty()) {
        obj << "usemtl " << it->second << "\n";
        current = m;
      }
      obj << "f";
      for (auto v : mesh.fv_range(f)) obj << ' ' << w.index[v.idx()] + 1;
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

unsigned char colorByte(float x) { return static_cast<unsigned char>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); }

template <class T>
void put(std::string& out, T value) {
  static_assert(std::endian::native == std::endian::little, "binary PLY is written little-endian");
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// Binary little-endian PLY, written here: OpenMesh's writer put a uchar custom property into
// ASCII files as a raw byte. Vertices as doubles; per face its colour and corbel's object id,
// kind and material index.
void writePly(const Scene& scene, const std::string& path, const ExportOptions& options) {
  const PolyMesh& mesh = scene.mesh();
  const bool yUp = options.up == UpAxis::Y;
  const Written w = collect(scene, options);
  const std::size_t faces = w.faceCount();
  std::ostringstream header;
  header << "ply\nformat binary_little_endian 1.0\ncomment corbel export: meters, " << (yUp ? "Y" : "Z") << " up\n"
         << "element vertex " << w.vertices.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
         << "element face " << faces << "\nproperty list uchar int vertex_indices\n"
         << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
         << "property int object_id\nproperty uchar kind\nproperty int material_id\nend_header\n";
  std::string out = header.str();
  for (auto v : w.vertices) {
    const Vec3 q = framed(mesh.point(v), yUp);
    for (int k = 0; k < 3; ++k) put<double>(out, q[k]);
  }
  for (const Written::Object& o : w.objects)
    for (auto f : o.faces) {
      const std::size_t n = mesh.valence(f);
      if (n > 255) throw Error("cannot write '" + path + "': a face of " + o.name + " has more than 255 corners");
      put<unsigned char>(out, static_cast<unsigned char>(n));
      for (auto v : mesh.fv_range(f)) put<std::int32_t>(out, w.index[v.idx()]);
      const Rgb c = faceColor(scene, f);
      for (int k = 0; k < 3; ++k) put<unsigned char>(out, colorByte(c[k]));
      put<std::int32_t>(out, static_cast<std::int32_t>(o.id));
      put<unsigned char>(out, static_cast<unsigned char>(scene.faceKind(f)));
      put<std::int32_t>(out, scene.faceMaterialIndex(f));
    }
  writeFileAtomic(path, out);
}

// OFF with a colour per face (red, green and blue, floats in [0, 1] after each face's corners):
// the header is "OFF", since "COFF" announces colours per vertex.
void writeOff(const Scene& scene, const std::string& path, const ExportOptions& options) {
  const PolyMesh& mesh = scene.mesh();
  const bool yUp = options.up == UpAxis::Y;
  const Written w = collect(scene, options);
  const std::size_t faces = w.faceCount();
  std::ostringstream off;
  off.precision(17);
  off << "OFF\n" << w.vertices.size() << ' ' << faces << " 0\n";
  for (auto v : w.vertices) {
    const Vec3 q = framed(mesh.point(v), yUp);
    off << q[0] << ' ' << q[1] << ' ' << q[2] << "\n";
  }
  off.precision(4);
  for (const Written::Object& o : w.objects)
    for (auto f : o.faces) {
      off << mesh.valence(f);
      for (auto v : mesh.fv_range(f)) off << ' ' << w.index[v.idx()];
      const Rgb c = faceColor(scene, f);
      off << ' ' << c[0] << ' ' << c[1] << ' ' << c[2] << "\n";
    }
  writeFileAtomic(path, off.str());
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
  const ExportFormat format = exportFormatFor(path);
  if (format != ExportFormat::Glb && ((options.instances && !options.instances->empty()) || options.compress))
    throw Error("cannot export to '" + path + "': instances and compression are written to .glb only");
  switch (format) {
    case ExportFormat::Obj: writeObj(scene, path, options); break;
    case ExportFormat::Ply: writePly(scene, path, options); break;
    case ExportFormat::Off: writeOff(scene, path, options); break;
    case ExportFormat::Glb: writeGlb(scene, path, options); break;
  }
}

std::string objToken(const std::string& name) {
  std::string t;
  for (unsigned char c : name) t += std::isalnum(c) || c == '-' || c == '_' || c == '.' ? static_cast<char>(c) : '_';
  return t.empty() ? "_" : t;
}

}  // namespace corbel
