// Binary glTF 2.0 export (docs/export.md): a node and mesh per object, a primitive per material,
// flat normals. Corners are welded where faces share a position, normal and texture coordinate;
// positions are 16-bit integers per object, dequantized by the node's translation and scale, and
// normals 8-bit (KHR_mesh_quantization); indices are 16-bit where they fit. With
// ExportOptions::textures, a PNG per built-in texture used and TEXCOORD_0 from each face's
// plane, 16-bit normalized where a patch of faces fits in [-1, 1] repeats; with ExportOptions::instances, meshes placed by EXT_mesh_gpu_instancing; with
// ExportOptions::compress, meshoptimizer's EXT_meshopt_compression. glTF is Y up:
// (x, y, z) → (x, z, −y). The JSON is written here (nlohmann); tinygltf only reads glb.
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/export.h"
#include "core/glb_writer.h"
#include "core/manifold_order.h"
#include "core/materials.h"
#include "core/spill_buffer.h"
#include "core/spill_streams.h"
#include "core/textures.h"

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <unordered_map>

namespace corbel {

namespace {

using json = nlohmann::json;

constexpr int kByte = 5120, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// Positions are quantized when the step this gives an object is at most this (an object up to
// 65 m across); a larger one keeps float positions.
constexpr double kMaxQuantizationStep = 1e-3;

// Every accessor of one kind lies in the one buffer view of that kind (a view per accessor made a
// town's JSON chunk a third of the file); compressed, in one of that kind's views of up to
// kChunkBytes each. Elements are padded to 4 bytes (glTF 2.0, 3.6.2.4).
enum ViewKind { kPositions16, kPositions32, kNormals, kTexcoords, kTexcoords16, kIndices16, kIndices32, kTranslations, kRotations, kViewKinds };
struct ViewKindInfo {
  int elementBytes;
  int target;  // 0: none (instance attributes)
};
constexpr ViewKindInfo kViewInfo[kViewKinds] = {{8, kArrayBuffer},         {12, kArrayBuffer},        {4, kArrayBuffer},
                                                {8, kArrayBuffer},         {4, kArrayBuffer},        {2, kElementArrayBuffer},
                                                {4, kElementArrayBuffer},
                                                {12, 0},                   {8, 0}};

// Compressed, a kind's bytes are encoded by meshoptimizer a chunk of at most this many at a time
// (more only for one accessor larger than that), each chunk its own buffer view, as the glb is
// written: the writer holds one open chunk per kind, as it holds 64 KiB of each kind uncompressed
// (SpillBuffer's memory), whatever the number of objects.
constexpr std::size_t kChunkBytes = std::size_t{1} << 16;

// x (> 0) rounded up to three significant digits, as the double nearest that decimal (which
// prints short).
double roundUp3(double x) {
  const int k = 2 - static_cast<int>(std::floor(std::log10(x)));  // x · 10^k in [100, 1000)
  auto at = [&](double m) { return k >= 0 ? m / std::pow(10.0, k) : m * std::pow(10.0, -k); };
  double m = std::ceil(x * std::pow(10.0, k));
  while (at(m) < x) m += 1;
  return at(m);
}

// glTF's frame from corbel's: (x, y, z) → (x, z, −y).
Vec3 toGltf(const Vec3& p) { return Vec3(p[0], p[2], -p[1]); }

// A unit normal as three normalized bytes (c / 127), chosen among the lattice points around it
// as the closest in direction whose length is within 0.005 of 1 (the Khronos validator allows
// 0.00674).
std::array<std::int8_t, 3> quantizeNormal(const Vec3& n) {
  std::array<std::int8_t, 3> best{0, 0, 0};
  double bestDot = -2;
  const double s[3] = {n[0] * 127, n[1] * 127, n[2] * 127};
  for (int m = 0; m < 8; ++m) {
    Vec3 c;
    for (int k = 0; k < 3; ++k) c[k] = std::clamp(m >> k & 1 ? std::ceil(s[k]) : std::floor(s[k]), -127.0, 127.0);
    const double len = c.norm() / 127;
    if (len == 0 || std::abs(len - 1) > 0.005) continue;
    const double dot = (c[0] * n[0] + c[1] * n[1] + c[2] * n[2]) / (127 * len);
    if (dot > bestDot) {
      bestDot = dot;
      for (int k = 0; k < 3; ++k) best[k] = static_cast<std::int8_t>(c[k]);
    }
  }
  if (bestDot == -2)  // no lattice point near enough in length (never for a unit normal): the nearest
    for (int k = 0; k < 3; ++k) best[k] = static_cast<std::int8_t>(std::lround(std::clamp(s[k], -127.0, 127.0)));
  return best;
}

// The document being written and its binary chunk. What grows with the objects (the buffer
// views' bytes and the accessors, meshes and nodes of the JSON) is kept in SpillBuffers, so that
// a town's glb goes through a temporary file rather than memory; the rest of the JSON (materials,
// images, the scene) is small and kept as a JSON value.
class GlbDocument {
 public:
  explicit GlbDocument(bool compress) : compress_(compress) { std::fill(std::begin(openChunk_), std::end(openChunk_), -1); }

  json doc = json::object();

  int push(const char* array, json value) {
    for (Spilled& s : spilled_)
      if (s.name == array) {
        if (s.count) s.text.append(",");
        s.text.append(value.dump(-1, ' ', false, json::error_handler_t::replace));
        return s.count++;
      }
    json& a = doc[array];
    if (a.is_null()) a = json::array();
    a.push_back(std::move(value));
    return static_cast<int>(a.size()) - 1;
  }

