#include "kifs/follow.h"

#include "core/error.h"
#include "core/geometry.h"
#include "core/placement.h"
#include "kifs/facings.h"
#include "kifs/kernel.h"

#include <map>
#include <set>
#include <string>

namespace corbel::kifs {

namespace {

std::string quoted(const std::string& name) { return "\"" + name + "\""; }

}  // namespace

const KifsSpec* followingSpec(const DocObject& o) {
  const auto* k = std::get_if<KifsSpec>(&o.spec);
  return k && k->mass.footprint == "object" ? k : nullptr;
}

TriangleSoup sceneTriangles(const Scene& scene, ObjectId id) {
  const PolyMesh& mesh = scene.mesh();
  TriangleSoup out;
  std::map<int, int> index;  // Scene vertex → soup point
  std::vector<Vec3> loop;
  std::vector<int> corners;
  for (auto f : scene.faces(id)) {
    loop.clear();
    corners.clear();
    for (auto v : mesh.fv_range(f)) {
      const auto [it, fresh] = index.try_emplace(v.idx(), int(out.points.size()));
      if (fresh) out.points.emplace_back(mesh.point(v)[0], mesh.point(v)[1], mesh.point(v)[2]);
      loop.push_back(mesh.point(v));
      corners.push_back(it->second);
    }
    for (const auto& t : triangulatePolygon(loop)) out.triangles.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
  }
  return out;
}

TriangleSoup massTriangles(const DocObject& mass, const KifsSpec& follower, const Scene& scene,
                           const TownBuildings& buildings) {
  const std::string& building = follower.mass.building;
  if (building.empty()) return sceneTriangles(scene, mass.id);
  const std::string what = "kifs.mass.building: ";
  if (!std::holds_alternative<TownSpec>(mass.spec))
    throw Error(what + quoted(mass.name) + " is not a town; only a town's buildings can be named (leave it empty)");
  if (!buildings) throw Error(what + "the buildings of town " + quoted(mass.name) + " are not at hand here");
  try {
    return trianglesOf(buildings(mass, building));
  } catch (const Error& e) {
    throw Error(what + "town " + quoted(mass.name) + " " + e.what());
  }
}

const DocObject& followedObject(const Document& doc, const DocObject& kifsObject) {
  const KifsSpec* spec = followingSpec(kifsObject);
  if (!spec) throw Error("kifs.mass.footprint: " + quoted(kifsObject.name) + " does not follow an object");
  std::string chain = quoted(kifsObject.name);
  std::set<ObjectId> seen{kifsObject.id};
  const DocObject* first = nullptr;
  for (const KifsSpec* s = spec; s;) {
    if (s->mass.object.empty()) throw Error("kifs.mass.object: names no object (the footprint \"object\" needs one)");
    const DocObject* next = doc.findByName(s->mass.object);
    if (!next) throw Error("kifs.mass.object: no object named " + quoted(s->mass.object));
    chain += " → " + quoted(next->name);
    if (!seen.insert(next->id).second) throw Error("kifs.mass.object: a cycle: " + chain);
    if (!first) first = next;
    s = followingSpec(*next);
  }
  if (followingSpec(*first))
    throw Error("kifs.mass.object: " + quoted(first->name) +
                " is a KIFS building that follows another object; a mass must be a shell (an extrusion, a box, a "
                "unit, a meshed KIFS building)");
  return *first;
}

std::shared_ptr<const MassField> followedMass(const Document& doc, const Scene& scene, const DocObject& kifsObject,
                                              Progress* progress, const TownBuildings& buildings) {
  const DocObject& mass = followedObject(doc, kifsObject);
  const KifsSpec& spec = std::get<KifsSpec>(kifsObject.spec);
  return bakeFollowedMass(mass, massTriangles(mass, spec, scene, buildings), paramsOf(spec), progress);
}

std::shared_ptr<const MassField> bakeFollowedMass(const DocObject& mass, const TriangleSoup& triangles,
                                                  const KifsParams& params, Progress* progress) {
  const std::string what = "kifs.mass.object: " + quoted(mass.name) + " ";
  if (triangles.triangles.empty()) throw Error(what + "has no faces in the Scene (is its build failing?)");
  try {
    const ShellDistance shell(triangles);
    auto field = std::make_shared<MassField>(bakeMassField(shell, params.mass.resolution, progress));
    const Vec3& t = mass.placement.translation;
    const auto [c, s] = cosSinDegrees(mass.placement.rotation_deg);
    const glm::dvec3 origin(t[0], t[1], t[2]);
    setFrame(*field, origin, glm::dvec2(c, s), facingsOf(triangles, origin, glm::dvec2(c, s), params.facade.period));
    return field;
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& e) {
    throw Error(what + "is " + e.what());
  }
}

Building buildingOf(const Document& doc, const Scene& scene, const DocObject& kifsObject, Progress* progress,
                    const TownBuildings& buildings) {
  const KifsParams params = paramsOf(std::get<KifsSpec>(kifsObject.spec));
  if (params.mass.footprint != Footprint::Object) return Building(params);
  return Building(params, followedMass(doc, scene, kifsObject, progress, buildings));
}

}  // namespace corbel::kifs
