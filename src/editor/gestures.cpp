#include "editor/gestures.h"

namespace corbel::editor {

const std::vector<Gesture>& paneGestures() {
  static const std::vector<Gesture> table = {
      {"3D view", "Left drag", "Orbit round the target."},
      {"3D view", "Right or middle drag, Shift+left drag", "Pan."},
      {"3D view", "Wheel", "Zoom towards the pointer (the point under it stays put)."},
      {"3D view", "Click", "Select the object under the pointer; on empty space, clear the selection."},
      {"3D view", "Shift+click, Ctrl+click", "Add the object to the selection; toggle it in or out."},
      {"3D view", "Ctrl+left drag, or B then drag", "Box select (Shift on release adds to the selection)."},
      {"3D view", "Drag the gizmo", "Arrows (x red, y green, z blue) move along an axis, the yellow square on the ground, the "
                                    "green square on x and z, the red one on y and z, the ring turns about z; type a "
                                    "value and press Enter; Ctrl snaps (0.5 m, 15°). A moved face within 10 pixels of "
                                    "another object's facing face is laid on it (Alt moves freely)."},
      {"3D view", "Click on the selected object", "Extrusion: pick the face (its plan edge and profile segment light "
                                                  "up in the panes). Town: pick a building. Simulated masonry: pick a block."},
      {"3D view", "P (Push/Pull), then drag a face", "Wall: its plan edge moves out or in (neighbours follow). Roof: its "
                                                   "profile segment turns about its lower end. Step or feature: its anchor "
                                                   "slides along its wall. Type a value and Enter (metres; a roof's pitch "
                                                   "in degrees); Ctrl snaps (0.1 m, 5°); Esc cancels. One undo step."},
      {"3D view", "P, then click a face", "The face follows the pointer until the next click or Enter (type a value meanwhile)."},
      {"3D view", "Alt during a roof's drag", "Only this edge turns: it gets its own copy of the profile (without Alt every "
                                              "edge sharing the profile turns). Type the value after letting Alt go."},
      {"3D view", "Drag a growth entry", "With the growth panel's Site tab open: move a core, landing, seed or envelope corner."},
      {"Axis widget", "Click an axis end", "Look from that axis towards the target, orthographic (X: right/left, Y: back/front, Z: top/bottom)."},
      {"Splitters", "Drag", "Resize the panel beside it (kept in your settings)."},
      {"Splitters", "Double-click", "Hide or show the panel (T and N do it from the keyboard)."},
      {"Plan pane", "Wheel; right or middle drag", "Zoom the plan; pan it."},
      {"Plan pane", "Drag a corner", "Move it (on the grid and snapped to angles unless Alt is held); neighbours follow."},
      {"Plan pane", "Click an edge; Shift+click", "Select it; add it to the selection."},
      {"Plan pane", "Drag on empty space", "Select the edges inside the box (Shift adds)."},
      {"Plan pane", "Double-click an edge", "Add a corner there."},
      {"Plan pane", "Delete or Backspace", "Remove the selected corner, step or feature."},
      {"Plan pane", "Type a length, Enter", "With one edge selected: its end corner moves along it to that length. Dragging a corner: the edge arriving at it takes the length (one undo step with the drag)."},
      {"Plan pane", "Drag a feature's marker", "Slide its anchor along its wall (a click edits it)."},
      {"Plan pane", "Click a step's marker", "Edit its repeat; Delete removes it."},
      {"Plan pane", "Draw loop: clicks, Enter, Esc", "Place corners; click the first one or press Enter to close; Esc cancels."},
      {"Plan pane", "Red ring with a cross", "Two edges cross or touch there: the plan is not built until they are apart."},
      {"Profile pane", "Drag a point", "Move it (z stays between its neighbours; 0.1 m steps unless Alt is held)."},
      {"Profile pane", "Double-click a segment", "Add a point."},
      {"Profile pane", "Click a segment; type a length, Enter", "Show its length and pitch; give it the length (the points above follow). Dragging a point: the segment below it."},
      {"Profile pane", "Delete or Backspace", "Remove the selected point."},
      {"Profile pane", "Drag a feature's marker", "Raise or lower its anchor (5 cm steps unless Alt is held)."},
      {"Growth site plan", "Drag an entry or envelope corner", "Move it in 0.5 m steps (one undo step)."},
      {"Completion region", "Drag a corner handle", "Resize the region; click a form's thumbnail to pick it."},
      {"Town plan view", "Click a building or edge", "Pick it for the overrides."},
  };
  return table;
}

}  // namespace corbel::editor
