// The editor's own panels: the object list and properties on the left, the status and log bar,
// the help window and the modal dialogs (unsaved changes, recovery, errors).
#include "editor/app.h"

#include "core/materials.h"
#include "editor/fields.h"
#include "editor/widget_marks.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace corbel::editor {

// A unit object by hand (editor/unit_edits.h): split by a plane, merged with a unit it touches;
// P pushes its walls. Each is one undo step.
void App::drawUnitEdits(const DocObject& object) {
  ImGui::TextDisabled("P pushes a wall past what it meets (Ng Fig. 8.4)");
  const auto& u = std::get<UnitSpec>(object.spec);
  if (unitSplit_.object != object.id) {  // the plane starts across the middle of the unit's x extent
    double lo = u.parts[0].lo[0], hi = u.parts[0].hi[0];
    for (const UnitPart& p : u.parts) {
      lo = std::min(lo, p.lo[0]);
      hi = std::max(hi, p.hi[0]);
    }
    unitSplit_ = {object.id, 0, 0.5 * (lo + hi)};
  }
  ImGui::RadioButton("x =", &unitSplit_.axis, 0);
  ImGui::SameLine();
  ImGui::RadioButton("y =", &unitSplit_.axis, 1);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  ImGui::InputDouble("##splitAt", &unitSplit_.at, 0, 0, "%.2f m");
  ImGui::SameLine();
  if (ImGui::Button("Split")) {
    try {
      ObjectId added = 0;
      Document d = splitUnit(history_.current(), object.id, unitSplit_.axis, unitSplit_.at, &added);
      deferredCommit()(std::move(d), "Split " + object.name, "");  // after the panel: `object` stays valid
      log("Split " + object.name + " at " + (unitSplit_.axis ? "y" : "x") + " = " + std::to_string(unitSplit_.at));
    } catch (const std::exception& e) {
      log("Split " + object.name + ": " + e.what(), true);
    }
  }
  // The units it touches over a face, each a merge.
  std::vector<ObjectId> touching;
  for (const DocObject& other : history_.current().objects) {
    if (other.id == object.id || !std::holds_alternative<UnitSpec>(other.spec)) continue;
    try {
      mergeUnits(history_.current(), object.id, other.id);
      touching.push_back(other.id);
    } catch (const std::exception&) {
    }
  }
  if (touching.empty()) {
    ImGui::TextDisabled("No unit touches it over a face to merge with.");
    return;
  }
  if (ImGui::BeginCombo("Merge with", "a unit it touches")) {
    for (ObjectId id : touching) {
      const DocObject* other = history_.current().find(id);
      if (ImGui::Selectable(other->name.c_str())) {
        deferredCommit()(mergeUnits(history_.current(), object.id, id), "Merge " + other->name + " into " + object.name, "");
        ImGui::EndCombo();
        return;
      }
    }
    ImGui::EndCombo();
  }
}

