#pragma once
// Every mouse gesture of the editor's panes, for the help window (F1): the 3D view, its axis
// widget, the splitters, the extrusion's plan and profile panes, the growth site's plan, the
// form completion region and the town's plan view. One table, so the help cannot miss a pane
// that is listed here; a pane that gains a gesture adds its row here. No GL.
#include <vector>

namespace corbel::editor {

struct Gesture {
  const char* pane;     // "3D view"
  const char* gesture;  // "Left drag"
  const char* what;     // "orbit"
};

const std::vector<Gesture>& paneGestures();

}  // namespace corbel::editor