  // An accessor over `bytes` appended to the view of `kind` (compressed: to that kind's open
  // chunk, which is encoded first when the bytes would take it past kChunkBytes); its bufferView
  // is set by write().
  int accessor(ViewKind kind, const void* data, std::size_t bytes, json a) {
    return accessor(kind, bytes, [&](const auto& append) { append(data, bytes); }, std::move(a));
  }

  // The same over `bytes` that `fill(append)` hands to append(data, n) in pieces.
  template <class Fill>
  int accessor(ViewKind kind, std::size_t bytes, const Fill& fill, json a) {
    std::uint32_t slot = kind;  // uncompressed: the kind; compressed: the chunk's number
    std::size_t filled = 0;
    if (!compress_) {
      SpillBuffer& v = views_[kind];
      a["byteOffset"] = v.size();
      fill([&](const void* data, std::size_t n) {
        v.append(data, n);
        filled += n;
      });
    } else {
      std::vector<unsigned char>& open = open_[kind];
      if (!open.empty() && open.size() + bytes > kChunkBytes) closeChunk(kind);
      if (openChunk_[kind] < 0) {
        openChunk_[kind] = static_cast<int>(chunks_.size());
        chunks_.push_back({kind});
      }
      a["byteOffset"] = open.size();
      fill([&](const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        open.insert(open.end(), p, p + n);
        filled += n;
      });
      slot = static_cast<std::uint32_t>(openChunk_[kind]);
    }
    if (filled != bytes) throw Error("a buffer view's bytes were not what its accessor counts");
    // A record per accessor: its slot (4 bytes), its JSON without the bufferView, a newline
    // (which a compact dump never holds).
    accessors_.append(&slot, 4);
    accessors_.append(a.dump(-1, ' ', false, json::error_handler_t::replace));
    accessors_.append("\n");
    return accessorCount_++;
  }

  // A buffer view of its own in the binary chunk (an image), never compressed.
  int rawView(const std::vector<unsigned char>& bytes) {
    align(bin_);
    const int view = push("bufferViews", json{{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes.size()}});
    bin_.insert(bin_.end(), bytes.begin(), bytes.end());
    return view;
  }

  void use(const std::string& extension, bool required) {
    used_.insert(extension);
    if (required) required_.insert(extension);
  }

