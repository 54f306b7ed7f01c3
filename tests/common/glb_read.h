#pragma once
// A glb read back the way the glTF 2.0 spec tells a client to, for tests: the GLB chunks, any
// accessor decoded to floats (normalized integers as the spec maps them, byteStride honoured),
// EXT_meshopt_compression's views decoded by meshoptimizer's decoder, and every primitive's
// triangles in the world frame: node transforms (the translation and scale that dequantize
// KHR_mesh_quantization positions) and EXT_mesh_gpu_instancing's copies applied.
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace corbel::test {

struct GlbFile {
  nlohmann::json json;
  std::vector<unsigned char> bin;  // buffer 0
  std::vector<std::vector<unsigned char>> views;  // every bufferView's bytes (decoded when compressed)
  std::size_t jsonBytes = 0;
};

inline GlbFile readGlbFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<unsigned char> all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto u32 = [&](std::size_t at) {
    if (at + 4 > all.size()) throw std::runtime_error(path + ": truncated");
    std::uint32_t x;
    std::memcpy(&x, all.data() + at, 4);
    return x;
  };
  if (u32(0) != 0x46546C67 || u32(4) != 2 || u32(8) != all.size()) throw std::runtime_error(path + ": not a glb 2");
  GlbFile g;
  const std::uint32_t jsonLength = u32(12);
  if (u32(16) != 0x4E4F534A) throw std::runtime_error(path + ": first chunk is not JSON");
  g.jsonBytes = jsonLength;
  g.json = nlohmann::json::parse(all.begin() + 20, all.begin() + 20 + jsonLength);
  const std::size_t binAt = 20 + jsonLength;
  if (binAt < all.size()) {
    if (u32(binAt + 4) != 0x004E4942) throw std::runtime_error(path + ": second chunk is not BIN");
    g.bin.assign(all.begin() + binAt + 8, all.begin() + binAt + 8 + u32(binAt));
  }
  for (const auto& v : g.json.value("bufferViews", nlohmann::json::array())) {
    const std::size_t length = v.at("byteLength");
    std::vector<unsigned char> bytes(length);
    if (v.contains("extensions") && v["extensions"].contains("EXT_meshopt_compression")) {
      const auto& e = v["extensions"]["EXT_meshopt_compression"];
      if (e.at("buffer") != 0) throw std::runtime_error("compressed data outside the GLB chunk");
      const unsigned char* src = g.bin.data() + e.value("byteOffset", std::size_t{0});
      const std::size_t srcLength = e.at("byteLength"), count = e.at("count"), stride = e.at("byteStride");
      const std::string mode = e.at("mode");
      if (e.value("filter", std::string("NONE")) != "NONE") throw std::runtime_error("meshopt filters are not read");
      if (count * stride != length) throw std::runtime_error("meshopt count × stride is not the view's length");
      int rc = -1;
      if (mode == "ATTRIBUTES")
        rc = meshopt_decodeVertexBuffer(bytes.data(), count, stride, src, srcLength);
      else if (mode == "TRIANGLES")
        rc = meshopt_decodeIndexBuffer(bytes.data(), count, stride, src, srcLength);
      else if (mode == "INDICES")
        rc = meshopt_decodeIndexSequence(bytes.data(), count, stride, src, srcLength);
      if (rc != 0) throw std::runtime_error("meshopt could not decode a view (" + mode + ")");
    } else {
      if (v.value("buffer", 0) != 0) throw std::runtime_error("a view outside the GLB chunk");
      const std::size_t at = v.value("byteOffset", std::size_t{0});
      if (at + length > g.bin.size()) throw std::runtime_error("a view past the GLB chunk");
      std::memcpy(bytes.data(), g.bin.data() + at, length);
    }
    g.views.push_back(std::move(bytes));
  }
  return g;
}

inline int componentsOf(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  throw std::runtime_error("accessor type " + type + " is not read");
}

