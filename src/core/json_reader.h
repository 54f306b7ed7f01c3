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

class JsonReader {
 public:
  JsonReader(const nlohmann::json& value, std::string path) : v_(value), path_(std::move(path)) {}

  const std::string& path() const { return path_; }
  const nlohmann::json& raw() const { return v_; }
  [[noreturn]] void fail(const std::string& reason) const { throw InputError(path_, reason); }

  // Object access. `key` missing → error (required) or nullopt (optional).
  JsonReader at(const std::string& key) const;
  std::optional<JsonReader> find(const std::string& key) const;
  void expectObject() const;
  // Keys present in the object but not in `known`, as full paths (for warnings).
  std::vector<std::string> unknownKeys(const std::set<std::string>& known) const;

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
  const nlohmann::json& v_;
  std::string path_;
};

// Parses text as JSON with a nesting limit (deeply nested input is refused before parsing,
// so no recursion can run away). Throws InputError with line and column on syntax faults.
nlohmann::json parseJsonText(const std::string& text, int maxDepth = 64);

}  // namespace corbel
