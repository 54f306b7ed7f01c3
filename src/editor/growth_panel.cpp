#include "editor/growth_panel.h"

#include "editor/fields.h"

#include "core/error.h"
#include "editor/completion_view.h"
#include "editor/pane_window.h"
#include "editor/view_map_context.h"
#include "growth/kernel.h"
#include "growth/site.h"
#include "render/gl.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace corbel::editor {

namespace {

const GrowthSpec* specOf(const GrowthHost& host) {
  const DocObject* o = host.doc ? host.doc->find(host.object) : nullptr;
  return o ? std::get_if<GrowthSpec>(&o->spec) : nullptr;
}

const char* itemName(SiteItem k) {
  switch (k) {
    case SiteItem::Core:
      return "core";
    case SiteItem::Circulation:
      return "circulation";
    case SiteItem::Seed:
      return "seed";
  }
  return "";
}

ImU32 colourOf(std::uint32_t id, float alpha) {
  const auto c = idColour(id);
  return IM_COL32(c[0], c[1], c[2], int(alpha * 255));
}

// Two doubles as one drag field ("at", "size"); true when changed.
bool dragPair(const char* label, double* v, double min = -1e6, double max = 1e6) {
  return ImGui::DragScalarN(label, ImGuiDataType_Double, v, 2, 0.1f, &min, &max, "%.2f");
}

}  // namespace

void GrowthPanel::reset() {
  running_ = false;
  selected_ = -1;
  siteError_.clear();
  dragging_ = false;
  slicing_ = false;
  inspection_.reset();
  texturesOf_ = nullptr;
  pendingFor_.reset();
  failedFor_.reset();
  inspectError_.clear();
  if (textures_[0]) glDeleteTextures(GLsizei(textures_.size()), textures_.data());
  textures_ = {};
}

void GrowthPanel::commitSteps(const GrowthHost& host, int steps, const std::string& label, const std::string& merge) {
  Document d = *host.doc;
  std::get<GrowthSpec>(d.find(host.object)->spec).steps = steps;
  host.commit(std::move(d), label, merge);
}

bool GrowthPanel::commitSite(const GrowthHost& host, const SiteEditResult& r, const std::string& label,
                             const std::string& merge, bool report) {
  if (!r.spec) {
    siteError_ = r.error;
    if (report) host.log(label + " refused: " + r.error, true);
    return false;
  }
  siteError_.clear();
  Document d = *host.doc;
  std::get<GrowthSpec>(d.find(host.object)->spec) = *r.spec;
  host.commit(std::move(d), label, merge);
  return true;
}

void GrowthPanel::parseSite(const GrowthSpec& spec) {
  if (summaryOf_ == spec.site) return;
  summaryOf_ = spec.site;
  try {
    site_ = growth::parseSite(spec.site);
    const growth::Site& site = *site_;
    char text[160];
    std::snprintf(text, sizeof text, "%.0f m² site, %d storeys of %.1f m, %zu cores, %zu circulation boxes, %zu seeds",
                  site.area(), site.storeys, site.storeyHeight, site.cores.size(), site.circulation.size(),
                  site.seeds.size());
    summary_ = text;
    hand_ = handPlaced(spec.site);
    frame_ = siteFrame(spec.site);
    planStorey_ = std::clamp(planStorey_, 0, site.storeys - 1);
    if (slicing_) slice_ = std::clamp(slice_, site.base, site.top());
  } catch (const std::exception&) {
    site_.reset();
    hand_ = {};
    frame_ = {};
    summary_.clear();  // the build reports the site's fault
  }
  if (selected_ >= itemCount(hand_, kind_)) selected_ = -1;
}

void GrowthPanel::step(const GrowthHost& host) {
  const GrowthSpec* spec = specOf(host);
  if (!spec || running_) return;
  if (const auto next = nextStep(*spec, growth::stoppedAfter(host.warnings)))
    commitSteps(host, next->steps, "Grow " + host.doc->find(host.object)->name + " one step");
}

void GrowthPanel::toggleRun(const GrowthHost& host) {
  if (running_) host.endDrag();
  running_ = !running_ && specOf(host);
}

void GrowthPanel::update(const GrowthHost& host) {
  pollInspection();
  const GrowthSpec* spec = specOf(host);
  if (!spec || !running_ || !host.current) return;
  if (!host.error.empty()) {
    running_ = false;
    return;
  }
  const auto next = nextStep(*spec, growth::stoppedAfter(host.warnings));
  if (!next) {
    running_ = false;
    host.endDrag();
    host.log("Growth: every unit stopped after " + std::to_string(spec->steps) + " steps", false);
    return;
  }
  commitSteps(host, next->steps, "Grow " + host.doc->find(host.object)->name, "grow" + std::to_string(host.object));
}

void GrowthPanel::add(const GrowthHost& host, SiteItem item) {
  const GrowthSpec* spec = specOf(host);
  if (!spec) return;
  parseSite(*spec);
  const std::string name = host.doc->find(host.object)->name;
  if (!site_) {
    host.log("Add a " + std::string(itemName(item)) + " to " + name + ": the site has a fault to fix first", true);
    return;
  }
  const int index = itemCount(hand_, item);
  SiteEditResult r;
  if (item == SiteItem::Core) {
    const auto spot = freeCoreSpot(*site_, Vec2(3, 3));
    if (!spot) return host.log("Add a core to " + name + ": no free 3 x 3 m place on the site", true);
    r = setCore(*spec, index, *spot);
  } else if (item == SiteItem::Circulation) {
    // A 3 × 3 m landing one storey high on the plan view's storey, where a core of that plan would fit.
    const auto spot = freeCoreSpot(*site_, Vec2(3, 3));
    if (!spot) return host.log("Add circulation to " + name + ": no free 3 x 3 m place on the site", true);
    const double z = site_->base + planStorey_ * site_->storeyHeight;
    r = setCirculation(*spec, index, {{spot->u0, spot->v0, z}, {spot->u1, spot->v1, z + site_->storeyHeight}});
  } else {
    growth::Seed like;
    like.storey = planStorey_;
    like.targetArea = 60;
    const auto spot = freeSeedSpot(*site_, like);
    if (!spot)
      return host.log(
          "Add a seed to " + name + ": no free, supported 3 x 3 m place on storey " + std::to_string(planStorey_),
          true);
    r = setSeed(*spec, index, *spot);
  }
  if (commitSite(host, r, "Add a " + std::string(itemName(item)) + " to " + name, "", true)) {
    kind_ = item;
    selected_ = index;
  }
}

