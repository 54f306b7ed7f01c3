#include "editor/kifs_panel.h"

#include "editor/symbols.h"

#include "editor/kifs_edits.h"
#include "editor/pane_window.h"
#include "editor/widget_marks.h"
#include "kifs/mesher.h"
#include "kifs/params.h"

#include <imgui.h>

#include <vector>

namespace corbel::editor {

namespace {

// One slider of a spec field: its label, the field and its range.
struct Field {
  const char* label;
  double* value;
  float lo, hi;
};

void heading(const char* text) {
  ImGui::Separator();
  ImGui::TextDisabled("%s", text);
}

}  // namespace

const char* kifsViewName(KifsView view) {
  switch (view) {
    case KifsView::Facades: return "Facade ids";
    case KifsView::Floors: return "Floors";
    case KifsView::Bare: return "Fractal alone";
    default: return "Shaded";
  }
}

void KifsPanel::draw(const KifsHost& host, float x, float y, float w, float h) {
  const DocObject* o = host.doc ? host.doc->find(host.object) : nullptr;
  const auto* current = o ? std::get_if<KifsSpec>(&o->spec) : nullptr;
  if (!current) return;
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("KIFS building", nullptr, kPaneFlags);
  ImGui::PushItemWidth(-150.0f);
  const std::string key = "kifs" + std::to_string(host.object) + ".";
  KifsSpec s = *current;
  std::string label, merge;  // set by the control that changed
  auto changed = [&](const std::string& what, bool drag = true) {
    label = "Edit " + what + " of " + o->name;
    merge = drag ? key + what : std::string();
  };
  auto sliders = [&](std::initializer_list<Field> fields) {
    for (const Field& f : fields) {
      float v = float(*f.value);
      if (ImGui::SliderFloat(f.label, &v, f.lo, f.hi, "%.3f")) {
        *f.value = v;
        changed(f.label);
      }
      explainSymbol(f.label);
      if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
    }
  };

  ImGui::Text("%s: KIFS building (McGraw)", o->name.c_str());
  if (ImGui::BeginCombo("Preset", s.preset.empty() ? "(none)" : s.preset.c_str())) {
    for (const std::string& name : kifs::presetNames())
      if (ImGui::Selectable(name.c_str(), name == s.preset)) {
        s = withPreset(s, name);
        label = "Apply the KIFS preset " + name + " to " + o->name;
      }
    ImGui::EndCombo();
  }
  if (!host.error.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", host.error.c_str());
    ImGui::PopTextWrapPos();
  }

  int view = int(view_);
  if (marks::combo("View", &view, "Shaded\0Facade ids (Fig. 5-6)\0Floors\0Fractal alone (Fig. 3c)\0", "kifs: view")) {
    view_ = KifsView(view);
    if (host.log) host.log(std::string("KIFS view: ") + kifsViewName(view_), false);
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "What the view shows of every ray-marched KIFS building: shaded; one colour per facade id "
        "(id_x + 4 id_z); one colour per storey; or the fractal carved by the outer shell alone, "
        "without the inner shell's walls");

  heading("Mass model");
  int footprint = s.mass.footprint == "T" ? 1 : s.mass.footprint == "H" ? 2 : s.mass.footprint == "object" ? 3 : 0;
  if (ImGui::Combo("Footprint", &footprint, "box\0T\0H\0another object\0")) {
    s.mass.footprint = footprint == 1 ? "T" : footprint == 2 ? "H" : footprint == 3 ? "object" : "box";
    if (footprint == 3 && s.mass.object.empty())
      for (const DocObject& m : host.doc->objects)  // the first object that can be a mass
        if (m.id != o->id && !std::holds_alternative<KifsSpec>(m.spec) && !std::holds_alternative<TownSpec>(m.spec)) {
          s.mass.object = m.name;
          break;
        }
    changed("footprint", false);
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The mass the fractal is carved from: a box, T or H of the sizes below, or another object's shell");
  if (s.mass.footprint == "object") {
    auto buildingsOf = [&](const DocObject& town) {
      return host.townBuildings ? host.townBuildings(town.id) : std::vector<std::string>{};
    };
    if (ImGui::BeginCombo("Follows", s.mass.object.empty() ? "(choose an object)" : s.mass.object.c_str())) {
      for (const DocObject& m : host.doc->objects)
        if (m.id != o->id && ImGui::Selectable(m.name.c_str(), m.name == s.mass.object)) {
          s.mass.object = m.name;
          s.mass.building.clear();
          if (std::holds_alternative<TownSpec>(m.spec))  // a town: one of its buildings, the first to start with
            if (const auto ids = buildingsOf(m); !ids.empty()) s.mass.building = ids.front();
          changed("the followed object", false);
        }
      ImGui::EndCombo();
    }
    const DocObject* followed = host.doc->findByName(s.mass.object);
    if (followed && std::holds_alternative<TownSpec>(followed->spec)) {
      const std::vector<std::string> ids = buildingsOf(*followed);
      if (ImGui::BeginCombo("Building", s.mass.building.empty() ? "(the whole town)" : s.mass.building.c_str(),
                            ImGuiComboFlags_HeightLarge)) {
        ImGuiListClipper clipper;  // a town may have thousands
        clipper.Begin(int(ids.size()));
        while (clipper.Step())
          for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i)
            if (ImGui::Selectable(ids[i].c_str(), ids[i] == s.mass.building)) {
              s.mass.building = ids[i];
              changed("the followed building", false);
            }
        ImGui::EndCombo();
      }
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The footprint id of the town's building the fractal follows (the Town panel shows ids)");
    }
    int resolution = s.mass.resolution;
    if (ImGui::SliderInt("Resolution", &resolution, 8, 256, "%d cells")) {
      s.mass.resolution = resolution;
      changed("resolution");
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Cells of the baked distance along the mass's longest side (baked in the background)");
    if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
    ImGui::PushTextWrapPos(0);
    ImGui::TextDisabled("(follows the object where it stands: this object's placement is ignored)");
    ImGui::PopTextWrapPos();
    sliders({{"Shell", &s.mass.shell, 0, 5}});
  } else {
    sliders({{"Half width", &s.mass.halfWidth, 1, 40},
             {"Half depth", &s.mass.halfDepth, 1, 40},
             {"Height", &s.mass.height, 2, 100},
             {"Wing", &s.mass.wing, 0.2f, 20},
             {"Shell", &s.mass.shell, 0, 5}});
  }
  if (ImGui::Checkbox("Curvilinear (Eq. 5-6)", &s.curvilinear.enabled)) changed("curvilinear", false);
  if (s.curvilinear.enabled)
    sliders({{"s_theta", &s.curvilinear.sTheta, 0.5f, 40},
             {"c_theta", &s.curvilinear.cTheta, -3.1416f, 3.1416f},
             {"s_r", &s.curvilinear.sR, 0.1f, 5},
             {"c_r", &s.curvilinear.cR, -40, 10},
             {"z0", &s.curvilinear.z0, -40, 40}});

  heading("Facade and fractal (Sec. 4)");
  double rx = s.facade.r[0], ry = s.facade.r[1], rz = s.facade.r[2];
  double cx = s.centre[0], cy = s.centre[1], cz = s.centre[2], theta = s.r2[1];
  sliders({{"w (bay)", &s.facade.period, 0.5f, 20},
           {"r1 (width)", &rx, 0, 0.5f},
           {"r2 (width)", &ry, 0, 0.5f},
           {"r3 (width)", &rz, 0, 0.5f},
           {"a1", &s.facade.a1, -2, 2},
           {"a2", &s.facade.a2, 0.05f, 4},
           {"b1", &s.facade.b1, -2, 2},
           {"b2", &s.facade.b2, -2, 2},
           {"x_c", &cx, 0, 2},
           {"y_c", &cy, 0, 2},
           {"z_c", &cz, 0, 2},
           {"R2 theta (deg)", &theta, -180, 180}});
  s.facade.r = Vec3(rx, ry, rz);
  s.centre = Vec3(cx, cy, cz);
  s.r2[1] = theta;

  heading("Storeys (Eq. 4)");
  sliders({{"h (storey)", &s.floors.height, 0.5f, 10},
           {"y0 (storey start)", &s.floors.y0, -10, 10},
           {"s_y (storey scale)", &s.floors.sy, 0.1f, 4}});

  if (ImGui::CollapsingHeader("Advanced")) {
    if (ImGui::SliderInt("M (iterations)", &s.iterations, 0, kifs::kMaxIterations)) changed("iterations");
    explainSymbol("M (iterations)");
    if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
    double r1x = s.r1[0], r1y = s.r1[1], r1z = s.r1[2];
    sliders({{"s (scale)", &s.scale, 1.05f, float(kifs::kMaxScale)},
             {"R1 x (deg)", &r1x, -180, 180},
             {"R1 y (deg)", &r1y, -180, 180},
             {"R1 z (deg)", &r1z, -180, 180},
             {"Bailout", &s.bailout, 4, 5000}});
    s.r1 = Vec3(r1x, r1y, r1z);
    if (ImGui::SliderInt("Steps", &s.trace.maxSteps, 16, 1000)) changed("steps");
    if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
  }

  heading("Mesh");
  if (s.meshResolution > 0) {
    ImGui::Text("Meshed into the Scene at %d cells", s.meshResolution);
    if (host.building) {
      ImGui::ProgressBar(float(host.fraction), ImVec2(-110, 0), "meshing");
      ImGui::SameLine();
    }
    if (ImGui::Button(host.building ? "Cancel" : "Ray-march only")) {
      s.meshResolution = 0;
      label = "Ray-march " + o->name;
    }
  } else {
    ImGui::SliderInt("Resolution", &resolution_, 16, 512);
    if (ImGui::Button("Mesh to Scene")) {
      s.meshResolution = resolution_;
      label = "Mesh " + o->name;
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Extract the building as a closed triangle mesh (marching tetrahedra), exportable like any object");
  }
  ImGui::PopItemWidth();
  ImGui::End();

  if (label.empty() || s == *current) return;
  Document d = *host.doc;
  try {
    setKifsSpec(d, host.object, s);
    host.commit(std::move(d), label, merge);
  } catch (const std::exception& e) {
    host.log(o->name + ": " + e.what(), true);
  }
}

}  // namespace corbel::editor