  // Lays the views out (compressed, with a fallback buffer that has no data, when asked) and
  // writes the glb atomically.
  void write(const std::string& path) {
    // The binary chunk: the images (bin_), then a view per kind (each after the zeros that align
    // it) or the encoded chunks, copied from their buffers straight into the file.
    struct Segment {
      std::size_t zeros;
      const SpillBuffer* bytes;
    };
    std::vector<Segment> bin;
    SpillBuffer images;
    images.append(bin_.data(), bin_.size());
    bin.push_back({0, &images});
    std::size_t binSize = bin_.size();
    std::vector<unsigned char>().swap(bin_);
    std::size_t zeros = 0;  // before the next segment
    auto alignBin = [&] {
      zeros += (4 - binSize % 4) % 4;
      binSize = (binSize + 3) / 4 * 4;
    };
    std::size_t fallback = 0;
    std::vector<int> viewOf;  // by accessor slot
    if (!compress_) {
      viewOf.assign(kViewKinds, -1);
      for (int k = 0; k < kViewKinds; ++k) {
        SpillBuffer& v = views_[k];
        if (v.empty()) continue;
        const ViewKindInfo& info = kViewInfo[k];
        json view{{"byteLength", v.size()}};
        if (info.target) view["target"] = info.target;
        if (info.target == kArrayBuffer) view["byteStride"] = info.elementBytes;
        alignBin();
        view["buffer"] = 0;
        view["byteOffset"] = binSize;
        bin.push_back({zeros, &v});
        zeros = 0;
        binSize += v.size();
        viewOf[k] = push("bufferViews", std::move(view));
      }
    } else {
      // The chunks still open are encoded, then a view per chunk is listed in the order they were
      // opened. The spec's fallback rules: each view points into a buffer marked as the fallback,
      // which has no data here (so the extension is required), and its extension into the binary
      // chunk, where the encoded chunks lie one after another after the images, each padded to 4
      // bytes.
      for (int k = 0; k < kViewKinds; ++k)
        if (openChunk_[k] >= 0) closeChunk(static_cast<ViewKind>(k));
      alignBin();
      const std::size_t encodedAt = binSize;
      if (!encoded_.empty()) {
        bin.push_back({zeros, &encoded_});
        zeros = 0;
        binSize += encoded_.size();
      }
      viewOf.reserve(chunks_.size());
      for (const Chunk& c : chunks_) {
        const ViewKindInfo& info = kViewInfo[c.kind];
        fallback = (fallback + 3) / 4 * 4;
        json view{{"buffer", 1}, {"byteOffset", fallback}, {"byteLength", c.raw}};
        if (info.target) view["target"] = info.target;
        if (info.target == kArrayBuffer) view["byteStride"] = info.elementBytes;
        view["extensions"]["EXT_meshopt_compression"] = {
            {"buffer", 0},
            {"byteOffset", encodedAt + c.encodedAt},
            {"byteLength", c.encoded},
            {"byteStride", info.elementBytes},
            {"mode", info.target == kElementArrayBuffer ? "TRIANGLES" : "ATTRIBUTES"},
            {"count", c.raw / info.elementBytes}};
        fallback += c.raw;
        viewOf.push_back(push("bufferViews", std::move(view)));
      }
    }
    // glTF forbids an empty buffer (byteLength >= 1): with nothing to hold, none.
    if (binSize) push("buffers", json{{"byteLength", binSize}});
    if (fallback) {
      if (!binSize) push("buffers", json{{"byteLength", 4}});  // never: compressed views take bytes
      push("buffers", json{{"byteLength", fallback}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
      use("EXT_meshopt_compression", true);
    }
    if (!used_.empty()) doc["extensionsUsed"] = used_;
    if (!required_.empty()) doc["extensionsRequired"] = required_;

    // The JSON chunk as nlohmann would dump the whole document (members in key order, no
    // spaces): the kept members and the spilled arrays merged by name.
    SpillBuffer text;
    std::vector<std::string> keys;
    for (const auto& [key, value] : doc.items()) keys.push_back(key);
    if (accessorCount_) keys.emplace_back("accessors");
    for (const Spilled& s : spilled_)
      if (s.count) keys.push_back(s.name);
    std::sort(keys.begin(), keys.end());
    text.append("{");
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const std::string& key = keys[i];
      text.append((i ? ",\"" : "\"") + key + "\":");
      if (key == "accessors" && accessorCount_) {
        text.append("[");
        writeAccessors(text, viewOf);
        text.append("]");
      } else if (const Spilled* s = spilledNamed(key); s && s->count) {
        text.append("[");
        s->text.read([&](const char* p, std::size_t n) { text.append(p, n); });
        text.append("]");
      } else {
        text.append(doc[key].dump(-1, ' ', false, json::error_handler_t::replace));
      }
    }
    text.append("}");
    while (text.size() % 4) text.append(" ");
    alignBin();
    const bool withBin = binSize > 0;
    const std::uint64_t total = 12 + 8 + text.size() + (withBin ? 8 + binSize : 0);
    if (total > 0xFFFFFFFFull)
      throw Error("cannot write '" + path + "': " + std::to_string(total) + " bytes, more than a glb holds (4 GiB)");
    const std::string temp = makeTempSibling(path);
    try {
      std::ofstream out(temp, std::ios::binary);
      auto u32 = [&](std::uint64_t x) {
        const auto y = static_cast<std::uint32_t>(x);
        out.write(reinterpret_cast<const char*>(&y), 4);
      };
      u32(0x46546C67);  // "glTF"
      u32(2);
      u32(total);
      u32(text.size());
      u32(0x4E4F534A);  // "JSON"
      text.copyTo(out);
      if (withBin) {
        u32(binSize);
        u32(0x004E4942);  // "BIN\0"
        static const char pad[3] = {0, 0, 0};
        for (const Segment& segment : bin) {
          out.write(pad, static_cast<std::streamsize>(segment.zeros));
          segment.bytes->copyTo(out);
        }
        out.write(pad, static_cast<std::streamsize>(zeros));
      }
      out.flush();
      if (!out) throw Error("cannot write '" + path + "'");
    } catch (...) {
      std::remove(temp.c_str());
      throw;
    }
    commitTempFile(temp, path);
  }

 private:
  struct Spilled {
    explicit Spilled(const char* n) : name(n) {}
    std::string name;
    SpillBuffer text;  // the elements' JSON, comma-separated
    int count = 0;
  };

  const Spilled* spilledNamed(const std::string& name) const {
    for (const Spilled& s : spilled_)
      if (s.name == name) return &s;
    return nullptr;
  }

  // The accessors' records as JSON elements, each with the bufferView of its kind first ("bufferView"
  // sorts before every other member of an accessor).
  void writeAccessors(SpillBuffer& text, const std::vector<int>& viewOf) const {
    std::string piece;
    enum { kSlot, kBrace, kBody } state = kSlot;
    std::uint32_t slot = 0;
    int slotBytes = 0;
    bool first = true;
    accessors_.read([&](const char* p, std::size_t n) {
      for (std::size_t i = 0; i < n; ++i) {
        const char c = p[i];
        if (state == kSlot) {
          slot |= static_cast<std::uint32_t>(static_cast<unsigned char>(c)) << (8 * slotBytes);
          if (++slotBytes == 4) state = kBrace;
        } else if (state == kBrace) {
          if (!first) piece += ',';
          first = false;
          piece += '{';
          if (slot < viewOf.size() && viewOf[slot] >= 0) piece += "\"bufferView\":" + std::to_string(viewOf[slot]) + ",";
          state = kBody;
        } else if (c == '\n') {
          state = kSlot;
          slot = 0;
          slotBytes = 0;
        } else {
          piece += c;
        }
      }
      if (piece.size() > (std::size_t{1} << 20)) {
        text.append(piece);
        piece.clear();
      }
    });
    text.append(piece);
  }

  static void align(std::vector<unsigned char>& b) {
    while (b.size() % 4) b.push_back(0);
  }

  // Encodes the open chunk of `kind` (TRIANGLES for indices, else ATTRIBUTES) onto encoded_,
  // padded to 4 bytes, and closes it. Throws corbel::Error when meshoptimizer cannot.
  void closeChunk(ViewKind kind) {
    std::vector<unsigned char>& raw = open_[kind];
    Chunk& chunk = chunks_[static_cast<std::size_t>(openChunk_[kind])];
    const ViewKindInfo& info = kViewInfo[kind];
    const std::size_t count = raw.size() / info.elementBytes;
    std::vector<unsigned char>& encoded = encodeScratch_;
    if (info.target == kElementArrayBuffer) {
      std::vector<unsigned int> indices(count);
      if (info.elementBytes == 2) {
        for (std::size_t i = 0; i < count; ++i) {
          std::uint16_t x;
          std::memcpy(&x, raw.data() + 2 * i, 2);
          indices[i] = x;
        }
      } else {
        std::memcpy(indices.data(), raw.data(), raw.size());
      }
      const unsigned int vertices = indices.empty() ? 0 : *std::max_element(indices.begin(), indices.end()) + 1;
      encoded.resize(meshopt_encodeIndexBufferBound(count, vertices));
      encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices.data(), count));
    } else {
      encoded.resize(meshopt_encodeVertexBufferBound(count, info.elementBytes));
      encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), raw.data(), count, info.elementBytes));
    }
    if (encoded.empty()) throw Error("meshoptimizer could not encode a buffer view");
    chunk.raw = raw.size();
    chunk.encodedAt = encoded_.size();
    chunk.encoded = encoded.size();
    encoded_.append(encoded.data(), encoded.size());
    static const char pad[3] = {0, 0, 0};
    encoded_.append(pad, (4 - encoded.size() % 4) % 4);
    raw.clear();
    openChunk_[kind] = -1;
  }

  // A compressed buffer view: `raw` bytes of one kind, encoded at encodedAt in encoded_.
  struct Chunk {
    ViewKind kind;
    std::size_t raw = 0, encodedAt = 0, encoded = 0;
  };

  bool compress_;
  std::vector<unsigned char> bin_;  // the images
  SpillBuffer views_[kViewKinds];  // uncompressed: each kind's bytes
  // Compressed: each kind's open chunk (its number in chunks_, -1 when none), the chunks in the
  // order they were opened, their encoded bytes one after another.
  std::vector<unsigned char> open_[kViewKinds];
  int openChunk_[kViewKinds];
  std::vector<Chunk> chunks_;
  SpillBuffer encoded_;
  std::vector<unsigned char> encodeScratch_;
  SpillBuffer accessors_;
  int accessorCount_ = 0;
  Spilled spilled_[3] = {Spilled("meshes"), Spilled("nodes"), Spilled("bufferViews")};  // a view per chunk
  std::set<std::string> used_, required_;
};

