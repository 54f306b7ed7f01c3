// The 3D view of the editor: its input (the tool), what it shows, and screenshots.
#include "editor/app.h"

#include "core/scene_pick.h"
#include "kifs/distance.h"
#include "kifs/kernel.h"
#include "kifs/trace.h"
#include "render/gl.h"
#include "render/kifs_pass.h"
#include "render/image.h"
#include "render/kifs_layer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <limits>

namespace corbel::editor {

void App::handleViewInput() {
  ToolContext c;
  c.viewport = &view_;
  // A press on a growth site's entry or envelope corner (its Site tab shown) drags that entry;
  // elsewhere the tool orbits.
  // The growth site's entries are dragged in its own frame.
  auto own = [this](const Ray& r) {
    const DocObject* g = selectedGrowth();
    return g ? Ray{g->placement.unapply(r.origin), g->placement.unapplyDirection(r.direction)} : r;
  };
  c.grab = [this, own](const Ray& world) {
    if (tapeTool_) return false;  // a drag orbits; clicks measure
    if (grabGizmo(tool_.pressX(), tool_.pressY())) return true;
    if (beginPushPull(world)) return true;
    const Ray r = own(world);
    return selectedGrowth() && growthPanel_.siteShown() && growthPanel_.beginViewDrag(growthHost(), r.origin, r.direction);
  };
  c.dragTo = [this, own](const Ray& world) {
    if (transform_.active() || pushPull_.active()) return;  // transformInput, pushPullInput follow the pointer
    const Ray r = own(world);
    if (selectedGrowth()) growthPanel_.viewDrag(growthHost(), r.origin, r.direction);
  };
  c.release = [this] {
    if (growthPanel_.viewDragging()) growthPanel_.endViewDrag(growthHost());
  };
  c.click = [this](const Ray& r) { tapeTool_ ? tapeClick(r) : clickInView(r); };
  c.boxSelect = [this](float x0, float y0, float x1, float y1) { boxSelect(x0, y0, x1, y1); };
  const bool overUi = ImGui::GetIO().WantCaptureMouse;
  // G or R began a transform: the frame's input is its own. A gizmo drag shares it with the
  // tool, whose release ends the grab.
  if (transform_.active() && !transformDragged_) {
    transformInput();
  } else if (pushPull_.active() && !pushPullDragged_) {
    pushPullInput();
  } else {
    for (const InputEvent& e : batch_.events) tool_.handle(e, overUi, c);
    if (transform_.active()) transformInput();
    if (pushPull_.active()) pushPullInput();
  }
  tapeInput();
  updateHover(overUi);
  drawTapeLabels();
  drawBoxBand();
  // The growth site was deselected (a menu, a shortcut) during the drag.
  if (growthPanel_.viewDragging() && !selectedGrowth()) growthPanel_.endViewDrag(growthHost());
}

std::optional<ObjectId> App::objectUnder(const Ray& r) {
  const Vec3 d = r.direction.normalized();
  std::optional<ObjectId> hit;
  double nearest = std::numeric_limits<double>::infinity();
  if (const auto p = pickScene(shownScene(), r.origin, d, [this](ObjectId id) { return pickable(id); })) {
    hit = p->object;
    nearest = p->t;
  }
  // KIFS buildings drawn by ray marching have no faces: the CPU twin of the shader marches the ray.
  for (const DocObject& o : history_.current().objects) {
    const auto* k = std::get_if<KifsSpec>(&o.spec);
    if (!k || k->meshResolution > 0 || !pickable(o.id)) continue;
    try {
      kifs::KifsParams params = render::kifsForView(kifs::paramsOf(*k), view_.camera, std::max(1, int(view_.height())));
      const kifs::Building b(params);
      // March in the building's own frame (a KIFS placement is rigid, so t is the same).
      const Vec3 o0 = o.placement.unapply(r.origin), d0 = o.placement.unapplyDirection(d);
      const kifs::Hit h = kifs::trace(b, {{o0[0], o0[1], o0[2]}, {d0[0], d0[1], d0[2]}});
      if (h.hit && h.t < nearest) {
        nearest = h.t;
        hit = o.id;
      }
    } catch (const std::exception&) {
      // a spec the kernel refuses is not drawn, so it cannot be clicked
    }
  }
  return hit;
}

void App::clickInView(const Ray& ray) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool add = io.KeyShift, toggle = io.KeyCtrl;
  const std::optional<ObjectId> hit = objectUnder(ray);
  const std::optional<ObjectId> active = selected();
  if (hit && hit == active && !add && !toggle) {
    // On the active extrusion a click picks a face: its provenance is logged and its plan edge
    // and profile segment are highlighted in the panes.
    const DocObject* o = history_.current().find(*active);
    // Each kind picks in its own frame: the ray is taken back through the placement.
    const Placement placement = o ? o->placement : Placement{};
    const Ray r{placement.unapply(ray.origin), placement.unapplyDirection(ray.direction)};
    if (const auto* spec = o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr) {
      const std::string what = panes_.pick(*spec, r.origin, r.direction);
      if (!what.empty()) log(o->name + ": picked " + what);
    }
    // On a town it picks one of its buildings for the Town panel.
    if (selectedTown()) townPanel_.pick(townHost(), r.origin, r.direction);
    // On a masonry object it places a load while the load tool is on; on a simulated one it
    // chooses a block for the remove-block tool.
    if (selectedMasonry() && statics_.placingLoad())
      statics_.placeLoad(staticsHost(), r.origin, r.direction);
    else if (selectedMasonry() && statics_.simulating())
      statics_.pickBlock(staticsHost(), r.origin, r.direction);
    return;
  }
  if (!hit) {
    if (!add && !toggle) selection_.clear();
    return;
  }
  if (toggle) selection_.toggle(*hit);
  else if (add) selection_.add(*hit);
  else selection_.select(*hit);
}

