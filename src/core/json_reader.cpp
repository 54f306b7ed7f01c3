#include "core/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace corbel {

std::string JsonReader::typeName(const nlohmann::json& v) {
  switch (v.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: return "a number";
    default: return "an unsupported value";
  }
}

void JsonReader::expectObject() const {
  if (!v_.is_object()) fail("expected an object, found " + typeName(v_));
}

namespace {

// "a.b" for plain keys; a key with other characters (spaces, quotes, control characters, an
// empty key) is written as a JSON string in brackets: a["two words"], a["\u0000"].
std::string childPath(const std::string& path, const std::string& key) {
  const bool plain = !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-';
  });
  if (!plain)
    return path + "[" + nlohmann::json(key).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "]";
  return path.empty() ? key : path + "." + key;
}

}  // namespace

JsonReader JsonReader::child(const nlohmann::json& value, std::string path,
                             const nlohmann::json::json_pointer& pointer) const {
  JsonReader r(value, std::move(path), unknown_);
  r.pointer_ = pointer;
  return r;
}

JsonReader JsonReader::at(const std::string& key) const {
  expectObject();
  auto it = v_.find(key);
  if (it == v_.end()) throw InputError(childPath(path_, key), "missing");
  return child(*it, childPath(path_, key), pointer_ / key);
}

std::optional<JsonReader> JsonReader::find(const std::string& key) const {
  expectObject();
  auto it = v_.find(key);
  if (it == v_.end()) return std::nullopt;
  return child(*it, childPath(path_, key), pointer_ / key);
}

JsonReader JsonReader::member(const std::string& key, std::string path) const {
  expectObject();
  auto it = v_.find(key);
  if (it == v_.end()) throw InputError(path, "missing");
  return child(*it, std::move(path), pointer_ / key);
}

JsonReader JsonReader::element(std::size_t index) const {
  if (!v_.is_array()) fail("expected an array, found " + typeName(v_));
  if (index >= v_.size()) fail("has no entry " + std::to_string(index));
  return child(v_[index], path_ + "[" + std::to_string(index) + "]", pointer_ / index);
}

std::vector<std::string> JsonReader::unknownKeys(const std::set<std::string>& known) const {
  std::vector<std::string> out;
  if (!v_.is_object()) return out;
  for (auto it = v_.begin(); it != v_.end(); ++it)
    if (!known.count(it.key())) {
      out.push_back(childPath(path_, it.key()));
      if (unknown_) unknown_->push_back({pointer_ / it.key(), it.value()});
    }
  return out;
}

std::vector<JsonReader> JsonReader::array(std::size_t maxCount) const {
  if (!v_.is_array()) fail("expected an array, found " + typeName(v_));
  if (v_.size() > maxCount)
    fail("has " + std::to_string(v_.size()) + " entries, more than the limit of " + std::to_string(maxCount));
  std::vector<JsonReader> out;
  out.reserve(v_.size());
  for (std::size_t i = 0; i < v_.size(); ++i) out.push_back(child(v_[i], path_ + "[" + std::to_string(i) + "]", pointer_ / i));
  return out;
}

double JsonReader::number() const {
  if (!v_.is_number()) fail("expected a number, found " + typeName(v_));
  const double d = v_.get<double>();
  if (!std::isfinite(d)) fail("number is not finite");
  return d;
}

double JsonReader::number(double lo, double hi) const {
  const double d = number();
  if (d < lo || d > hi) {
    std::ostringstream s;
    s << d << " is outside [" << lo << ", " << hi << "]";
    fail(s.str());
  }
  return d;
}

