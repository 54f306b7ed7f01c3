#include "editor/statics_panel.h"

#include "editor/statics_panel_parts.h"
#include "editor/symbols.h"
#include "editor/widget_marks.h"

#include "editor/masonry_edits.h"
#include "editor/pane_window.h"
#include "statics/tolerances.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace corbel::editor {

using namespace statics_panel;

namespace {

constexpr int kLandscapeSamples = 41;
constexpr int kGridSamples = 21;  // per axis: 441 analyses, on every core

ImU32 colorU32(const std::array<float, 4>& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], c[3])); }

}  // namespace

bool statics_panel::collect(std::unique_ptr<BackgroundJob>& job, bool wait, std::string* error) {
  if (!job) return false;
  if (wait) job->wait();
  if (!job->finished()) return false;
  job->wait();
  bool ok = !job->progress().cancelled();
  try {
    job->rethrow();
  } catch (const Cancelled&) {
    ok = false;
  } catch (const std::exception& e) {
    if (error) *error = e.what();
    ok = false;
  }
  job.reset();
  return ok;
}

void statics_panel::drawChanges(const char* id, const std::vector<ParameterChange>& changes) {
  if (changes.empty() || !ImGui::BeginTable(id, 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) return;
  ImGui::TableSetupColumn("changed");
  ImGui::TableSetupColumn("before");
  ImGui::TableSetupColumn("after");
  ImGui::TableHeadersRow();
  for (const ParameterChange& c : changes) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(c.name.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%.4g", c.before);
    ImGui::TableNextColumn();
    ImGui::Text("%.4g", c.after);
  }
  ImGui::EndTable();
}

StaticsPanel::~StaticsPanel() {
  for (auto* job : {&analysis_, &search_, &resolve_, &sceneJob_, &togetherJob_})
    if (*job) {
      (*job)->progress().cancel();
      (*job)->wait();
    }
}

void StaticsPanel::reset() {
  if (analysis_) analysis_->progress().cancel();
  analysing_.reset();
  pendingResolve_.reset();
  view_.reset();
  landscape_.reset();
  grid_.reset();
  landscapeChoice_.clear();
  landscapeChoice2_.clear();
  sim_.reset();
  removeChoice_.clear();
  if (sceneJob_) sceneJob_->progress().cancel();
  sceneView_.reset();
  if (togetherJob_) togetherJob_->progress().cancel();
  togetherView_.reset();
  togetherChanges_.clear();
}

void StaticsPanel::toggleLandscapeGrid(const StaticsHost& host) {
  if (!landscapeChoice2_.empty()) {
    landscapeChoice2_.clear();
    return;
  }
  const DocObject* o = objectOf(host);
  const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
  if (!spec) return;
  std::vector<std::string> names;
  for (const MasonryFree& f : spec->free) names.push_back(f.name);
  if (view_)
    for (const statics::FreeParameter& f : view_->suggestedFree)
      if (std::find(names.begin(), names.end(), f.name) == names.end()) names.push_back(f.name);
  if (names.size() < 2) {
    host.log("Energy landscape: the model has fewer than two parameters to free", true);
    return;
  }
  landscapeChoice_ = names[0];
  landscapeChoice2_ = names[1];
}

void StaticsPanel::cancelSearch() {
  if (search_) search_->progress().cancel();
}

std::optional<StaticsPanel::Range> StaticsPanel::rangeOf(const MasonrySpec& spec, const std::string& name) const {
  for (const MasonryFree& f : spec.free)
    if (f.name == name) return std::make_pair(name, std::make_pair(f.lo, f.hi));
  if (view_)
    for (const statics::Parameter& p : view_->parameters)
      if (p.name == name && p.continuous) return std::make_pair(name, defaultBounds(p, view_->suggestedFree));
  return std::nullopt;
}

std::optional<StaticsPanel::Range> StaticsPanel::landscapeFor(const MasonrySpec& spec) const {
  auto chosen = landscapeChoice_;
  if (chosen.empty()) {
    if (!spec.free.empty())
      chosen = spec.free.front().name;
    else if (view_ && !view_->suggestedFree.empty())
      chosen = view_->suggestedFree.front().name;
  }
  if (chosen.empty()) return std::nullopt;
  return rangeOf(spec, chosen);
}

std::optional<StaticsPanel::Range> StaticsPanel::landscape2For(const MasonrySpec& spec) const {
  const auto first = landscapeFor(spec);
  if (!first || landscapeChoice2_.empty() || landscapeChoice2_ == first->first) return std::nullopt;
  return rangeOf(spec, landscapeChoice2_);
}

bool StaticsPanel::gridMatches(const std::optional<Range>& x, const std::optional<Range>& y) const {
  const auto same = [](const LandscapeAxis& a, const Range& r) {
    return a.parameter == r.first && a.lo == r.second.first && a.hi == r.second.second;
  };
  return grid_ && x && y && same(grid_->x, *x) && same(grid_->y, *y);
}

void StaticsPanel::startAnalysis(const MasonrySpec& spec) {
  auto work = std::make_shared<AnalysisWork>();
  work->spec = spec;
  const auto range = landscapeFor(spec), range2 = landscape2For(spec);
  work->range = range;
  work->range2 = range2;
  analysing_ = work;
  analysis_ = std::make_unique<BackgroundJob>("Statics analysis", [work, range, range2](Progress& progress) {
    work->view = analyseMasonry(work->spec, &progress);
    work->viewDone = true;
    if (!range || !work->view.error.empty()) return;
    if (range2) {
      const LandscapeAxis x{range->first, range->second.first, range->second.second, kGridSamples};
      const LandscapeAxis y{range2->first, range2->second.first, range2->second.second, kGridSamples};
      work->grid = sampleLandscapeGrid(work->spec, x, y, &progress);
    } else {
      work->landscape = sampleLandscape(work->spec, range->first, range->second.first, range->second.second,
                                        kLandscapeSamples, &progress);
    }
  });
}

void StaticsPanel::finishSearch(const StaticsHost& host) {
  std::string error;
  const bool cancelled = search_ && search_->progress().cancelled();
  const bool ok = collect(search_, host.wait, &error);
  if (search_) return;  // still running
  if (!ok) {
    host.log(cancelled ? "Make it stand: cancelled, nothing changed" : "Make it stand failed: " + error, !cancelled);
    return;
  }
  lastSearch_ = *searchResult_;
  lastChanges_.clear();
  std::string why;
  if (auto next = applySearch(*host.doc, searchObject_, searchStart_, *searchResult_, &why)) {
    const DocObject* o = host.doc->find(searchObject_);
    if (const DocObject* after = next->find(searchObject_))
      lastChanges_ = parameterChanges(searchStart_, std::get<MasonrySpec>(after->spec));
    host.commit(std::move(*next), "Make " + o->name + " stand", "");
    host.endDrag();
    host.log("Make it stand: " + searchResult_->message, searchResult_->status != statics::SearchStatus::Feasible);
  } else {
    host.log("Make it stand: " + searchResult_->message + "; not applied: " + why, true);
  }
}

void StaticsPanel::updateResolve(const StaticsHost& host) {
  if (resolve_) {
    std::string error;
    const bool ok = collect(resolve_, host.wait, &error);
    if (resolve_) return;  // still running
    if (ok) {
      // Into the drag's undo step (same merge key); dropped if the spec moved on meanwhile, and
      // the newest value is re-solved next.
      if (auto next = applySearch(*host.doc, resolveObject_, resolveStart_, *resolveResult_))
        host.commit(std::move(*next), "Edit " + resolveParameter_,
                    "masonry" + std::to_string(resolveObject_) + ".value." + resolveParameter_);
    } else if (!error.empty()) {
      host.log("Keeping it standing: " + error, true);
    }
  }
  const DocObject* o = objectOf(host);
  const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
  if (!pendingResolve_ || !spec || search_) return;
  resolveObject_ = o->id;
  resolveStart_ = *spec;
  resolveParameter_ = *pendingResolve_;
  pendingResolve_.reset();
  auto result = std::make_shared<statics::SearchResult>();
  resolveResult_ = result;
  const MasonrySpec start = *spec;
  const std::string name = resolveParameter_;
  resolve_ = std::make_unique<BackgroundJob>("Keep it standing", [result, start, name](Progress& progress) {
    *result = resolveAfterEdit(start, name, &progress);
    if (result->status == statics::SearchStatus::Cancelled) progress.cancel();
  });
  if (host.wait) updateResolve(host);
}

void StaticsPanel::analyseScene(const StaticsHost& host) {
  const DocObject* o = objectOf(host);
  const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
  if (!spec || !host.scene || sceneJob_) return;
  statics::SceneBlockOptions blocks;
  for (ObjectId id : sceneLoads_)
    if (host.scene->hasObject(id)) blocks.nonstructural.push_back(id);
  const statics::AnalysisOptions options = analysisOptionsOf(*spec);
  auto scene = std::make_shared<Scene>(*host.scene);  // the worker's own copy
  auto result = std::make_shared<MasonryView>();
  sceneResult_ = result;
  sceneJobRevision_ = host.scene->revision();
  sceneJob_ =
      std::make_unique<BackgroundJob>("Statics of the Scene", [scene, blocks, options, result](Progress& progress) {
        *result = analyseSceneBlocks(*scene, blocks, options, &progress);
      });
  if (host.wait) collectScene(host);
}

void StaticsPanel::collectScene(const StaticsHost& host) {
  std::string error;
  if (collect(sceneJob_, host.wait, &error)) {
    sceneView_ = std::move(*sceneResult_);
    sceneRevision_ = sceneJobRevision_;
    if (!sceneView_->error.empty()) host.log("Statics of the Scene: " + sceneView_->error, true);
  } else if (!error.empty()) {
    host.log("Statics of the Scene: " + error, true);
  }
}

void StaticsPanel::update(const StaticsHost& host) {
  if (sceneJob_) collectScene(host);
  if (togetherJob_) collectTogether(host);
  if (sim_) {
    const DocObject* o = objectOf(host);
    const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
    if (!spec || !(*spec == sim_->spec())) {
      sim_.reset();
      host.log("Simulation closed: the model changed", false);
    } else {
      sim_->advance(host.frameSeconds);
    }
  }
  updateResolve(host);
  if (search_) finishSearch(host);
  if (analysis_) {
    std::string error;
    if (collect(analysis_, host.wait, &error)) {
      view_ = std::move(analysing_->view);
      if (analysing_->landscape) landscape_ = std::move(*analysing_->landscape);
      if (analysing_->grid) grid_ = std::move(*analysing_->grid);
    } else if (!analysis_) {
      // Cancelled or failed while sampling the landscape: the analysis itself still shows.
      if (analysing_ && analysing_->viewDone) view_ = std::move(analysing_->view);
      if (!error.empty()) host.log("Statics analysis: " + error, true);
    }
  }
  const DocObject* o = objectOf(host);
  const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
  if (!spec || analysis_) return;
  const auto range = landscapeFor(*spec), range2 = landscape2For(*spec);
  const bool viewStale = !view_ || !(view_->spec == *spec);
  const bool landscapeStale =
      range && (range2 ? !gridMatches(range, range2)
                       : (!landscape_ || landscape_->parameter != range->first ||
                          landscape_->lo != range->second.first || landscape_->hi != range->second.second));
  if (!viewStale && !landscapeStale) return;
  if (analysing_ && analysing_->spec == *spec && analysing_->range == range && analysing_->range2 == range2)
    return;  // done; it failed or was cancelled
  startAnalysis(*spec);
  if (host.wait) {
    StaticsHost again = host;
    again.frameSeconds = 0;  // this frame's simulation steps are taken
    update(again);
  }
}

void StaticsPanel::makeItStand(const StaticsHost& host) {
  if (search_) return;
  const DocObject* o = objectOf(host);
  const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
  if (!spec) return;
  searchObject_ = o->id;
  searchStart_ = *spec;
  auto result = std::make_shared<statics::SearchResult>();
  searchResult_ = result;
  const MasonrySpec start = *spec;
  auto trace = std::make_shared<SearchTrace>();
  searchTrace_ = trace;
  try {
    searchFree_ = searchFreeOf(*spec);
  } catch (const std::exception&) {
    searchFree_.clear();  // the search itself reports what is wrong with the spec
  }
  host.log("Make " + o->name + " stand…", false);
  search_ = std::make_unique<BackgroundJob>("Make it stand", [result, start, trace](Progress& progress) {
    *result = searchMasonry(start, &progress, 200, trace.get());
    if (result->status == statics::SearchStatus::Cancelled) progress.cancel();
  });
  if (host.wait) finishSearch(host);
}

void StaticsPanel::drawOverlay(render::Overlay& overlay, render::Overlay& onTop, const MasonrySpec& spec,
                               const Placement& placement) const {
  // The together and Scene analyses are of the world; the object's own is in its frame.
  const MasonryView* shown = togetherShown() ? &*togetherView_ : sceneShown() ? &*sceneView_ : nullptr;
  const bool world = shown != nullptr;
  if (!shown) {
    if (!view_ || !(view_->spec == spec)) return;
    if (shownSimulation(spec)) return;  // the analysis is of the design, not of the moving blocks
    shown = &*view_;
  }
  MasonryPicture picture = masonryPicture(*shown, colours_, arrows_);
  if (world) {
    for (ColouredPolygon& p : picture.polygons)
      for (Vec3& c : p.corners) c = placement.unapply(c);
    for (ForceArrow& a : picture.arrows) a.from = placement.unapply(a.from), a.to = placement.unapply(a.to);
  }
  for (const ColouredPolygon& p : picture.polygons) overlay.polygon(p.corners, p.color);
  for (const ForceArrow& a : picture.arrows) onTop.arrow(a.from, a.to, arrowColor(a), 0.25);
}

void StaticsPanel::drawParameters(const StaticsHost& host, const MasonrySpec& spec) {
  if (!view_) return;
  const std::string key = "masonry" + std::to_string(host.object) + ".";
  auto apply = [&](const std::function<void(Document&)>& change, const std::string& label, const std::string& merge) {
    Document d = *host.doc;
    try {
      change(d);
      host.commit(std::move(d), label, merge.empty() ? std::string() : key + merge);
    } catch (const std::exception& e) {
      host.log(e.what(), true);
    }
  };
  if (!ImGui::BeginTable("parameters", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) return;
  ImGui::TableSetupColumn("parameter", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn("free in [lo, hi]", ImGuiTableColumnFlags_WidthStretch, 1.6f);
  ImGui::TableHeadersRow();
  for (const statics::Parameter& p : view_->parameters) {
    ImGui::PushID(p.name.c_str());
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(p.name.c_str());
    if (ImGui::IsItemHovered() && !p.description.empty()) ImGui::SetTooltip("%s", p.description.c_str());
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(-1);
    // The value as the spec has it (the view may lag behind by a frame).
    double value = p.value;
    for (const MasonryParameter& q : spec.parameters)
      if (q.name == p.name) value = q.value;
    if (p.continuous) {
      float v = float(value);
      const float lo = std::isfinite(p.lo) ? float(p.lo) : -1e4f, hi = std::isfinite(p.hi) ? float(p.hi) : 1e4f;
      if (ImGui::DragFloat("##value", &v, 0.002f, lo, hi, "%.4f", ImGuiSliderFlags_AlwaysClamp)) {
        apply([&](Document& d) { setMasonryParameter(d, host.object, p.name, v); }, "Edit " + p.name,
              "value." + p.name);
        const bool isFree =
            std::any_of(spec.free.begin(), spec.free.end(), [&](const MasonryFree& f) { return f.name == p.name; });
        if (interactive_ && !isFree && !spec.free.empty()) pendingResolve_ = p.name;
      }
    } else {
      int v = int(std::lround(value));
      const int lo = std::isfinite(p.lo) ? int(p.lo) : 0, hi = std::isfinite(p.hi) ? int(std::min(p.hi, 1e6)) : 1000;
      if (ImGui::DragInt("##value", &v, 0.1f, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp))
        apply([&](Document& d) { setMasonryParameter(d, host.object, p.name, v); }, "Edit " + p.name,
              "value." + p.name);
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
    ImGui::TableNextColumn();
    if (!p.continuous) {
      ImGui::TextDisabled("(a count)");
      ImGui::PopID();
      continue;
    }
    const auto f =
        std::find_if(spec.free.begin(), spec.free.end(), [&](const MasonryFree& x) { return x.name == p.name; });
    bool isFree = f != spec.free.end();
    if (ImGui::Checkbox("##free", &isFree)) {
      std::optional<std::pair<double, double>> bounds;
      if (isFree) bounds = defaultBounds(p, view_->suggestedFree);
      apply([&](Document& d) { setMasonryFree(d, host.object, p.name, bounds); }, (isFree ? "Free " : "Fix ") + p.name,
            "");
      host.endDrag();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Free: \"Make it stand\" may change it within the bounds");
    if (f != spec.free.end()) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(-1);
      float lo = float(f->lo), hi = float(f->hi);
      const float min = std::isfinite(p.lo) ? float(p.lo) : -1e4f, max = std::isfinite(p.hi) ? float(p.hi) : 1e4f;
      if (ImGui::DragFloatRange2("##bounds", &lo, &hi, 0.002f, min, max, "%.3f", "%.3f", ImGuiSliderFlags_AlwaysClamp))
        apply([&](Document& d) { setMasonryFree(d, host.object, p.name, std::make_pair(double(lo), double(hi))); },
              "Edit the bounds of " + p.name, "bounds." + p.name);
      if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
    }
    ImGui::PopID();
  }
  ImGui::EndTable();
}

void StaticsPanel::drawSettings(const StaticsHost& host, const MasonrySpec& spec) {
  const std::string key = "masonry" + std::to_string(host.object) + ".";
  auto set = [&](double friction, bool conservative, double kern, const std::string& label, const std::string& merge) {
    Document d = *host.doc;
    try {
      setMasonryAnalysis(d, host.object, friction, conservative, kern);
      host.commit(std::move(d), label, merge.empty() ? std::string() : key + merge);
    } catch (const std::exception& e) {
      host.log(e.what(), true);
    }
  };
  // One row: friction α, α/√2, kern margin.
  ImGui::PushItemWidth(std::min(70.0f, ImGui::GetContentRegionAvail().x * 0.18f));
  float friction = float(spec.friction);
  if (ImGui::DragFloat("friction α", &friction, 0.005f, 0.0f, 2.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp))
    set(friction, spec.conservativeFriction, spec.kern, "Edit friction", "friction");
  marks::mark("friction");
  if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Coefficient of static friction at the joints (Sec. 3.1); stone on stone about 0.6 to 0.7");
  ImGui::SameLine();
  bool conservative = spec.conservativeFriction;
  if (ImGui::Checkbox("α/√2", &conservative)) {
    set(spec.friction, conservative, spec.kern, conservative ? "Use friction α/√2" : "Use friction α", "");
    host.endDrag();
  }
  marks::mark("conservative friction");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Use α/√2, so the friction pyramid lies inside the friction cone (Sec. 3.1): safe, but a design that "
        "needs friction near α is called not standing");
  ImGui::SameLine();
  float kern = float(spec.kern);
  if (ImGui::DragFloat("kern margin", &kern, 0.002f, 0.0f, 0.95f, "%.3f", ImGuiSliderFlags_AlwaysClamp))
    set(spec.friction, spec.conservativeFriction, kern, "Edit kern margin", "kern");
  marks::mark("kern margin");
  if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Geometric factor of safety (Sec. 3.4): every contact is shrunk by this factor about its centre, and "
        "the thrust must pass within what is left (0.667: the middle third)");
  ImGui::PopItemWidth();
}

void StaticsPanel::drawLoads(const StaticsHost& host, const MasonrySpec& spec) {
  ImGui::Separator();
  if (ImGui::Button(placingLoad_ ? "Stop placing" : "Place a load")) placingLoad_ = !placingLoad_;
  marks::mark("place load");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Loads (Sec. 3.4): click a block in the 3D view for a weight where you click, or wind on the face you "
        "click; each load is listed below");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);
  marks::combo("##load kind", &loadKind_, "weight (kg)\0wind (Pa)\0", "load kind");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  if (loadKind_ == 0)
    ImGui::DragFloat("##mass", &loadMass_, 10.0f, 0.0f, 1e7f, "%.0f kg", ImGuiSliderFlags_AlwaysClamp);
  else
    ImGui::DragFloat("##pressure", &windPressure_, 10.0f, -1e6f, 1e6f, "%.0f Pa", ImGuiSliderFlags_AlwaysClamp);
  if (placingLoad_) ImGui::TextColored(kGood, "click a block in the 3D view to place it");
  const std::string key = "masonry" + std::to_string(host.object) + ".load.";
  std::optional<std::size_t> remove;
  for (std::size_t k = 0; k < spec.loads.size(); ++k) {
    const MasonryLoad& l = spec.loads[k];
    ImGui::PushID(int(k));
    ImGui::AlignTextToFramePadding();
    ImGui::Text("%s on %s", l.name.c_str(), l.block.c_str());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 30);
    MasonryLoad next = l;
    bool changed = false;
    if (l.face >= 0) {
      float p = float(l.pressure);
      changed = ImGui::DragFloat("##pa", &p, 10.0f, -1e6f, 1e6f, "%.0f Pa", ImGuiSliderFlags_AlwaysClamp);
      next.pressure = p;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("pressure on face %d of the block, pushing into it", l.face);
    } else if (l.force[0] == 0 && l.force[1] == 0) {
      float m = float(loadMass(l));
      changed = ImGui::DragFloat("##kg", &m, 10.0f, 0.0f, 1e7f, "%.0f kg", ImGuiSliderFlags_AlwaysClamp);
      next.force = Vec3(0.0, 0.0, -kGravity * m);
    } else {
      ImGui::Text("(%.3g, %.3g, %.3g) N", l.force[0], l.force[1], l.force[2]);
    }
    marks::mark("load " + std::to_string(k));
    if (changed) {
      Document d = *host.doc;
      try {
        setMasonryLoad(d, host.object, k, next);
        host.commit(std::move(d), "Edit " + l.name, key + std::to_string(k));
      } catch (const std::exception& e) {
        host.log(e.what(), true);
      }
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) remove = k;
    marks::mark("remove load " + std::to_string(k));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove %s", l.name.c_str());
    ImGui::PopID();
  }
  if (remove) {
    Document d = *host.doc;
    const std::string name = spec.loads[*remove].name;
    removeMasonryLoad(d, host.object, *remove);
    host.commit(std::move(d), "Remove " + name, "");
    host.endDrag();
  }
}

