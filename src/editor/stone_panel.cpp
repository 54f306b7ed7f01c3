#include "editor/stone_panel.h"

#include "editor/statics_panel_parts.h"
#include "editor/stone_edits.h"
#include "editor/widget_marks.h"

#include <imgui.h>

namespace corbel::editor {

using namespace statics_panel;

namespace {

const ExtrusionSpec* extrusionOf(const StaticsHost& host) {
  const DocObject* o = objectOf(host);
  return o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr;
}

// The section's settings as the panel shows them: the stone model's parameter, its label and
// its value in the section.
struct Setting {
  const char* name;
  const char* label;
  double value;
  float speed;
  const char* format;
};

std::vector<Setting> settingsOf(const StoneWalls& m) {
  return {{"thickness", "wall thickness", m.thickness, 0.01f, "%.3f m"},
          {"courseHeight", "course height", m.courseHeight, 0.01f, "%.3f m"},
          {"blockLength", "block length", m.blockLength, 0.01f, "%.3f m"},
          {"coveringWeight", "roof covering", m.coveringWeight, 10.0f, "%.0f N/m²"},
          {"density", "stone density", m.density, 10.0f, "%.0f kg/m³"},
          {"windPressure", "wind pressure", m.windPressure, 10.0f, "%.0f N/m²"},
          {"windDirection", "wind towards", m.windDirection, 1.0f, "%.0f°"}};
}

}  // namespace

StonePanel::~StonePanel() {
  if (analysis_) analysis_->progress().cancel();
  if (search_) search_->progress().cancel();
}

void StonePanel::reset() {
  analysis_.reset();
  search_.reset();
  analysing_.reset();
  shown_.reset();
  lastChanges_.clear();
}

void StonePanel::update(const StaticsHost& host) {
  if (search_) finishSearch(host);
  if (analysis_) {
    std::string error;
    if (collect(analysis_, host.wait, &error) && analysing_) shown_ = *analysing_;
    if (!error.empty()) host.log("Stone analysis: " + error, true);
  }
  const ExtrusionSpec* e = extrusionOf(host);
  if (!e || !e->masonry || analysis_) return;
  if ((shown_ && shown_->spec == *e) || (analysing_ && analysing_->spec == *e)) return;
  auto work = std::make_shared<Analysis>();
  work->spec = *e;
  analysing_ = work;
  analysis_ = std::make_unique<BackgroundJob>("Stone analysis", [work](Progress& progress) {
    work->view = analyseStone(work->spec, &progress);
  });
  if (host.wait) update(host);
}

void StonePanel::makeItStand(const StaticsHost& host) {
  const ExtrusionSpec* e = extrusionOf(host);
  if (!e || !e->masonry || search_) return;
  searchStart_ = *e;
  searchObject_ = host.object;
  auto result = std::make_shared<statics::SearchResult>();
  searchResult_ = result;
  const ExtrusionSpec start = *e;
  const bool addButtresses = addButtresses_;
  host.log("Make the stone walls stand…", false);
  search_ = std::make_unique<BackgroundJob>("Make the walls stand", [result, start, addButtresses](Progress& progress) {
    const std::vector<statics::FreeParameter> free = stoneSearchFree(start, addButtresses);
    *result = searchStone(start, &progress, 200, &free);
    if (result->status == statics::SearchStatus::Cancelled) progress.cancel();
  });
  if (host.wait) finishSearch(host);
}

void StonePanel::finishSearch(const StaticsHost& host) {
  std::string error;
  const bool cancelled = search_ && search_->progress().cancelled();
  const bool ok = collect(search_, host.wait, &error);
  if (search_) return;  // still running
  if (!ok) {
    host.log(cancelled ? "Make the walls stand: cancelled, nothing changed" : "Make the walls stand failed: " + error,
             !cancelled);
    return;
  }
  std::string why;
  const auto next = applyStoneSearch(*host.doc, searchObject_, searchStart_, *searchResult_, &why);
  if (!next) {
    host.log("Make the walls stand: " + why, true);
    return;
  }
  lastChanges_.clear();
  for (const statics::FreeParameter& f : searchResult_->free) {
    for (const Setting& s : settingsOf(*searchStart_.masonry))
      if (f.name == s.name && s.value != searchResult_->values[f.name])
        lastChanges_.push_back({s.label, s.value, searchResult_->values[f.name]});
    const double depth = buttressDepthOf(searchStart_);
    if (f.name == "buttressDepth" && depth != searchResult_->values[f.name])
      lastChanges_.push_back({"buttress depth", depth, searchResult_->values[f.name]});
  }
  const DocObject* o = host.doc->find(searchObject_);
  host.commit(*next, "Make the stone walls of " + (o ? o->name : std::string("the extrusion")) + " stand", "");
  host.endDrag();
  host.log("Make the walls stand: " + searchResult_->message, false);
}

void StonePanel::draw(const StaticsHost& host) {
  const ExtrusionSpec* e = extrusionOf(host);
  if (!e) return;
  ImGui::Separator();
  ImGui::TextDisabled("Stone (Whiting et al. on this extrusion)");
  bool on = e->masonry.has_value();
  if (ImGui::Checkbox("Build in stone", &on)) {
    host.commit(setStone(*host.doc, host.object, on), on ? "Build the walls in stone" : "Walls not in stone", "");
    return;
  }
  marks::mark("build in stone");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Course the walls into stone blocks carrying the roof's weight and thrust, and analyse them");
  if (!on) return;
  const StoneWalls& m = *e->masonry;
  const MasonryView* view = shown_ && shown_->spec.masonry ? &shown_->view : nullptr;
  for (const Setting& s : settingsOf(m)) {
    float v = float(s.value);
    float lo = 0, hi = 1e6f;
    if (view)
      for (const statics::Parameter& p : view->parameters)
        if (p.name == s.name) lo = float(p.lo), hi = float(p.hi);
    if (ImGui::DragFloat(s.label, &v, s.speed, lo, hi, s.format, ImGuiSliderFlags_AlwaysClamp)) {
      try {
        host.commit(setStoneSetting(*host.doc, host.object, s.name, v), std::string("Edit ") + s.label,
                    "stone" + std::to_string(host.object) + "." + s.name);
      } catch (const std::exception& ex) {
        host.log(ex.what(), true);
      }
      return;
    }
    marks::mark(std::string("stone ") + s.label);
    if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
  }
  {
    // The buttress steps' depth: sizes them, or (from 0) adds buttresses as steps.
    float v = float(buttressDepthOf(*e));
    float hi = 10;
    if (view)
      for (const statics::Parameter& p : view->parameters)
        if (p.name == "buttressDepth") hi = float(p.hi);
    if (ImGui::DragFloat("buttress depth", &v, 0.01f, 0.0f, hi, "%.3f m", ImGuiSliderFlags_AlwaysClamp)) {
      try {
        host.commit(setStoneSetting(*host.doc, host.object, "buttressDepth", v), "Edit buttress depth",
                    "stone" + std::to_string(host.object) + ".buttressDepth");
      } catch (const std::exception& ex) {
        host.log(ex.what(), true);
      }
      return;
    }
    marks::mark("stone buttress depth");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("How far the buttress steps reach out of the walls; from 0 it adds buttresses as steps");
    if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
  }
  bool ties = m.ties;
  if (ImGui::Checkbox("tie beams", &ties)) {
    try {
      host.commit(setStoneSetting(*host.doc, host.object, "ties", ties ? 1 : 0),
                  ties ? "Tie the roof" : "Roof without ties", "");
    } catch (const std::exception& ex) {
      host.log(ex.what(), true);
    }
    return;
  }
  marks::mark("stone ties");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("With tie beams the roof pushes no thrust onto the wall heads");

  // What spans each door and window: a combo per anchor (every instance of a repeat alike).
  for (const MeshAnchor& a : e->anchors) {
    if (a.feature != FeatureKind::Door && a.feature != FeatureKind::Window) continue;
    OpeningHead head = OpeningHead::Lintel;
    for (const StoneOpening& o : m.openings)
      if (o.anchor == a.name) head = o.head;
    int choice = int(head);
    if (marks::combo(("over " + a.name).c_str(), &choice, "lintel\0flat arch\0semicircular arch\0",
                     "stone head " + a.name)) {
      try {
        host.commit(setOpeningHead(*host.doc, host.object, a.name, OpeningHead(choice)),
                    "Span " + a.name + " with a " + std::string(choice == 0 ? "lintel" : choice == 1 ? "flat arch" : "semicircular arch"),
                    "");
      } catch (const std::exception& ex) {
        host.log(ex.what(), true);
      }
      return;
    }
  }
  if (search_) {
    ImGui::ProgressBar(float(search_->progress().fraction()), ImVec2(-80, 0), "searching");
    ImGui::SameLine();
    if (ImGui::Button("Cancel##stone")) search_->progress().cancel();
    return;
  }
  if (analysis_) ImGui::TextDisabled("Analysing the walls…");
  if (!shown_ || !(shown_->spec == *e)) {
    if (!analysis_) ImGui::TextDisabled("(waiting for the analysis)");
  }
  if (view) {
    if (!view->error.empty()) {
      ImGui::PushTextWrapPos(0);
      ImGui::TextColored(kBad, "%s", view->error.c_str());
      ImGui::PopTextWrapPos();
    } else {
      ImGui::PushTextWrapPos(0);
      for (const Verdict& verdict : staticsVerdicts(*view))
        ImGui::TextColored(verdict.stands ? kGood : kBad, "%s", verdict.text.c_str());
      ImGui::TextWrapped("y/W² = %.4g, %zu blocks, %zu interfaces", view->result.yNormalised, view->blockFaces.size(),
                         view->result.interfaces.size());
      marks::mark("stone verdict");
      ImGui::PopTextWrapPos();
    }
  }
  if (ImGui::Button("Make the walls stand")) makeItStand(host);
  marks::mark("stone make it stand");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Search the wall thickness (and the buttresses' depth) until the walls carry the roof; one undo step");
  ImGui::SameLine();
  ImGui::Checkbox("add buttresses", &addButtresses_);
  marks::mark("stone add buttresses");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Let Make the walls stand add buttresses as steps of the extrusion (and deepen them)");
  ImGui::Checkbox("Show blocks", &showBlocks_);
  marks::mark("stone show blocks");
  ImGui::SameLine();
  ImGui::Checkbox("forces", &showForces_);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("The interface forces and the ground's reactions as arrows");
  drawChanges("stone changes", lastChanges_);
}

void StonePanel::drawOverlay(render::Overlay& overlay, render::Overlay& onTop, const ExtrusionSpec& spec) const {
  if (!showBlocks_ || !shown_ || !(shown_->spec == spec) || !shown_->view.error.empty()) return;
  const MasonryPicture picture = masonryPicture(shown_->view, true, showForces_);
  for (const ColouredPolygon& p : picture.polygons) overlay.polygon(p.corners, p.color);
  for (const ForceArrow& a : picture.arrows) onTop.arrow(a.from, a.to, arrowColor(a), 0.25);
}

}  // namespace corbel::editor
