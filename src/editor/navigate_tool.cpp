#include "editor/navigate_tool.h"

#include "editor/camera_views.h"

#include <cmath>

namespace corbel::editor {

namespace {
// GLFW's codes of the two Shift keys and of the mouse buttons (the events carry GLFW's codes).
constexpr int kLeftShift = 340, kRightShift = 344, kLeftControl = 341, kRightControl = 345;
constexpr int kLeft = 0, kRight = 1, kMiddle = 2;
}  // namespace

void NavigateTool::handle(const InputEvent& e, bool overUi, ToolContext& c) {
  using T = InputEvent::Type;
  Viewport& view = *c.viewport;
  switch (e.type) {
    case T::Key:
      if (e.code == kLeftShift || e.code == kRightShift) shift_ = e.down;
      if (e.code == kLeftControl || e.code == kRightControl) ctrl_ = e.down;
      break;
    case T::Move: {
      const float dx = havePointer_ ? float(e.x) - x_ : 0.0f, dy = havePointer_ ? float(e.y) - y_ : 0.0f;
      x_ = float(e.x), y_ = float(e.y);
      havePointer_ = true;
      if (gesture_ == Gesture::Orbit) view.camera.orbit(dx, dy);
      if (gesture_ == Gesture::Pan) view.camera.pan(dx, dy, int(view.height()));
      if (gesture_ == Gesture::Grab && c.dragTo) c.dragTo(view.ray(x_, y_));
      break;
    }
    case T::Leave:
      if (gesture_ == Gesture::None) havePointer_ = false;
      break;
    case T::Scroll:
      // Towards the pointer: the point under it stays under it.
      if (gesture_ == Gesture::None && havePointer_ && !overUi && view.contains(x_, y_))
        zoomTowards(view.camera, 2.0 * (x_ - view.x()) / view.width() - 1.0, 1.0 - 2.0 * (y_ - view.y()) / view.height(),
                    view.aspect(), e.y);
      break;
    case T::Button:
      if (e.down) {
        if (gesture_ != Gesture::None || !havePointer_ || overUi || !view.contains(x_, y_)) break;
        if (e.code != kLeft && e.code != kRight && e.code != kMiddle) break;
        button_ = e.code;
        pressX_ = x_, pressY_ = y_;
        if (e.code == kLeft && (ctrl_ || boxArmed_))
          gesture_ = Gesture::Box;
        else if (e.code == kLeft && !shift_)
          gesture_ = c.grab && c.grab(view.ray(x_, y_)) ? Gesture::Grab : Gesture::Orbit;
        else
          gesture_ = Gesture::Pan;
      } else if (e.code == button_) {
        const Gesture ended = gesture_;
        gesture_ = Gesture::None;
        button_ = -1;
        if (ended == Gesture::Grab && c.release) c.release();
        if (ended == Gesture::Box) {
          boxArmed_ = false;
          // A box too small to be one is a click (Ctrl+click toggles).
          if (std::hypot(x_ - pressX_, y_ - pressY_) < kClickSlop) {
            if (c.click) c.click(view.ray(x_, y_));
          } else if (c.boxSelect) {
            c.boxSelect(pressX_, pressY_, x_, y_);
          }
        }
        if (ended == Gesture::Orbit && std::hypot(x_ - pressX_, y_ - pressY_) < kClickSlop && c.click)
          c.click(view.ray(x_, y_));
      }
      break;
    case T::Char:
      break;
  }
}

}  // namespace corbel::editor