bool StaticsPanel::placeLoad(const StaticsHost& host, const Vec3& origin, const Vec3& direction) {
  const DocObject* o = objectOf(host);
  const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
  if (!spec || !view_ || view_->blockFaces.empty()) return false;
  const std::optional<BlockHit> hit = firstBlockHit(*view_, origin, direction);
  if (!hit) {
    host.log("Place a load: click a block of " + o->name + " (not the ground)", true);
    return false;
  }
  Document d = *host.doc;
  try {
    const LoadKind kind = loadKind_ == 0 ? LoadKind::Weight : LoadKind::Pressure;
    const std::size_t k = addMasonryLoad(d, host.object, loadAt(*view_, *hit, kind, kind == LoadKind::Weight ? loadMass_ : windPressure_));
    const MasonryLoad& l = masonryOf(d, host.object).loads[k];
    char amount[64];
    if (kind == LoadKind::Weight)
      std::snprintf(amount, sizeof amount, "%.0f kg", loadMass(l));
    else
      std::snprintf(amount, sizeof amount, "%.0f Pa on face %d", l.pressure, l.face);
    const std::string what = l.name + " (" + amount + ") on " + l.block;
    host.commit(std::move(d), "Add " + l.name, "");
    host.endDrag();
    host.log("Placed " + what, false);
  } catch (const std::exception& e) {
    host.log(std::string("Place a load: ") + e.what(), true);
    return false;
  }
  return true;
}