// The texture as a PNG image in the binary chunk, a repeating sampler and a texture.
int addTexture(GlbDocument& g, const MaterialTexture& tex, const std::string& name) {
  std::vector<unsigned char> png;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        const auto* p = static_cast<const unsigned char*>(data);
        out->insert(out->end(), p, p + size);
      },
      &png, tex.size, tex.size, 3, tex.rgb.data(), tex.size * 3);
  if (png.empty()) throw Error("cannot encode the texture of '" + name + "' as PNG");
  const int image = g.push("images", json{{"name", name}, {"mimeType", "image/png"}, {"bufferView", g.rawView(png)}});
  if (!g.doc.contains("samplers"))
    g.push("samplers", json{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}});
  return g.push("textures", json{{"name", name}, {"sampler", 0}, {"source", image}});
}

// The materials of the file, by glTF label.
class Materials {
 public:
  Materials(GlbDocument& g, const ExportOptions& options) : g_(g), options_(options) {}

  struct Use {
    int material;
    TextureUse texture;
  };

  Use of(ObjectId id, bool textured, const std::string& m, Kind kind, const std::string& tag) {
    std::string label = m.empty() ? std::string(kindName(kind)) : m;
    // A face with a texture of its own (a style's tag texture) gets a glTF material of its own,
    // whatever its material's colour: the texture carries the colour.
    const SurfaceTexture* own = textured && options_.tagTextures ? options_.tagTextures(id, tag) : nullptr;
    const TextureUse use = textured ? textureFor(own, m) : TextureUse{};
    // Textured and plain materials never share a name (Godot shares materials by name across
    // files, so a plain house would pick up a town's textured brick).
    if (use.texture) label += " (texture " + std::string(use.name) + ")";
    if (const auto found = index_.find(label); found != index_.end()) return {found->second, use};
    const Rgb c = materialColor(m, kind);
    json pbr{{"baseColorFactor", {c[0], c[1], c[2], 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.9}};
    if (use.texture) {  // the texture carries the colour: base colour = factor × texel
      const std::string texName(use.name);
      auto t = textures_.find(texName);
      if (t == textures_.end()) t = textures_.emplace(texName, addTexture(g_, *use.texture, texName)).first;
      pbr["baseColorTexture"] = {{"index", t->second}};
      pbr["baseColorFactor"] = {1.0, 1.0, 1.0, 1.0};
    }
    const int index = g_.push("materials", json{{"name", label}, {"pbrMetallicRoughness", pbr}});
    index_[label] = index;
    return {index, use};
  }

 private:
  GlbDocument& g_;
  const ExportOptions& options_;
  std::map<std::string, int> index_, textures_;
};

// One object's faces gathered into glTF's layout: up to three vertex sets, each shared by the
// primitives (one per material) that draw from it: the faces without texture coordinates; the
// textured faces whose coordinates fit in [-1, 1] once shifted by whole repeats (16-bit
// normalized, KHR_mesh_quantization: windows, sills, doors and other small faces); the other
// textured faces (floats). The shift by whole repeats is chosen per patch, the faces joined by
// corners where they share a position, a normal and a repeat (a window frame's front), so that
// such corners weld as well.
class MeshBuilder {
 public:
  // A face in corbel's frame with its glTF material and, when textured, its texture's repeat.
  void face(const std::vector<Vec3>& poly, const Materials::Use& use) {
    Vec3 n = newellNormal(poly);
    const double len = n.norm();
    if (len > 0) n /= len;
    const std::array<std::int8_t, 3> qn = quantizeNormal(toGltf(n));
    const bool textured = use.texture.texture != nullptr;
    Group& g = groups_[textured ? 1 : 0];
    const auto base = static_cast<std::uint32_t>(g.corners.size());
    const auto index = static_cast<std::uint32_t>(g.faces.size());
    g.faces.push_back(textured ? use.texture.metres : 0.0);
    for (const Vec3& p : poly) {
      Corner c;
      c.p = toGltf(p);
      c.n = qn;
      c.face = index;
      if (textured) {  // planeUv over the repeat, v flipped (glTF's v runs down the image); not yet shifted
        const Vec2 t = planeUv(p, n) / use.texture.metres;
        if (std::isfinite(t[0]) && std::isfinite(t[1])) c.uv = {t[0], -t[1]};  // (0, 0) on a face without a normal
      }
      g.corners.push_back(c);
      for (int k = 0; k < 3; ++k) {
        lo_[k] = std::min(lo_[k], c.p[k]);
        hi_[k] = std::max(hi_[k], c.p[k]);
      }
    }
    for (const auto& t : triangulatePolygon(poly))
      g.triangles.push_back({base + t[0], base + t[1], base + t[2], static_cast<std::uint32_t>(use.material), index});
  }

