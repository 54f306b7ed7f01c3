// Binary glTF 2.0 export through tinygltf: one node and mesh per object (named as the
// object), one primitive per material, flat normals; with ExportOptions::textures, a PNG
// texture per built-in texture used (by a material, or by a tag: ExportOptions::tagTextures)
// and TEXCOORD_0 from each face's plane. glTF is Y up: (x, y, z) → (x, z, −y).
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/export.h"
#include "core/materials.h"
#include "core/textures.h"

#include <stb_image_write.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>

namespace corbel {

namespace {

struct PrimitiveData {
  std::vector<float> positions, normals, uvs;
  std::vector<std::uint32_t> indices;
};

int addView(tinygltf::Model& model, const void* data, std::size_t bytes, int target) {
  auto& buffer = model.buffers[0].data;
  while (buffer.size() % 4) buffer.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), p, p + bytes);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

// The geometry of every primitive shares three buffer views (vec3 attributes, texture
// coordinates, indices): a view per accessor made a town's JSON chunk a third view records.
// Accessors point at a Shared kind until finish() writes the views and sets the indices.
class SharedViews {
 public:
  enum Kind { Vec3, Vec2, Index, kKinds };

  int accessor(tinygltf::Model& model, Kind kind, const void* data, std::size_t bytes) {
    std::vector<unsigned char>& b = bytes_[kind];
    tinygltf::Accessor a;
    a.byteOffset = b.size();
    const auto* p = static_cast<const unsigned char*>(data);
    b.insert(b.end(), p, p + bytes);
    model.accessors.push_back(a);
    const int index = static_cast<int>(model.accessors.size()) - 1;
    users_[kind].push_back(index);
    return index;
  }

  void finish(tinygltf::Model& model) {
    static constexpr int kStride[kKinds] = {12, 8, 0};
    static constexpr int kTarget[kKinds] = {TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_TARGET_ARRAY_BUFFER,
                                            TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER};
    for (int k = 0; k < kKinds; ++k) {
      if (bytes_[k].empty()) continue;
      const int view = addView(model, bytes_[k].data(), bytes_[k].size(), kTarget[k]);
      // Vertex attributes sharing a view need its stride (glTF 2.0, 3.6.2.4).
      if (kStride[k]) model.bufferViews[view].byteStride = kStride[k];
      for (int a : users_[k]) model.accessors[a].bufferView = view;
      std::vector<unsigned char>().swap(bytes_[k]);
    }
  }

 private:
  std::vector<unsigned char> bytes_[kKinds];
  std::vector<int> users_[kKinds];
};

int addVec3Accessor(tinygltf::Model& model, SharedViews& views, const std::vector<float>& values, bool withBounds) {
  const int index = views.accessor(model, SharedViews::Vec3, values.data(), values.size() * sizeof(float));
  tinygltf::Accessor& a = model.accessors[index];
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.count = values.size() / 3;
  a.type = TINYGLTF_TYPE_VEC3;
  if (withBounds) {
    std::vector<double> lo(3, 1e300), hi(3, -1e300);
    for (std::size_t i = 0; i < values.size(); ++i) {
      lo[i % 3] = std::min<double>(lo[i % 3], values[i]);
      hi[i % 3] = std::max<double>(hi[i % 3], values[i]);
    }
    a.minValues = lo;
    a.maxValues = hi;
  }
  return index;
}

int addVec2Accessor(tinygltf::Model& model, SharedViews& views, const std::vector<float>& values) {
  const int index = views.accessor(model, SharedViews::Vec2, values.data(), values.size() * sizeof(float));
  tinygltf::Accessor& a = model.accessors[index];
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.count = values.size() / 2;
  a.type = TINYGLTF_TYPE_VEC2;
  return index;
}

int addIndexAccessor(tinygltf::Model& model, SharedViews& views, const std::vector<std::uint32_t>& indices) {
  const int index =
      views.accessor(model, SharedViews::Index, indices.data(), indices.size() * sizeof(std::uint32_t));
  tinygltf::Accessor& a = model.accessors[index];
  a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  a.count = indices.size();
  a.type = TINYGLTF_TYPE_SCALAR;
  return index;
}

// The texture as a PNG image in the binary buffer, a repeating sampler and a texture.
int addTexture(tinygltf::Model& model, const MaterialTexture& tex, const std::string& name) {
  std::vector<unsigned char> png;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        const auto* p = static_cast<const unsigned char*>(data);
        out->insert(out->end(), p, p + size);
      },
      &png, tex.size, tex.size, 3, tex.rgb.data(), tex.size * 3);
  if (png.empty()) throw Error("cannot encode the texture of '" + name + "' as PNG");
  tinygltf::Image image;
  image.name = name;
  image.mimeType = "image/png";
  image.bufferView = addView(model, png.data(), png.size(), 0);
  model.images.push_back(image);
  if (model.samplers.empty()) {
    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_REPEAT;
    model.samplers.push_back(sampler);
  }
  tinygltf::Texture texture;
  texture.name = name;
  texture.sampler = 0;
  texture.source = static_cast<int>(model.images.size()) - 1;
  model.textures.push_back(texture);
  return static_cast<int>(model.textures.size()) - 1;
}

}  // namespace