void StaticsPanel::drawAnalysis(const MasonrySpec& spec) {
  ImGui::Separator();
  ImGui::TextDisabled("Analysis (penalty QP, Sec. 3.2)");
  if (!view_) {
    ImGui::TextDisabled("analysing...");
    return;
  }
  if (!(view_->spec == spec)) ImGui::TextDisabled("(updating: showing the previous state)");
  if (!view_->error.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(kBad, "%s", view_->error.c_str());
    ImGui::PopTextWrapPos();
    return;
  }
  const statics::AnalysisResult& r = view_->result;
  for (const Verdict& v : staticsVerdicts(*view_)) ImGui::TextColored(v.stands ? kGood : kBad, "%s", v.text.c_str());
  ImGui::Text("y = %.4g N²    y/W² = %.4g", r.y, r.yNormalised);
  explainSymbol("y/W²");
  ImGui::Text("W = %.4g N, %zu blocks, %zu interfaces", r.totalWeight, view_->blockFaces.size(), r.interfaces.size());
  ImGui::Text("solver: %s, %d iterations, residual %.2g", statics::toString(r.status).c_str(), r.iterations,
              r.equilibriumResidual);
  ImGui::Text("tension sites: %zu", r.tensionSites.size());
  if (!r.tensionSites.empty())
    ImGui::Text("largest tension %.4g N (%.3g W)", r.tensionSites.front().tension,
                r.tensionSites.front().tension / std::max(r.totalWeight, 1e-300));
  ImGui::Checkbox("Colour blocks by tension", &colours_);
  ImGui::SameLine();
  ImGui::Checkbox("Force arrows", &arrows_);
  // Legend: stone (no tension) to blue (the block with the most tension).
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float w = 160, h = 12;
  for (int i = 0; i < 32; ++i) {
    const auto c = tensionColor(i / 31.0);
    dl->AddRectFilled(ImVec2(at.x + w * i / 32, at.y), ImVec2(at.x + w * (i + 1) / 32 + 1, at.y + h),
                      ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 1)));
  }
  ImGui::Dummy(ImVec2(w, h));
  ImGui::SameLine();
  ImGui::TextDisabled("share of tension, 0 to 1");
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled("arrows: interface forces in compression (red), tension (blue), ground reactions (green)");
  ImGui::PopTextWrapPos();
}

