// The growth panel's view maps (src/growth/view_map.h): the inspection's maps uploaded as GL
// textures once per inspection and drawn two a row over the 3D view.
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

void GrowthPanel::uploadViewMaps() {
  if (!inspection_ || texturesOf_ == inspection_.get()) return;
  if (!textures_[0]) glGenTextures(GLsizei(textures_.size()), textures_.data());
  for (growth::ViewDirection d : growth::kViewDirections) {
    const int k = int(d);
    images_[k] = viewMapImage(inspection_->views[d], d, 320);
    for (int layer = 0; layer < 2; ++layer) {
      glBindTexture(GL_TEXTURE_2D, textures_[k + 4 * layer]);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, images_[k].width, images_[k].height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   (layer ? images_[k].depthRgba : images_[k].rgba).data());
    }
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  texturesOf_ = inspection_.get();
}

void GrowthPanel::drawViewMaps(const GrowthHost& host, float x, float y, float w) {
  const DocObject* o = host.doc ? host.doc->find(host.object) : nullptr;
  if (!showViewMaps_ || !(o && std::get_if<GrowthSpec>(&o->spec))) return;
  uploadViewMaps();
  // Two maps a row, as wide as the 3D view allows (at most 320 pixels each).
  const float iw = std::clamp(std::floor((w - 40) / 2), 120.0f, 320.0f);
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(2 * iw + 30, 0), ImGuiCond_Appearing);
  if (!ImGui::Begin("View maps (Sec. 5.2)", &showViewMaps_)) {
    ImGui::End();
    return;
  }
  if (!inspection_ || !texturesOf_) {
    ImGui::TextDisabled("measuring the model...");
    ImGui::End();
    return;
  }
  const growth::ViewMap& first = inspection_->views[growth::ViewDirection::PosX];
  if (inspection_->maps == "exact")
    ImGui::TextDisabled("exact CPU maps (cells on every box edge)");
  else
    ImGui::TextDisabled("%s: %d x %d pixels from +x", inspection_->maps.c_str(), first.columns(), first.rows());
  ImGui::TextDisabled("unit ids in false colour (cores and circulation grey), under them the depth");
  ImGui::TextDisabled("(nearest white); as seen from each side");
  for (growth::ViewDirection d : growth::kViewDirections) {
    const int k = int(d);
    if (k % 2) ImGui::SameLine();
    ImGui::BeginGroup();
    const growth::ViewMap& map = inspection_->views[d];
    int seen = 0;
    for (const auto& [id, a] : map.areas())
      if (id != growth::kEmptyId && id != growth::kObstacleId && a > 0) ++seen;
    ImGui::Text("from %s: %d units seen", viewDirectionName(d), seen);
    const float ih = iw * float(images_[k].height) / float(std::max(images_[k].width, 1));
    for (int layer = 0; layer < 2; ++layer) {
      ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(textures_[k + 4 * layer])),
                   ImVec2(iw, ih));
      if (!ImGui::IsItemHovered()) continue;
      const ImVec2 mp = ImGui::GetIO().MousePos, ip = ImGui::GetItemRectMin();
      const int px = std::clamp(int((mp.x - ip.x) / iw * images_[k].width), 0, images_[k].width - 1);
      const int py = std::clamp(int((mp.y - ip.y) / ih * images_[k].height), 0, images_[k].height - 1);
      const std::uint32_t id = images_[k].idAt(px, py);
      // The face's coordinate along the view axis (growth::frontDepth negates it for -x, -y).
      const bool positive = d == growth::ViewDirection::PosX || d == growth::ViewDirection::PosY;
      const double at = positive ? images_[k].depthAt(px, py) : -images_[k].depthAt(px, py);
      const char axis = d == growth::ViewDirection::PosX || d == growth::ViewDirection::NegX ? 'x' : 'y';
      if (id == growth::kEmptyId)
        ImGui::SetTooltip("nothing");
      else if (id == growth::kObstacleId)
        ImGui::SetTooltip("a core or circulation, its face at %c = %.2f m", axis, at);
      else
        ImGui::SetTooltip("unit %u: %.1f m² seen from %s; this face at %c = %.2f m", id, map.area(id),
                          viewDirectionName(d), axis, at);
    }
    ImGui::EndGroup();
  }
  ImGui::End();
}

}  // namespace corbel::editor
