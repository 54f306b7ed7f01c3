#pragma once
// The 3D view's default tool: left drag orbits, right or middle drag (or Shift+left) pans, the
// wheel zooms towards the pointer; a left click picks (ToolContext::click) and a left press on
// something that takes it drags that instead of the camera (ToolContext::grab). A left drag
// begun with Ctrl held, or after armBox() (the B key), draws a selection box (ToolContext::boxSelect).
#include "editor/tool.h"

namespace corbel::editor {

class NavigateTool : public Tool {
 public:
  std::string id() const override { return "navigate"; }
  void handle(const InputEvent& e, bool overUi, ToolContext& context) override;
  bool busy() const override { return gesture_ != Gesture::None; }

  static constexpr float kClickSlop = 3.0f;  // pixels a click may move between press and release

  // The next left drag in the view draws a selection box (Blender's B).
  void armBox() { boxArmed_ = true; }
  bool boxArmed() const { return boxArmed_; }
  // The box being dragged (press point, pointer), if one is.
  bool boxing() const { return gesture_ == Gesture::Box; }
  float pressX() const { return pressX_; }
  float pressY() const { return pressY_; }
  // The pointer's last position in the window, once it has moved there.
  bool havePointer() const { return havePointer_; }
  float pointerX() const { return x_; }
  float pointerY() const { return y_; }

 private:
  enum class Gesture { None, Orbit, Pan, Grab, Box };
  Gesture gesture_ = Gesture::None;
  int button_ = -1;                      // the button that began the gesture
  bool shift_ = false;                   // a Shift key is down
  bool ctrl_ = false;                    // a Ctrl key is down
  bool boxArmed_ = false;                // B was pressed: the next left drag draws a box
  bool havePointer_ = false;             // a move has been seen (the pointer is in the window)
  float x_ = 0, y_ = 0;                  // the pointer
  float pressX_ = 0, pressY_ = 0;        // where the gesture began
};

}  // namespace corbel::editor