void StaticsPanel::drawSearch(const StaticsHost& host) {
  ImGui::Separator();
  ImGui::TextDisabled("Parameter search (Sec. 4)");
  if (search_) {
    ImGui::ProgressBar(float(search_->progress().fraction()), ImVec2(-80, 0),
                       ("evaluating " + search_->progress().stage()).c_str());
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) cancelSearch();
    // The infeasibility history as the evaluations come (Fig. 8's descent), before the end.
    const std::vector<double> live = searchTrace_ ? searchTrace_->measures() : std::vector<double>{};
    if (!live.empty()) {
      std::vector<float> h(live.begin(), live.end());
      ImGui::Text("%zu evaluations so far, y/W² %.3g", live.size(), live.back());
      ImGui::PlotLines("##live-history", h.data(), int(h.size()), 0, "y/W² per evaluation", 0.0f, FLT_MAX,
                       ImVec2(ImGui::GetContentRegionAvail().x, 60));
    }
  } else {
    if (ImGui::Button("Make it stand")) makeItStand(host);
    ImGui::SameLine();
    ImGui::Checkbox("Keep it standing while I drag", &interactive_);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Fig. 13: after each change to a fixed parameter, the free ones are searched again from where "
          "they are, in the background, into the same undo step");
    if (resolve_) {
      ImGui::SameLine();
      ImGui::TextDisabled("re-solving...");
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Move the free parameters within their bounds to minimise y (the model's suggested ones when "
          "none is free); one undo step");
  }
  if (lastSearch_) {
    const statics::SearchResult& s = *lastSearch_;
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(s.status == statics::SearchStatus::Feasible ? kGood : kBad, "%s: %s",
                       statics::toString(s.status).c_str(), s.message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Text("%d evaluations, %.2f s, y/W² %.3g -> %.3g", s.evaluations, s.seconds, s.initialMeasure, s.measure);
    drawChanges("changes", lastChanges_);
    if (!s.history.empty()) {
      std::vector<float> h(s.history.begin(), s.history.end());
      ImGui::PlotLines("##history", h.data(), int(h.size()), 0, "y/W² per evaluation", 0.0f, FLT_MAX,
                       ImVec2(ImGui::GetContentRegionAvail().x, 60));
    }
  }
}