  bool empty() const { return groups_[0].triangles.empty() && groups_[1].triangles.empty(); }

  // Writes the mesh; returns its index, and the node's translation and scale that dequantize
  // its positions (none when they stay float). `quantize` false: float positions (instanced
  // meshes, whose node transform would apply after the instances' own).
  int write(GlbDocument& doc, const std::string& name, bool quantize, json& node) {
    centre_ = Vec3(0, 0, 0);
    step_ = 0;
    if (quantize) {
      // Short decimals, so the JSON stays short: the centre to the millimetre, the step rounded
      // up to three significant digits (the box still fits in ±32,767 steps).
      double half = 0;
      for (int k = 0; k < 3; ++k) {
        centre_[k] = std::round((lo_[k] + hi_[k]) / 2 * 1000) / 1000;
        half = std::max({half, hi_[k] - centre_[k], centre_[k] - lo_[k]});
      }
      step_ = half > 0 ? roundUp3(half / 32767) : 1.0;
      if (step_ > kMaxQuantizationStep) step_ = 0;
    }
    json primitives = json::array();
    emit(doc, groups_[0], {}, Uv::None, primitives);
    if (!groups_[1].triangles.empty()) {
      const std::vector<Uv> uvOf = shiftTextureCoordinates(groups_[1]);
      emit(doc, groups_[1], uvOf, Uv::Short, primitives);
      emit(doc, groups_[1], uvOf, Uv::Float, primitives);
    }
    if (step_ > 0) {
      node["translation"] = {centre_[0], centre_[1], centre_[2]};
      node["scale"] = {step_, step_, step_};
    }
    return doc.push("meshes", json{{"name", name}, {"primitives", std::move(primitives)}});
  }

 private:
  enum class Uv : std::uint8_t { None, Short, Float };
  struct Corner {
    Vec3 p;
    std::array<std::int8_t, 3> n{};
    std::uint32_t face = 0;
    std::array<double, 2> uv{0, 0};  // in repeats; shifted by write()
  };
  struct Triangle {
    std::uint32_t a, b, c, material, face;
  };
  struct Group {
    std::vector<Corner> corners;
    std::vector<Triangle> triangles;
    std::vector<double> faces;  // each face's repeat in metres (0: untextured)
  };
  struct Key {
    std::int32_t p[3];
    std::int8_t n[3];
    std::uint32_t uv[2];
    bool operator==(const Key& o) const {
      return std::memcmp(p, o.p, sizeof p) == 0 && std::memcmp(n, o.n, sizeof n) == 0 &&
             std::memcmp(uv, o.uv, sizeof uv) == 0;
    }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ull;
      auto mix = [&](std::uint64_t x) { h = (h ^ x) * 1099511628211ull; };
      for (int i = 0; i < 3; ++i) mix(static_cast<std::uint32_t>(k.p[i]));
      mix(static_cast<std::uint8_t>(k.n[0]) | static_cast<std::uint8_t>(k.n[1]) << 8 |
          static_cast<std::uint32_t>(static_cast<std::uint8_t>(k.n[2])) << 16);
      mix(k.uv[0]);
      mix(k.uv[1]);
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };

  // A corner's position as written (16-bit steps about the centre, or a float's bits) in `key`,
  // and its value in `value`.
  void positionOf(const Corner& c, Key& key, std::array<double, 3>& value) const {
    for (int k = 0; k < 3; ++k) {
      if (step_ > 0) {
        value[k] = std::clamp<double>(std::lround((c.p[k] - centre_[k]) / step_), -32767, 32767);
        key.p[k] = static_cast<std::int32_t>(value[k]);
      } else {
        const float f = static_cast<float>(c.p[k]);
        value[k] = f;
        std::memcpy(&key.p[k], &f, 4);
      }
      key.n[k] = c.n[k];
    }
  }