const Scene& App::shownScene() {
  // The selected growth site sliced at a height (Fig. 8.3): its faces below the cut only.
  if (const auto h = growthFor_ && selected() == growthFor_ ? growthPanel_.sliceHeight() : std::nullopt;
      h && scene_.hasObject(*growthFor_)) {
    if (sliceSceneOf_ != scene_.revision() || sliceHeightOf_ != *h || sliceObjectOf_ != *growthFor_) {
      sliceScene_ = scene_;
      const Scene::ObjectInfo& info = scene_.objects().at(*growthFor_);
      sliceScene_.replaceObject(*growthFor_, info.kind, info.name, sliceBelow(objectMesh(scene_, *growthFor_), *h));
      sliceSceneOf_ = scene_.revision();
      sliceHeightOf_ = *h;
      sliceObjectOf_ = *growthFor_;
    }
    return sliceScene_;
  }
  const DocObject* m = selectedMasonry();
  const Simulation* sim = m && m->visible ? statics_.shownSimulation(std::get<MasonrySpec>(m->spec)) : nullptr;
  if (!sim) return scene_;
  if (simSceneOf_ != scene_.revision() || simRevisionOf_ != sim->revision() || simObjectOf_ != m->id) {
    simScene_ = scene_;
    showSimulation(simScene_, m->id, *sim, m->placement);
    simSceneOf_ = scene_.revision();
    simRevisionOf_ = sim->revision();
    simObjectOf_ = m->id;
  }
  return simScene_;
}