void GrowthPanel::addStorey(const GrowthHost& host) {
  const GrowthSpec* spec = specOf(host);
  if (!spec) return;
  parseSite(*spec);
  const std::string label = "Add a storey to " + host.doc->find(host.object)->name;
  if (!frame_.valid) return host.log(label + ": the site has a fault to fix first", true);
  commitSite(host, setStoreys(*spec, frame_.storeys + 1, frame_.storeyHeight), label, "", true);
}

void GrowthPanel::widenSite(const GrowthHost& host, double dx) {
  const GrowthSpec* spec = specOf(host);
  if (!spec) return;
  parseSite(*spec);
  const std::string label = "Widen the site of " + host.doc->find(host.object)->name;
  if (!frame_.valid) return host.log(label + ": the site has a fault to fix first", true);
  if (!frame_.box) return host.log(label + " refused: the envelope is a polygon (edit its corners)", true);
  const growth::Box b = site_->bounds();
  commitSite(host, setEnvelopeBox(*spec, Vec2(b.lo[0], b.lo[1]), Vec2(b.hi[0] - b.lo[0] + dx, b.hi[1] - b.lo[1])),
             label, "", true);
}

void GrowthPanel::removeSelected(const GrowthHost& host) {
  const GrowthSpec* spec = specOf(host);
  if (!spec || selected_ < 0) return;
  const std::string label = "Delete " + std::string(itemName(kind_)) + " " + std::to_string(selected_ + 1) + " of " +
                            host.doc->find(host.object)->name;
  if (commitSite(host, removeItem(*spec, kind_, selected_), label, "", true)) selected_ = -1;
}

void GrowthPanel::sliceStorey(const GrowthHost& host, int by) {
  const GrowthSpec* spec = specOf(host);
  if (!spec) return;
  parseSite(*spec);
  if (!site_) return;
  const growth::Site& s = *site_;
  // Storey levels: base + k·h for k = 1..storeys (the top: no slice).
  int k = slicing_ ? int(std::ceil((slice_ - s.base) / s.storeyHeight - 1e-9)) : s.storeys;
  k = std::clamp(k + by, 1, s.storeys);
  slicing_ = k < s.storeys;
  slice_ = s.base + k * s.storeyHeight;
}

void GrowthPanel::requestInspection(const GrowthHost& host, const growth::GrowthInput& spec) {
  if (inspection_ && inspection_->of == spec && inspection_->maps == host.maps) return;
  if (pendingFor_ && *pendingFor_ == spec && pendingMaps_ == host.maps) return;
  if (failedFor_ && *failedFor_ == spec && failedMaps_ == host.maps) return;
  if (!host.current || running_ || pendingFor_) return;  // measured once the Scene shows it
  pendingFor_ = spec;
  pendingMaps_ = host.maps;
  // The GL mapper renders on a context of its own (render::ContextViewMapper), so this may run
  // off the UI thread like the exact one.
  auto work = [spec, mapper = host.mapper, maps = host.maps]() -> std::shared_ptr<const GrowthInspection> {
    return std::make_shared<const GrowthInspection>(inspectGrowth(spec, nullptr, mapper.get(), maps));
  };
  if (host.wait) {
    std::promise<std::shared_ptr<const GrowthInspection>> p;
    try {
      p.set_value(work());
    } catch (...) {
      p.set_exception(std::current_exception());
    }
    pending_ = p.get_future();
    pollInspection();
  } else {
    pending_ = std::async(std::launch::async, work);
  }
}

