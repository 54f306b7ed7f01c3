#pragma once
// Tools of the 3D view. A tool is a small state machine fed the view's input events, one at a
// time in the order they happened; what a gesture means for the Document (pick this, drag
// that) it asks of the editor through a ToolContext, so a tool is tested with events alone.
#include "editor/input_queue.h"
#include "editor/viewport.h"

#include <functional>
#include <string>

namespace corbel::editor {

struct ToolContext {
  Viewport* viewport = nullptr;
  // A press of the left button: true when something under the pointer takes the drag (a
  // growth site's core, say); it then follows dragTo until release.
  std::function<bool(const Ray&)> grab;
  std::function<void(const Ray&)> dragTo;
  std::function<void()> release;
  // A click: the left button pressed and let go without moving (and nothing grabbed).
  std::function<void(const Ray&)> click;
  // A box dragged (B first, or Ctrl held at the press): its corners in window pixels.
  std::function<void(float x0, float y0, float x1, float y1)> boxSelect;
};

class Tool {
 public:
  virtual ~Tool() = default;
  virtual std::string id() const = 0;  // "navigate": the action id's last part
  // One event. `overUi`: a panel has the pointer (ImGui wants the mouse), so a press or a
  // scroll is not the view's; a gesture already begun carries on wherever the pointer goes.
  virtual void handle(const InputEvent& e, bool overUi, ToolContext& context) = 0;
  // A gesture is in progress (a button held since a press in the view).
  virtual bool busy() const = 0;
};

}  // namespace corbel::editor
