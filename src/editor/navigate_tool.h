#pragma once
// The 3D view's default tool: left drag orbits, right or middle drag (or Shift+left) pans, the
// wheel zooms towards the pointer; a left click picks (ToolContext::click) and a left press on something that
// takes it drags that instead of the camera (ToolContext::grab).
#include "editor/tool.h"

namespace corbel::editor {

class NavigateTool : public Tool {
 public:
  std::string id() const override { return "navigate"; }
  void handle(const InputEvent& e, bool overUi, ToolContext& context) override;
  bool busy() const override { return gesture_ != Gesture::None; }

  static constexpr float kClickSlop = 3.0f;  // pixels a click may move between press and release

 private:
  enum class Gesture { None, Orbit, Pan, Grab };
  Gesture gesture_ = Gesture::None;
  int button_ = -1;                      // the button that began the gesture
  bool shift_ = false;                   // a Shift key is down
  bool havePointer_ = false;             // a move has been seen (the pointer is in the window)
  float x_ = 0, y_ = 0;                  // the pointer
  float pressX_ = 0, pressY_ = 0;        // where the gesture began
};

}  // namespace corbel::editor
