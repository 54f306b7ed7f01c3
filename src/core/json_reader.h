#pragma once
// JsonReader: typed access to a parsed JSON value that remembers its path, so every fault is
// reported as "objects[2].box.size: expected [x, y, z] numbers". Shared by every loader.
#include "core/error.h"
#include "core/geometry.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace corbel {

// A key a reader did not know: where it was (as a JSON pointer from the root reader) and its
// value. Project files keep such keys so a save by this build writes them back
// (core/project_io.h).
struct UnknownKey {
  nlohmann::json::json_pointer pointer;
  nlohmann::json value;
};

class JsonReader {
 public:
  JsonReader(const nlohmann::json& value, std::string path) : v_(value), path_(std::move(path)) {}
  // A root reader whose unknownKeys() calls, on it and on every reader derived from it, also
  // record each unknown key and its value in `unknown`.
  JsonReader(const nlohmann::json& value, std::string path, std::vector<UnknownKey>* unknown)
      : v_(value), path_(std::move(path)), unknown_(unknown) {}

  const std::string& path() const { return path_; }
  const nlohmann::json::json_pointer& pointer() const { return pointer_; }
  const nlohmann::json& raw() const { return v_; }
  [[noreturn]] void fail(const std::string& reason) const { throw InputError(path_, reason); }

  // Object access. `key` missing → error (required) or nullopt (optional).
  JsonReader at(const std::string& key) const;
  std::optional<JsonReader> find(const std::string& key) const;
  void expectObject() const;
  // Keys present in the object but not in `known`, as full paths (for warnings); recorded
  // with their values where the root reader was given a list for them.
  std::vector<std::string> unknownKeys(const std::set<std::string>& known) const;

  // The member `key` of an object, or the entry `index` of an array, reported at `path` (for
  // maps keyed by names the caller writes its own form, like overrides["osm:w1"]).
  JsonReader member(const std::string& key, std::string path) const;
  JsonReader element(std::size_t index) const;

  // Array access.
  std::vector<JsonReader> array(std::size_t maxCount) const;

  double number() const;                       // finite double
  double number(double lo, double hi) const;   // finite and within [lo, hi]
  long integer(long lo, long hi) const;        // an integer within [lo, hi]
  bool boolean() const;
  std::string string(std::size_t maxLength) const;
  Vec3 vec3() const;                           // [x, y, z] finite numbers
  std::pair<long, long> integerPair(long lo, long hi) const;
  Vec2 vec2() const;

 private:
  static std::string typeName(const nlohmann::json& v);
  JsonReader child(const nlohmann::json& value, std::string path, const nlohmann::json::json_pointer& pointer) const;
  const nlohmann::json& v_;
  std::string path_;
  nlohmann::json::json_pointer pointer_;
  std::vector<UnknownKey>* unknown_ = nullptr;
};

// Parses text as JSON with a nesting limit (deeply nested input is refused before parsing,
// so no recursion can run away). Throws InputError with line and column on syntax faults.
nlohmann::json parseJsonText(const std::string& text, int maxDepth = 64);

}  // namespace corbel