void App::drawObjectProperties(const DocObject& object) {
  Document d = history_.current();
  DocObject* o = d.find(object.id);
  const std::string key = "obj" + std::to_string(object.id) + ".";
  bool changed = false;
  std::string label, field;
  auto edited = [&](const char* what, const char* fieldName) {
    changed = true;
    label = std::string("Edit ") + what + " of " + object.name;
    field = fieldName;
  };

  if (std::string n; commitText("Name", o->name, n, limits::kMaxNameLength)) {
    if (n.empty())
      log("An object needs a name.", true);
    else if (n != o->name && d.findByName(n))
      log("Another object is already called \"" + n + "\".", true);
    else if (n != o->name) {
      o->name = n;
      edited("name", "name");
    }
  }
  if (auto* bp = std::get_if<BoxSpec>(&o->spec)) {
    BoxSpec& b = *bp;
    ImGui::Separator();
    ImGui::TextDisabled("Box");
    float origin[3] = {float(b.origin[0]), float(b.origin[1]), float(b.origin[2])};
    if (ImGui::DragFloat3("Origin (m)", origin, 0.1f, -1e5f, 1e5f, "%.2f")) {
      b.origin = Vec3(origin[0], origin[1], origin[2]);
      edited("origin", "origin");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    float size[3] = {float(b.size[0]), float(b.size[1]), float(b.size[2])};
    if (ImGui::DragFloat3("Size (m)", size, 0.05f, 0.1f, 1e4f, "%.2f", ImGuiSliderFlags_AlwaysClamp)) {
      b.size = Vec3(size[0], size[1], size[2]);
      edited("size", "size");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    float rot = float(b.rotation_deg);
    if (ImGui::DragFloat("Rotation (°)", &rot, 0.5f, -360.f, 360.f, "%.1f")) {
      b.rotation_deg = rot;
      edited("rotation", "rotation");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    if (ImGui::BeginCombo("Material", b.material.c_str())) {
      for (const auto& m : builtinMaterials()) {
        const Rgb c = m.color;
        ImGui::ColorButton(("##c" + std::string(m.name)).c_str(), ImVec4(c[0], c[1], c[2], 1),
                           ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
        ImGui::SameLine();
        if (ImGui::Selectable(std::string(m.name).c_str(), b.material == m.name)) {
          b.material = m.name;
          edited("material", "");
        }
      }
      ImGui::EndCombo();
    }
    int rep[2] = {b.repeat_x, b.repeat_y};
    if (ImGui::DragInt2("Repeat", rep, 0.1f, 1, 100, "%d", ImGuiSliderFlags_AlwaysClamp)) {
      b.repeat_x = std::max(1, rep[0]);
      b.repeat_y = std::max(1, rep[1]);
      edited("repeat", "repeat");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    float spacing[2] = {float(b.spacing_x), float(b.spacing_y)};
    if (ImGui::DragFloat2("Spacing (m)", spacing, 0.1f, -1e3f, 1e3f, "%.2f")) {
      b.spacing_x = spacing[0];
      b.spacing_y = spacing[1];
      edited("spacing", "spacing");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    if (changed) {
      if (auto problem = checkBoxSpec(b)) {
        log(object.name + ": " + *problem, true);
        changed = false;
      }
    }
  } else if (auto* e = std::get_if<ExtrusionSpec>(&o->spec)) {
    ImGui::Separator();
    ImGui::TextDisabled("Procedural extrusion");
    std::size_t corners = 0;
    for (const auto& l : e->loops) corners += l.points.size();
    ImGui::Text("%zu loop%s, %zu corners, %zu profile%s", e->loops.size(), e->loops.size() == 1 ? "" : "s", corners,
                e->profiles.size(), e->profiles.size() == 1 ? "" : "s");
    if (ImGui::BeginCombo("Material", e->material.c_str())) {
      for (const auto& m : builtinMaterials())
        if (ImGui::Selectable(std::string(m.name).c_str(), e->material == m.name)) {
          e->material = m.name;
          edited("material", "");
        }
      ImGui::EndCombo();
    }
    float base = float(e->baseZ);
    if (ImGui::DragFloat("Base height (m)", &base, 0.05f, -1e4f, 1e4f, "%.2f")) {
      e->baseZ = base;
      edited("base height", "base");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    // Sec. 4.8's three schemes, in the order of the enum; manual ranks the profile segments
    // tagged "high" over untagged ones over "low" ones.
    constexpr Priority kPriorities[] = {Priority::MaximiseVolume, Priority::MinimiseVolume, Priority::Manual};
    int priority = 0;
    while (priority < 2 && kPriorities[priority] != e->priority) ++priority;
    if (marks::combo("Ambiguity", &priority, "maximise volume\0minimise volume\0manual (segment tags high, low)\0",
                     "ambiguity")) {
      e->priority = kPriorities[priority];
      edited("ambiguity priority", "");
    }
    for (const Profile& p : e->profiles)
      ImGui::BulletText("%s: %zu segment%s", p.name.c_str(), p.points.size() - 1, p.points.size() == 2 ? "" : "s");
  } else if (auto* t = std::get_if<TownSpec>(&o->spec)) {
    ImGui::Separator();
    ImGui::TextDisabled("Town from footprints (Kelly & Wonka Sec. 3.7); edit it in the Town panel");
    ImGui::Text("seed %llu, %s detail, %zu override%s", static_cast<unsigned long long>(t->seed), t->detail.c_str(),
                t->overrides.size(), t->overrides.size() == 1 ? "" : "s");
  } else if (auto* u = std::get_if<UnitSpec>(&o->spec)) {
    ImGui::Separator();
    ImGui::TextDisabled("Housing unit (Ng Sec. 5.1): frozen from a growth site, or a completed form's");
    double floor = 0;
    for (const UnitPart& p : u->parts) floor += (p.hi[0] - p.lo[0]) * (p.hi[1] - p.lo[1]);
    ImGui::Text("%zu part%s, floor area %.1f m²", u->parts.size(), u->parts.size() == 1 ? "" : "s", floor);
    if (ImGui::BeginCombo("Material", u->material.c_str())) {
      for (const auto& m : builtinMaterials())
        if (ImGui::Selectable(std::string(m.name).c_str(), u->material == m.name)) {
          u->material = m.name;
          edited("material", "");
        }
      ImGui::EndCombo();
    }
    drawUnitEdits(object);
  }
  // A pick from a list (a material, the priority) is an undo step of its own; typed and dragged
  // values merge while the same field keeps changing.
  if (changed) commit(std::move(d), label, field.empty() ? std::string() : key + field);

  ImGui::Separator();
  ImGui::TextDisabled("Shell");
  if (const auto* k = std::get_if<KifsSpec>(&object.spec); k && k->meshResolution == 0) {
    ImGui::TextWrapped("Ray-marched: no shell in the Scene (KIFS panel > Mesh to Scene makes one).");
    return;
  }
  // What the view shows of an object whose build failed is its last good shell, if any: the
  // verdict below is about that shell, not the object as it is now.
  const auto st = sync_.status().find(object.id);
  const std::string error = st == sync_.status().end() ? std::string() : st->second.error;
  if (!error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.35f, 1));
    ImGui::TextWrapped("Not built: %s", error.c_str());
    ImGui::PopStyleColor();
    if (!scene_.hasObject(object.id)) return;
    ImGui::TextDisabled("The view shows the last shell that built:");
  } else if (!scene_.hasObject(object.id)) {
    ImGui::TextDisabled(live_.current() ? "No shell." : "Building...");
    return;
  } else if (!live_.current()) {
    ImGui::TextDisabled("Updating: the numbers are the previous shell's.");
  }
  const ValidityReport r = scene_.validate(object.id);
  ImGui::Text("%zu faces, %zu vertices, %zu edges", r.faces, r.vertices, r.edges);
  ImGui::Text("Euler characteristic %ld, %zu component%s", r.euler, r.components, r.components == 1 ? "" : "s");
  ImGui::Text("Area %.2f m², volume %.2f m³", r.area, r.volume);
  if (r.closedManifold() && error.empty() && live_.current())
    ImGui::TextColored(ImVec4(0.4f, 0.85f, 0.4f, 1), "closed, 2-manifold, consistent");
  else if (r.closedManifold())
    ImGui::TextDisabled("(that shell was closed and 2-manifold)");
  for (const auto& p : r.problems()) ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", p.c_str());
}

namespace {

// Begins a window without title or frame that fills the part of the layout `part` picks.
void beginFixedWindow(const char* name, Rect Layout::*part, const PanelSizes& sizes) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const Rect r = layoutWindow(vp->Size.x, vp->Size.y, ImGui::GetFrameHeight(), false, sizes).*part;
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + r.x, vp->Pos.y + r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  ImGui::Begin(name, nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus);
}

}  // namespace

void App::drawLeftPanel() {
  if (!panelSizes().leftShown) return;  // hidden by its splitter or View > Left Panel
  beginFixedWindow("Panel", &Layout::leftPanel, panelSizes());
  ImGui::PushItemWidth(-110.0f);  // leave room for the labels
  const Document& current = history_.current();
  ImGui::Separator();
  ImGui::TextDisabled("Objects");
  if (current.objects.empty()) ImGui::TextDisabled("No objects. Object > Add Box (Ctrl+B).");
  for (const DocObject& o : current.objects) {
    ImGui::PushID(static_cast<int>(o.id));
    bool visible = o.visible;
    if (ImGui::Checkbox("##visible", &visible)) {
      Document d = current;
      d.find(o.id)->visible = visible;
      commit(std::move(d), std::string(visible ? "Show " : "Hide ") + o.name);
      ImGui::PopID();
      break;  // `current` changed
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Visible");
    ImGui::SameLine();
    // An object whose build failed is flagged: a red mark before its name, the kernel's message
    // in the tooltip.
    if (const auto st = sync_.status().find(o.id); st != sync_.status().end() && !st->second.error.empty()) {
      ImGui::TextColored(ImVec4(1, 0.35f, 0.3f, 1), "(!)");
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Not built: %s", st->second.error.c_str());
      ImGui::SameLine();
    }
    // The list follows the view: every selected object highlighted, the one under the pointer in
    // the view brighter, a locked one marked; Shift adds, Ctrl toggles, as in the view.
    const bool hovered = selection_.hover == o.id;
    if (hovered) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.4f, 1.0f));
    if (ImGui::Selectable((o.name + (o.locked ? "  (locked)" : "")).c_str(), selection_.contains(o.id))) {
      const ImGuiIO& io = ImGui::GetIO();
      if (io.KeyCtrl) selection_.toggle(o.id);
      else if (io.KeyShift) selection_.add(o.id);
      else selection_.select(o.id);
      listFollows_ = selected();  // chosen here: no need to scroll to it
    }
    if (hovered) ImGui::PopStyleColor();
    if (selected() == o.id && listFollows_ != o.id) {
      ImGui::SetScrollHereY(0.3f);  // picked in the view: bring it into the list's sight
      listFollows_ = o.id;
    }
    ImGui::PopID();
  }
  if (selected()) {
    if (const DocObject* o = history_.current().find(*selected())) drawObjectProperties(*o);
    if (const DocObject* o = selected() ? history_.current().find(*selected()) : nullptr) drawPlacementFields(*o);
    if (stoneFor_ && selected() == stoneFor_) stone_.draw(staticsHost());
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

void App::drawStatusBar() {
  beginFixedWindow("Status", &Layout::statusBar, panelSizes());
  if (job_) {
    ImGui::ProgressBar(static_cast<float>(job_->progress().fraction()), ImVec2(260, 0),
                       (job_->title() + " " + job_->progress().stage()).c_str());
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) job_->progress().cancel();
    ImGui::SameLine();
  }
  if (live_.cancelled()) {
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "Build cancelled (the view shows the previous result)");
    ImGui::SameLine();
  } else if (!live_.current()) {
    // A build longer than a frame runs off the UI thread; the 3D view keeps the last result.
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "Updating geometry... (the view shows the previous result)");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "An edit takes longer than a frame to build: it runs in the background and the newest edit wins");
    ImGui::SameLine();
  }
  ImGui::Text("%s%s  |  %zu objects, %zu triangles  |  %.0f fps", path_.empty() ? "(unsaved project)" : path_.c_str(),
              history_.dirty() ? " *" : "", history_.current().objects.size(), renderer_->triangleCount(),
              ImGui::GetIO().Framerate);
  ImGui::Separator();
  ImGui::BeginChild("log");
  for (const LogLine& l : log_) {
    if (l.error)
      ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", l.text.c_str());
    else
      ImGui::TextUnformatted(l.text.c_str());
  }
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY() - 4) ImGui::SetScrollHereY(1.0f);
  ImGui::EndChild();
  ImGui::End();
}