void GrowthPanel::pollInspection() {
  if (!pendingFor_ || !pending_.valid()) return;
  if (pending_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  try {
    inspection_ = pending_.get();
    inspectError_.clear();
  } catch (const std::exception& e) {
    failedFor_ = pendingFor_;
    failedMaps_ = pendingMaps_;
    inspectError_ = e.what();
  }
  pendingFor_.reset();
}

void GrowthPanel::drawGrow(const GrowthHost& host, const GrowthSpec& spec) {
  const DocObject* o = host.doc->find(host.object);
  int seed = static_cast<int>(spec.seed);
  ImGui::SetNextItemWidth(160);
  if (commitInt("Seed", static_cast<int>(spec.seed), seed) && seed >= 0) {
    Document d = *host.doc;
    std::get<GrowthSpec>(d.find(host.object)->spec).seed = static_cast<std::uint64_t>(seed);
    host.commit(std::move(d), "Seed " + o->name, "");
  }
  const int stopped = growth::stoppedAfter(host.warnings);
  if (spec.steps < 0)
    ImGui::Text("Grown until every unit stopped%s", host.current ? "" : " (growing...)");
  else
    ImGui::Text("Grown %d step%s%s", spec.steps, spec.steps == 1 ? "" : "s", host.current ? "" : " (growing...)");
  if (stopped >= 0 && host.current) ImGui::TextDisabled("every unit stopped after %d steps", stopped);

  const auto next = nextStep(spec, stopped);
  ImGui::BeginDisabled(!next || running_);
  if (ImGui::Button("Step")) step(host);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!next && !running_);
  if (ImGui::Button(running_ ? "Pause" : "Run")) toggleRun(host);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(spec.steps < 0);
  if (ImGui::Button("Grow to the end")) {
    running_ = false;
    commitSteps(host, -1, "Grow " + o->name + " to the end");
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(spec.steps == 0);
  if (ImGui::Button("Reset")) {
    running_ = false;
    commitSteps(host, 0, "Reset the growth of " + o->name);
  }
  ImGui::EndDisabled();
  ImGui::TextDisabled("Run commits one step at a time as the view catches up;");
  ImGui::TextDisabled("the whole run is one undo step.");
  ImGui::BeginDisabled(running_ || freezing_ != nullptr || host.busy);
  if (ImGui::Button("Freeze units")) freeze(host);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextDisabled(spec.aroundUnits ? "grows around the unit objects" : "units become objects to edit by hand");
  // The view maps the runs grow on (Sec. 5.2): an editor setting, like the slice and shadows.
  ImGui::Separator();
  ImGui::TextUnformatted("View maps:");
  ImGui::SameLine();
  if (host.glViewMaps) {
    int gl = *host.glViewMaps ? 1 : 0;
    ImGui::RadioButton("exact (CPU)", &gl, 0);
    ImGui::SameLine();
    ImGui::RadioButton("GL", &gl, 1);
    *host.glViewMaps = gl == 1;
    if (gl && host.glPixel) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(110);
      char current[32];
      std::snprintf(current, sizeof current, "%.2g m pixels", *host.glPixel);
      if (ImGui::BeginCombo("##pixel", current)) {
        for (double p : kEditorViewMapPixels) {
          char label[32];
          std::snprintf(label, sizeof label, "%.2g m pixels", p);
          if (ImGui::Selectable(label, p == *host.glPixel)) *host.glPixel = p;
        }
        ImGui::EndCombo();
      }
    }
    if (*host.glViewMaps != (host.mapper != nullptr) ||
        (host.glPixel && *host.glViewMaps && host.maps != glMapsName(*host.glPixel)))
      ImGui::TextDisabled("regrowing on the %s maps...", *host.glViewMaps ? "GL" : "exact");
    else
      ImGui::TextDisabled("growing on %s", host.maps.c_str());
  } else {
    ImGui::TextDisabled("exact (CPU); no GL context for GL maps");
  }
  if (site_) {
    // The slice (Fig. 8.3): a view setting, not an edit.
    ImGui::Separator();
    ImGui::Checkbox("Slice", &slicing_);
    ImGui::SameLine();
    float h = float(slicing_ ? slice_ : site_->top());
    ImGui::SetNextItemWidth(-1);
    ImGui::BeginDisabled(!slicing_);
    if (ImGui::SliderFloat("##slice", &h, float(site_->base), float(site_->top()), "hide at and above %.1f m"))
      slice_ = h;
    ImGui::EndDisabled();
    if (!slicing_) slice_ = site_->top();
    if (slicing_) {
      const double storeys = (slice_ - site_->base) / site_->storeyHeight;
      ImGui::TextDisabled("storeys below the cut: %.1f of %d (plans seen from above)", storeys, site_->storeys);
    }
  }
  if (host.shadows && host.sunAzimuth && host.sunElevation) {
    // Shadows from a movable sun (Fig. 8.5): the 3D view's setting, for every object.
    ImGui::Separator();
    ImGui::Checkbox("Shadows", host.shadows);
    ImGui::BeginDisabled(!*host.shadows);
    float az = float(*host.sunAzimuth), el = float(*host.sunElevation);
    ImGui::SetNextItemWidth(-120);
    if (ImGui::SliderFloat("sun azimuth", &az, -180.0f, 180.0f, "%.0f°")) *host.sunAzimuth = az;
    ImGui::SetNextItemWidth(-120);
    if (ImGui::SliderFloat("sun elevation", &el, 5.0f, 90.0f, "%.0f°")) *host.sunElevation = el;
    ImGui::EndDisabled();
  }
}

