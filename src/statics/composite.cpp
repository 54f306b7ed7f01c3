#include "statics/composite.h"

#include "core/error.h"
#include "statics/builder.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <set>

namespace corbel::statics {

std::pair<std::string, std::string> splitCompositeName(const std::string& name) {
  const auto slash = name.find('/');
  if (slash == std::string::npos) throw Error("\"" + name + "\" is not a part's parameter (part/parameter)");
  return {name.substr(0, slash), name.substr(slash + 1)};
}

ParametricModel compositeModel(std::vector<CompositePart> parts) {
  if (parts.empty()) throw Error("a composite needs at least one masonry object");
  std::set<std::string> names;
  ParametricModel m;
  m.name = "composite";
  m.description = "masonry objects analysed together:";
  for (const CompositePart& p : parts) {
    if (p.name.empty() || p.name.find('/') != std::string::npos)
      throw Error("a masonry object analysed with others needs a name without '/' (\"" + p.name + "\")");
    if (!names.insert(p.name).second) throw Error("two masonry objects are called \"" + p.name + "\"; rename one");
    m.description += " " + p.name;
    for (Parameter q : p.model.parameters.all()) {
      q.name = p.name + "/" + q.name;
      m.parameters.add(std::move(q));
    }
    for (FreeParameter f : p.model.suggestedFree) {
      f.name = p.name + "/" + f.name;
      m.suggestedFree.push_back(std::move(f));
    }
  }
  auto shared = std::make_shared<const std::vector<CompositePart>>(std::move(parts));
  m.build = [shared](const ParameterSet& values) {
    Assembly out;
    bool first = true;
    double lowest = std::numeric_limits<double>::infinity();
    BBox all;
    for (const CompositePart& part : *shared) {
      ParameterSet own = part.model.parameters;
      for (const Parameter& q : own.all()) own.set(q.name, values[part.name + "/" + q.name]);
      Assembly a = part.model.build(own);
      if (first) {
        out.gravity = a.gravity;
        out.g = a.g;
        first = false;
      } else if ((a.gravity - out.gravity).norm() > 1e-12 || a.g != out.g) {
        throw Error(part.name + ": its gravity differs from the other objects' (a tilted template cannot be analysed "
                                "with others)");
      }
      const auto [c, s] = cosSinDegrees(part.placement.rotation_deg);
      const auto turn = [c = c, s = s](const Vec3& v) { return Vec3(c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]); };
      for (Block& b : a.blocks) {
        if (b.fixed) continue;
        for (Vec3& v : b.vertices) {
          v = part.placement.apply(v);
          all.add(v);
          lowest = std::min(lowest, v[2]);
        }
        // Forces turn with the object but do not scale with it; their points move as its blocks.
        for (PointLoad& l : b.pointLoads) {
          l.at = part.placement.apply(l.at);
          l.force = turn(l.force);
        }
        b.liveLoad = turn(b.liveLoad);
        b.name = part.name + "/" + b.name;
        out.blocks.push_back(std::move(b));
      }
    }
    if (out.blocks.empty()) throw Error("the masonry objects have no free blocks");
    out.blocks.push_back(boxBlock("ground", Vec3(all.lo[0] - 1, all.lo[1] - 1, lowest - 1.0),
                                  Vec3(all.hi[0] + 1, all.hi[1] + 1, lowest), 1.0, true));
    return out;
  };
  return m;
}

}  // namespace corbel::statics
