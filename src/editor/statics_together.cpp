// The statics panel's "All masonry objects together" section (statics/composite.h,
// editor/masonry_edits.h: masonryTogether): the selected object analysed with every other
// masonry object of the Document, and "Make them stand together" over all their free
// parameters, one undo step.
#include "editor/statics_panel.h"

#include "editor/statics_panel_parts.h"
#include "editor/widget_marks.h"

#include <imgui.h>

#include <cstdio>

namespace corbel::editor {

using namespace statics_panel;

void StaticsPanel::analyseTogether(const StaticsHost& host) {
  if (!host.doc || togetherJob_) return;
  auto work = std::make_shared<TogetherWork>();
  try {
    work->together = masonryTogether(*host.doc, host.object, togetherToleranceMm_ / 1000.0);
  } catch (const std::exception& e) {
    host.log(std::string("Analyse together: ") + e.what(), true);
    return;
  }
  work->started = *host.doc;
  togetherWork_ = work;
  togetherJob_ = std::make_unique<BackgroundJob>("Statics of the objects together", [work](Progress& progress) {
    work->view = analyseModel(work->together.model, work->together.model.parameters, work->together.options, &progress);
  });
  if (host.wait) collectTogether(host);
}

void StaticsPanel::makeThemStand(const StaticsHost& host) {
  if (!host.doc || togetherJob_) return;
  auto work = std::make_shared<TogetherWork>();
  try {
    work->together = masonryTogether(*host.doc, host.object, togetherToleranceMm_ / 1000.0);
  } catch (const std::exception& e) {
    host.log(std::string("Make them stand together: ") + e.what(), true);
    return;
  }
  work->started = *host.doc;
  work->search = true;
  togetherWork_ = work;
  host.log("Make the masonry objects stand together…", false);
  togetherJob_ = std::make_unique<BackgroundJob>("Make them stand together", [work](Progress& progress) {
    work->result = searchTogether(work->together, &progress);
    if (work->result.status == statics::SearchStatus::Cancelled) progress.cancel();
    // The analysis at what it found, so the view shows the result.
    statics::ParameterSet values = work->result.values.all().empty() ? work->together.model.parameters
                                                                     : work->result.values;
    work->view = analyseModel(work->together.model, values, work->together.options, &progress);
  });
  if (host.wait) collectTogether(host);
}

void StaticsPanel::collectTogether(const StaticsHost& host) {
  std::string error;
  const bool cancelled = togetherJob_ && togetherJob_->progress().cancelled();
  const bool ok = collect(togetherJob_, host.wait, &error);
  if (togetherJob_) return;  // still running
  const std::shared_ptr<TogetherWork> work = togetherWork_;
  togetherWork_.reset();
  if (!ok) {
    if (cancelled)
      host.log("Together: cancelled, nothing changed", false);
    else if (!error.empty())
      host.log("Together: " + error, true);
    return;
  }
  if (!work->search) {
    togetherView_ = std::move(work->view);
    togetherOf_ = work->started;
    if (!togetherView_->error.empty()) host.log("Together: " + togetherView_->error, true);
    return;
  }
  std::string why;
  const auto next = applyTogether(*host.doc, work->started, work->together, work->result, &why);
  if (!next) {
    host.log("Make them stand together: " + why, true);
    return;
  }
  togetherChanges_.clear();
  for (const statics::FreeParameter& f : work->result.free) {
    const double before = work->together.model.parameters[f.name], after = work->result.values[f.name];
    if (before != after) togetherChanges_.push_back({f.name, before, after});
  }
  host.commit(*next, "Make the masonry objects stand together", "");
  host.endDrag();
  togetherView_ = std::move(work->view);
  togetherOf_ = *next;
  host.log("Make them stand together: " + work->result.message, false);
}

void StaticsPanel::drawTogether(const StaticsHost& host) {
  const bool open = ImGui::CollapsingHeader("All masonry objects together");
  marks::mark("together header");
  if (!open) return;
  if (!host.doc) return;
  int others = 0;
  for (const DocObject& o : host.doc->objects) others += std::holds_alternative<MasonrySpec>(o.spec) && o.id != host.object;
  if (others == 0) {
    ImGui::TextDisabled("(no other masonry object: add columns, arches, walls to build with)");
    return;
  }
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.3f);
  ImGui::DragFloat("contact tolerance", &togetherToleranceMm_, 0.05f, 0.0f, 100.0f, "%.2f mm",
                   ImGuiSliderFlags_AlwaysClamp);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Faces of different objects this close, and facing each other, carry one another (a joint)");
  if (togetherJob_) {
    ImGui::ProgressBar(float(togetherJob_->progress().fraction()), ImVec2(-80, 0),
                       togetherWork_ && togetherWork_->search ? "searching" : "analysing");
    ImGui::SameLine();
    if (ImGui::Button("Cancel##together")) togetherJob_->progress().cancel();
    return;
  }
  if (ImGui::Button("Analyse together")) analyseTogether(host);
  marks::mark("analyse together");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("This object and the %d other masonry object(s) as one structure, each resting on the others", others);
  ImGui::SameLine();
  if (ImGui::Button("Make them stand together")) makeThemStand(host);
  marks::mark("make them stand together");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Search the free parameters of every masonry object at once; one undo step");
  if (!togetherView_) return;
  ImGui::SameLine();
  ImGui::Checkbox("Show##together", &showTogether_);
  if (!(togetherOf_ == *host.doc)) ImGui::TextDisabled("(the objects have changed since: analyse again)");
  const MasonryView& v = *togetherView_;
  if (!v.error.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(kBad, "%s", v.error.c_str());
    ImGui::PopTextWrapPos();
    return;
  }
  for (const Verdict& verdict : staticsVerdicts(v))
    ImGui::TextColored(verdict.stands ? kGood : kBad, "%s", verdict.text.c_str());
  ImGui::Text("y/W² = %.4g, %zu blocks, %zu interfaces", v.result.yNormalised, v.blockFaces.size(),
              v.result.interfaces.size());
  drawChanges("together changes", togetherChanges_);
}

}  // namespace corbel::editor