void GrowthPanel::drawPlan(const GrowthHost& host, const GrowthSpec& spec, float w, float h) {
  const growth::Site& site = *site_;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  dl->AddRectFilled(p0, ImVec2(p0.x + w, p0.y + h), IM_COL32(30, 32, 36, 255));
  const growth::Box b = site.bounds();
  const CellMap m = fitInCell({b.lo[0], b.lo[1], b.hi[0], b.hi[1]}, {p0.x, p0.y, w, h}, 6.0f);
  dl->PushClipRect(p0, ImVec2(p0.x + w, p0.y + h), true);
  auto rect = [&](double x0, double y0, double x1, double y1, ImU32 fill, ImU32 line, float thick = 1.0f) {
    float ax, ay, bx, by;
    m.apply(x0, y1, ax, ay);
    m.apply(x1, y0, bx, by);
    if (fill) dl->AddRectFilled(ImVec2(ax, ay), ImVec2(bx, by), fill);
    if (line) dl->AddRect(ImVec2(ax, ay), ImVec2(bx, by), line, 0, 0, thick);
  };
  std::vector<ImVec2> outline;
  for (const Vec2& p : site.plan) {
    float px, py;
    m.apply(p[0], p[1], px, py);
    outline.emplace_back(px, py);
  }
  dl->AddPolyline(outline.data(), int(outline.size()), IM_COL32(150, 150, 160, 255), ImDrawFlags_Closed, 1.0f);
  // The envelope's corners are handles: dragging one moves it (a box becomes a polygon).
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const ImVec2& c = outline[i];
    const bool held = dragCorner_ == int(i);
    dl->AddRectFilled(ImVec2(c.x - 3, c.y - 3), ImVec2(c.x + 3, c.y + 3),
                      held ? IM_COL32(255, 215, 50, 255) : IM_COL32(170, 170, 180, 255));
  }
  const double z0 = site.base + planStorey_ * site.storeyHeight, z1 = z0 + site.storeyHeight;
  const ImU32 selLine = IM_COL32(255, 215, 50, 255);
  // Generated seeds (not editable) dimmed, then the file's own entries.
  for (std::size_t i = hand_.seeds.size(); i < site.seeds.size(); ++i)
    if (site.seeds[i].storey == planStorey_) {
      const growth::Seed& s = site.seeds[i];
      rect(s.at[0], s.at[1], s.at[0] + s.size[0], s.at[1] + s.size[1], IM_COL32(70, 110, 80, 160), 0);
    }
  for (std::size_t i = 0; i < hand_.circulation.size(); ++i) {
    const growth::Box& c = hand_.circulation[i];
    if (c.lo[2] < z1 - 1e-9 && c.hi[2] > z0 + 1e-9)
      rect(c.lo[0], c.lo[1], c.hi[0], c.hi[1], IM_COL32(80, 90, 110, 255), 0);
  }
  for (const growth::Rect& c : hand_.cores) rect(c.u0, c.v0, c.u1, c.v1, IM_COL32(120, 120, 125, 255), 0);
  for (std::size_t i = 0; i < hand_.seeds.size(); ++i)
    if (hand_.seeds[i].storey == planStorey_) {
      const growth::Seed& s = hand_.seeds[i];
      rect(s.at[0], s.at[1], s.at[0] + s.size[0], s.at[1] + s.size[1], colourOf(std::uint32_t(i + 1), 0.9f),
           IM_COL32(20, 20, 20, 255));
    }
  if (selected_ >= 0) {
    if (kind_ == SiteItem::Core) {
      const growth::Rect& c = hand_.cores[selected_];
      rect(c.u0, c.v0, c.u1, c.v1, 0, selLine, 2.0f);
    } else if (kind_ == SiteItem::Circulation) {
      const growth::Box& c = hand_.circulation[selected_];
      rect(c.lo[0], c.lo[1], c.hi[0], c.hi[1], 0, selLine, 2.0f);
    } else {
      const growth::Seed& s = hand_.seeds[selected_];
      rect(s.at[0], s.at[1], s.at[0] + s.size[0], s.at[1] + s.size[1], 0, selLine, 2.0f);
    }
  }
  dl->PopClipRect();
  // Click picks what lies under the mouse (seeds, then circulation, then cores, on this storey);
  // dragging moves it in 0.5 m steps, one undo step per drag.
  ImGui::InvisibleButton("plan", ImVec2(w, h));
  const ImVec2 mp = ImGui::GetIO().MousePos;
  double mx, my;
  m.invert(mp.x, mp.y, mx, my);
  if (ImGui::IsItemActivated()) {
    dragging_ = false;
    dragCorner_ = -1;
    if (const auto corner = pickEnvelopeCorner(site.plan, mx, my, 6.0 / m.s)) {
      dragCorner_ = *corner;
      dragPlan_ = site.plan;
      dragX_ = mx, dragY_ = my;
    }
  }
  if (dragCorner_ >= 0 && ImGui::IsItemActive()) {
    const std::string merge = "site" + std::to_string(host.object) + "envelope corner" + std::to_string(dragCorner_);
    const std::string label = "Move corner " + std::to_string(dragCorner_ + 1) + " of the envelope";
    if (const auto r = dragEnvelopeCorner(spec, dragPlan_, site.plan, dragCorner_, mx - dragX_, my - dragY_)) {
      commitSite(host, *r, label, merge, false);
      siteEditOpen_ = true;
    }
  }
  if (dragCorner_ >= 0 && ImGui::IsItemDeactivated()) dragCorner_ = -1;
  if (ImGui::IsItemActivated() && dragCorner_ < 0) {
    dragging_ = false;
    selected_ = -1;
    if (const auto pick = pickItem(hand_, site, planStorey_, mx, my)) {
      kind_ = pick->first;
      selected_ = pick->second;
      dragging_ = true;
      dragX_ = mx, dragY_ = my;
      dragFrom_ = hand_;
    }
  }
  if (dragging_ && ImGui::IsItemActive() && selected_ >= 0) {
    const std::string merge = "site" + std::to_string(host.object) + itemName(kind_) + std::to_string(selected_);
    const std::string label = "Move " + std::string(itemName(kind_)) + " " + std::to_string(selected_ + 1);
    if (const auto r = dragItem(spec, dragFrom_, hand_, kind_, selected_, mx - dragX_, my - dragY_)) {
      commitSite(host, *r, label, merge, false);
      siteEditOpen_ = true;
    }
  }
  if (ImGui::IsItemDeactivated()) dragging_ = false;
}