void App::drawView() {
  int fbw = 0, fbh = 0;
  glfwGetFramebufferSize(window_, &fbw, &fbh);
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float sx = fbw / std::max(vp->Size.x, 1.0f), sy = fbh / std::max(vp->Size.y, 1.0f);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fbw, fbh);
  glClearColor(0.11f, 0.11f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const Document& doc = history_.current();
  // The sun of the shadows; without them the studio sun, so the model looks as it always did.
  settings_.sun =
      settings_.shadows ? std::optional<Vec3>(render::sunDirection(sunAzimuth_, sunElevation_)) : std::nullopt;
  // A selected town is not tinted as a whole: its picked building is outlined instead.
  settings_.highlight = selectedTown() ? std::nullopt : selected();
  // Tension colours and force arrows of the selected masonry object, when it is shown.
  renderer_->overlay().clear();
  renderer_->overlayOnTop().clear();
  // The panels draw the active object's overlays in its own frame: placed below.
  const Placement activePlacement = [&] {
    const DocObject* o = selected() ? doc.find(*selected()) : nullptr;
    return o ? o->placement : Placement{};
  }();
  const render::Overlay::Mark below = renderer_->overlay().mark(), above = renderer_->overlayOnTop().mark();
  if (const DocObject* m = selectedMasonry(); m && m->visible)
    statics_.drawOverlay(renderer_->overlay(), renderer_->overlayOnTop(), std::get<MasonrySpec>(m->spec), m->placement);
  if (const DocObject* o = selected() ? doc.find(*selected()) : nullptr; o && o->visible && stoneFor_ == o->id)
    if (const auto* e = std::get_if<ExtrusionSpec>(&o->spec))
      stone_.drawOverlay(renderer_->overlay(), renderer_->overlayOnTop(), *e);
  if (growthFor_ && selected() == growthFor_) completion_.drawOverlay(renderer_->overlayOnTop());
  if (selectedTown()) townPanel_.drawOverlay(townHost(), renderer_->overlayOnTop());
  if (selectedGrowth()) growthPanel_.drawViewOverlay(renderer_->overlayOnTop());
  renderer_->overlay().placeSince(below, activePlacement);
  renderer_->overlayOnTop().placeSince(above, activePlacement);
  drawStudioOverlay();
  drawPushPullOverlay();
  drawTapeOverlay();
  drawErrorMarks(renderer_->overlayOnTop());
  renderer_->setScene(shownScene(), settings_);
  const int px = int(view_.x() * sx), py = int((vp->Size.y - view_.y() - view_.height()) * sy),
            pw = int(view_.width() * sx), ph = int(view_.height() * sy);
  renderer_->draw(view_.camera, px, py, pw, ph, settings_);
  // KIFS buildings that are not meshed: ray-marched over the Scene, depth-tested against it.
  // Followers of a mass object (footprint "object") are not in `raymarched` (no Scene given):
  // their masses are baked in the background and added with them.
  render::RaymarchedKifs raymarched = render::raymarchedKifs(doc, settings_.visible);
  if (followers_.update(doc, scene_, live_.current(), settings_.visible,
                        [this](const std::string& line, bool error) { log(line, error); }, scripted(),
                        city::buildingMeshes(townCache_)))
    ++kifsGeneration_;
  for (const KifsFollowers::Shown& f : followers_.shown(doc, settings_.visible)) {
    raymarched.buildings.push_back(f.params);
    raymarched.placements.push_back(Placement{});
    raymarched.masses.push_back(f.mass);
  }
  if (!raymarched.buildings.empty() && !kifsFailed_) {
    try {
      if (!kifsPass_) kifsPass_ = std::make_unique<render::KifsPass>();
      if (!kifsLayer_) kifsLayer_ = std::make_unique<render::KifsLayer>();
      // Progressive refinement: march again only when the buildings, the camera or the
      // viewport changed; coarse (1/4 of the pixels each way) while they keep changing, full
      // size once they have been still for a moment. Other frames reuse the cached layer.
      std::vector<std::pair<KifsSpec, Placement>> specs;
      for (const DocObject& o : doc.objects)
        if (const auto* k = std::get_if<KifsSpec>(&o.spec); k && k->meshResolution == 0 && settings_.visible(o.id))
          specs.emplace_back(*k, o.placement);
      const std::array<double, 10> view{
          view_.camera.target[0], view_.camera.target[1], view_.camera.target[2], view_.camera.azimuth_deg, view_.camera.elevation_deg,
          view_.camera.distance,  view_.camera.fov_deg,   double(pw),        double(ph), double(view_.camera.orthographic)};
      const auto now = std::chrono::steady_clock::now();
      if (specs != kifsSpecs_ || view != kifsView_) {
        kifsSpecs_ = std::move(specs);
        kifsView_ = view;
        kifsChanged_ = now;
        ++kifsGeneration_;
      }
      const bool still = now - kifsChanged_ > std::chrono::milliseconds(300);
      std::vector<kifs::KifsParams> buildings;
      for (const kifs::KifsParams& p : raymarched.buildings) buildings.push_back(render::kifsForView(p, view_.camera, ph));
      const KifsView shown = kifsPanel_.view();
      const render::KifsMode mode = shown == KifsView::Facades ? render::KifsMode::Facades
                                    : shown == KifsView::Floors ? render::KifsMode::Floors
                                    : shown == KifsView::Bare   ? render::KifsMode::Bare
                                                                : render::KifsMode::Shaded;
      kifsLayer_->update(*kifsPass_, buildings, view_.camera, pw, ph, still ? 1 : 4, mode,
                         std::to_string(kifsGeneration_) + "/" + std::to_string(int(mode)), raymarched.placements,
                         raymarched.masses);
      kifsLayer_->composite(px, py, pw, ph);
    } catch (const std::exception& e) {
      log(std::string("KIFS buildings cannot be drawn: ") + e.what(), true);
      kifsFailed_ = true;
    }
  }
}

void App::saveScreenshot() {
  namespace fs = std::filesystem;
  const fs::path project = path_.empty() ? fs::path("untitled") : fs::path(path_);
  const fs::path folder = project.has_parent_path() ? project.parent_path() : fs::current_path();
  fs::path shot;
  for (int n = 1;; ++n) {
    shot = folder / (project.stem().string() + "-shot-" + std::to_string(n) + ".png");
    std::error_code ec;
    if (!fs::exists(shot, ec) || n > 100000) break;
  }
  try {
    takeScreenshot(shot.string());
    log("Saved a screenshot: " + shot.string());
  } catch (const std::exception& e) {
    log(std::string("The screenshot was not saved: ") + e.what(), true);
  }
}

void App::takeScreenshot(const std::string& path) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  render::Image img(w, h);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  img.flipVertically();
  for (std::size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  render::writePng(img, path);
}

}  // namespace corbel::editor
