// The studio's selection and placement in the 3D view: hover, box select, frame selected, the
// transform gizmo and Blender's G and R (editor/transform.h), duplicate, copy and paste between
// projects (editor/clipboard.h), hide and lock. Its actions are registered here, apart from
// app_actions.cpp, so the menus and F1 list them like any other.
#include "editor/app.h"

#include "core/error.h"
#include "editor/box_select.h"
#include "editor/clipboard.h"
#include "editor/fields.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>
#include <filesystem>

namespace corbel::editor {

namespace {
constexpr render::Rgba kSelectedColour{1.0f, 0.6f, 0.1f, 1.0f};
constexpr render::Rgba kHoverColour{0.85f, 0.9f, 1.0f, 0.9f};
constexpr render::Rgba kAxisColour[3] = {{0.95f, 0.25f, 0.25f, 1}, {0.3f, 0.85f, 0.3f, 1}, {0.3f, 0.5f, 1.0f, 1}};
constexpr render::Rgba kRingColour{1.0f, 0.85f, 0.2f, 1.0f};
constexpr float kHandlePixels = 8.0f;  // how near the pointer must be to a gizmo handle

void boxLines(render::Overlay& o, const BBox& b, const render::Rgba& c) {
  auto corner = [&](int i) { return Vec3(i & 1 ? b.hi[0] : b.lo[0], i & 2 ? b.hi[1] : b.lo[1], i & 4 ? b.hi[2] : b.lo[2]); };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) o.line(corner(i), corner(i | bit), c);
}

float segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = OpenMesh::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(OpenMesh::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return float((a + t * ab - p).norm());
}
}  // namespace

bool App::pickable(ObjectId id) const {
  const DocObject* o = history_.current().find(id);
  return o && !o->locked && (!settings_.visible || settings_.visible(id));
}

BBox App::objectBounds(ObjectId id) const {
  BBox box = scene_.bounds(id);
  if (box.empty()) {
    // A ray-marched KIFS building has no faces: its placed bounds.
    const DocObject* o = history_.current().find(id);
    if (o && std::holds_alternative<KifsSpec>(o->spec)) {
      Document one;
      one.objects.push_back(*o);
      box = render::raymarchedKifs(one, nullptr).bounds;
    }
  }
  return box;
}

std::vector<ObjectId> App::movableSelection() const {
  std::vector<ObjectId> out;
  for (ObjectId id : selection_.ids())
    if (const DocObject* o = history_.current().find(id); o && !o->locked) out.push_back(id);
  return out;
}

float App::gizmoLength() const { return float(0.15 * view_.camera.distance); }

Vec3 App::selectionPivot() const {
  BBox box;
  for (ObjectId id : movableSelection()) box.add(objectBounds(id));
  if (box.empty()) return Vec3(0, 0, 0);
  return Vec3(box.center()[0], box.center()[1], box.lo[2]);
}

void App::beginTransform(Transform::Mode mode, bool dragged) {
  std::map<ObjectId, Placement> start;
  for (ObjectId id : movableSelection()) start[id] = history_.current().find(id)->placement;
  if (start.empty()) return;
  const Ray r = view_.ray(tool_.pointerX(), tool_.pointerY());
  transform_.begin(mode, start, selectionPivot(), r);
  if (mode == Transform::Mode::Move) {
    // The faces a move snaps onto: every other object's, placed where they stand now; the reach
    // is a few pixels at the pivot's depth, so it feels the same at every zoom.
    std::vector<ObjectId> moving, others;
    for (const auto& [id, p] : start) moving.push_back(id);
    for (const auto& [id, info] : scene_.objects())
      if (!start.count(id)) others.push_back(id);
    const Vec3 pivot = transform_.pivot();
    const Ray a = view_.ray(tool_.pointerX(), tool_.pointerY()), b = view_.ray(tool_.pointerX() + kFaceSnapPixels, tool_.pointerY());
    const double depth = (pivot - a.origin).norm();
    const double reach = ((a.origin + depth * a.direction) - (b.origin + depth * b.direction)).norm();
    transform_.setFaceSnap(axisFaces(scene_, moving), std::make_shared<FaceSnapTargets>(axisFaces(scene_, others)), reach);
  }
  transformDragged_ = dragged;
  transformCommitted_ = false;
  history_.closeMerge();
}