void App::drawModals() {
  if (showUnsavedPrompt_) {
    ImGui::OpenPopup("Unsaved changes");
    showUnsavedPrompt_ = false;
  }
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The project has unsaved changes. Save them first?");
    if (ImGui::Button("Save")) {
      ImGui::CloseCurrentPopup();
      if (!path_.empty() && saveTo(path_)) {
        if (afterUnsavedPrompt_) afterUnsavedPrompt_();
      } else if (path_.empty()) {
        auto then = afterUnsavedPrompt_;
        fileDialog_.open(FileDialog::Mode::Save, "Save project as", {".corbel"}, "",
                         [this, then](const std::string& p) {
                           if (saveTo(p) && then) then();
                         });
      }
      afterUnsavedPrompt_ = nullptr;
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      ImGui::CloseCurrentPopup();
      history_.markSaved();  // the user chose to drop them
      recovery_.discard();
      if (afterUnsavedPrompt_) afterUnsavedPrompt_();
      afterUnsavedPrompt_ = nullptr;
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      ImGui::CloseCurrentPopup();
      afterUnsavedPrompt_ = nullptr;
    }
    ImGui::EndPopup();
  }

  if (!recoveryOffers_.empty() && !ImGui::IsPopupOpen("Recover unsaved work?")) ImGui::OpenPopup("Recover unsaved work?");
  if (ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("corbel found work that was not saved when its window closed:");
    ImGui::Text("(this window's document is kept until you choose)");
    std::optional<std::size_t> recovered, dropped;
    if (ImGui::BeginTable("recoverable", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders)) {
      for (std::size_t i = 0; i < recoveryOffers_.size(); ++i) {
        const RecoveredWork& w = recoveryOffers_[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%s", w.originalPath.empty() ? "a new project" : w.originalPath.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%s, %zu objects", w.savedAt.empty() ? "autosaved" : w.savedAt.c_str(), w.document.objects.size());
        ImGui::TableNextColumn();
        if (ImGui::Button("Recover")) recovered = i;
        ImGui::SameLine();
        if (ImGui::Button("Discard")) dropped = i;
        ImGui::PopID();
      }
      ImGui::EndTable();
    }
    if (recoveryOffers_.size() > 1)
      ImGui::TextWrapped("The work not recovered now is offered again the next time corbel starts.");
    if (ImGui::Button("Later")) {
      recoveryOffers_.clear();
      ImGui::CloseCurrentPopup();
    }
    if (recovered) {
      recover(recoveryOffers_[*recovered]);
      recoveryOffers_.clear();  // the rest stay on disk for the next start
      ImGui::CloseCurrentPopup();
    } else if (dropped) {
      recovery_.discardOrphan(recoveryOffers_[*dropped]);
      recoveryOffers_.erase(recoveryOffers_.begin() + static_cast<long>(*dropped));
      if (recoveryOffers_.empty()) ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  if (showError_) {
    ImGui::OpenPopup("Error");
    showError_ = false;
  }
  if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushTextWrapPos(560);
    ImGui::TextUnformatted(errorMessage_.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("OK")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  fileDialog_.draw();
}

}  // namespace corbel::editor
