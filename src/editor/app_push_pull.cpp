// The Push/Pull tool of the 3D view (P): a press on a face of an extrusion drags what the face
// comes from (editor/push_pull.h, extrude/push_pull.h) — a wall's plan edge, a roof's profile
// segment, a step's or a feature's anchor — live, as one undo step. A click without a drag
// leaves the face following the pointer until the next click or Enter; digits typed meanwhile
// give the exact value.
#include "editor/app.h"

#include "extrude/extrude.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>

namespace corbel::editor {

namespace {
constexpr render::Rgba kFaceColour{1.0f, 0.85f, 0.2f, 1.0f};
constexpr render::Rgba kGuideColour{1.0f, 0.55f, 0.1f, 1.0f};
constexpr render::Rgba kHoverFaceColour{0.85f, 0.9f, 1.0f, 0.9f};

Ray intoFrame(const Placement& p, const Ray& world) {
  return Ray{p.unapply(world.origin), p.unapplyDirection(world.direction)};
}
}  // namespace

void App::togglePushPullTool() {
  pushPullTool_ = !pushPullTool_;
  if (pushPullTool_ && tapeTool_) toggleTapeTool();
  if (!pushPullTool_ && pushPull_.active()) endPushPull(false);
  pushPullHover_ = {};
  hoverKey_ = {};  // the face under the pointer is looked for again
  log(pushPullTool_ ? "Push/Pull: drag a face of a building (P again, or the toolbar, to leave)" : "Push/Pull off");
}

// The face of an extrusion or a unit under the pointer, its object, and the ray in that object's frame.
std::optional<App::PushPullPick> App::pushPullPick(const Ray& world) {
  const std::optional<ObjectId> id = objectUnder(world);
  const DocObject* o = id ? history_.current().find(*id) : nullptr;
  if (const auto* unit = o ? std::get_if<UnitSpec>(&o->spec) : nullptr) {
    PushPullPick p;
    p.object = o->id;
    p.ray = intoFrame(o->placement, world);
    p.unit = pickUnitFace(*unit, p.ray.origin, p.ray.direction);
    if (!p.unit) return std::nullopt;
    p.target.hit = p.unit->hit;
    p.target.outline = p.unit->outline;
    return p;
  }
  const auto* spec = o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr;
  if (!spec) return std::nullopt;
  if (pushPullBuilt_.object != o->id || pushPullBuilt_.state != history_.stateId()) {
    pushPullBuilt_ = {};
    try {
      pushPullBuilt_.result = extrude::extrude(*spec);
    } catch (const std::exception&) {
      return std::nullopt;  // a spec the kernel refuses has nothing to drag
    }
    pushPullBuilt_.object = o->id;
    pushPullBuilt_.state = history_.stateId();
  }
  PushPullPick p;
  p.object = o->id;
  p.ray = intoFrame(o->placement, world);
  p.target = extrude::pushpull::pick(*spec, pushPullBuilt_.result, p.ray.origin, p.ray.direction);
  if (p.target.kind == extrude::pushpull::Kind::None) return std::nullopt;
  return p;
}

bool App::beginPushPull(const Ray& world) {
  if (!pushPullTool_ || pushPull_.active() || transform_.active()) return false;
  const auto p = pushPullPick(world);
  if (!p) return false;
  selection_.select(p->object);
  if (p->unit)
    pushPull_.beginUnit(history_.current(), p->object, *p->unit, p->ray);
  else
    pushPull_.begin(std::get<ExtrusionSpec>(history_.current().find(p->object)->spec), p->target, p->ray);
  pushPullObject_ = p->object;
  pushPullPlacement_ = history_.current().find(p->object)->placement;
  pushPullDragged_ = true;
  pushPullCommitted_ = false;
  pushPullError_.clear();
  history_.closeMerge();
  return true;
}

void App::previewPushPull() {
  if (pushPull_.unitMode()) {
    Document d;
    try {
      d = pushPull_.document();
      pushPullError_.clear();
    } catch (const std::exception& e) {
      pushPullError_ = e.what();
      d = pushPull_.startDocument();  // nothing moves while the push cannot be made
    }
    if (d == history_.current()) return;
    commit(std::move(d), pushPull_.label(), "push-pull");
    pushPullCommitted_ = true;
    return;
  }
  ExtrusionSpec s;
  try {
    s = pushPull_.spec();
    pushPullError_.clear();
  } catch (const std::exception& e) {
    pushPullError_ = e.what();
    return;
  }
  Document d = history_.current();
  DocObject* o = d.find(pushPullObject_);
  auto* now = o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr;
  if (!now || *now == s) return;
  *now = std::move(s);
  commit(std::move(d), pushPull_.label(), "push-pull");
  pushPullCommitted_ = true;
}

void App::endPushPull(bool confirm) {
  if (confirm) {
    previewPushPull();
    if (!pushPullError_.empty()) log(pushPull_.label() + ": " + pushPullError_, true);
    const DocObject* o = history_.current().find(pushPullObject_);
    const auto* s = o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr;
    const bool unchanged = pushPull_.unitMode() ? history_.current() == pushPull_.startDocument()
                                                : s && *s == pushPull_.startSpec();
    if (pushPullCommitted_ && unchanged) {
      history_.undo();  // back where it began: no step
    } else if (pushPullCommitted_) {
      const std::string d = pushPull_.describe();
      log(d.substr(0, d.find("  —")));
      // The panes follow: the dragged wall's or roof's edge and its profile (its own copy after Alt).
      const auto& t = pushPull_.target();
      if (s && panesFor_ == pushPullObject_ && (t.kind == extrude::pushpull::Kind::Wall || t.kind == extrude::pushpull::Kind::Roof))
        panes_.showEdge(*s, t.loop, t.edge, t.segment >= 0 ? std::optional<int>(t.segment) : std::nullopt);
    }
  } else if (pushPullCommitted_) {
    history_.undo();
  }
  history_.closeMerge();
  pushPull_.end();
  pushPullDragged_ = false;
  pushPullBuilt_ = {};
}

// Keys, characters and buttons while a push/pull runs: they belong to it.
void App::pushPullInput() {
  const Placement placement = pushPullPlacement_;
  for (const InputEvent& e : batch_.events) {
    if (!pushPull_.active()) break;
    using T = InputEvent::Type;
    if (e.type == T::Move) pushPull_.pointer(intoFrame(placement, view_.ray(float(e.x), float(e.y))));
    if (e.type == T::Char && e.codepoint < 128) pushPull_.type(char(e.codepoint));
    if (e.type == T::Key && e.down) {
      if (e.code == GLFW_KEY_BACKSPACE) pushPull_.backspace();
      if ((e.code == GLFW_KEY_LEFT_ALT || e.code == GLFW_KEY_RIGHT_ALT) && !pushPull_.unitMode()) pushPull_.setOwnCopy(true);
      if (e.code == GLFW_KEY_ENTER || e.code == GLFW_KEY_KP_ENTER) endPushPull(true);
      if (e.code == GLFW_KEY_ESCAPE) endPushPull(false);
    }
    if (e.type == T::Button) {
      if (!pushPullDragged_ && e.down && e.code == 0) {
        endPushPull(true);
      } else if (e.down && e.code == 1) {
        endPushPull(false);
      } else if (pushPullDragged_ && !e.down && e.code == 0) {
        // A click that did not drag, with nothing typed, leaves the face on the pointer.
        const bool still = std::hypot(tool_.pointerX() - tool_.pressX(), tool_.pointerY() - tool_.pressY()) <
                           NavigateTool::kClickSlop;
        if (still && pushPull_.typed().empty())
          pushPullDragged_ = false;
        else
          endPushPull(true);
      }
    }
  }
  if (!pushPull_.active()) return;
  const ImGuiIO& io = ImGui::GetIO();
  pushPull_.setSnap(io.KeyCtrl);
  // Alt held or pressed at any time during the drag gives a roof's edge its own profile (it
  // stays so: X11 sends no characters while Alt is held, so the value is typed after it).
  if (io.KeyAlt) pushPull_.setOwnCopy(true);
  previewPushPull();
  ImGui::SetTooltip("%s%s%s", pushPull_.describe().c_str(), pushPullError_.empty() ? "" : "\n",
                    pushPullError_.c_str());
}

void App::updatePushPullHover() {
  pushPullHover_ = {};
  if (!pushPullTool_ || pushPull_.active() || !tool_.havePointer() || tool_.busy() ||
      !view_.contains(tool_.pointerX(), tool_.pointerY()))
    return;
  if (const auto p = pushPullPick(view_.ray(tool_.pointerX(), tool_.pointerY()))) {
    pushPullHover_.object = p->object;
    pushPullHover_.outline = p->target.outline;
  }
}

// The face being dragged as it was (yellow) and the line it moves along (orange; a roof: its
// turning line); with the tool on and nothing dragged, the face under the pointer.
void App::drawPushPullOverlay() {
  render::Overlay& top = renderer_->overlayOnTop();
  const render::Overlay::Mark mark = top.mark();
  auto outline = [&](const std::vector<Vec3>& pts, const render::Rgba& c) {
    for (std::size_t i = 0; i < pts.size(); ++i) top.line(pts[i], pts[(i + 1) % pts.size()], c);
  };
  Placement placement;
  if (pushPull_.active()) {
    placement = pushPullPlacement_;
    const auto& t = pushPull_.target();
    outline(t.outline, kFaceColour);
    if (t.kind == extrude::pushpull::Kind::Roof) {
      const Vec3 axis = OpenMesh::cross(Vec3(0, 0, 1), pushPull_.guideDirection());
      top.line(pushPull_.pivot() - axis * 1e3, pushPull_.pivot() + axis * 1e3, kGuideColour);
    } else {
      top.line(t.hit - pushPull_.guideDirection() * 1e3, t.hit + pushPull_.guideDirection() * 1e3, kGuideColour);
    }
  } else if (pushPullTool_ && pushPullHover_.object) {
    const DocObject* o = history_.current().find(pushPullHover_.object);
    if (!o) return;
    placement = o->placement;
    outline(pushPullHover_.outline, kHoverFaceColour);
  } else {
    return;
  }
  top.placeSince(mark, placement);
}

void App::registerPushPullActions() {
  actions_.add({"tool.push_pull", "Object", "Push/Pull",
                "Drag a face of a building: a wall moves its plan edge, a roof turns its profile segment, a step or a "
                "feature slides along its wall; a housing unit's wall collides and extrudes past what it meets. Type a "
                "value and Enter (metres; a roof's pitch in degrees); Ctrl snaps; Alt gives a roof's edge its own "
                "profile. P again leaves the tool.",
                {GLFW_KEY_P}, false, [this] { togglePushPullTool(); }, nullptr, [this] { return pushPullTool_; }});
}

}  // namespace corbel::editor