void App::previewTransform() {
  const auto placements = transform_.placements();
  Document d = history_.current();
  bool changed = false;
  for (const auto& [id, p] : placements)
    if (DocObject* o = d.find(id); o && !(o->placement == p)) {
      o->placement = p;
      changed = true;
    }
  if (!changed) return;
  const std::string what = placements.size() == 1 ? d.find(placements.begin()->first)->name
                                                   : std::to_string(placements.size()) + " objects";
  commit(std::move(d), (transform_.mode() == Transform::Mode::Move ? "Move " : "Rotate ") + what, "transform");
  transformCommitted_ = true;
}

void App::endTransform(bool confirm) {
  if (confirm) {
    previewTransform();
    if (transformCommitted_) log(history_.undoLabel() + ": " + transform_.describe().substr(0, transform_.describe().find("  —")));
  } else if (transformCommitted_) {
    history_.undo();
  }
  history_.closeMerge();
  transform_.end();
  transformDragged_ = false;
}

// Keys, characters and buttons while a transform runs: they belong to it, not to the tool.
void App::transformInput() {
  for (const InputEvent& e : batch_.events) {
    if (!transform_.active()) break;
    using T = InputEvent::Type;
    if (e.type == T::Move) transform_.pointer(view_.ray(float(e.x), float(e.y)));
    if (e.type == T::Char && e.codepoint < 128) transform_.type(char(e.codepoint));
    if (e.type == T::Key && e.down) {
      if (e.code == GLFW_KEY_X) transform_.setAxis(Transform::Axis::X);
      if (e.code == GLFW_KEY_Y) transform_.setAxis(Transform::Axis::Y);
      if (e.code == GLFW_KEY_Z) transform_.setAxis(Transform::Axis::Z);
      if (e.code == GLFW_KEY_BACKSPACE) transform_.backspace();
      if (e.code == GLFW_KEY_ENTER || e.code == GLFW_KEY_KP_ENTER) endTransform(true);
      if (e.code == GLFW_KEY_ESCAPE) endTransform(false);
    }
    if (e.type == T::Button) {
      if (!transformDragged_ && e.down && e.code == 0) endTransform(true);
      else if (e.down && e.code == 1) endTransform(false);
      else if (transformDragged_ && !e.down && e.code == 0) endTransform(true);
    }
  }
  if (!transform_.active()) return;
  transform_.setSnap(ImGui::GetIO().KeyCtrl);
  transform_.setFaceSnapOn(!ImGui::GetIO().KeyAlt);
  previewTransform();
  ImGui::SetTooltip("%s", transform_.describe().c_str());
}

// A press on a gizmo handle: an axis arrow moves along it, the square between x and y moves in
// the ground plane, the ring turns about z.
bool App::grabGizmo(float px, float py) {
  if (movableSelection().empty() || transform_.active() || pushPullTool_) return false;
  const Vec3 pivot = selectionPivot();
  const double len = gizmoLength();
  const auto c = projectToWindow(view_, pivot);
  if (!c) return false;
  const Vec2 p(px, py);
  const Vec3 axes[3] = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  // The plane squares (from 0.25 to 0.45 of the arrows): on the ground, then upright across y
  // (x and z) and across x (y and z); a press near a square's diagonal takes it.
  const std::pair<Vec3, Transform::Axis> squares[3] = {
      {Vec3(1, 1, 0), Transform::Axis::Free}, {Vec3(1, 0, 1), Transform::Axis::XZ}, {Vec3(0, 1, 1), Transform::Axis::YZ}};
  for (const auto& [span, axis] : squares) {
    const auto a = projectToWindow(view_, pivot + span * (0.25 * len)), b = projectToWindow(view_, pivot + span * (0.45 * len));
    // A square seen (nearly) edge-on lies along an arrow (the upright ones in the top view): it
    // leaves the press to the arrow.
    Vec3 u(0, 0, 0), v(0, 0, 0);
    for (int k = 0, first = 1; k < 3; ++k)
      if (span[k] != 0) (first ? u : v)[k] = 0.2 * len, first = 0;
    const auto o = projectToWindow(view_, pivot + span * (0.25 * len));
    const auto ou = projectToWindow(view_, pivot + span * (0.25 * len) + u), ov = projectToWindow(view_, pivot + span * (0.25 * len) + v);
    if (!o || !ou || !ov) continue;
    const Vec2 su = *ou - *o, sv = *ov - *o;
    const double area = std::abs(su[0] * sv[1] - su[1] * sv[0]);
    if (area < 0.25 * su.norm() * sv.norm()) continue;
    if (a && b && segmentDistance(p, *a, *b) < kHandlePixels && ((*b) - *a).norm() > 4) {
      beginTransform(Transform::Mode::Move, true);
      if (axis != Transform::Axis::Free) transform_.setAxis(axis);
      return true;
    }
  }
  for (int k = 0; k < 3; ++k) {
    const auto tip = projectToWindow(view_, pivot + axes[k] * len);
    if (tip && segmentDistance(p, *c, *tip) < kHandlePixels && ((*tip) - *c).norm() > 4) {
      beginTransform(Transform::Mode::Move, true);
      transform_.setAxis(k == 0 ? Transform::Axis::X : k == 1 ? Transform::Axis::Y : Transform::Axis::Z);
      return true;
    }
  }
  constexpr int kRing = 48;
  for (int i = 0; i < kRing; ++i) {
    const double a0 = 2 * M_PI * i / kRing, a1 = 2 * M_PI * (i + 1) / kRing;
    const auto s = projectToWindow(view_, pivot + Vec3(std::cos(a0), std::sin(a0), 0) * 1.2 * len),
               t = projectToWindow(view_, pivot + Vec3(std::cos(a1), std::sin(a1), 0) * 1.2 * len);
    if (s && t && segmentDistance(p, *s, *t) < kHandlePixels) {
      beginTransform(Transform::Mode::Rotate, true);
      return true;
    }
  }
  return false;
}

