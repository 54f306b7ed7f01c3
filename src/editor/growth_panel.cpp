#include "editor/growth_panel.h"

#include "editor/growth_edits.h"
#include "growth/kernel.h"
#include "growth/site.h"

#include <imgui.h>

#include <cstdio>

namespace corbel::editor {

namespace {

const GrowthSpec* specOf(const GrowthHost& host) {
  const DocObject* o = host.doc ? host.doc->find(host.object) : nullptr;
  return o ? std::get_if<GrowthSpec>(&o->spec) : nullptr;
}

}  // namespace

void GrowthPanel::commitSteps(const GrowthHost& host, int steps, const std::string& label, const std::string& merge) {
  Document d = *host.doc;
  std::get<GrowthSpec>(d.find(host.object)->spec).steps = steps;
  host.commit(std::move(d), label, merge);
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

void GrowthPanel::draw(const GrowthHost& host, float x, float y, float w, float h) {
  const GrowthSpec* spec = specOf(host);
  if (!spec) return;
  const DocObject* o = host.doc->find(host.object);
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Growth", nullptr, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse);
  ImGui::Text("%s: growth site (Ng, Ch. 4)", o->name.c_str());
  if (summaryOf_ != spec->site) {
    summaryOf_ = spec->site;
    try {
      const growth::Site site = growth::parseSite(spec->site);
      char text[160];
      std::snprintf(text, sizeof text,
                    "%.0f m² site, %d storeys of %.1f m, %zu cores, %zu circulation boxes, %zu seeds", site.area(),
                    site.storeys, site.storeyHeight, site.cores.size(), site.circulation.size(), site.seeds.size());
      summary_ = text;
    } catch (const std::exception&) {
      summary_.clear();  // the build reports the site's fault
    }
  }
  if (!summary_.empty()) ImGui::TextWrapped("%s", summary_.c_str());
  if (!host.error.empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", host.error.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::Separator();
  int seed = static_cast<int>(spec->seed);
  ImGui::SetNextItemWidth(160);
  if (ImGui::InputInt("Seed", &seed, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue) && seed >= 0) {
    Document d = *host.doc;
    std::get<GrowthSpec>(d.find(host.object)->spec).seed = static_cast<std::uint64_t>(seed);
    host.commit(std::move(d), "Seed " + o->name, "");
  }
  const int stopped = growth::stoppedAfter(host.warnings);
  if (spec->steps < 0)
    ImGui::Text("Grown until every unit stopped%s", host.current ? "" : " (growing...)");
  else
    ImGui::Text("Grown %d step%s%s", spec->steps, spec->steps == 1 ? "" : "s", host.current ? "" : " (growing...)");
  if (stopped >= 0 && host.current) ImGui::TextDisabled("every unit stopped after %d steps", stopped);

  const auto next = nextStep(*spec, stopped);
  ImGui::BeginDisabled(!next || running_);
  if (ImGui::Button("Step")) step(host);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!next && !running_);
  if (ImGui::Button(running_ ? "Pause" : "Run")) toggleRun(host);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(spec->steps < 0);
  if (ImGui::Button("Grow to the end")) {
    running_ = false;
    commitSteps(host, -1, "Grow " + o->name + " to the end");
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(spec->steps == 0);
  if (ImGui::Button("Reset")) {
    running_ = false;
    commitSteps(host, 0, "Reset the growth of " + o->name);
  }
  ImGui::EndDisabled();
  ImGui::TextDisabled("Run commits one step at a time as the view catches up;");
  ImGui::TextDisabled("the whole run is one undo step.");
  ImGui::End();
}

}  // namespace corbel::editor