void StaticsPanel::drawGrid(const LandscapeGrid& g, const std::vector<std::pair<double, double>>& path) {
  const std::vector<std::array<float, 4>> colours = landscapeColors(g);
  const float side = std::min(ImGui::GetContentRegionAvail().x, 260.0f);
  const float cw = side / float(g.x.samples), ch = side / float(g.y.samples);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  for (int j = 0; j < g.y.samples; ++j)
    for (int i = 0; i < g.x.samples; ++i) {
      // The second parameter grows upwards, as on a plot.
      const ImVec2 a(at.x + cw * float(i), at.y + ch * float(g.y.samples - 1 - j));
      dl->AddRectFilled(a, ImVec2(a.x + cw + 0.5f, a.y + ch + 0.5f),
                        colorU32(colours[static_cast<std::size_t>(j) * g.x.samples + i]));
    }
  // The search's evaluations over the grid, in order (Fig. 8's optimisation path): white
  // dots joined by lines on black rings, the last one larger.
  const auto place = [](const LandscapeAxis& a, double v) {
    return a.hi > a.lo ? (v - a.lo) / (a.hi - a.lo) * (a.samples - 1) : 0.0;
  };
  const auto screen = [&](const std::pair<double, double>& p) {
    return ImVec2(at.x + cw * float(place(g.x, p.first) + 0.5),
                  at.y + ch * float(g.y.samples - 1 - place(g.y, p.second) + 0.5));
  };
  for (std::size_t k = 0; k < path.size(); ++k) {
    const float r = k + 1 == path.size() ? 4.5f : 2.5f;
    dl->AddCircleFilled(screen(path[k]), r + 1.5f, IM_COL32(0, 0, 0, 255));
  }
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (k > 0) dl->AddLine(screen(path[k - 1]), screen(path[k]), IM_COL32(255, 255, 255, 255), 1.5f);
    dl->AddCircleFilled(screen(path[k]), k + 1 == path.size() ? 4.5f : 2.5f, IM_COL32(255, 255, 255, 255));
  }
  ImGui::InvisibleButton("##grid", ImVec2(side, side));
  if (ImGui::IsItemHovered()) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const int i = std::clamp(int((m.x - at.x) / cw), 0, g.x.samples - 1);
    const int j = std::clamp(g.y.samples - 1 - int((m.y - at.y) / ch), 0, g.y.samples - 1);
    ImGui::SetTooltip("%s = %.4g, %s = %.4g\ny/W² = %.4g%s", g.x.parameter.c_str(), g.x.valueAt(i),
                      g.y.parameter.c_str(), g.y.valueAt(j), g.at(i, j), g.standsAt(i, j) ? " (stands)" : "");
  }
  ImGui::TextDisabled("%s in [%.3g, %.3g] across, %s in [%.3g, %.3g] up", g.x.parameter.c_str(), g.x.lo, g.x.hi,
                      g.y.parameter.c_str(), g.y.lo, g.y.hi);
  // Legend: red stands (y = 0); the ramp is log10 y/W² from the grid's least to its largest.
  const ImVec2 l = ImGui::GetCursorScreenPos();
  const float w = 120, h = 10;
  dl->AddRectFilled(l, ImVec2(l.x + h, l.y + h), colorU32(kLandscapeStandsColor));
  for (int k = 0; k < 24; ++k)
    dl->AddRectFilled(ImVec2(l.x + 2 * h + w * k / 24, l.y), ImVec2(l.x + 2 * h + w * (k + 1) / 24 + 1, l.y + h),
                      colorU32(landscapeRampColor(k / 23.0)));
  ImGui::Dummy(ImVec2(2 * h + w, h));
  ImGui::SameLine();
  ImGui::TextDisabled("stands; log y/W², low to high");
  std::size_t standing = 0;
  for (char c : g.stands) standing += c != 0;
  ImGui::Text("stands at %zu of %zu samples", standing, g.stands.size());
  const auto [mi, mj] = g.minimum();
  if (mi >= 0 && !g.standsAt(mi, mj))
    ImGui::Text("least y/W² %.3g at %s = %.3g, %s = %.3g", g.at(mi, mj), g.x.parameter.c_str(), g.x.valueAt(mi),
                g.y.parameter.c_str(), g.y.valueAt(mj));
}

