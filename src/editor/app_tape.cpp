// The tape measure of the 3D view (M, or the toolbar's Measure): a click sets the start, the
// next the end; the distance and its run along x, y and z show beside the tape and in the log.
// Points snap to corners, midpoints and edges of the face under the pointer (editor/tape_measure.h).
// Esc clears the tape; M again leaves the tool. A drag still orbits.
#include "editor/app.h"

#include "editor/box_select.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>

namespace corbel::editor {

namespace {
constexpr float kSnapPixels = 8.0f;  // how near a corner or an edge the pointer must come
constexpr render::Rgba kTapeColour{1.0f, 0.45f, 0.0f, 1.0f};  // orange: seen on walls and sky alike
constexpr render::Rgba kAxisColours[3] = {{0.95f, 0.3f, 0.3f, 1.0f}, {0.4f, 0.85f, 0.35f, 1.0f}, {0.35f, 0.55f, 1.0f, 1.0f}};
constexpr render::Rgba kSnapColours[5] = {
    {0.7f, 0.7f, 0.7f, 1.0f},   // ground
    {0.3f, 0.6f, 1.0f, 1.0f},   // face
    {0.9f, 0.2f, 0.2f, 1.0f},   // edge
    {0.3f, 0.9f, 0.9f, 1.0f},   // midpoint
    {0.3f, 0.95f, 0.3f, 1.0f},  // corner
};
}  // namespace

double App::worldPerPixel(const Vec3& p) const {
  const render::OrbitCamera& c = view_.camera;
  const double h = std::max(1.0f, view_.height());
  if (c.orthographic) return 2 * c.halfHeight() / h;
  const Vec3 eye = c.eye(), forward = (c.target - eye).normalized();
  const double depth = std::max(OpenMesh::dot(p - eye, forward), c.nearPlane());
  return 2 * depth * std::tan(c.fov_deg * M_PI / 360.0) / h;
}

void App::toggleTapeTool() {
  tapeTool_ = !tapeTool_;
  tape_.clear();
  tape_.hover(std::nullopt);
  if (tapeTool_ && pushPullTool_) togglePushPullTool();
  hoverKey_ = {};
  log(tapeTool_ ? "Measure: click two points (corners, midpoints and edges snap); Esc clears, M leaves"
                : "Measure off");
}

void App::updateTapeHover() {
  if (!tapeTool_ || !tool_.havePointer() || !view_.contains(tool_.pointerX(), tool_.pointerY())) {
    tape_.hover(std::nullopt);
    return;
  }
  tape_.hover(tapePoint(shownScene(), view_.ray(tool_.pointerX(), tool_.pointerY()),
                        [this](const Vec3& p) { return kSnapPixels * worldPerPixel(p); },
                        [this](ObjectId id) { return pickable(id); }));
}

void App::tapeClick(const Ray& world) {
  const auto p = tapePoint(shownScene(), world, [this](const Vec3& q) { return kSnapPixels * worldPerPixel(q); },
                           [this](ObjectId id) { return pickable(id); });
  if (!p) return;  // the sky: nothing to measure from
  tape_.click(*p);
  if (tape_.done()) log("Measure: " + tape_.describe());
}

void App::tapeInput() {
  if (!tapeTool_) return;
  for (const InputEvent& e : batch_.events)
    if (e.type == InputEvent::Type::Key && e.down && e.code == GLFW_KEY_ESCAPE && !ImGui::GetIO().WantTextInput) {
      if (tape_.start()) {
        tape_.clear();
        log("Measure: cleared");
      } else {
        toggleTapeTool();
      }
    }
}

// The tape's lines in the view (drawn with the scene, after the UI's frame has ended).
void App::drawTapeOverlay() {
  if (!tapeTool_) return;
  render::Overlay& top = renderer_->overlayOnTop();
  // The point under the pointer: a small cross in its snap's colour.
  if (const auto& h = tape_.hovered()) {
    const double r = 5 * worldPerPixel(h->at);
    const render::Rgba& c = kSnapColours[int(h->snap)];
    top.line(h->at - Vec3(r, 0, 0), h->at + Vec3(r, 0, 0), c);
    top.line(h->at - Vec3(0, r, 0), h->at + Vec3(0, r, 0), c);
    top.line(h->at - Vec3(0, 0, r), h->at + Vec3(0, 0, r), c);
  }
  if (!tape_.span()) return;
  const int axis = tape_.axis();
  top.line(tape_.start()->at, tape_.end()->at, axis >= 0 ? kAxisColours[axis] : kTapeColour);
}

// The tape's words, within the UI's frame: the reading at the tape's middle, and how the
// point under the pointer snaps.
void App::drawTapeLabels() {
  if (!tapeTool_) return;
  if (tape_.hovered() && !tape_.done() && view_.contains(tool_.pointerX(), tool_.pointerY()))
    ImGui::SetTooltip("%s", snapName(tape_.hovered()->snap));
  const auto span = tape_.span();
  if (!span) return;
  const auto mid = projectToWindow(view_, (tape_.start()->at + tape_.end()->at) * 0.5);
  if (!mid) return;
  const std::string text = tape_.describe();
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const ImVec2 at(float((*mid)[0]) + 8, float((*mid)[1]) - size.y - 4);
  dl->AddRectFilled(ImVec2(at.x - 4, at.y - 2), ImVec2(at.x + size.x + 4, at.y + size.y + 2), IM_COL32(20, 20, 24, 210), 3);
  dl->AddText(at, IM_COL32(240, 240, 240, 255), text.c_str());
}

void App::registerTapeActions() {
  actions_.add({"tool.measure", "Object", "Measure",
                "Tape measure: click a point, then another, to read the distance and its run along x, y and z. Points "
                "snap to corners, edge midpoints and edges of the face under the pointer, else the face, else the "
                "ground. Esc clears the tape; M again leaves the tool.",
                {GLFW_KEY_M}, false, [this] { toggleTapeTool(); }, nullptr, [this] { return tapeTool_; }});
}

}  // namespace corbel::editor