  // Shifts the textured corners' coordinates by whole repeats, one shift per patch (faces joined
  // where corners share a written position, a normal and a repeat), and returns per face whether
  // its patch is written as 16-bit normalized integers (every coordinate then in [-1, 1]) or as
  // floats (shifted so that the smallest u and v are in [0, 1), as faceTextureCoordinates does).
  std::vector<Uv> shiftTextureCoordinates(Group& g) const {
    std::vector<std::uint32_t> parent(g.faces.size());
    for (std::uint32_t f = 0; f < parent.size(); ++f) parent[f] = f;
    auto root = [&](std::uint32_t f) {
      while (parent[f] != f) f = parent[f] = parent[parent[f]];
      return f;
    };
    std::unordered_map<Key, std::uint32_t, KeyHash> firstFace;
    firstFace.reserve(g.corners.size());
    std::array<double, 3> unused{};
    for (const Corner& c : g.corners) {
      Key key{};
      positionOf(c, key, unused);
      const double metres = g.faces[c.face];
      std::memcpy(key.uv, &metres, 8);
      const auto [it, fresh] = firstFace.try_emplace(key, c.face);
      if (!fresh) parent[root(c.face)] = root(it->second);
    }
    struct Extent {
      std::array<double, 2> lo{1e300, 1e300}, hi{-1e300, -1e300};
    };
    std::vector<Extent> extent(g.faces.size());
    for (const Corner& c : g.corners) {
      Extent& e = extent[root(c.face)];
      for (int k = 0; k < 2; ++k) {
        e.lo[k] = std::min(e.lo[k], c.uv[k]);
        e.hi[k] = std::max(e.hi[k], c.uv[k]);
      }
    }
    // Per patch root: the shift and how it is written. An integer s with hi − 1 <= s <= lo + 1
    // puts [lo, hi] into [-1, 1].
    std::vector<std::array<double, 2>> shift(g.faces.size());
    std::vector<Uv> kind(g.faces.size(), Uv::Float);
    for (std::uint32_t f = 0; f < g.faces.size(); ++f) {
      if (root(f) != f) continue;
      const Extent& e = extent[f];
      std::array<double, 2> s{};
      bool fits = true;
      for (int k = 0; k < 2; ++k) {
        s[k] = std::ceil(e.hi[k] - 1);
        fits = fits && s[k] <= e.lo[k] + 1;
      }
      if (fits) {
        kind[f] = Uv::Short;
        shift[f] = s;
      } else {
        shift[f] = {std::floor(e.lo[0]), std::floor(e.lo[1])};
      }
    }
    for (Corner& c : g.corners) {
      const std::uint32_t r = root(c.face);
      for (int k = 0; k < 2; ++k) c.uv[k] -= shift[r][k];
    }
    std::vector<Uv> byFace(g.faces.size());
    for (std::uint32_t f = 0; f < g.faces.size(); ++f) byFace[f] = kind[root(f)];
    return byFace;
  }

  // Writes the vertex set of group `g`'s faces whose kind in `uvOf` is `uv` (all of them for
  // Uv::None) and a primitive per material over it. Corners equal in every attribute as written
  // become one vertex; triangles the weld made degenerate (corners within one quantization step)
  // are left out.
  void emit(GlbDocument& doc, const Group& g, const std::vector<Uv>& uvOf, Uv uv, json& primitives) const {
    auto inSet = [&](std::uint32_t face) { return uv == Uv::None || uvOf[face] == uv; };
    std::vector<std::uint32_t> vertexOf(g.corners.size());
    std::unordered_map<Key, std::uint32_t, KeyHash> seen;
    std::vector<std::int16_t> p16, uv16;
    std::vector<float> p32, uv32;
    std::vector<std::int8_t> normals;
    std::uint32_t vertices = 0;
    std::array<double, 3> qlo{1e300, 1e300, 1e300}, qhi{-1e300, -1e300, -1e300};
    for (std::size_t i = 0; i < g.corners.size(); ++i) {
      const Corner& c = g.corners[i];
      if (!inSet(c.face)) continue;
      Key key{};
      std::array<double, 3> value{};
      positionOf(c, key, value);
      std::array<std::int16_t, 2> q{};
      std::array<float, 2> f{};
      for (int k = 0; k < 2; ++k) {
        if (uv == Uv::Short) {
          q[k] = static_cast<std::int16_t>(std::clamp<long>(std::lround(c.uv[k] * 32767), -32767, 32767));
          key.uv[k] = static_cast<std::uint16_t>(q[k]);
        } else if (uv == Uv::Float) {
          f[k] = static_cast<float>(c.uv[k]);
          std::memcpy(&key.uv[k], &f[k], 4);
        }
      }
      const auto [it, fresh] = seen.try_emplace(key, vertices);
      vertexOf[i] = it->second;
      if (!fresh) continue;
      ++vertices;
      for (int k = 0; k < 3; ++k) {
        qlo[k] = std::min(qlo[k], value[k]);
        qhi[k] = std::max(qhi[k], value[k]);
        if (step_ > 0)
          p16.push_back(static_cast<std::int16_t>(value[k]));
        else
          p32.push_back(static_cast<float>(value[k]));
        normals.push_back(c.n[k]);
      }
      if (step_ > 0) p16.push_back(0);
      normals.push_back(0);
      if (uv == Uv::Short) uv16.insert(uv16.end(), {q[0], q[1]});
      if (uv == Uv::Float) uv32.insert(uv32.end(), {f[0], f[1]});
    }
    if (vertices == 0) return;
    json attributes;
    if (step_ > 0) {
      const std::array<int, 3> ilo{static_cast<int>(qlo[0]), static_cast<int>(qlo[1]), static_cast<int>(qlo[2])},
          ihi{static_cast<int>(qhi[0]), static_cast<int>(qhi[1]), static_cast<int>(qhi[2])};
      attributes["POSITION"] =
          doc.accessor(kPositions16, p16.data(), p16.size() * 2,
                       {{"componentType", kShort}, {"count", vertices}, {"type", "VEC3"}, {"min", ilo}, {"max", ihi}});
    } else {
      attributes["POSITION"] =
          doc.accessor(kPositions32, p32.data(), p32.size() * 4,
                       {{"componentType", kFloat}, {"count", vertices}, {"type", "VEC3"}, {"min", qlo}, {"max", qhi}});
    }
    attributes["NORMAL"] =
        doc.accessor(kNormals, normals.data(), normals.size(),
                     {{"componentType", kByte}, {"normalized", true}, {"count", vertices}, {"type", "VEC3"}});
    if (uv == Uv::Short)
      attributes["TEXCOORD_0"] =
          doc.accessor(kTexcoords16, uv16.data(), uv16.size() * 2,
                       {{"componentType", kShort}, {"normalized", true}, {"count", vertices}, {"type", "VEC2"}});
    if (uv == Uv::Float)
      attributes["TEXCOORD_0"] = doc.accessor(kTexcoords, uv32.data(), uv32.size() * 4,
                                              {{"componentType", kFloat}, {"count", vertices}, {"type", "VEC2"}});
    // A primitive per material, in the order of their glTF indices.
    std::map<std::uint32_t, std::vector<std::uint32_t>> byMaterial;
    for (const Triangle& t : g.triangles) {
      if (!inSet(t.face)) continue;
      const std::uint32_t a = vertexOf[t.a], b = vertexOf[t.b], c = vertexOf[t.c];
      if (a == b || b == c || a == c) continue;
      byMaterial[t.material].insert(byMaterial[t.material].end(), {a, b, c});
    }
    for (const auto& [material, indices] : byMaterial) {
      int index;
      if (vertices <= 65535) {
        const std::vector<std::uint16_t> i16(indices.begin(), indices.end());
        index = doc.accessor(kIndices16, i16.data(), i16.size() * 2,
                             {{"componentType", kUnsignedShort}, {"count", indices.size()}, {"type", "SCALAR"}});
      } else {
        index = doc.accessor(kIndices32, indices.data(), indices.size() * 4,
                             {{"componentType", kUnsignedInt}, {"count", indices.size()}, {"type", "SCALAR"}});
      }
      primitives.push_back({{"attributes", attributes}, {"indices", index}, {"material", material}});
    }
  }