void StaticsPanel::drawLandscape(const MasonrySpec& spec) {
  ImGui::Separator();
  ImGui::TextDisabled("Energy landscape (Fig. 8)");
  if (!view_) return;
  const auto range = landscapeFor(spec);
  const auto range2 = landscape2For(spec);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("over");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.45f);
  if (ImGui::BeginCombo("##over", range ? range->first.c_str() : "(choose)")) {
    for (const statics::Parameter& p : view_->parameters)
      if (p.continuous && ImGui::Selectable(p.name.c_str(), range && range->first == p.name)) landscapeChoice_ = p.name;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::TextUnformatted("and");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##and", range2 ? range2->first.c_str() : "(none)")) {
    if (ImGui::Selectable("(none)", !range2)) landscapeChoice2_.clear();
    for (const statics::Parameter& p : view_->parameters)
      if (p.continuous && (!range || p.name != range->first) &&
          ImGui::Selectable(p.name.c_str(), range2 && range2->first == p.name))
        landscapeChoice2_ = p.name;
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("A second parameter: y/W² over a grid of both (Fig. 8)");
  if (!range) return;
  const bool sampling = range2 ? !gridMatches(range, range2) : (!landscape_ || landscape_->parameter != range->first);
  if (sampling) {
    if (analysis_) {
      ImGui::ProgressBar(float(analysis_->progress().fraction()), ImVec2(-80, 0), "sampling");
      // Cancel stops the sampling only: the analysis before it is kept (and shown).
      if (analysing_ && analysing_->viewDone) {
        ImGui::SameLine();
        if (ImGui::Button("Cancel##landscape")) analysis_->progress().cancel();
      }
    } else {
      ImGui::TextDisabled("not sampled (cancelled): change the range or the model to sample again");
    }
    return;
  }
  if (range2) {
    drawGrid(*grid_, searchTrace_ ? searchPathOnGrid(*grid_, searchFree_, searchTrace_->values())
                                  : std::vector<std::pair<double, double>>{});
    return;
  }
  std::vector<float> m;
  for (double v : landscape_->measure) m.push_back(std::isfinite(v) ? float(v) : 0.0f);
  char caption[96];
  std::snprintf(caption, sizeof caption, "y/W² over %s in [%.3g, %.3g]", landscape_->parameter.c_str(), landscape_->lo,
                landscape_->hi);
  ImGui::PlotLines("##landscape", m.data(), int(m.size()), 0, caption, 0.0f, FLT_MAX,
                   ImVec2(ImGui::GetContentRegionAvail().x, 110));
  std::size_t standing = 0;
  for (double v : landscape_->measure) standing += v <= statics::kFeasibleMeasure;
  ImGui::Text("stands at %zu of %zu samples", standing, landscape_->measure.size());
}