// The envelope (a box's origin and size, or the polygon's corners), the storeys and the
// generate_seeds controls: each change is one edit checked by the kernel (merged while a field
// is held), refused with its message as the entries' edits are.
void GrowthPanel::drawFrame(const GrowthHost& host, const GrowthSpec& spec) {
  if (!frame_.valid) return;
  const std::string name = host.doc->find(host.object)->name;
  SiteEditResult r;
  bool changed = false;
  std::string label, merge;
  ImGui::PushItemWidth(-135);
  if (ImGui::CollapsingHeader("Envelope and storeys", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (frame_.box) {
      const growth::Box b = [&] {
        growth::Site s;
        s.plan = frame_.plan;
        return s.bounds();
      }();
      double origin[2] = {b.lo[0], b.lo[1]}, size[2] = {b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]};
      bool c = dragPair("origin (m)", origin);
      c |= dragPair("box size (m)", size, 0.1, 1e6);
      if (c) {
        r = setEnvelopeBox(spec, Vec2(origin[0], origin[1]), Vec2(size[0], size[1]));
        changed = true, label = "Edit the envelope of " + name, merge = "envelope";
      }
      if (ImGui::Button("Edit as a polygon")) {
        r = setEnvelopePolygon(spec, frame_.plan);
        changed = true, label = "Make the envelope of " + name + " a polygon";
      }
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The box's four corners become a polygon's, to move, add or remove.");
    } else {
      for (std::size_t i = 0; i < frame_.plan.size(); ++i) {
        ImGui::PushID(int(i));
        double p[2] = {frame_.plan[i][0], frame_.plan[i][1]};
        const std::string l = "corner " + std::to_string(i + 1);
        if (ImGui::SmallButton("+")) {
          r = insertEnvelopeCorner(spec, int(i));
          changed = true, label = "Add a corner after corner " + std::to_string(i + 1) + " of the envelope of " + name;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Add a corner halfway to the next one");
        ImGui::SameLine();
        ImGui::BeginDisabled(frame_.plan.size() <= 3);
        if (ImGui::SmallButton("-")) {
          r = removeEnvelopeCorner(spec, int(i));
          changed = true, label = "Remove corner " + std::to_string(i + 1) + " of the envelope of " + name;
        }
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
          ImGui::SetTooltip("Remove this corner (a plan keeps 3)");
        ImGui::SameLine();
        if (dragPair(l.c_str(), p)) {
          r = moveEnvelopeCorner(spec, int(i), Vec2(p[0], p[1]));
          changed = true, label = "Edit the envelope of " + name, merge = "envelope";
        }
        ImGui::PopID();
      }
      if (ImGui::Button("Make it a box")) {
        const growth::Box b = [&] {
          growth::Site s;
          s.plan = frame_.plan;
          return s.bounds();
        }();
        r = setEnvelopeBox(spec, Vec2(b.lo[0], b.lo[1]), Vec2(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]));
        changed = true, label = "Make the envelope of " + name + " its bounding box";
      }
    }
    int storeys = frame_.storeys;
    double height = frame_.storeyHeight;
    const double hmin = 0.5, hmax = 100;
    bool c = ImGui::InputInt("storeys", &storeys);
    c |= ImGui::DragScalar("storey height (m)", ImGuiDataType_Double, &height, 0.05f, &hmin, &hmax, "%.2f");
    if (c) {
      r = setStoreys(spec, storeys, height);
      changed = true, label = "Edit the storeys of " + name, merge = "storeys";
    }
  }
  if (ImGui::CollapsingHeader("Generated seeds")) {
    bool on = frame_.controls.has_value();
    growth::SeedControls g = on ? *frame_.controls : growth::SeedControls{};
    bool c = ImGui::Checkbox("generate seeds at exits", &on);
    if (on) {
      c |= ImGui::InputInt("count", &g.count);
      double size[2] = {g.size[0], g.size[1]}, area[2] = {g.areaLo, g.areaHi};
      const double smin = 0, smax = 1e4;
      c |= dragPair("seed size (m)", size, 0.1, 1e4);
      c |= ImGui::DragScalar("spacing (m)", ImGuiDataType_Double, &g.spacing, 0.1f, &smin, &smax, "%.2f");
      c |= dragPair("target area (m²)", area, 1, 1e6);
      int shuffle = int(g.seed);
      c |= ImGui::InputInt("shuffle seed", &shuffle);
      g.size = Vec2(size[0], size[1]);
      g.areaLo = area[0], g.areaHi = area[1];
      g.seed = unsigned(std::max(shuffle, 0));
      ImGui::TextDisabled("storeys (none ticked: every storey the circulation serves):");
      for (int k = 0; k < frame_.storeys && k < 12; ++k) {
        if (k) ImGui::SameLine();
        bool ticked = std::find(g.storeys.begin(), g.storeys.end(), k) != g.storeys.end();
        ImGui::PushID(k);
        if (ImGui::Checkbox(std::to_string(k).c_str(), &ticked)) {
          if (ticked)
            g.storeys.push_back(k), std::sort(g.storeys.begin(), g.storeys.end());
          else
            g.storeys.erase(std::find(g.storeys.begin(), g.storeys.end(), k));
          c = true;
        }
        ImGui::PopID();
      }
    }
    if (c) {
      r = setSeedControls(spec, on ? std::optional<growth::SeedControls>(g) : std::nullopt);
      changed = true, label = "Edit the seed generation of " + name, merge = "seedcontrols";
    }
  }
  if (ImGui::CollapsingHeader("Growth behaviour")) {
    // The view behaviour's settings (docs/growth.md, "Growth settings"); each drag one undo step.
    growth::GrowthSettings g = frame_.growth;
    const double zero = 0, one = 1, penaltyMax = 1000, ratioMax = 10, aspectMin = 1, aspectMax = 100;
    const auto tip = [](const char* text) {
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
    };
    bool c = ImGui::DragScalar("view conflict τ", ImGuiDataType_Double, &g.tau, 0.005f, &zero, &one, "%.3f");
    tip("A move is refused if it leaves any unit under (1 − τ) of its best view");
    c |= ImGui::DragScalar("intrusion penalty", ImGuiDataType_Double, &g.intrusionPenalty, 0.01f, &zero, &penaltyMax,
                           "%.2f /m²");
    tip("Score a move loses per m² of view it takes from other units");
    c |= ImGui::DragScalar("double-volume chance", ImGuiDataType_Double, &g.doubleVolumeChance, 0.005f, &zero, &one,
                           "%.3f");
    tip("Chance a unit makes one part a double volume at half its target");
    c |= ImGui::DragScalar("aspect chance", ImGuiDataType_Double, &g.aspectChance, 0.005f, &zero, &one, "%.3f");
    tip("Chance a step takes the squarest move rather than the one with the best view");
    c |= ImGui::DragScalar("max aspect 1 :", ImGuiDataType_Double, &g.maxAspect, 0.02f, &aspectMin, &aspectMax,
                           "%.2f");
    tip("No part's plan grows longer than this many times its width");
    c |= ImGui::DragScalar("view goal ratio", ImGuiDataType_Double, &g.viewGoalRatio, 0.005f, &zero, &ratioMax,
                           "%.3f");
    tip("A unit's goal view is this times its target floor area (orders units by their view deficit)");
    c |= ImGui::InputInt("patience", &g.patience);
    tip("Steps without a valid move before a unit is stuck");
    int sub[2] = {g.minSubUnits, g.maxSubUnits};
    c |= ImGui::DragInt2("sub-units", sub, 0.05f, 1, 8);
    tip("Least and most sub-units a target is grown as (drawn evenly)");
    g.minSubUnits = sub[0], g.maxSubUnits = std::max(sub[0], sub[1]);
    g.patience = std::clamp(g.patience, 1, 1000);
    if (c) {
      r = setGrowthSettings(spec, g);
      changed = true, label = "Edit the growth behaviour of " + name, merge = "growthsettings";
    }
  }
  ImGui::PopItemWidth();
  if (changed) {
    commitSite(host, r, label, "site" + std::to_string(host.object) + merge, false);
    siteEditOpen_ = true;
  }
}