  Group groups_[2];  // untextured, textured
  std::array<double, 3> lo_{1e300, 1e300, 1e300}, hi_{-1e300, -1e300, -1e300};
  Vec3 centre_{0, 0, 0};
  double step_ = 0;
};

// A rotation matrix (columns) as a unit quaternion (x, y, z, w).
std::array<double, 4> quaternionOf(const Vec3& c0, const Vec3& c1, const Vec3& c2) {
  const double m00 = c0[0], m10 = c0[1], m20 = c0[2], m01 = c1[0], m11 = c1[1], m21 = c1[2], m02 = c2[0],
               m12 = c2[1], m22 = c2[2];
  std::array<double, 4> q{};
  const double trace = m00 + m11 + m22;
  if (trace > 0) {
    const double s = 2 * std::sqrt(1 + trace);
    q = {(m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, s / 4};
  } else if (m00 > m11 && m00 > m22) {
    const double s = 2 * std::sqrt(1 + m00 - m11 - m22);
    q = {s / 4, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s};
  } else if (m11 > m22) {
    const double s = 2 * std::sqrt(1 + m11 - m00 - m22);
    q = {(m01 + m10) / s, s / 4, (m12 + m21) / s, (m02 - m20) / s};
  } else {
    const double s = 2 * std::sqrt(1 + m22 - m00 - m11);
    q = {(m02 + m20) / s, (m12 + m21) / s, s / 4, (m10 - m01) / s};
  }
  const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& x : q) x /= len;
  return q;
}

}  // namespace

// The file being written: the document, its materials and the scene's nodes so far.
struct GlbWriter::State {
  explicit State(const ExportOptions& o) : options(o), g(o.compress), materials(g, options) {
    g.doc["asset"] = {{"version", "2.0"}, {"generator", "corbel"}};
    if (!options.copyright.empty()) g.doc["asset"]["copyright"] = options.copyright;
  }

  // One object: `faces(use)` hands each face's polygon and its material, kind and tag to `use`.
  template <class Faces>
  void object(ObjectId id, Kind kind, const std::string& name, const Faces& faces) {
    if (options.include && !options.include(id)) return;
    const bool textured = options.textured ? options.textured(id) : options.textures;
    MeshBuilder builder;
    faces([&](const std::vector<Vec3>& poly, const std::string& material, Kind faceKind, const std::string& tag) {
      builder.face(poly, materials.of(id, textured, material, faceKind, tag));
    });
    if (builder.empty()) return;
    json node{{"name", name}};
    node["mesh"] = builder.write(g, name, true, node);
    json extras{{"corbel_object_id", static_cast<int>(id)}, {"corbel_kind", std::string(kindName(kind))}};
    // The placement the vertices were moved by, in corbel's frame (z up): a town's buildings
    // stand where the scene shows them, and this takes them back to the town's own frame.
    if (const auto pl = options.placements.find(id); pl != options.placements.end()) {
      const Placement& p = pl->second;
      extras["corbel_placement"] = {
          {"translation", {p.translation[0], p.translation[1], p.translation[2]}},
          {"rotation_deg", p.rotation_deg},
          {"scale", p.scale},
          {"frame", "z up; p_scene = translation + Rz(rotation_deg) * (scale * p_object)"}};
    }
    node["extras"] = std::move(extras);
    sceneNodes.push_back(g.push("nodes", std::move(node)));
    any = true;
  }

  // A copy of instanced mesh `mesh`, as written: its translation (3 floats) onto stream 2 mesh,
  // its rotation (4 normalized shorts) onto stream 2 mesh + 1.
  void place(std::size_t mesh, const RigidPlacement& p) {
    const auto [t, r] = encode(p);
    placed.append(2 * mesh, t.data(), sizeof t);
    placed.append(2 * mesh + 1, r.data(), sizeof r);
  }

  // A placement in glTF's frame (rotation C R Cᵀ for corbel's rotation R and C the change of
  // axes): its translation as floats, its rotation as a quaternion of normalized shorts (each
  // component within 1.6e-5).
  static std::pair<std::array<float, 3>, std::array<std::int16_t, 4>> encode(const RigidPlacement& p) {
    const Vec3 t = toGltf(p.translation);
    // Column j of C R Cᵀ is C (R (Cᵀ e_j)); Cᵀ takes glTF's x, y, z to corbel's x, −z, y.
    const auto q = quaternionOf(toGltf(p.ex), toGltf(p.ez), -toGltf(p.ey));
    std::array<std::int16_t, 4> r{};
    for (int k = 0; k < 4; ++k) r[k] = static_cast<std::int16_t>(std::lround(q[k] * 32767));
    return {{static_cast<float>(t[0]), static_cast<float>(t[1]), static_cast<float>(t[2])}, r};
  }

