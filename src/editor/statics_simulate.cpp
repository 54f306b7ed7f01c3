// The statics panel's Simulate section (Sec. 5, Fig. 14; editor/simulation.h): the collapse
// simulation of the panel's object made on first use, Play, Step, Reset, a shake, a block
// removed (chosen in the list or clicked in the view), and its progress.
#include "editor/statics_panel.h"

#include "editor/statics_panel_parts.h"
#include "editor/symbols.h"

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

Simulation* StaticsPanel::simulationFor(const StaticsHost& host) {
  const DocObject* o = objectOf(host);
  const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
  if (!spec) return nullptr;
  if (sim_ && sim_->spec() == *spec) return sim_.get();
  try {
    sim_ = std::make_unique<Simulation>(*spec);
  } catch (const std::exception& e) {
    sim_.reset();
    host.log("Simulate " + o->name + ": " + e.what(), true);
  }
  return sim_.get();
}

const Simulation* StaticsPanel::shownSimulation(const MasonrySpec& spec) const {
  return sim_ && sim_->spec() == spec ? sim_.get() : nullptr;
}

void StaticsPanel::simulatePlay(const StaticsHost& host) {
  if (Simulation* s = simulationFor(host)) s->togglePlay();
}

void StaticsPanel::simulateStep(const StaticsHost& host, int steps) {
  if (Simulation* s = simulationFor(host)) s->step(steps);
}

void StaticsPanel::simulateReset(const StaticsHost& host) {
  if (Simulation* s = simulationFor(host)) s->reset();
}

void StaticsPanel::simulateShake(const StaticsHost& host) {
  if (Simulation* s = simulationFor(host)) {
    s->shake();
    const sim::ShakeSpec k = sim::paperShake(s->design());
    char line[128];
    std::snprintf(line, sizeof line, "Shake: the ground moves %.2f m/s along x within %.1f ms at t = %.2f s",
                  k.velocity, 1000 * k.duration, s->time());
    host.log(line, false);
  }
}

void StaticsPanel::simulateRemove(const StaticsHost& host) {
  Simulation* s = simulationFor(host);
  if (!s) return;
  const std::string name = removeChoice_.empty() ? s->topBlock() : removeChoice_;
  if (name.empty()) {
    host.log("Remove block: no block left to remove", true);
    return;
  }
  try {
    s->removeBlock(name);
    host.log("Removed block \"" + name + "\" from the simulation", false);
  } catch (const std::exception& e) {
    host.log(std::string("Remove block: ") + e.what(), true);
  }
  removeChoice_.clear();
}

bool StaticsPanel::pickBlock(const StaticsHost& host, const Vec3& origin, const Vec3& direction) {
  if (!sim_) return false;
  const int b = sim_->blockAt(origin, direction);
  if (b < 0) return false;
  const statics::Block& block = sim_->design().blocks[b];
  if (block.fixed) return false;
  removeChoice_ = block.name;
  if (removeOnClick_)
    simulateRemove(host);
  else
    host.log("Chose block \"" + block.name + "\": Remove block takes it out of the simulation", false);
  return true;
}

void StaticsPanel::drawSimulation(const StaticsHost& host) {
  ImGui::Separator();
  ImGui::TextDisabled("Simulate (Sec. 5, Fig. 14)");
  if (ImGui::Button(sim_ && sim_->playing() ? "Pause" : "Play")) simulatePlay(host);
  ImGui::SameLine();
  if (ImGui::Button("Step")) simulateStep(host);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("One fixed step (1/240 s)");
  ImGui::SameLine();
  if (ImGui::Button("Reset")) simulateReset(host);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the design state, paused");
  ImGui::SameLine();
  if (ImGui::Button("Shake")) simulateShake(host);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The paper's ground shake: 4 m/s within 1/60 s on a 10 m model, scaled to this one");
  if (sim_) {
    ImGui::SameLine();
    if (ImGui::Button("Close")) {
      sim_.reset();
      return;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show the design again");
  }
  // The remove-block tool: a block chosen from the list or by a click in the 3D view.
  const std::vector<std::string> names = sim_ ? sim_->removableBlocks() : std::vector<std::string>{};
  const std::string shown =
      removeChoice_.empty() ? (sim_ ? sim_->topBlock() : std::string("(top block)")) : removeChoice_;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  if (ImGui::BeginCombo("##block", shown.c_str())) {
    for (const std::string& n : names)
      if (ImGui::Selectable(n.c_str(), n == shown)) removeChoice_ = n;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button("Remove block")) simulateRemove(host);
  ImGui::SameLine();
  ImGui::Checkbox("on click", &removeOnClick_);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("A click on a block in the 3D view chooses it; with this on, removes it at once");
  if (!sim_) {
    ImGui::TextDisabled("The design as built; the Document never changes.");
    return;
  }
  ImGui::Text("t = %.2f s, largest displacement %.1f mm", sim_->time(), 1000 * sim_->largestDisplacement());
  const int fallen = sim_->fallenCount();
  int moving = 0;
  for (const statics::Block& b : sim_->design().blocks) moving += !b.fixed;
  ImGui::TextColored(fallen ? kBad : kGood, "%d of %d blocks fallen%s", fallen, moving,
                     sim_->playing() ? "" : " (paused)");
}

}  // namespace corbel::editor