void GrowthPanel::drawSite(const GrowthHost& host, const GrowthSpec& spec) {
  if (!site_) {
    ImGui::TextWrapped("The site has a fault (above); fix it in the site file first.");
    return;
  }
  const growth::Site& site = *site_;
  const std::string name = host.doc->find(host.object)->name;
  ImGui::SetNextItemWidth(120);
  ImGui::SliderInt("Plan storey", &planStorey_, 0, site.storeys - 1);
  ImGui::SameLine();
  ImGui::TextDisabled("drag to move or reshape");
  drawPlan(host, spec, ImGui::GetContentRegionAvail().x, 120);
  drawFrame(host, spec);

  int kind = static_cast<int>(kind_);
  for (int k = 0; k < 3; ++k) {
    if (k) ImGui::SameLine();
    char label[40];
    std::snprintf(label, sizeof label, "%s (%d)",
                  k == 0   ? "Cores"
                  : k == 1 ? "Circulation"
                           : "Seeds",
                  itemCount(hand_, SiteItem(k)));
    if (ImGui::RadioButton(label, &kind, k)) {
      kind_ = SiteItem(k);
      selected_ = -1;
    }
  }
  if (site.seeds.size() > hand_.seeds.size())
    ImGui::TextDisabled("%zu more seeds generated at exits (Generated seeds, above)",
                        site.seeds.size() - hand_.seeds.size());
  const int count = itemCount(hand_, kind_);
  if (ImGui::Button("Add")) add(host, kind_);
  ImGui::SameLine();
  ImGui::BeginDisabled(selected_ < 0);
  if (ImGui::Button("Delete")) removeSelected(host);
  ImGui::EndDisabled();

  if (selected_ >= 0 && selected_ < count) {
    const std::string merge = "site" + std::to_string(host.object) + itemName(kind_) + std::to_string(selected_);
    const std::string label =
        "Edit " + std::string(itemName(kind_)) + " " + std::to_string(selected_ + 1) + " of " + name;
    SiteEditResult r;
    bool changed = false;
    ImGui::PushItemWidth(-90);
    if (kind_ == SiteItem::Core) {
      const growth::Rect& c = hand_.cores[selected_];
      double at[2] = {c.u0, c.v0}, size[2] = {c.u1 - c.u0, c.v1 - c.v0};
      changed |= dragPair("at (m)", at);
      changed |= dragPair("size (m)", size, 0.1, 1e6);
      if (changed) r = setCore(spec, selected_, {at[0], at[1], at[0] + size[0], at[1] + size[1]});
    } else if (kind_ == SiteItem::Circulation) {
      const growth::Box& c = hand_.circulation[selected_];
      double at[3] = {c.lo[0], c.lo[1], c.lo[2]}, size[3] = {c.size(0), c.size(1), c.size(2)};
      const double lo = -1e6, hi = 1e6, smin = 0.1;
      changed |= ImGui::DragScalarN("at (m)", ImGuiDataType_Double, at, 3, 0.1f, &lo, &hi, "%.2f");
      changed |= ImGui::DragScalarN("size (m)", ImGuiDataType_Double, size, 3, 0.1f, &smin, &hi, "%.2f");
      if (changed)
        r = setCirculation(spec, selected_,
                           {{at[0], at[1], at[2]}, {at[0] + size[0], at[1] + size[1], at[2] + size[2]}});
    } else {
      growth::Seed s = hand_.seeds[selected_];
      double at[2] = {s.at[0], s.at[1]}, size[2] = {s.size[0], s.size[1]};
      changed |= dragPair("at (m)", at);
      changed |= dragPair("size (m)", size, 0.1, 1e6);
      changed |= ImGui::InputInt("storey", &s.storey);
      int byVolume = s.targetVolume > 0;
      double target = byVolume ? s.targetVolume : s.targetArea;
      const double tmin = 1, tmax = 1e6;
      changed |= ImGui::DragScalar(byVolume ? "target m³" : "target m²", ImGuiDataType_Double, &target, 1.0f, &tmin,
                                   &tmax, "%.0f");
      const int wasByVolume = byVolume;
      ImGui::RadioButton("floor area", &byVolume, 0);
      ImGui::SameLine();
      ImGui::RadioButton("volume", &byVolume, 1);
      if (byVolume != wasByVolume) {
        // Keep the size of the target: a volume is the area times one storey.
        target = byVolume ? target * site.storeyHeight : target / site.storeyHeight;
        changed = true;
      }
      s.targetArea = byVolume ? 0 : target;
      s.targetVolume = byVolume ? target : 0;
      if (std::string behaviour; commitText("behaviour", s.behaviour, behaviour, 63)) {
        s.behaviour = behaviour;
        changed = true;
      }
      ImGui::TextUnformatted("locked:");
      for (growth::Side side : growth::kAllSides) {
        ImGui::SameLine();
        bool locked = s.locked[int(side)];
        const std::string sideLabel(growth::sideName(side));
        if (ImGui::Checkbox(sideLabel.c_str(), &locked)) {
          s.locked[int(side)] = locked;
          changed = true;
        }
      }
      s.at = Vec2(at[0], at[1]);
      s.size = Vec2(size[0], size[1]);
      if (changed) r = setSeed(spec, selected_, s);
    }
    ImGui::PopItemWidth();
    if (changed) {
      commitSite(host, r, label, merge, false);
      siteEditOpen_ = true;
    }
  }
  if (ImGui::BeginListBox("##items", ImVec2(-1, 4.5f * ImGui::GetTextLineHeightWithSpacing()))) {
    for (int i = 0; i < count; ++i) {
      char text[120];
      if (kind_ == SiteItem::Core) {
        const growth::Rect& c = hand_.cores[i];
        std::snprintf(text, sizeof text, "core %d: at (%.1f, %.1f), %.1f x %.1f m", i + 1, c.u0, c.v0, c.u1 - c.u0,
                      c.v1 - c.v0);
      } else if (kind_ == SiteItem::Circulation) {
        const growth::Box& c = hand_.circulation[i];
        std::snprintf(text, sizeof text, "circulation %d: at (%.1f, %.1f, %.1f), %.1f x %.1f x %.1f m", i + 1, c.lo[0],
                      c.lo[1], c.lo[2], c.size(0), c.size(1), c.size(2));
      } else {
        const growth::Seed& s = hand_.seeds[i];
        std::snprintf(text, sizeof text, "seed %d: storey %d at (%.1f, %.1f), %s %.0f", i + 1, s.storey, s.at[0],
                      s.at[1], s.targetArea > 0 ? "area" : "volume", s.targetArea > 0 ? s.targetArea : s.targetVolume);
      }
      ImGui::PushID(i);
      if (ImGui::Selectable(text, selected_ == i)) {
        selected_ = i;
        if (kind_ == SiteItem::Seed) planStorey_ = hand_.seeds[i].storey;
      }
      ImGui::PopID();
    }
    ImGui::EndListBox();
  }
  // A drag (or a run of edits of one field) is one undo step, closed when the field is let go;
  // a refused value is logged then, once.
  if (siteEditOpen_ && !ImGui::IsAnyItemActive()) {
    siteEditOpen_ = false;
    host.endDrag();
    if (!siteError_.empty()) host.log("Site edit refused: " + siteError_, true);
  }
  if (!siteError_.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "refused: %s", siteError_.c_str());
    ImGui::PopTextWrapPos();
  }
}

