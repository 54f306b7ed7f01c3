#pragma once
// The flags of the panes the layout places right of the 3D view: never moved, resized or
// folded by hand, and never taking the keyboard merely by appearing (a pane that opens because
// a click in the 3D view selected an object leaves the keys with the view).
#include <imgui.h>

namespace corbel::editor {

inline constexpr ImGuiWindowFlags kPaneFlags = ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                                               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoFocusOnAppearing;

}  // namespace corbel::editor