void App::updateHover(bool overUi) {
  if (tool_.busy() || transform_.active() || overUi || !tool_.havePointer() ||
      !view_.contains(tool_.pointerX(), tool_.pointerY())) {
    selection_.hover.reset();
    hoverKey_ = {};
    pushPullHover_ = {};
    tape_.hover(std::nullopt);
    return;
  }
  // Picked again only when the pointer, the Scene or the camera changed.
  const std::array<double, 8> key{tool_.pointerX(), tool_.pointerY(), double(scene_.revision()), view_.camera.azimuth_deg,
                                  view_.camera.elevation_deg, view_.camera.distance, view_.camera.target[0],
                                  view_.camera.target[1] + 1e3 * double(history_.stateId())};
  if (key == hoverKey_) return;
  hoverKey_ = key;
  selection_.hover = objectUnder(view_.ray(tool_.pointerX(), tool_.pointerY()));
  updatePushPullHover();
  updateTapeHover();
}

void App::boxSelect(float x0, float y0, float x1, float y1) {
  std::vector<std::pair<ObjectId, BBox>> marched;
  for (const DocObject& o : history_.current().objects)
    if (const auto* k = std::get_if<KifsSpec>(&o.spec); k && k->meshResolution == 0) marched.emplace_back(o.id, objectBounds(o.id));
  const std::vector<ObjectId> inside = objectsInBox(scene_, view_, Vec2(x0, y0), Vec2(x1, y1),
                                                    [this](ObjectId id) { return pickable(id); }, marched);
  if (!ImGui::GetIO().KeyShift) selection_.clear();
  for (ObjectId id : inside) selection_.add(id);
  log("Box select: " + std::to_string(inside.size()) + " object" + (inside.size() == 1 ? "" : "s"));
}