// Accessor `index` as doubles, count × components; normalized integers as glTF 2.0, 3.11 maps them.
inline std::vector<double> accessorValues(const GlbFile& g, int index) {
  const auto& a = g.json.at("accessors").at(index);
  const int components = componentsOf(a.at("type"));
  const std::size_t count = a.at("count");
  const int type = a.at("componentType");
  const bool normalized = a.value("normalized", false);
  const std::size_t size = type == 5120 || type == 5121 ? 1 : type == 5122 || type == 5123 ? 2 : 4;
  const auto& view = g.json.at("bufferViews").at(a.at("bufferView").get<int>());
  const std::size_t stride = view.value("byteStride", size * components);
  const std::vector<unsigned char>& bytes = g.views.at(a.at("bufferView").get<int>());
  const std::size_t offset = a.value("byteOffset", std::size_t{0});
  std::vector<double> out(count * components);
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < components; ++c) {
      const std::size_t at = offset + i * stride + c * size;
      if (at + size > bytes.size()) throw std::runtime_error("accessor past its view");
      const unsigned char* p = bytes.data() + at;
      double v = 0;
      switch (type) {
        case 5120: { std::int8_t x; std::memcpy(&x, p, 1); v = normalized ? std::max(x / 127.0, -1.0) : x; break; }
        case 5121: { std::uint8_t x; std::memcpy(&x, p, 1); v = normalized ? x / 255.0 : x; break; }
        case 5122: { std::int16_t x; std::memcpy(&x, p, 2); v = normalized ? std::max(x / 32767.0, -1.0) : x; break; }
        case 5123: { std::uint16_t x; std::memcpy(&x, p, 2); v = normalized ? x / 65535.0 : x; break; }
        case 5125: { std::uint32_t x; std::memcpy(&x, p, 4); v = x; break; }
        case 5126: { float x; std::memcpy(&x, p, 4); v = x; break; }
        default: throw std::runtime_error("component type not read");
      }
      out[i * components + c] = v;
    }
  return out;
}

using Mat4 = std::array<double, 16>;  // column-major, as glTF

inline Mat4 identity4() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

inline Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + rr] * b[c * 4 + k];
      r[c * 4 + rr] = s;
    }
  return r;
}

// T · R · S from a translation, a unit quaternion (x, y, z, w) and a scale.
inline Mat4 trs(const std::array<double, 3>& t, const std::array<double, 4>& q, const std::array<double, 3>& s) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                       2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                       2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};  // columns
  Mat4 m = identity4();
  for (int c = 0; c < 3; ++c)
    for (int rr = 0; rr < 3; ++rr) m[c * 4 + rr] = r[c * 3 + rr] * s[c];
  m[12] = t[0];
  m[13] = t[1];
  m[14] = t[2];
  return m;
}

inline std::array<double, 3> apply(const Mat4& m, double x, double y, double z) {
  return {m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13],
          m[2] * x + m[6] * y + m[10] * z + m[14]};
}

inline Mat4 localMatrix(const nlohmann::json& node) {
  if (node.contains("matrix")) {
    Mat4 m;
    for (int i = 0; i < 16; ++i) m[i] = node["matrix"][i];
    return m;
  }
  std::array<double, 3> t{0, 0, 0}, s{1, 1, 1};
  std::array<double, 4> q{0, 0, 0, 1};
  if (node.contains("translation")) for (int i = 0; i < 3; ++i) t[i] = node["translation"][i];
  if (node.contains("rotation")) for (int i = 0; i < 4; ++i) q[i] = node["rotation"][i];
  if (node.contains("scale")) for (int i = 0; i < 3; ++i) s[i] = node["scale"][i];
  return trs(t, q, s);
}

// One drawn copy of a primitive: its triangles' corners in the world frame (glTF's, Y up).
struct WorldPrimitive {
  int node = -1, mesh = -1, material = -1, instance = -1;  // instance: -1 when not instanced
  std::string nodeName;
  std::vector<std::array<double, 3>> positions;  // the primitive's vertices, placed
  std::vector<std::array<double, 3>> normals;    // as decoded, not transformed
  std::vector<std::array<double, 2>> uvs;        // TEXCOORD_0, none without
  std::vector<std::uint32_t> indices;
  double step = 0;  // the node's dequantization scale (its largest scale), 0 when 1
};