  void write(const std::string& path) {
    // Instanced meshes: a node each, its copies (its own placements, then those given to place())
    // placed by EXT_mesh_gpu_instancing: translations as floats, rotations as normalized 16-bit
    // quaternions.
    std::vector<Vec3> poly;
    if (options.instances)
      for (std::size_t i = 0; i < options.instances->size(); ++i) {
        const InstancedMesh& im = (*options.instances)[i];
        const std::size_t n = im.placements.size() + placed.size(2 * i) / 12;
        if (n == 0) continue;
        MeshBuilder builder;
        for (std::size_t f = 0; f < im.mesh.faces.size(); ++f) {
          poly.clear();
          for (int v : im.mesh.faces[f]) poly.push_back(im.mesh.points[v]);
          builder.face(poly, materials.of(0, options.textures, im.mesh.materials[im.mesh.faceMaterial[f]], Kind::Shell,
                                          im.mesh.tags[im.mesh.faceTag[f]]));
        }
        if (builder.empty()) continue;
        json node{{"name", im.name}};
        node["mesh"] = builder.write(g, im.name, false, node);
        std::vector<float> translations;
        std::vector<std::int16_t> rotations;
        translations.reserve(im.placements.size() * 3);
        rotations.reserve(im.placements.size() * 4);
        for (const RigidPlacement& p : im.placements) {
          const auto [t, r] = encode(p);
          translations.insert(translations.end(), t.begin(), t.end());
          rotations.insert(rotations.end(), r.begin(), r.end());
        }
        const int t = g.accessor(
            kTranslations, n * 12,
            [&](const auto& append) {
              append(translations.data(), translations.size() * 4);
              placed.read(2 * i, append);
            },
            {{"componentType", kFloat}, {"count", n}, {"type", "VEC3"}});
        const int r = g.accessor(
            kRotations, n * 8,
            [&](const auto& append) {
              append(rotations.data(), rotations.size() * 2);
              placed.read(2 * i + 1, append);
            },
            {{"componentType", kShort}, {"normalized", true}, {"count", n}, {"type", "VEC4"}});
        node["extensions"]["EXT_mesh_gpu_instancing"] = {{"attributes", {{"TRANSLATION", t}, {"ROTATION", r}}}};
        g.use("EXT_mesh_gpu_instancing", true);
        sceneNodes.push_back(g.push("nodes", std::move(node)));
        any = true;
      }
    if (any) g.use("KHR_mesh_quantization", true);  // normals are bytes in every mesh

    json sceneJson{{"name", "corbel"}};
    if (!sceneNodes.empty()) sceneJson["nodes"] = std::move(sceneNodes);
    if (const auto& geo = options.georeference; !geo.proj.empty()) {
      json r{{"proj", geo.proj},
             {"origin", {geo.lon, geo.lat, geo.height}},
             {"axes", "glTF +X east, -Z north, +Y up, metres"}};
      if (!geo.crs.empty()) r["crs"] = geo.crs;
      sceneJson["extras"] = {{"georeference", std::move(r)}};
    }
    g.push("scenes", std::move(sceneJson));
    g.doc["scene"] = 0;
    g.write(path);
  }

  const ExportOptions options;
  GlbDocument g;
  Materials materials;
  SpillStreams placed;  // the copies given to place(), as written
  json sceneNodes = json::array();
  bool any = false;
};

GlbWriter::GlbWriter(const ExportOptions& options) : state_(std::make_unique<State>(options)) {}

GlbWriter::~GlbWriter() = default;

void GlbWriter::add(ObjectId id, Kind kind, const std::string& name, const MeshData& mesh) {
  std::size_t rejected = 0;
  const std::vector<int> order = manifoldFaceOrder(mesh, rejected);
  // A face's tag and material as Scene::replaceObject reads them (none where out of range).
  auto entry = [](const std::vector<int>& of, std::size_t f, const std::vector<std::string>& names) -> const std::string& {
    static const std::string none;
    const int k = f < of.size() ? of[f] : 0;
    return k >= 0 && static_cast<std::size_t>(k) < names.size() ? names[k] : none;
  };
  std::vector<Vec3> poly;
  state_->object(id, kind, name, [&](const auto& use) {
    for (int f : order) {
      poly.clear();
      for (int v : mesh.faces[f]) poly.push_back(mesh.points[v]);
      use(poly, entry(mesh.faceMaterial, f, mesh.materials), kind, entry(mesh.faceTag, f, mesh.tags));
    }
  });
}

void GlbWriter::place(std::size_t mesh, const RigidPlacement& placement) { state_->place(mesh, placement); }

void GlbWriter::write(const std::string& path) { state_->write(path); }

void writeGlb(const Scene& scene, const std::string& path, const ExportOptions& options) {
  GlbWriter::State state(options);
  const PolyMesh& mesh = scene.mesh();
  const auto byObject = scene.facesByObject();
  std::vector<Vec3> poly;
  for (const auto& [id, info] : scene.objects()) {
    const auto found = byObject.find(id);
    if (found == byObject.end()) continue;
    state.object(id, info.kind, info.name, [&](const auto& use) {
      for (auto f : found->second) {
        poly.clear();
        for (auto v : mesh.fv_range(f)) poly.push_back(mesh.point(v));
        use(poly, scene.faceMaterial(f), scene.faceKind(f), scene.faceTag(f));
      }
    });
  }
  state.write(path);
}

}  // namespace corbel