void App::drawStudioOverlay() {
  render::Overlay& top = renderer_->overlayOnTop();
  // While a face is pushed or pulled its outline and guide line say what moves: no box.
  for (ObjectId id : selection_.ids())
    if (const BBox b = objectBounds(id); !b.empty() && !pushPull_.active()) boxLines(top, b, kSelectedColour);
  if (selection_.hover && !selection_.contains(*selection_.hover))
    if (const BBox b = objectBounds(*selection_.hover); !b.empty()) boxLines(top, b, kHoverColour);
  if (movableSelection().empty() || pushPullTool_) return;  // the Push/Pull tool drags faces, not objects
  const Vec3 pivot = transform_.active() ? transform_.pivot() : selectionPivot();
  const double len = gizmoLength();
  const bool rotating = transform_.mode() == Transform::Mode::Rotate;
  const Vec3 axes[3] = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  for (int k = 0; k < 3; ++k) {
    const bool chosen = transform_.active() && int(transform_.axis()) == k + 1;
    if (chosen) top.line(pivot - axes[k] * 1e4, pivot + axes[k] * 1e4, kAxisColour[k]);  // the constraint line
    if (!rotating) top.arrow(pivot, pivot + axes[k] * len, kAxisColour[k], 0.25);
  }
  if (!rotating) {
    // The squares: on the ground (yellow), upright across y (green: x and z) and across x
    // (red: y and z), each in the colour of the axis it keeps still.
    const std::pair<int, int> spans[3] = {{0, 1}, {0, 2}, {1, 2}};
    const render::Rgba colours[3] = {kRingColour, kAxisColour[1], kAxisColour[0]};
    for (int s = 0; s < 3; ++s) {
      auto corner = [&](double u, double v) {
        Vec3 c(0, 0, 0);
        c[spans[s].first] = u, c[spans[s].second] = v;
        return pivot + c * len;
      };
      top.line(corner(0.25, 0.25), corner(0.45, 0.25), colours[s]);
      top.line(corner(0.45, 0.25), corner(0.45, 0.45), colours[s]);
      top.line(corner(0.45, 0.45), corner(0.25, 0.45), colours[s]);
      top.line(corner(0.25, 0.45), corner(0.25, 0.25), colours[s]);
    }
  }
  constexpr int kRing = 48;
  for (int i = 0; i < kRing; ++i) {
    const double a0 = 2 * M_PI * i / kRing, a1 = 2 * M_PI * (i + 1) / kRing;
    top.line(pivot + Vec3(std::cos(a0), std::sin(a0), 0) * 1.2 * len, pivot + Vec3(std::cos(a1), std::sin(a1), 0) * 1.2 * len,
             kRingColour);
  }
}

// The rubber band of a box select, over the view.
void App::drawBoxBand() {
  if (!tool_.boxing()) return;
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const ImVec2 a(tool_.pressX(), tool_.pressY()), b(tool_.pointerX(), tool_.pointerY());
  dl->AddRectFilled(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                    IM_COL32(255, 160, 40, 40));
  dl->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
              IM_COL32(255, 160, 40, 220));
}

void App::frameSelected() {
  BBox box;
  for (ObjectId id : selection_.ids()) box.add(objectBounds(id));
  if (box.empty()) return frameAll();
  view_.frame(box);
}

void App::registerStudioActions() {
  auto add = [this](Action a) { actions_.add(std::move(a)); };
  auto anySelected = [this] { return !selection_.empty(); };
  auto anyMovable = [this] { return !movableSelection().empty() && !transform_.active(); };
  add({"view.frame_selected", "View", "Frame Selected", "Fit the selected objects in the view (all when none is).",
       {GLFW_KEY_F}, false, [this] { frameSelected(); }});
  add({"select.box", "Select", "Box Select",
       "The next left drag in the 3D view selects the objects inside its box (also Ctrl+left drag; Shift at release adds).",
       {GLFW_KEY_B}, false, [this] { tool_.armBox(); }});
  add({"select.all", "Select", "Select All", "Select every visible object that is not locked.", {GLFW_KEY_A, true}, false,
       [this] {
         selection_.clear();
         for (const DocObject& o : history_.current().objects)
           if (pickable(o.id)) selection_.add(o.id);
       }});
  add({"select.none", "Select", "Select None", "Clear the selection.", {GLFW_KEY_A, false, false, true}, false,
       [this] { selection_.clear(); }, anySelected});
  add({"object.move", "Object", "Move",
       "Move the selection with the pointer (Blender's G): X, Y or Z keeps to an axis, type a distance and Enter, Ctrl "
       "snaps to 0.5 m, a face near another object's face lies on it (Alt: freely); click or Enter confirms, Esc or "
       "right click cancels. One undo step.",
       {GLFW_KEY_G}, true, [this] { beginTransform(Transform::Mode::Move, false); }, anyMovable, {}, true});
  add({"object.rotate", "Object", "Rotate",
       "Turn the selection about z round its base centre (Blender's R): type degrees and Enter, Ctrl snaps to 15°. One "
       "undo step.",
       {GLFW_KEY_R}, true, [this] { beginTransform(Transform::Mode::Rotate, false); }, anyMovable});
  add({"object.copy", "Edit", "Copy Objects", "Copy the selected objects to the clipboard (as project JSON).",
       {GLFW_KEY_C, true}, false, [this] {
         const std::string folder =
             path_.empty() ? std::string() : std::filesystem::absolute(path_).parent_path().lexically_normal().string();
         glfwSetClipboardString(window_, objectsToClipboard(history_.current(), selection_.ids(), folder).c_str());
         log("Copied " + std::to_string(selection_.ids().size()) + " object(s)");
       }, anySelected, {}, true});
  add({"object.paste", "Edit", "Paste Objects",
       "Add the clipboard's objects where they were; their file paths are read against the project they came from.",
       {GLFW_KEY_V, true}, true, [this] {
         const char* text = glfwGetClipboardString(window_);
         Document d = history_.current();
         try {
           const std::vector<ObjectId> ids = pasteObjects(d, text ? text : "");
           commit(std::move(d), "Paste " + std::to_string(ids.size()) + " object(s)");
           selection_.clear();
           for (ObjectId id : ids) selection_.add(id);
           log("Pasted " + std::to_string(ids.size()) + " object(s)");
         } catch (const std::exception& e) {
           log(std::string("Paste: ") + e.what(), true);
         }
       }});
  add({"object.hide", "Object", "Hide Selected", "Hide the selected objects (Blender's H).", {GLFW_KEY_H}, true,
       [this] {
         Document d = history_.current();
         for (ObjectId id : selection_.ids()) d.find(id)->visible = false;
         commit(std::move(d), "Hide " + std::to_string(selection_.ids().size()) + " object(s)");
         selection_.clear();
       }, anySelected, {}, true});
  add({"object.show_all", "Object", "Show All", "Show every hidden object (Blender's Alt+H).",
       {GLFW_KEY_H, false, false, true}, true, [this] {
         Document d = history_.current();
         for (DocObject& o : d.objects) o.visible = true;
         commit(std::move(d), "Show all");
       }});
  add({"object.lock", "Object", "Lock / Unlock",
       "Lock the selected objects (a locked one cannot be picked in the 3D view or moved), or unlock them if all are locked.",
       {GLFW_KEY_L, false, true}, true, [this] {
         Document d = history_.current();
         bool allLocked = true;
         for (ObjectId id : selection_.ids()) allLocked = allLocked && d.find(id)->locked;
         for (ObjectId id : selection_.ids()) d.find(id)->locked = !allLocked;
         commit(std::move(d), std::string(allLocked ? "Unlock " : "Lock ") + std::to_string(selection_.ids().size()) +
                                  " object(s)");
       }, anySelected});
}