void GrowthPanel::drawStatistics(const GrowthHost& host) {
  (void)host;
  ImGui::Checkbox("View maps", &showViewMaps_);
  ImGui::SameLine();
  ImGui::TextDisabled("the four projections (Sec. 5.2)");
  if (!inspectError_.empty() && failedFor_) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", inspectError_.c_str());
    ImGui::PopTextWrapPos();
    return;
  }
  if (!inspection_) {
    ImGui::TextDisabled("measuring the model...");
    return;
  }
  if (pendingFor_ || !host.current || running_ || !(inspection_->of == growth::growthInputOf(*host.doc, *host.doc->find(host.object))) || inspection_->maps != host.maps)
    ImGui::TextDisabled("(of the model before the last change; measuring...)");
  if (ImGui::BeginTable("table81", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("Table 8.1", ImGuiTableColumnFlags_WidthStretch, 0.45f);
    ImGui::TableSetupColumn("this model", ImGuiTableColumnFlags_WidthStretch, 0.55f);
    ImGui::TableHeadersRow();
    for (const auto& [k, v] : statisticsRows(inspection_->stats)) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(k.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(v.c_str());
    }
    ImGui::EndTable();
  }
  ImGui::TextDisabled("occupants: Type A > 85 m² five, B 50-85 m² three, C 30-50 m² one");
}

void GrowthPanel::freeze(const GrowthHost& host) {
  const DocObject* o = host.doc->find(host.object);
  if (!o || !std::holds_alternative<GrowthSpec>(o->spec)) return;
  auto job = std::make_shared<Freezing>();
  job->of = growth::growthInputOf(*host.doc, *o);
  freezing_ = job;
  auto work = [job, mapper = host.mapper](Progress& p) { job->grown = growth::grow(job->of, &p, mapper.get()); };
  if (host.wait || !host.startJob) {
    Progress p;
    try {
      work(p);
      job->done = true;
    } catch (const std::exception& e) {
      host.log(std::string("Freeze failed: ") + e.what(), true);
      freezing_.reset();
      return;
    }
    applyFreeze(host);
    return;
  }
  host.startJob("Growing " + o->name + " to freeze its units", std::move(work), [job] { job->done = true; });
}

void GrowthPanel::applyFreeze(const GrowthHost& host) {
  if (freezing_ && !freezing_->done && !host.busy && !host.wait) freezing_.reset();  // failed or cancelled
  if (!freezing_ || !freezing_->done) return;
  const std::shared_ptr<Freezing> job = std::move(freezing_);
  const DocObject* o = host.doc->find(host.object);
  if (!o || !std::holds_alternative<GrowthSpec>(o->spec) || !(growth::growthInputOf(*host.doc, *o) == job->of)) {
    host.log("Freeze: the site changed while it grew; freeze again", true);
    return;
  }
  try {
    std::vector<ObjectId> added;
    Document d = freezeGrowth(*host.doc, host.object, job->grown, &added);
    host.commit(std::move(d), "Freeze the units of " + o->name, "");
    host.log("Froze " + std::to_string(added.size()) + " units of " + o->name +
             " into unit objects; the site grows around them", false);
  } catch (const std::exception& e) {
    host.log(std::string("Freeze: ") + e.what(), true);
  }
}

