#pragma once
// The editor's GL view maps (Sec. 5.2): render::GlViewMapper on the context of a hidden GLFW
// window of its own. The growth builds (core/live_sync.h) and the view-map inspector run off
// the UI thread, where the window's context is not current and cannot be made current (it is
// the UI thread's); each of their renders takes the hidden context on its own thread instead
// (render::ContextViewMapper: one at a time), so the window's GL state is never touched.
#include "render/gl_view_mapper.h"

#include <memory>
#include <string>

namespace corbel::editor {

// The default pixel size of the editor's GL view maps: Alpha's 90 × 15 m sides are 360 × 60 pixels,
// and a whole run on them costs about 6 ms a step more than on the exact maps (docs/growth.md).
inline constexpr double kEditorViewMapPixel = 0.25;
// The pixels the Grow tab offers.
inline constexpr double kEditorViewMapPixels[] = {0.1, 0.25, 0.5};

// Makes the hidden window (call on the main thread, after glfwInit, with the window's context
// current; it stays current). Null, with the reason in *why, when GLFW cannot make a GL 3.3 core
// context.
std::shared_ptr<render::ContextViewMapper> makeEditorGlViewMapper(double pixelSize, std::string* why);

// The name the panels show and key their measurements by: "GL, 0.25 m pixels".
std::string glMapsName(double pixelSize);

}  // namespace corbel::editor
