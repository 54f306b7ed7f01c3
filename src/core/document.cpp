#include "core/document.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace corbel {

DocObject* Document::find(ObjectId id) {
  for (auto& o : objects)
    if (o.id == id) return &o;
  return nullptr;
}

const DocObject* Document::find(ObjectId id) const {
  return const_cast<Document*>(this)->find(id);
}

const DocObject* Document::findByName(const std::string& n) const {
  for (const auto& o : objects)
    if (o.name == n) return &o;
  return nullptr;
}

ObjectId Document::nextId() const {
  ObjectId next = 1;
  for (const auto& o : objects) next = std::max(next, o.id + 1);
  return next;
}

std::string Document::uniqueName(const std::string& base) const {
  if (!findByName(base)) return base;
  for (int i = 2;; ++i) {
    std::string candidate = base + " " + std::to_string(i);
    if (!findByName(candidate)) return candidate;
  }
}

ObjectId Document::add(const std::string& base, Spec spec) {
  DocObject o;
  o.id = nextId();
  o.name = uniqueName(base);
  o.spec = std::move(spec);
  objects.push_back(std::move(o));
  return objects.back().id;
}

bool Document::remove(ObjectId id) {
  auto it = std::find_if(objects.begin(), objects.end(), [&](const DocObject& o) { return o.id == id; });
  if (it == objects.end()) return false;
  objects.erase(it);
  return true;
}

std::optional<std::string> checkBoxSpec(const BoxSpec& s) {
  std::ostringstream err;
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(s.origin[k]) || std::abs(s.origin[k]) > limits::kMaxCoordinate) {
      err << "origin: coordinates must be finite and within " << limits::kMaxCoordinate << " m";
      return err.str();
    }
    if (!std::isfinite(s.size[k]) || s.size[k] < limits::kMinSize || s.size[k] > limits::kMaxCoordinate) {
      err << "size: each extent must be between " << limits::kMinSize << " and " << limits::kMaxCoordinate
          << " m (got " << s.size[k] << ")";
      return err.str();
    }
  }
  if (!std::isfinite(s.rotation_deg) || std::abs(s.rotation_deg) > 3600)
    return "rotation: must be a finite angle in degrees";
  if (s.repeat_x < 1 || s.repeat_y < 1) return "repeat.count: counts must be at least 1";
  if (static_cast<long>(s.repeat_x) * s.repeat_y > limits::kMaxRepeat) {
    err << "repeat.count: " << s.repeat_x << " x " << s.repeat_y << " boxes exceeds the limit of "
        << limits::kMaxRepeat;
    return err.str();
  }
  if (!std::isfinite(s.spacing_x) || !std::isfinite(s.spacing_y) ||
      std::abs(s.spacing_x) * s.repeat_x > limits::kMaxCoordinate ||
      std::abs(s.spacing_y) * s.repeat_y > limits::kMaxCoordinate)
    return "repeat.spacing: must be finite and keep the copies within the coordinate limit";
  if (s.material.size() > limits::kMaxNameLength) return "material: name too long";
  return std::nullopt;
}

}  // namespace corbel

namespace corbel {

std::optional<std::string> checkPlanBackground(const PlanBackground& b) {
  if (b.image.empty()) return "image: the image's path must not be empty";
  if (b.image.size() > limits::kMaxPathLength) return "image: the path is longer than 4096 bytes";
  if (b.image.find('\0') != std::string::npos) return "image: a path cannot hold a NUL character";
  if (!std::isfinite(b.scale) || b.scale < limits::kMinBackgroundScale || b.scale > limits::kMaxBackgroundScale)
    return "scale: must be within [1e-06, 10000] metres per pixel";
  for (int k = 0; k < 2; ++k)
    if (!std::isfinite(b.origin[k]) || std::abs(b.origin[k]) > limits::kMaxCoordinate)
      return "origin: must lie within 1e7 m of the origin";
  if (!std::isfinite(b.opacity) || b.opacity < 0 || b.opacity > 1) return "opacity: must be within [0, 1]";
  return std::nullopt;
}

}  // namespace corbel

namespace corbel {

std::optional<std::string> checkUnitSpec(const UnitSpec& s) {
  if (s.parts.empty()) return "parts: a unit needs at least one part";
  if (s.parts.size() > limits::kMaxUnitParts)
    return "parts: " + std::to_string(s.parts.size()) + " parts exceeds the limit of " +
           std::to_string(limits::kMaxUnitParts);
  for (std::size_t i = 0; i < s.parts.size(); ++i) {
    const UnitPart& p = s.parts[i];
    const std::string at = "parts[" + std::to_string(i) + "]: ";
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p.lo[k]) || !std::isfinite(p.hi[k]) || std::abs(p.lo[k]) > limits::kMaxCoordinate ||
          std::abs(p.hi[k]) > limits::kMaxCoordinate)
        return at + "coordinates must be finite and within 1e+07 m";
      if (p.hi[k] - p.lo[k] < limits::kMinSize) return at + "hi must exceed lo on every axis";
    }
  }
  if (s.material.size() > limits::kMaxNameLength) return "material: name too long";
  return std::nullopt;
}