void GrowthPanel::draw(const GrowthHost& host, float x, float y, float w, float h) {
  const GrowthSpec* spec = specOf(host);
  if (!spec) return;
  applyFreeze(host);
  const DocObject* o = host.doc->find(host.object);
  parseSite(*spec);
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Growth", nullptr, kPaneFlags);
  ImGui::Text("%s: growth site (Ng, Ch. 4)", o->name.c_str());
  if (!summary_.empty()) ImGui::TextWrapped("%s", summary_.c_str());
  if (!host.error.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", host.error.c_str());
    ImGui::PopTextWrapPos();
  }
  statsShown_ = false;
  siteShown_ = false;
  if (ImGui::BeginTabBar("growthTabs")) {
    const char* names[3] = {"Grow", "Site", "Statistics"};
    for (int t = 0; t < 3; ++t) {
      const ImGuiTabItemFlags flags = wantTab_ == t ? ImGuiTabItemFlags_SetSelected : 0;
      if (!ImGui::BeginTabItem(names[t], nullptr, flags)) continue;
      ImGui::BeginChild("tab");
      if (t == 0) drawGrow(host, *spec);
      if (t == 1) {
        siteShown_ = true;
        drawSite(host, *spec);
      }
      if (t == 2) {
        statsShown_ = true;
        drawStatistics(host);
      }
      ImGui::EndChild();
      ImGui::EndTabItem();
    }
    wantTab_ = -1;
    ImGui::EndTabBar();
  }
  ImGui::End();
  if (statsShown_ || showViewMaps_) requestInspection(host, growth::growthInputOf(*host.doc, *o));
}

bool GrowthPanel::beginViewDrag(const GrowthHost& host, const Vec3& origin, const Vec3& dir) {
  viewGrab_.reset();
  const DocObject* o = host.doc->find(host.object);
  const auto* spec = o ? std::get_if<GrowthSpec>(&o->spec) : nullptr;
  if (!spec || !siteShown_) return false;
  parseSite(*spec);
  if (!site_) return false;
  viewGrab_ = grabInView(hand_, *site_, origin, dir);
  if (!viewGrab_) return false;
  dragFrom_ = hand_;
  dragPlan_ = site_->plan;
  if (viewGrab_->item) {
    kind_ = *viewGrab_->item;
    selected_ = viewGrab_->index;
    if (kind_ == SiteItem::Seed) planStorey_ = hand_.seeds[std::size_t(selected_)].storey;
  }
  return true;
}

void GrowthPanel::viewDrag(const GrowthHost& host, const Vec3& origin, const Vec3& dir) {
  if (!viewGrab_) return;
  const DocObject* o = host.doc->find(host.object);
  const auto* spec = o ? std::get_if<GrowthSpec>(&o->spec) : nullptr;
  if (!spec) return;
  parseSite(*spec);
  if (!site_) return;
  const auto p = rayOnPlane(origin, dir, viewGrab_->z);
  if (!p) return;
  const double dx = (*p)[0] - viewGrab_->at[0], dy = (*p)[1] - viewGrab_->at[1];
  const std::string where = std::to_string(host.object);
  if (viewGrab_->item) {
    const SiteItem item = *viewGrab_->item;
    const int i = viewGrab_->index;
    if (const auto r = dragItem(*spec, dragFrom_, hand_, item, i, dx, dy))
      commitSite(host, *r, "Move " + std::string(itemName(item)) + " " + std::to_string(i + 1),
                 "site" + where + itemName(item) + std::to_string(i) + " in view", false);
  } else if (const auto r = dragEnvelopeCorner(*spec, dragPlan_, site_->plan, viewGrab_->index, dx, dy)) {
    commitSite(host, *r, "Move corner " + std::to_string(viewGrab_->index + 1) + " of the envelope",
               "site" + where + "envelope corner" + std::to_string(viewGrab_->index) + " in view", false);
  }
}

void GrowthPanel::endViewDrag(const GrowthHost& host) {
  if (!viewGrab_) return;
  viewGrab_.reset();
  host.endDrag();
  if (!siteError_.empty()) host.log("Site edit refused: " + siteError_, true);
}

void GrowthPanel::drawViewOverlay(render::Overlay& overlay) const {
  if (!siteShown_ || !site_) return;
  const growth::Site& site = *site_;
  const render::Rgba frame{0.3f, 0.42f, 0.65f, 1}, chosen{1.0f, 0.84f, 0.2f, 1};
  const std::size_t n = site.plan.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = site.plan[i], &b = site.plan[(i + 1) % n];
    const bool held = viewGrab_ && !viewGrab_->item && viewGrab_->index == int(i);
    for (double z : {site.base, site.top()}) overlay.line(Vec3(a[0], a[1], z), Vec3(b[0], b[1], z), frame);
    overlay.line(Vec3(a[0], a[1], site.base), Vec3(a[0], a[1], site.top()), held ? chosen : frame);
  }
  if (selected_ < 0 || selected_ >= itemCount(hand_, kind_)) return;
  Vec3 lo, hi;
  if (kind_ == SiteItem::Core) {
    const growth::Rect& c = hand_.cores[std::size_t(selected_)];
    lo = Vec3(c.u0, c.v0, site.base), hi = Vec3(c.u1, c.v1, site.top());
  } else if (kind_ == SiteItem::Circulation) {
    const growth::Box& c = hand_.circulation[std::size_t(selected_)];
    lo = Vec3(c.lo[0], c.lo[1], c.lo[2]), hi = Vec3(c.hi[0], c.hi[1], c.hi[2]);
  } else {
    const growth::Seed& s = hand_.seeds[std::size_t(selected_)];
    const double z = site.base + s.storey * site.storeyHeight;
    lo = Vec3(s.at[0], s.at[1], z), hi = Vec3(s.at[0] + s.size[0], s.at[1] + s.size[1], z + site.storeyHeight);
  }
  const Vec3 c[8] = {Vec3(lo[0], lo[1], lo[2]), Vec3(hi[0], lo[1], lo[2]), Vec3(hi[0], hi[1], lo[2]),
                     Vec3(lo[0], hi[1], lo[2]), Vec3(lo[0], lo[1], hi[2]), Vec3(hi[0], lo[1], hi[2]),
                     Vec3(hi[0], hi[1], hi[2]), Vec3(lo[0], hi[1], hi[2])};
  for (int k = 0; k < 4; ++k) {
    overlay.line(c[k], c[(k + 1) % 4], chosen);
    overlay.line(c[4 + k], c[4 + (k + 1) % 4], chosen);
    overlay.line(c[k], c[4 + k], chosen);
  }
}

}  // namespace corbel::editor
