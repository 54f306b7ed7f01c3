#pragma once
// One push/pull drag in the 3D view (the Push/Pull tool, P), as a state machine without GL or
// ImGui: it starts on a face picked by extrude/push_pull.h and turns the pointer's ray (in the
// extrusion's own frame) into that face's edit. A wall follows the pointer along the plan
// edge's outward normal, a roof's pitch follows the pointer round the segment's lower end (in
// the vertical plane across the edge), a step or a feature follows it along its wall. Digits
// typed meanwhile give the exact value (metres out; the new pitch in degrees; metres along the
// wall); Ctrl snaps (0.1 m, 5°); with own copy (Alt) a roof's edge gets a profile of its own
// first. The App commits what spec() gives (one undo step per drag). On a unit object's side
// (beginUnit) the pointer reads metres out along the side's normal and document() pushes the
// wall with collide-and-extrude (editor/unit_edits.h).
#include "core/document.h"
#include "editor/typed_value.h"
#include "editor/unit_edits.h"
#include "editor/viewport.h"
#include "extrude/push_pull.h"

#include <optional>
#include <string>

namespace corbel::editor {

inline constexpr double kPushSnap = 0.1;   // m
inline constexpr double kPitchSnap = 5.0;  // degrees

class PushPull {
 public:
  // Starts on `target` of `spec` with the pointer's ray (the extrusion's frame).
  void begin(const ExtrusionSpec& spec, const extrude::pushpull::Target& target, const Ray& ray);
  // Starts on side `face` of unit object `unit` in `doc` (the ray in the unit's frame).
  void beginUnit(const Document& doc, ObjectId unit, const UnitFace& face, const Ray& ray);
  bool unitMode() const { return unit_ != 0; }
  ObjectId unitObject() const { return unit_; }
  const Document& startDocument() const { return startDoc_; }
  // Unit mode: the document with the push made; throws InputError when it cannot be.
  Document document() const;
  bool active() const { return active_; }
  void end() { active_ = false; }
  const extrude::pushpull::Target& target() const { return target_; }
  const ExtrusionSpec& startSpec() const { return start_; }

  void pointer(const Ray& ray) { ray_ = ray; }
  void setSnap(bool snap) { snap_ = snap; }
  void setOwnCopy(bool own) { ownCopy_ = own; }
  // A typed character of the value ('0'-'9', '.', '-'); false if it is none of those.
  bool type(char c) { return typed_.type(c); }
  void backspace() { typed_.backspace(); }
  const std::string& typed() const { return typed_.text(); }

  // The value now: the typed one when there is one, else the pointer's (clamped, snapped).
  double value() const;
  // The spec with the edit made; throws InputError for a typed value it refuses.
  ExtrusionSpec spec() const;
  // The undo label ("Push wall", "Turn roof", "Slide dormer") and a status line.
  std::string label() const;
  std::string describe() const;
  // Where the drag moves things: a point and a unit direction (for the guide line).
  Vec3 guideFrom() const { return target_.hit; }
  Vec3 guideDirection() const;
  // The roof's turning line (its lower end) when the target is a roof.
  Vec3 pivot() const { return pivot_; }

 private:
  double pointerValue(const Ray& ray) const;
  std::optional<double> rawPitch(const Ray& ray) const;
  bool active_ = false;
  ExtrusionSpec start_;
  extrude::pushpull::Target target_;
  Ray startRay_, ray_;
  bool snap_ = false, ownCopy_ = false;
  TypedValue typed_;
  // Wall and slide: the line the pointer is read on. Roof: the profile plane's axes (inward
  // horizontal, up) and the turning line's point, and the segment's pitch at the start.
  Vec3 along_{1, 0, 0}, inward_{0, 1, 0}, pivot_{0, 0, 0};
  double startPitch_ = 0, startPointerPitch_ = 0;
  ObjectId unit_ = 0;  // unit mode: the unit object, its side, and the document at the start
  UnitFace face_;
  Document startDoc_;
};

}  // namespace corbel::editor