void StaticsPanel::drawScene(const StaticsHost& host) {
  // Folded by default, as the together section: the panel keeps the landscape in sight.
  if (!ImGui::CollapsingHeader("Every block in the Scene")) return;
  if (!host.scene) return;
  ImGui::PushTextWrapPos(0);
  ImGui::TextDisabled(
      "Every object of kind Block analysed together (each connected piece one block, density "
      "by material; pieces tagged \"ground\" fixed, else a ground plane), with the objects "
      "ticked below carried as loads by the blocks under them.");
  ImGui::PopTextWrapPos();
  int others = 0;
  for (const auto& [id, info] : host.scene->objects()) {
    if (info.kind == Kind::Block) continue;
    if (others++ == 0) ImGui::TextDisabled("carried as loads:");
    bool load = sceneLoads_.count(id) > 0;
    ImGui::PushID(static_cast<int>(id));
    if (ImGui::Checkbox(info.name.empty() ? "(unnamed)" : info.name.c_str(), &load)) {
      if (load)
        sceneLoads_.insert(id);
      else
        sceneLoads_.erase(id);
    }
    ImGui::PopID();
  }
  if (sceneJob_) {
    ImGui::TextDisabled("analysing the Scene...");
  } else if (ImGui::Button("Analyse the Scene")) {
    analyseScene(host);
  }
  if (!sceneView_) return;
  ImGui::SameLine();
  ImGui::Checkbox("Show in the view", &showScene_);
  if (sceneRevision_ != host.scene->revision()) ImGui::TextDisabled("(the Scene has changed since: analyse again)");
  const MasonryView& v = *sceneView_;
  if (!v.error.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(kBad, "%s", v.error.c_str());
    ImGui::PopTextWrapPos();
    return;
  }
  const statics::AnalysisResult& r = v.result;
  if (r.feasible)
    ImGui::TextColored(kGood, "the Scene's blocks stand together");
  else
    ImGui::TextColored(kBad, "the Scene's blocks do not stand: they need tension to hold");
  const std::vector<Verdict> verdicts = staticsVerdicts(v);
  for (std::size_t i = 1; i < verdicts.size(); ++i)  // the strict LP's, and whether they disagree
    ImGui::TextColored(verdicts[i].stands ? kGood : kBad, "%s", verdicts[i].text.c_str());
  ImGui::Text("y/W² = %.4g, W = %.4g N, %zu blocks%s", r.yNormalised, r.totalWeight, v.blockFaces.size(),
              v.groundPlaneAdded ? " (with a ground plane)" : "");
  ImGui::Text("%zu interfaces, %zu tension sites; solver: %s", r.interfaces.size(), r.tensionSites.size(),
              statics::toString(r.status).c_str());
  if (v.sceneLoads > 0) ImGui::Text("%d pieces carried as loads, %.4g N", v.sceneLoads, v.sceneLoadWeight);
}

void StaticsPanel::draw(const StaticsHost& host, float x, float y, float w, float h) {
  const DocObject* o = objectOf(host);
  const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
  if (!spec) return;
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Statics", nullptr, kPaneFlags);
  ImGui::Text("%s: masonry model \"%s\"", o->name.c_str(), spec->model.c_str());
  drawParameters(host, *spec);
  drawSettings(host, *spec);
  drawLoads(host, *spec);
  drawAnalysis(*spec);
  drawScene(host);
  drawTogether(host);
  drawSearch(host);
  drawSimulation(host);
  drawLandscape(*spec);
  ImGui::End();
}

}  // namespace corbel::editor
