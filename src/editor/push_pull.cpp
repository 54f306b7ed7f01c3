#include "editor/push_pull.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>

namespace corbel::editor {

namespace pp = extrude::pushpull;

namespace {
constexpr double kDegrees = 180.0 / std::numbers::pi;

Vec3 flat(const Vec2& v) { return Vec3(v[0], v[1], 0); }

// The parameter s of the point of the line p + s·u (u a unit vector) nearest the ray; nullopt
// when they are (nearly) parallel.
std::optional<double> lineParameter(const Vec3& p, const Vec3& u, const Ray& r) {
  const Vec3 d = r.direction.normalized(), w = p - r.origin;
  const double b = OpenMesh::dot(u, d), den = 1 - b * b;
  if (den < 1e-6) return std::nullopt;
  return (b * OpenMesh::dot(d, w) - OpenMesh::dot(u, w)) / den;
}

const Anchor* anchorOf(const ExtrusionSpec& s, const pp::Target& t) {
  if (t.kind == pp::Kind::Step && t.step >= 0 && t.step < int(s.steps.size())) return &s.steps[t.step].anchor;
  if (t.kind == pp::Kind::Feature && t.feature >= 0 && t.feature < int(s.anchors.size())) return &s.anchors[t.feature].anchor;
  return nullptr;
}
}  // namespace

void PushPull::beginUnit(const Document& doc, ObjectId unit, const UnitFace& face, const Ray& ray) {
  begin(ExtrusionSpec{}, pp::Target{}, ray);
  active_ = true;
  unit_ = unit;
  face_ = face;
  startDoc_ = doc;
  target_.hit = face.hit;
  target_.outline = face.outline;
  along_ = Vec3(0, 0, 0);
  along_[growth::sideAxis(face.side)] = growth::sideSign(face.side);
}

Document PushPull::document() const {
  if (!unit_) return startDoc_;
  const double v = value();
  if (std::abs(v) < 1e-9) return startDoc_;
  return pushUnitFace(startDoc_, unit_, face_.part, face_.side, v);
}

void PushPull::begin(const ExtrusionSpec& spec, const pp::Target& target, const Ray& ray) {
  unit_ = 0;
  startDoc_ = {};
  active_ = target.kind != pp::Kind::None;
  start_ = spec;
  target_ = target;
  startRay_ = ray_ = ray;
  typed_.clear();
  ownCopy_ = snap_ = false;
  if (!active_) return;
  if (target.kind == pp::Kind::Wall || target.kind == pp::Kind::Roof) {
    const Vec2 n = pp::edgeNormal(spec, target.loop, target.edge);
    along_ = target.kind == pp::Kind::Wall ? flat(n) : Vec3(-n[1], n[0], 0);
    inward_ = -flat(n);
  } else if (const Anchor* a = anchorOf(spec, target)) {
    along_ = flat(anchorDirection(spec, *a).value_or(Vec2(1, 0)));
  }
  if (target.kind == pp::Kind::Roof) {
    // The segment's lower end: in the profile plane (w inward from the hit point, z up) the
    // face's corners all lie on or above it along the segment's direction.
    startPitch_ = pp::segmentPitch(spec.profiles[target.profile], target.segment);
    const Vec2 d(std::cos(startPitch_ / kDegrees), std::sin(startPitch_ / kDegrees));
    double lowest = std::numeric_limits<double>::infinity();
    for (const Vec3& c : target.outline)
      lowest = std::min(lowest, OpenMesh::dot(Vec2(OpenMesh::dot(c - target.hit, inward_), c[2]), d));
    const Vec2 hit(0, target.hit[2]);
    const Vec2 low = target.outline.empty() ? hit : hit - d * (OpenMesh::dot(hit, d) - lowest);
    pivot_ = target.hit + inward_ * low[0] + Vec3(0, 0, low[1] - target.hit[2]);
    startPointerPitch_ = rawPitch(ray).value_or(startPitch_);
  }
}

Vec3 PushPull::guideDirection() const { return target_.kind == pp::Kind::Roof ? inward_ : along_; }

// The pitch (degrees) of the line from the turning line to where the ray meets the profile
// plane; nullopt when the ray runs along the plane.
std::optional<double> PushPull::rawPitch(const Ray& r) const {
  const double den = OpenMesh::dot(along_, r.direction);
  if (std::abs(den) < 1e-9 * r.direction.norm()) return std::nullopt;
  const double t = OpenMesh::dot(along_, target_.hit - r.origin) / den;
  const Vec3 q = r.origin + t * r.direction;
  return std::atan2(q[2] - pivot_[2], OpenMesh::dot(q - pivot_, inward_)) * kDegrees;
}

// The pointer's value before snapping: metres along the line, or the segment's pitch turned
// as far as the pointer has turned round the segment's lower end.
double PushPull::pointerValue(const Ray& r) const {
  if (!unit_ && target_.kind == pp::Kind::Roof) {
    const auto pitch = rawPitch(r);
    if (!pitch) return startPitch_;
    double turn = *pitch - startPointerPitch_;
    while (turn > 180) turn -= 360;
    while (turn < -180) turn += 360;
    return startPitch_ + turn;
  }
  const auto a = lineParameter(target_.hit, along_, startRay_), b = lineParameter(target_.hit, along_, r);
  return a && b ? *b - *a : 0.0;
}

double PushPull::value() const {
  if (const std::optional<double> typed = typed_.value()) return *typed;
  double v = pointerValue(ray_);
  if (!unit_ && target_.kind == pp::Kind::Roof) {
    if (snap_) v = std::round(v / kPitchSnap) * kPitchSnap;
    const Profile& p = start_.profiles[target_.profile];
    auto [lo, hi] = pp::pitchRange(p, target_.segment);
    if (hi <= 90) lo = 1;  // the last segment must lean in
    return std::clamp(v, lo, hi);
  }
  return snap_ ? std::round(v / kPushSnap) * kPushSnap : v;
}

ExtrusionSpec PushPull::spec() const {
  const double v = value();
  switch (target_.kind) {
    case pp::Kind::Wall: return pp::pushEdge(start_, target_.loop, target_.edge, v);
    case pp::Kind::Roof: {
      int profile = target_.profile;
      const PlanLoop& l = start_.loops[target_.loop];
      if (ownCopy_ && pp::profileUsers(start_, profile) > 1 && l.profile.at(target_.edge) == profile) {
        ExtrusionSpec s = pp::ownProfile(start_, target_.loop, target_.edge, &profile);
        return pp::turnSegment(std::move(s), profile, target_.segment, v);
      }
      return pp::turnSegment(start_, profile, target_.segment, v);
    }
    case pp::Kind::Step: return pp::slideStep(start_, target_.step, v);
    case pp::Kind::Feature: return pp::slideFeature(start_, target_.feature, v);
    case pp::Kind::None: break;
  }
  return start_;
}

std::string PushPull::label() const {
  if (unit_)
    return face_.side == growth::Side::Top ? "Move unit ceiling" : face_.side == growth::Side::Bottom ? "Move unit floor" : "Push unit wall";
  switch (target_.kind) {
    case pp::Kind::Wall: return "Push wall";
    case pp::Kind::Roof: return "Turn roof";
    case pp::Kind::Step: return "Slide " + start_.steps[target_.step].name;
    case pp::Kind::Feature: return "Slide " + start_.anchors[target_.feature].name;
    case pp::Kind::None: break;
  }
  return {};
}

std::string PushPull::describe() const {
  char buf[320];
  const double v = value();
  const std::string typed = typed_.text().empty() ? "" : " (typed " + typed_.text() + ")";
  if (unit_) {
    std::snprintf(buf, sizeof buf, "%s (part %d, side %s): %.3f m out%s", label().c_str(), face_.part,
                  std::string(growth::sideName(face_.side)).c_str(), v, typed.c_str());
    if (growth::sideAxis(face_.side) == 2)
      return std::string(buf) + "  — moves by whole storeys (a room of one or two); type a value, Enter or click confirms, Esc cancels";
    return std::string(buf) + "  — collides and extrudes past what it meets; type a value, Enter or click confirms, Esc cancels";
  }
  switch (target_.kind) {
    case pp::Kind::Wall:
      std::snprintf(buf, sizeof buf, "Push wall (loop %d, edge %d): %.3f m out%s", target_.loop, target_.edge, v,
                    typed.c_str());
      break;
    case pp::Kind::Roof: {
      const int users = pp::profileUsers(start_, target_.profile);
      const std::string& name = start_.profiles[target_.profile].name;
      const bool alone = ownCopy_ && users > 1;
      std::snprintf(buf, sizeof buf, "Turn roof (profile \"%s\" segment %d, %s): pitch %.2f°%s%s", name.c_str(),
                    target_.segment,
                    alone ? "this edge alone" : (std::to_string(users) + (users == 1 ? " edge" : " edges")).c_str(), v,
                    typed.c_str(), users > 1 && !alone ? "  — Alt: this edge alone" : "");
      break;
    }
    case pp::Kind::Step:
    case pp::Kind::Feature:
      std::snprintf(buf, sizeof buf, "%s along its wall: %.3f m%s", label().c_str(), v, typed.c_str());
      break;
    case pp::Kind::None: return {};
  }
  return std::string(buf) + "  — type a value, Ctrl snaps, Enter or click confirms, Esc cancels";
}

}  // namespace corbel::editor