std::optional<std::pair<int, int>> parseTownEdgeKey(const std::string& key) {
  const auto colon = key.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == key.size()) return std::nullopt;
  int parts[2] = {0, 0};
  std::size_t k = 0;
  for (int i = 0; i < 2; ++i, ++k) {
    const std::size_t end = i == 0 ? colon : key.size();
    if (end - k > 6) return std::nullopt;  // below 10⁶, and no overflow
    for (; k < end; ++k) {
      if (key[k] < '0' || key[k] > '9') return std::nullopt;
      parts[i] = parts[i] * 10 + (key[k] - '0');
    }
  }
  // One spelling per edge, so that equal overrides compare equal: no leading zeros.
  if (townEdgeKey(parts[0], parts[1]) != key) return std::nullopt;
  return std::pair{parts[0], parts[1]};
}

std::string townEdgeKey(int loop, int edge) { return std::to_string(loop) + ":" + std::to_string(edge); }

std::optional<std::string> checkTownSpec(const TownSpec& s) {
  if (s.footprints.empty() && s.footprintsJson.empty()) return "footprints: a footprint file or embedded GeoJSON is needed";
  if (s.style.empty() && s.styleJson.empty()) return "style: a style file or an embedded style is needed";
  if (s.detail != "massing" && s.detail != "steps" && s.detail != "full")
    return "detail: expected \"massing\", \"steps\" or \"full\", found \"" + s.detail + "\"";
  if (s.overrides.size() > limits::kMaxTownOverrides) return "overrides: too many";
  for (const auto& [id, o] : s.overrides) {
    const std::string at = "overrides[\"" + id + "\"]";
    if (id.empty()) return "overrides: a footprint id must not be empty";
    if (o.empty()) return at + ": overrides nothing";
    for (const auto& [side, profile] : o.profiles) {
      if (side != "street" && side != "side" && side != "back")
        return at + ".profiles: expected \"street\", \"side\" or \"back\", found \"" + side + "\"";
      if (profile.empty()) return at + ".profiles." + side + ": the profile name must not be empty";
    }
    for (const auto& [key, profile] : o.edges) {
      if (!parseTownEdgeKey(key))
        return at + ".edges: expected an edge \"LOOP:EDGE\" (as \"0:3\"), found \"" + key + "\"";
      if (profile.empty()) return at + ".edges[\"" + key + "\"]: the profile name must not be empty";
    }
  }
  if (s.streets.size() > limits::kMaxTownStreets) return "streets: too many (at most 256)";
  for (std::size_t k = 0; k < s.streets.size(); ++k) {
    const TownStreet& st = s.streets[k];
    const std::string at = "streets[" + std::to_string(k) + "]";
    if (st.points.size() < 2 || st.points.size() > limits::kMaxStreetPoints)
      return at + ".points: expected 2 to 64 control points, found " + std::to_string(st.points.size());
    for (std::size_t i = 0; i < st.points.size(); ++i) {
      for (double v : st.points[i])
        if (!std::isfinite(v) || std::abs(v) > limits::kMaxCoordinate)
          return at + ".points[" + std::to_string(i) + "]: coordinates must be finite and within 1e+07 m";
      if (i > 0 && st.points[i] == st.points[i - 1])
        return at + ".points[" + std::to_string(i) + "]: repeats the point before it";
    }
    const auto range = [&](const char* name, double v, double lo, double hi) -> std::optional<std::string> {
      if (!(v >= lo && v <= hi))
        return at + "." + name + ": expected " + std::to_string(int(lo)) + " to " + std::to_string(int(hi)) + " m";
      return std::nullopt;
    };
    if (auto e = range("width", st.width, 1, 100)) return e;
    if (auto e = range("setback", st.setback, 0, 50)) return e;
    if (auto e = range("depth", st.depth, 3, 200)) return e;
    if (auto e = range("plot_width", st.plotWidth, 3, 200)) return e;
  }
  return std::nullopt;
}

}  // namespace corbel

namespace corbel {

bool scalable(const Spec& spec) {
  return std::holds_alternative<BoxSpec>(spec) || std::holds_alternative<ExtrusionSpec>(spec) ||
         std::holds_alternative<UnitSpec>(spec);
}

}  // namespace corbel