void writeGlb(const Scene& scene, const std::string& path, const ExportOptions& options) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "corbel";
  model.buffers.emplace_back();
  model.scenes.emplace_back();
  model.defaultScene = 0;
  std::map<std::string, int> materialIndex, textureIndex;  // by glTF material label, by texture name
  const PolyMesh& mesh = scene.mesh();
  SharedViews views;

  const auto byObject = scene.facesByObject();
  for (const auto& [id, info] : scene.objects()) {
    if (options.include && !options.include(id)) continue;
    const bool textured = options.textured ? options.textured(id) : options.textures;
    std::map<std::string, PrimitiveData> byMaterial;
    std::vector<Vec3> poly;
    std::vector<Vec2> uv;
    const auto found = byObject.find(id);
    if (found == byObject.end()) continue;
    for (auto f : found->second) {
      const std::string& m = scene.faceMaterial(f);
      std::string label = m.empty() ? std::string(kindName(scene.faceKind(f))) : m;
      // A face with a texture of its own (a style's tag texture) gets a glTF material of its own,
      // whatever its material's colour: the texture carries the colour.
      const SurfaceTexture* own =
          textured && options.tagTextures ? options.tagTextures(id, scene.faceTag(f)) : nullptr;
      const TextureUse use = textured ? textureFor(own, m) : TextureUse{};
      // Textured and plain materials never share a name (Godot shares materials by name across
      // files, so a plain house would pick up a town's textured brick).
      if (use.texture) label += " (texture " + std::string(use.name) + ")";
      if (!materialIndex.count(label)) {
        tinygltf::Material mat;
        mat.name = label;
        const Rgb c = materialColor(m, scene.faceKind(f));
        mat.pbrMetallicRoughness.baseColorFactor = {c[0], c[1], c[2], 1.0};
        mat.pbrMetallicRoughness.metallicFactor = 0.0;
        mat.pbrMetallicRoughness.roughnessFactor = 0.9;
        if (use.texture) {  // the texture carries the colour: base colour = factor × texel
          const std::string texName(use.name);
          if (!textureIndex.count(texName)) textureIndex[texName] = addTexture(model, *use.texture, texName);
          mat.pbrMetallicRoughness.baseColorTexture.index = textureIndex[texName];
          mat.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
        }
        model.materials.push_back(mat);
        materialIndex[label] = static_cast<int>(model.materials.size()) - 1;
      }
      PrimitiveData& prim = byMaterial[label];
      poly.clear();
      for (auto v : mesh.fv_range(f)) poly.push_back(mesh.point(v));
      Vec3 n = newellNormal(poly);
      const double len = n.norm();
      if (len > 0) n /= len;
      const auto base = static_cast<std::uint32_t>(prim.positions.size() / 3);
      for (const Vec3& p : poly) {
        prim.positions.insert(prim.positions.end(),
                              {static_cast<float>(p[0]), static_cast<float>(p[2]), static_cast<float>(-p[1])});
        prim.normals.insert(prim.normals.end(),
                            {static_cast<float>(n[0]), static_cast<float>(n[2]), static_cast<float>(-n[1])});
      }
      if (use.texture) {  // texture coordinates from the plane (core/textures.h)
        faceTextureCoordinates(poly, n, use.metres, uv);
        for (const Vec2& t : uv) prim.uvs.insert(prim.uvs.end(), {static_cast<float>(t[0]), static_cast<float>(t[1])});
      }
      for (const auto& t : triangulatePolygon(poly))
        prim.indices.insert(prim.indices.end(), {base + t[0], base + t[1], base + t[2]});
    }
    tinygltf::Mesh gm;
    gm.name = info.name;
    for (auto& [label, prim] : byMaterial) {
      tinygltf::Primitive p;
      p.mode = TINYGLTF_MODE_TRIANGLES;
      p.material = materialIndex[label];
      p.attributes["POSITION"] = addVec3Accessor(model, views, prim.positions, true);
      p.attributes["NORMAL"] = addVec3Accessor(model, views, prim.normals, false);
      if (!prim.uvs.empty()) p.attributes["TEXCOORD_0"] = addVec2Accessor(model, views, prim.uvs);
      p.indices = addIndexAccessor(model, views, prim.indices);
      gm.primitives.push_back(p);
    }
    if (gm.primitives.empty()) continue;
    model.meshes.push_back(gm);
    tinygltf::Node node;
    node.name = info.name;
    node.mesh = static_cast<int>(model.meshes.size()) - 1;
    tinygltf::Value::Object extras{{"corbel_object_id", tinygltf::Value(static_cast<int>(id))},
                                   {"corbel_kind", tinygltf::Value(std::string(kindName(info.kind)))}};
    // The placement the vertices were moved by, in corbel's frame (z up): a town's buildings
    // stand where the scene shows them, and this takes them back to the town's own frame.
    if (const auto pl = options.placements.find(id); pl != options.placements.end()) {
      const Placement& p = pl->second;
      tinygltf::Value::Array t{tinygltf::Value(p.translation[0]), tinygltf::Value(p.translation[1]),
                               tinygltf::Value(p.translation[2])};
      extras["corbel_placement"] = tinygltf::Value(tinygltf::Value::Object{
          {"translation", tinygltf::Value(t)},
          {"rotation_deg", tinygltf::Value(p.rotation_deg)},
          {"scale", tinygltf::Value(p.scale)},
          {"frame", tinygltf::Value(std::string("z up; p_scene = translation + Rz(rotation_deg) * (scale * p_object)"))}});
    }
    node.extras = tinygltf::Value(extras);
    model.nodes.push_back(node);
    model.scenes[0].nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
  }

  views.finish(model);
  // Nothing exported: glTF forbids an empty buffer (byteLength >= 1), so write none; and a
  // named scene, since tinygltf writes a scene without nodes or name as null.
  if (model.buffers[0].data.empty()) model.buffers.clear();
  model.scenes[0].name = "corbel";
  if (!options.copyright.empty()) model.asset.copyright = options.copyright;
  if (const auto& g = options.georeference; !g.proj.empty()) {
    using V = tinygltf::Value;
    V::Object geo{{"proj", V(g.proj)},
                  {"origin", V(V::Array{V(g.lon), V(g.lat), V(g.height)})},
                  {"axes", V(std::string("glTF +X east, -Z north, +Y up, metres"))}};
    if (!g.crs.empty()) geo["crs"] = V(g.crs);
    model.scenes[0].extras = V(V::Object{{"georeference", V(geo)}});
  }
  tinygltf::TinyGLTF writer;
  const std::string temp = makeTempSibling(path);
  if (!writer.WriteGltfSceneToFile(&model, temp, true, true, false, true)) {
    std::remove(temp.c_str());
    throw Error("cannot write '" + path + "' (glTF writer failed)");
  }
  commitTempFile(temp, path);
}

}  // namespace corbel
