// The plan pane's tracing image (a PlanBackground): its texture, the Background popup, the
// image chosen in the dialog, and calibration by two points of known distance.
#include "editor/extrusion_panes.h"

#include "editor/fields.h"
#include "render/gl.h"
#include "render/image.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace corbel::editor {

void ExtrusionPanes::setBackground(const PaneHost& host, std::optional<PlanBackground> b, const std::string& label,
                                   const std::string& mergeKey) {
  Document d = *host.doc;
  DocObject* o = d.find(host.object);
  if (!o) return;
  if (b)
    if (auto bad = checkPlanBackground(*b)) {
      host.log(label + ": " + *bad, true);
      return;
    }
  if (o->background == b) return;
  o->background = std::move(b);
  const std::string name = o->name;
  host.commit(std::move(d), label + " (" + name + ")", mergeKey);
}

bool ExtrusionPanes::backgroundTexture(const PaneHost& host, const PlanBackground& b) {
  if (b.image == texturePath_) return texture_ != 0;
  texturePath_ = b.image;
  textureError_.clear();
  render::Image img;
  try {
    img = render::readImage(b.image, 8192);
  } catch (const std::exception& e) {
    textureError_ = e.what();
    host.log("Background image: " + textureError_ + " (the plan is shown without it)", true);
    if (texture_) glDeleteTextures(1, &texture_);
    texture_ = 0;
    return false;
  }
  GLint bound = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  if (!texture_) glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(bound));
  textureW_ = img.width;
  textureH_ = img.height;
  fitted_ = false;  // frame the new image with the plan
  return true;
}

// The Background popup: choose, place, fade, calibrate or remove the tracing image.
void ExtrusionPanes::backgroundFields(const PaneHost& host, const DocObject& object, const ExtrusionSpec& spec) {
  if (ImGui::Button("Choose image…")) {
    const std::string start = object.background ? object.background->image : std::string();
    backgroundDialog_.open(FileDialog::Mode::Open, "Background image",
                           {".png", ".jpg", ".jpeg", ".PNG", ".JPG", ".JPEG"}, start,
                           [this](const std::string& path) { chosenBackground_ = path; });
    ImGui::CloseCurrentPopup();
  }
  if (!object.background) {
    ImGui::SameLine();
    ImGui::TextDisabled("none: a PNG or JPEG to trace the plan from");
    return;
  }
  PlanBackground b = *object.background;
  ImGui::SameLine();
  if (ImGui::Button("Remove")) {
    setBackground(host, std::nullopt, "Remove background");
    ImGui::CloseCurrentPopup();
    return;
  }
  ImGui::TextWrapped("%s", b.image.c_str());
  if (b.image == texturePath_ && !textureError_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 100, 255));
    ImGui::TextWrapped("%s", textureError_.c_str());
    ImGui::PopStyleColor();
  } else if (texture_ && b.image == texturePath_) {
    ImGui::Text("%d x %d px = %.2f x %.2f m", textureW_, textureH_, textureW_ * b.scale, textureH_ * b.scale);
  }
  double scale = b.scale;
  ImGui::SetNextItemWidth(140);
  if (commitDouble("metres per pixel", b.scale, scale, "%.5f")) {
    b.scale = scale;
    setBackground(host, b, "Scale background");
  }
  const float wasOrigin[2] = {float(b.origin[0]), float(b.origin[1])};
  float origin[2];
  ImGui::SetNextItemWidth(140);
  if (commitFloats("lower-left corner (m)", wasOrigin, origin, 2)) {
    b.origin = Vec2(origin[0], origin[1]);
    setBackground(host, b, "Move background");
  }
  float opacity = float(b.opacity);
  ImGui::SetNextItemWidth(140);
  if (ImGui::SliderFloat("opacity", &opacity, 0.0f, 1.0f, "%.2f")) {
    b.opacity = opacity;
    setBackground(host, b, "Fade background", "plan-background-opacity");
  }
  if (ImGui::IsItemDeactivatedAfterEdit()) host.endDrag();
  if (ImGui::Button("Calibrate: click two points")) {
    calibrating_ = 2;
    ImGui::CloseCurrentPopup();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Click two points of the image whose distance you know, then type it: the image is scaled about the first");
  ImGui::SameLine();
  if (ImGui::Button("Centre on plan") && texture_ && b.image == texturePath_) {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const PlanLoop& l : spec.loops)
      for (const Vec2& p : l.points)
        x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]), x1 = std::max(x1, p[0]), y1 = std::max(y1, p[1]);
    if (x0 <= x1) {
      b.origin = Vec2((x0 + x1 - textureW_ * b.scale) / 2, (y0 + y1 - textureH_ * b.scale) / 2);
      setBackground(host, b, "Move background");
    }
  }
}

// Commits the image chosen in the dialog last frame; a first image is fitted to the plan.
void ExtrusionPanes::useChosenBackground(const PaneHost& host, const DocObject* object, const ExtrusionSpec& spec) {
if (chosenBackground_ && object) {
  const std::string path = *chosenBackground_;
  chosenBackground_.reset();
  PlanBackground b = object->background.value_or(PlanBackground());
  const bool fresh = !object->background;
  b.image = path;
  texturePath_.clear();  // read it again, even if it is the same file
  if (backgroundTexture(host, b)) {
    if (fresh) {
      // Fit the image's longer side to 1.5 times the plan's, centred on it.
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      for (const PlanLoop& l : spec.loops)
        for (const Vec2& p : l.points)
          x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]), x1 = std::max(x1, p[0]), y1 = std::max(y1, p[1]);
      if (x0 <= x1) {
        b.scale = std::clamp(1.5 * std::max(x1 - x0, y1 - y0) / std::max(textureW_, textureH_),
                             limits::kMinBackgroundScale, limits::kMaxBackgroundScale);
        b.origin = Vec2((x0 + x1 - textureW_ * b.scale) / 2, (y0 + y1 - textureH_ * b.scale) / 2);
      }
    }
    setBackground(host, b, "Set background");
  }
}
}

// After two clicks: the popup that takes their true distance and scales the image about the first.
void ExtrusionPanes::calibratePopup(const PaneHost& host, const DocObject* object) {
if (ImGui::BeginPopup("calibrate")) {
  ImGui::Text("The two points are %.3f m apart on the plan.", (calibrateB_ - calibrateA_).norm());
  ImGui::SetNextItemWidth(120);
  ImGui::InputFloat("their true distance (m)", &calibrateDistance_, 0.1f, 1.0f, "%.3f");
  const double now = (calibrateB_ - calibrateA_).norm();
  if (ImGui::Button("Scale the image") && object && object->background && now > 1e-9 && calibrateDistance_ > 0) {
    const double f = calibrateDistance_ / now;
    PlanBackground b = *object->background;
    b.scale *= f;
    b.origin = calibrateA_ + (b.origin - calibrateA_) * f;  // the first point stays put
    setBackground(host, b, "Calibrate background");
    calibratePopup_ = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel##calibrate")) {
    calibratePopup_ = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
} else {
  calibratePopup_ = false;
}
}

}  // namespace corbel::editor