long JsonReader::integer(long lo, long hi) const {
  if (!v_.is_number()) fail("expected an integer, found " + typeName(v_));
  long value = 0;
  if (v_.is_number_unsigned()) {
    const auto u = v_.get<std::uint64_t>();
    if (hi < 0 || u > static_cast<std::uint64_t>(hi)) fail(std::to_string(u) + " is larger than " + std::to_string(hi));
    value = static_cast<long>(u);
  } else if (v_.is_number_integer()) {
    value = static_cast<long>(v_.get<std::int64_t>());
  } else {
    const double d = v_.get<double>();
    if (!std::isfinite(d) || d != std::floor(d)) fail("expected an integer, found a fractional number");
    // 2^63 compares equal to (double)LONG_MAX but does not fit a long.
    if (d < static_cast<double>(lo) || d > static_cast<double>(hi) || d >= 0x1p63) {
      std::ostringstream s;
      s << d << " is outside [" << lo << ", " << hi << "]";
      fail(s.str());
    }
    value = static_cast<long>(d);
  }
  if (value < lo || value > hi)
    fail(std::to_string(value) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return value;
}

bool JsonReader::boolean() const {
  if (!v_.is_boolean()) fail("expected true or false, found " + typeName(v_));
  return v_.get<bool>();
}

std::string JsonReader::string(std::size_t maxLength) const {
  if (!v_.is_string()) fail("expected a string, found " + typeName(v_));
  const auto& s = v_.get_ref<const std::string&>();
  if (s.size() > maxLength) fail("text longer than " + std::to_string(maxLength) + " bytes");
  return s;
}

Vec3 JsonReader::vec3() const {
  if (!v_.is_array() || v_.size() != 3 || !v_[0].is_number() || !v_[1].is_number() || !v_[2].is_number())
    fail("expected [x, y, z] numbers");
  Vec3 p;
  for (int k = 0; k < 3; ++k) p[k] = JsonReader(v_[k], path_ + "[" + std::to_string(k) + "]").number();
  return p;
}

Vec2 JsonReader::vec2() const {
  if (!v_.is_array() || v_.size() != 2 || !v_[0].is_number() || !v_[1].is_number())
    fail("expected [x, y] numbers");
  Vec2 p;
  for (int k = 0; k < 2; ++k) p[k] = JsonReader(v_[k], path_ + "[" + std::to_string(k) + "]").number();
  return p;
}

std::pair<long, long> JsonReader::integerPair(long lo, long hi) const {
  if (!v_.is_array() || v_.size() != 2) fail("expected [a, b] integers");
  return {JsonReader(v_[0], path_ + "[0]").integer(lo, hi), JsonReader(v_[1], path_ + "[1]").integer(lo, hi)};
}

namespace {

// Builds the DOM like nlohmann's own parser and remembers where it is, so that a number too
// large for a double (1e999: valid JSON, but nlohmann refuses it) is reported at its path.
class PathTrackingBuilder {
 public:
  using json = nlohmann::json;
  explicit PathTrackingBuilder(json& root) : root_(root) {}

  bool null() { return put(nullptr); }
  bool boolean(bool v) { return put(v); }
  bool number_integer(json::number_integer_t v) { return put(v); }
  bool number_unsigned(json::number_unsigned_t v) { return put(v); }
  bool number_float(json::number_float_t v, const json::string_t&) { return put(v); }
  bool string(json::string_t& v) { return put(std::move(v)); }
  bool binary(json::binary_t& v) { return put(json::binary(std::move(v))); }
  bool start_object(std::size_t) { return push(json::object()); }
  bool key(json::string_t& k) {
    keys_.back() = k;
    return true;
  }
  bool end_object() { return pop(); }
  bool start_array(std::size_t) { return push(json::array()); }
  bool end_array() { return pop(); }
  bool parse_error(std::size_t, const std::string& token, const nlohmann::json::exception& e) {
    if (e.id == 406) throw InputError(path(), "number is not finite (" + token + " is out of range)");
    std::string what = e.what();
    // Drop nlohmann's "[json.exception.parse_error.101] " prefix; keep line/column and reason.
    const auto close = what.find("] ");
    if (close != std::string::npos) what = what.substr(close + 2);
    throw InputError("", "not valid JSON: " + what);
  }

 private:
  template <class V>
  bool put(V&& v) {
    slot() = json(std::forward<V>(v));
    return true;
  }
  json& slot() {
    if (stack_.empty()) return root_;
    json& top = *stack_.back();
    if (top.is_array()) {
      top.push_back(nullptr);
      return top.back();
    }
    return top[keys_.back()];
  }
  bool push(json container) {
    json& s = slot();
    s = std::move(container);
    stack_.push_back(&s);
    keys_.emplace_back();
    return true;
  }
  bool pop() {
    stack_.pop_back();
    keys_.pop_back();
    return true;
  }
  // Path of the value being read: in the innermost array the next index, in outer arrays
  // the index of the element that holds the rest.
  std::string path() const {
    std::string out;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      if (stack_[i]->is_array()) {
        const std::size_t n = stack_[i]->size();
        out += "[" + std::to_string(i + 1 == stack_.size() ? n : n - 1) + "]";
      } else {
        out = childPath(out, keys_[i]);
      }
    }
    return out;
  }

  json& root_;
  std::vector<json*> stack_;
  std::vector<std::string> keys_;
};

}  // namespace

nlohmann::json parseJsonText(const std::string& text, int maxDepth) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError("", "file is empty");
  // Nesting pre-scan outside strings.
  int depth = 0;
  bool inString = false;
  std::size_t line = 1, column = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    ++column;
    if (c == '\n') {
      ++line;
      column = 0;
    }
    if (inString) {
      if (c == '\\') {
        ++i;
        ++column;
      } else if (c == '"') {
        inString = false;
      }
      continue;
    }
    if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > maxDepth) {
        std::ostringstream s;
        s << "line " << line << ", column " << column << ": nesting deeper than " << maxDepth << " levels";
        throw InputError("", s.str());
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  nlohmann::json root;
  PathTrackingBuilder builder(root);
  nlohmann::json::sax_parse(text, &builder);  // faults throw from builder.parse_error
  return root;
}

}  // namespace corbel
