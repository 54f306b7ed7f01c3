#include "kifs/kernel.h"

#include "core/error.h"
#include "kifs/distance.h"
#include "kifs/follow.h"
#include "kifs/mass_field.h"
#include "kifs/mesher.h"

#include <set>

namespace corbel::kifs {

static_assert(limits::kMaxKifsMeshResolution == kMaxMeshResolution, "the project format's limit is the mesher's");

namespace {

Footprint footprintOf(const std::string& name) {
  if (name == "box") return Footprint::Box;
  if (name == "T") return Footprint::T;
  if (name == "H") return Footprint::H;
  if (name == "object") return Footprint::Object;
  throw Error("kifs.mass.footprint: must be \"box\", \"T\", \"H\" or \"object\", got \"" + name + "\"");
}

std::string footprintName(Footprint f) {
  switch (f) {
    case Footprint::T: return "T";
    case Footprint::H: return "H";
    case Footprint::Object: return "object";
    case Footprint::Box: break;
  }
  return "box";
}

// Calls f(spec field, parameter field) for every field the two hold, so both directions of
// the conversion read one list. The trace's pixel angle is the renderer's, not the spec's.
template <class S, class P, class F>
void eachField(S& s, P& p, F&& f) {
  f(s.iterations, p.iterations);
  f(s.scale, p.scale);
  f(s.centre, p.centre);
  f(s.r1, p.r1);
  f(s.r2, p.r2);
  f(s.bailout, p.bailout);
  f(s.mass.footprint, p.mass.footprint);
  f(s.mass.halfWidth, p.mass.halfWidth);
  f(s.mass.halfDepth, p.mass.halfDepth);
  f(s.mass.height, p.mass.height);
  f(s.mass.wing, p.mass.wing);
  f(s.mass.shell, p.mass.shell);
  f(s.mass.resolution, p.mass.resolution);
  f(s.facade.period, p.facade.period);
  f(s.facade.r, p.facade.r);
  f(s.facade.a1, p.facade.a1);
  f(s.facade.a2, p.facade.a2);
  f(s.facade.b1, p.facade.b1);
  f(s.facade.b2, p.facade.b2);
  f(s.floors.height, p.floors.height);
  f(s.floors.y0, p.floors.y0);
  f(s.floors.sy, p.floors.sy);
  f(s.curvilinear.enabled, p.curvilinear.enabled);
  f(s.curvilinear.sTheta, p.curvilinear.sTheta);
  f(s.curvilinear.cTheta, p.curvilinear.cTheta);
  f(s.curvilinear.sR, p.curvilinear.sR);
  f(s.curvilinear.cR, p.curvilinear.cR);
  f(s.curvilinear.z0, p.curvilinear.z0);
  f(s.trace.maxSteps, p.trace.maxSteps);
  f(s.trace.lipschitz, p.trace.lipschitz);
  f(s.trace.overRelax, p.trace.overRelax);
  f(s.trace.hitFactor, p.trace.hitFactor);
}

// Spec field → parameter field.
struct ToParams {
  template <class T>
  void operator()(const T& s, T& p) const {
    p = s;
  }
  void operator()(const Vec3& s, glm::dvec3& p) const { p = {s[0], s[1], s[2]}; }
  void operator()(const Vec3& s, Rotation& p) const { p = {s[0], s[1], s[2]}; }
  void operator()(const std::string& s, Footprint& p) const { p = footprintOf(s); }
};

// Parameter field → spec field.
struct ToSpec {
  template <class T>
  void operator()(T& s, const T& p) const {
    s = p;
  }
  void operator()(Vec3& s, const glm::dvec3& p) const { s = Vec3(p.x, p.y, p.z); }
  void operator()(Vec3& s, const Rotation& p) const { s = Vec3(p.xDeg, p.yDeg, p.zDeg); }
  void operator()(std::string& s, const Footprint& p) const { s = footprintName(p); }
};

}  // namespace

KifsParams paramsOf(const KifsSpec& spec) {
  KifsParams p;
  eachField(spec, p, ToParams{});
  validate(p);
  return p;
}

KifsSpec specOf(const KifsParams& params, std::string preset) {
  KifsSpec s;
  s.preset = std::move(preset);
  eachField(s, params, ToSpec{});
  return s;
}

namespace {

// What a meshed follower reads: the objects its kifs.mass.object chain names, as far as the
// chain goes (so the build finds the mass, or the same error followedObject gives on the whole
// Document), then what the mass's own builder reads.
std::vector<DocObject> followerInputs(const SceneSync& sync, const Document& doc, const DocObject& o) {
  const KifsSpec* spec = followingSpec(o);
  if (!spec || spec->meshResolution <= 0) return {};
  std::vector<DocObject> out;
  std::set<ObjectId> seen{o.id};
  for (const KifsSpec* s = spec; s && !s->mass.object.empty();) {
    const DocObject* next = doc.findByName(s->mass.object);
    if (!next || !seen.insert(next->id).second) break;
    out.push_back(*next);
    s = followingSpec(*next);
  }
  if (out.size() == 1)
    for (DocObject& more : sync.inputsOf(doc, out.front()))
      if (more.id != o.id) out.push_back(std::move(more));
  return out;
}

}  // namespace

void registerKernel(SceneSync& sync) {
  const SceneSync* self = &sync;
  auto inputs = [self](const Document& doc, const DocObject& o) { return followerInputs(*self, doc, o); };
  sync.setBuilder<KifsSpec>(inputs, [self](const DocObject& o, const std::vector<DocObject>& read, Progress* progress) {
    const auto& spec = std::get<KifsSpec>(o.spec);
    const KifsParams params = paramsOf(spec);
    BuildResult b;
    b.kind = Kind::Ornament;
    if (spec.meshResolution <= 0) return b;
    if (params.mass.footprint == Footprint::Object) {
      // The mass object is built here from its spec, as the Scene holds it (world space), and
      // baked as the view bakes it; the mesh stands where the mass does.
      if (!spec.mass.building.empty())
        throw Error("kifs.meshResolution: a building that follows one building of a town is ray-marched only (0); "
                    "exports mesh it");
      Document chain;
      chain.objects.push_back(o);
      chain.objects.insert(chain.objects.end(), read.begin(), read.end());
      const DocObject& mass = followedObject(chain, chain.objects.front());
      MeshData shell;
      try {
        shell = self->buildPlaced(mass, self->inputsOf(chain, mass), progress);
      } catch (const Cancelled&) {
        throw;
      } catch (const std::exception& e) {
        throw Error("kifs.mass.object: \"" + mass.name + "\" does not build: " + e.what());
      }
      const Building building(params, bakeFollowedMass(mass, trianglesOf(shell), params, progress));
      b.mesh = meshBuilding(building, spec.meshResolution, progress);
      b.worldSpace = true;
    } else {
      b.mesh = meshBuilding(Building(params), spec.meshResolution, progress);
    }
    const int material = b.mesh.addMaterial(spec.material);
    for (int& m : b.mesh.faceMaterial) m = material;
    return b;
  });
}

}  // namespace corbel::kifs