inline std::vector<WorldPrimitive> worldPrimitives(const GlbFile& g) {
  std::vector<WorldPrimitive> out;
  const auto& nodes = g.json.value("nodes", nlohmann::json::array());
  std::vector<std::pair<int, Mat4>> stack;
  const auto& scene = g.json.at("scenes").at(g.json.value("scene", 0));
  for (const auto& n : scene.value("nodes", nlohmann::json::array())) stack.emplace_back(n.get<int>(), identity4());
  while (!stack.empty()) {
    const auto [index, parent] = stack.back();
    stack.pop_back();
    const auto& node = nodes.at(index);
    const Mat4 world = multiply(parent, localMatrix(node));
    for (const auto& c : node.value("children", nlohmann::json::array())) stack.emplace_back(c.get<int>(), world);
    if (!node.contains("mesh")) continue;
    double step = 0;
    if (node.contains("scale")) step = std::max({node["scale"][0].get<double>(), node["scale"][1].get<double>(), node["scale"][2].get<double>()});
    // The copies: one identity copy, or EXT_mesh_gpu_instancing's (node × instance, the spec's order).
    std::vector<Mat4> copies{world};
    if (node.contains("extensions") && node["extensions"].contains("EXT_mesh_gpu_instancing")) {
      const auto& at = node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
      std::vector<double> t, r, s;
      if (at.contains("TRANSLATION")) t = accessorValues(g, at["TRANSLATION"]);
      if (at.contains("ROTATION")) r = accessorValues(g, at["ROTATION"]);
      if (at.contains("SCALE")) s = accessorValues(g, at["SCALE"]);
      const std::size_t count = std::max({t.size() / 3, r.size() / 4, s.size() / 3});
      copies.clear();
      for (std::size_t i = 0; i < count; ++i) {
        std::array<double, 3> tt{0, 0, 0}, ss{1, 1, 1};
        std::array<double, 4> q{0, 0, 0, 1};
        if (!t.empty()) tt = {t[3 * i], t[3 * i + 1], t[3 * i + 2]};
        if (!r.empty()) {  // normalized: quantized quaternions are unit only to within their step
          q = {r[4 * i], r[4 * i + 1], r[4 * i + 2], r[4 * i + 3]};
          const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
          for (double& x : q) x /= len;
        }
        if (!s.empty()) ss = {s[3 * i], s[3 * i + 1], s[3 * i + 2]};
        copies.push_back(multiply(world, trs(tt, q, ss)));
      }
    }
    const auto& mesh = g.json.at("meshes").at(node["mesh"].get<int>());
    for (const auto& p : mesh.at("primitives")) {
      const std::vector<double> pos = accessorValues(g, p.at("attributes").at("POSITION"));
      std::vector<double> nrm;
      if (p["attributes"].contains("NORMAL")) nrm = accessorValues(g, p["attributes"]["NORMAL"]);
      std::vector<double> uv;
      if (p["attributes"].contains("TEXCOORD_0")) uv = accessorValues(g, p["attributes"]["TEXCOORD_0"]);
      std::vector<std::uint32_t> idx;
      if (p.contains("indices"))
        for (double v : accessorValues(g, p["indices"])) idx.push_back(static_cast<std::uint32_t>(v));
      else
        for (std::uint32_t i = 0; i < pos.size() / 3; ++i) idx.push_back(i);
      for (std::size_t c = 0; c < copies.size(); ++c) {
        WorldPrimitive w;
        w.node = index;
        w.nodeName = node.value("name", "");
        w.mesh = node["mesh"];
        w.material = p.value("material", -1);
        w.instance = copies.size() == 1 && !node.contains("extensions") ? -1 : static_cast<int>(c);
        w.step = step;
        for (std::size_t i = 0; i < pos.size() / 3; ++i) w.positions.push_back(apply(copies[c], pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]));
        for (std::size_t i = 0; i < nrm.size() / 3; ++i) w.normals.push_back({nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]});
        for (std::size_t i = 0; i < uv.size() / 2; ++i) w.uvs.push_back({uv[2 * i], uv[2 * i + 1]});
        w.indices = idx;
        out.push_back(std::move(w));
      }
    }
  }
  return out;
}

}  // namespace corbel::test