void App::duplicateSelected() {
  Document d = history_.current();
  BBox box;
  for (ObjectId id : selection_.ids()) box.add(objectBounds(id));
  const double shift = box.empty() ? 10.0 : box.size()[0] + 2.0;
  std::vector<ObjectId> copies;
  for (ObjectId id : selection_.ids()) {
    const DocObject o = *d.find(id);
    const ObjectId c = d.add(o.name, o.spec);
    DocObject& copy = *d.find(c);
    copy.background = o.background;
    copy.kept = o.kept;
    copy.placement = o.placement;
    copy.placement.translation[0] += shift;  // beside the originals, along x
    copies.push_back(c);
  }
  commit(std::move(d), "Duplicate " + std::to_string(copies.size()) + " object(s)");
  selection_.clear();
  for (ObjectId c : copies) selection_.add(c);
}

// Typed placement values for the active object, each one undo step.
void App::drawPlacementFields(const DocObject& object) {
  ImGui::Separator();
  ImGui::TextDisabled("Placement");
  Placement p = object.placement;
  bool changed = false;
  const float t[3] = {float(p.translation[0]), float(p.translation[1]), float(p.translation[2])};
  float nt[3];
  if (commitFloats("Move (m)", t, nt, 3, "%.3f")) {
    for (int k = 0; k < 3; ++k) p.translation[k] = nt[k];
    changed = true;
  }
  if (double r; commitDouble("Turn (°)", p.rotation_deg, r, "%.2f")) p.rotation_deg = r, changed = true;
  if (scalable(object.spec)) {
    if (double s; commitDouble("Scale", p.scale, s, "%.3f")) p.scale = s, changed = true;
  }
  bool locked = object.locked;
  const bool lockClicked = ImGui::Checkbox("Locked", &locked);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("A locked object cannot be picked in the 3D view or moved.");
  if (changed) {
    if (const auto problem = checkPlacement(p)) {
      log(object.name + ": placement." + *problem, true);
      return;
    }
  }
  if (!changed && !lockClicked) return;
  Document d = history_.current();
  DocObject* o = d.find(object.id);
  if (!o) return;
  o->placement = p;
  o->locked = locked;
  commit(std::move(d), (lockClicked ? (locked ? "Lock " : "Unlock ") : "Place ") + object.name);
}

}  // namespace corbel::editor
