#include "core/project_io.h"

#include "core/atomic_file.h"
#include "core/json_reader.h"

#include <set>

namespace corbel {

namespace {

using ojson = nlohmann::ordered_json;

ojson vec(const Vec3& v) { return ojson::array({v[0], v[1], v[2]}); }

ojson boxToJson(const BoxSpec& b) {
  ojson j;
  j["origin"] = vec(b.origin);
  j["size"] = vec(b.size);
  j["rotation"] = b.rotation_deg;
  j["material"] = b.material;
  j["repeat"] = {{"count", {b.repeat_x, b.repeat_y}}, {"spacing", {b.spacing_x, b.spacing_y}}};
  return j;
}

BoxSpec boxFromJson(const JsonReader& r, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"origin", "size", "rotation", "material", "repeat"}))
    warnings.push_back(k + ": unknown key ignored");
  BoxSpec b;
  if (auto v = r.find("origin")) b.origin = v->vec3();
  b.size = r.at("size").vec3();
  if (auto v = r.find("rotation")) b.rotation_deg = v->number();
  if (auto v = r.find("material")) b.material = v->string(limits::kMaxNameLength);
  if (auto rep = r.find("repeat")) {
    rep->expectObject();
    for (auto& k : rep->unknownKeys({"count", "spacing"})) warnings.push_back(k + ": unknown key ignored");
    if (auto c = rep->find("count")) {
      auto [nx, ny] = c->integerPair(1, limits::kMaxRepeat);
      if (nx * ny > limits::kMaxRepeat)
        c->fail(std::to_string(nx) + " x " + std::to_string(ny) + " boxes exceeds the limit of " +
                std::to_string(limits::kMaxRepeat));
      b.repeat_x = static_cast<int>(nx);
      b.repeat_y = static_cast<int>(ny);
    }
    if (auto s = rep->find("spacing")) {
      const Vec2 sp = s->vec2();
      b.spacing_x = sp[0];
      b.spacing_y = sp[1];
    }
  }
  if (auto problem = checkBoxSpec(b)) {
    // checkBoxSpec names the field ("size: ..."); anchor it at this spec's path.
    const auto colon = problem->find(": ");
    const std::string field = colon == std::string::npos ? std::string() : problem->substr(0, colon);
    throw InputError(field.empty() ? r.path() : r.path() + "." + field,
                     colon == std::string::npos ? *problem : problem->substr(colon + 2));
  }
  return b;
}

}  // namespace

LoadedProject parseProject(const std::string& text) {
  const nlohmann::json root = parseJsonText(text);
  JsonReader r(root, "");
  if (!root.is_object()) r.fail("a project file must hold a JSON object");
  LoadedProject out;
  const std::string format = r.at("format").string(64);
  if (format != "corbel") r.at("format").fail("expected \"corbel\", found \"" + format + "\"");
  const long version = r.at("version").integer(0, 1L << 30);
  if (version > kProjectVersion)
    r.at("version").fail("this file was written by a newer corbel (format version " + std::to_string(version) +
                         "); this build reads versions up to " + std::to_string(kProjectVersion) +
                         ". Update corbel to open it.");
  if (version < 1) r.at("version").fail("format version must be at least 1");
  for (auto& k : r.unknownKeys({"format", "version", "name", "objects"}))
    out.warnings.push_back(k + ": unknown key ignored");

  Document& doc = out.document;
  if (auto n = r.find("name")) doc.name = n->string(limits::kMaxNameLength);
  std::set<ObjectId> ids;
  std::set<std::string> names;
  if (auto objs = r.find("objects")) {
    for (const JsonReader& o : objs->array(limits::kMaxObjects)) {
      o.expectObject();
      DocObject obj;
      const JsonReader idReader = o.at("id");
      obj.id = static_cast<ObjectId>(idReader.integer(1, 0x7fffffff));
      if (!ids.insert(obj.id).second) idReader.fail("id " + std::to_string(obj.id) + " is used twice");
      const JsonReader nameReader = o.at("name");
      obj.name = nameReader.string(limits::kMaxNameLength);
      if (obj.name.empty()) nameReader.fail("name must not be empty");
      if (!names.insert(obj.name).second) nameReader.fail("name \"" + obj.name + "\" is used twice");
      if (auto v = o.find("visible")) obj.visible = v->boolean();
      static const std::set<std::string> specKeys = {"box"};
      int specCount = 0;
      for (const auto& key : specKeys) specCount += o.find(key) ? 1 : 0;
      if (specCount == 0) o.fail("no spec: expected one of \"box\"");
      if (specCount > 1) o.fail("more than one spec: an object has exactly one");
      obj.spec = boxFromJson(o.at("box"), out.warnings);
      for (auto& k : o.unknownKeys({"id", "name", "visible", "box"}))
        out.warnings.push_back(k + ": unknown key ignored");
      doc.objects.push_back(std::move(obj));
    }
  }
  return out;
}

LoadedProject loadProject(const std::string& path) {
  const std::string text = readFile(path, kMaxProjectBytes);
  try {
    return parseProject(text);
  } catch (const InputError& e) {
    throw InputError(e.where.empty() ? path : path + ": " + e.where, e.reason);
  }
}

std::string serializeProject(const Document& doc) {
  ojson root;
  root["format"] = "corbel";
  root["version"] = kProjectVersion;
  root["name"] = doc.name;
  ojson objects = ojson::array();
  for (const DocObject& o : doc.objects) {
    ojson j;
    j["id"] = o.id;
    j["name"] = o.name;
    j["visible"] = o.visible;
    std::visit([&](const BoxSpec& b) { j["box"] = boxToJson(b); }, o.spec);
    objects.push_back(std::move(j));
  }
  root["objects"] = std::move(objects);
  return root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

void saveProject(const Document& doc, const std::string& path) { writeFileAtomic(path, serializeProject(doc)); }

}  // namespace corbel
