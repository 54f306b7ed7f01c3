#include "kifs/params.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace corbel::kifs {

double escapeRadius(const KifsParams& p) { return std::max(2.0, glm::length(p.centre)); }

namespace {

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Checks one value; `what` says the allowed range in words.
void require(bool ok, const std::string& field, const std::string& what, double value) {
  if (!ok) throw Error("kifs." + field + ": must be " + what + ", got " + number(value));
}
void finite(const std::string& field, double v) { require(std::isfinite(v), field, "a finite number", v); }

}  // namespace

void validate(const KifsParams& p) {
  require(p.iterations >= 0 && p.iterations <= kMaxIterations, "iterations",
          "a whole number in 0.." + std::to_string(kMaxIterations), p.iterations);
  finite("scale", p.scale);
  require(p.scale > 1.0 && p.scale <= kMaxScale, "scale", "in (1, " + number(kMaxScale) + "]", p.scale);
  for (int i = 0; i < 3; ++i) finite("centre[" + std::to_string(i) + "]", p.centre[i]);
  for (const auto& [name, r] : {std::pair{"r1", p.r1}, std::pair{"r2", p.r2}}) {
    finite(std::string(name) + ".x", r.xDeg);
    finite(std::string(name) + ".y", r.yDeg);
    finite(std::string(name) + ".z", r.zDeg);
  }
  const double rho = escapeRadius(p);
  require(!std::isnan(p.bailout) && p.bailout >= rho * rho, "bailout",
          "at least ρ² = max(2, |centre|)² = " + number(rho * rho) + " (docs/kifs.md)", p.bailout);

  const MassModel& m = p.mass;
  if (m.footprint == Footprint::Object) {  // the mass object's shell; the half-sizes are unused
    require(m.resolution >= 1 && m.resolution <= kMaxMassResolution, "mass.resolution",
            "a whole number in 1.." + std::to_string(kMaxMassResolution), m.resolution);
    finite("mass.shell", m.shell);
    require(m.shell >= 0, "mass.shell", ">= 0", m.shell);
    require(!p.curvilinear.enabled, "curvilinear.enabled", "false for a building that follows a mass object", 1);
  } else {
    for (const auto& [name, v] : {std::pair{"mass.halfWidth", m.halfWidth}, std::pair{"mass.halfDepth", m.halfDepth},
                                  std::pair{"mass.height", m.height}}) {
      finite(name, v);
      require(v > 0, name, "> 0", v);
    }
    finite("mass.shell", m.shell);
    require(m.shell >= 0 && m.shell < std::min({m.halfWidth, m.halfDepth, m.height}), "mass.shell",
            "in [0, the smallest half-size or height)", m.shell);
    if (m.footprint != Footprint::Box) {
      finite("mass.wing", m.wing);
      require(m.wing > m.shell && m.wing < std::min(m.halfWidth, m.halfDepth), "mass.wing",
              "between mass.shell and the smaller half-size", m.wing);
    }
  }

  const Facade& f = p.facade;
  finite("facade.period", f.period);
  require(f.period > 0, "facade.period", "> 0", f.period);
  for (int i = 0; i < 3; ++i) finite("facade.r[" + std::to_string(i) + "]", f.r[i]);
  for (const auto& [name, v] : {std::pair{"facade.a1", f.a1}, std::pair{"facade.a2", f.a2},
                                std::pair{"facade.b1", f.b1}, std::pair{"facade.b2", f.b2}})
    finite(name, v);

  const Floors& fl = p.floors;
  finite("floors.height", fl.height);
  require(fl.height > 0, "floors.height", "> 0", fl.height);
  finite("floors.y0", fl.y0);
  finite("floors.sy", fl.sy);
  require(fl.sy > 0, "floors.sy", "> 0", fl.sy);

  const Curvilinear& c = p.curvilinear;
  if (c.enabled) {
    finite("curvilinear.sTheta", c.sTheta);
    require(c.sTheta > 0, "curvilinear.sTheta", "> 0", c.sTheta);
    finite("curvilinear.cTheta", c.cTheta);
    finite("curvilinear.sR", c.sR);
    require(c.sR > 0, "curvilinear.sR", "> 0", c.sR);
    finite("curvilinear.cR", c.cR);
    finite("curvilinear.z0", c.z0);
    const double outer = m.halfDepth / c.sR - c.cR;
    require(outer > 0, "curvilinear.cR", "such that the outer radius halfDepth/sR − cR is > 0", c.cR);
  }

  const Trace& t = p.trace;
  require(t.maxSteps >= 1 && t.maxSteps <= 100000, "trace.maxSteps", "in 1..100000", t.maxSteps);
  finite("trace.lipschitz", t.lipschitz);
  require(t.lipschitz > 0 && t.lipschitz <= 1, "trace.lipschitz", "in (0, 1]", t.lipschitz);
  finite("trace.overRelax", t.overRelax);
  require(t.overRelax >= 1 && t.overRelax < 2, "trace.overRelax", "in [1, 2)", t.overRelax);
  finite("trace.hitFactor", t.hitFactor);
  require(t.hitFactor > 0, "trace.hitFactor", "> 0", t.hitFactor);
  finite("trace.pixelAngle", t.pixelAngle);
  require(t.pixelAngle > 0, "trace.pixelAngle", "> 0", t.pixelAngle);
}

}  // namespace corbel::kifs
