#pragma once
// The editor's input as a queue of events. The window's callbacks push every key, character,
// mouse button, cursor move and scroll with its time; each frame takes the events it can
// show without merging two changes of one key or button, and leaves the rest for the next
// frame. A tap (press and release between two frames) is thus seen as a press in one frame
// and a release in the next, however slow the frames are: none is lost.
// No GLFW or ImGui here (editor/glfw_input.h feeds both from it), so tests drive it directly.
#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace corbel::editor {

struct InputEvent {
  enum class Type { Key, Char, Button, Move, Scroll, Leave };
  Type type = Type::Move;
  int code = 0;          // Key: the GLFW key code; Button: 0 left, 1 right, 2 middle, ...
  bool down = false;     // Key, Button: pressed (true) or released
  unsigned codepoint = 0;  // Char: the Unicode code point typed
  double x = 0, y = 0;   // Move: the cursor in window pixels; Scroll: the wheel's steps
  double time = 0;       // seconds, on the clock the window's callbacks read
};

// One frame's share of the queue.
struct InputBatch {
  std::vector<InputEvent> events;  // in the order they happened
  bool empty() const { return events.empty(); }
};

// GLFW's codes of Shift, Control, Alt and Super, left and right.
inline constexpr int kFirstModifierKey = 340, kLastModifierKey = 347;
bool isModifierKey(int code);

class InputQueue {
 public:
  void push(const InputEvent& e) { queue_.push_back(e); }
  bool empty() const { return queue_.empty(); }
  std::size_t size() const { return queue_.size(); }
  // The events this frame shows, taken from the front of the queue. It stops before an event
  // that would hide one already taken: a second change of the same key or button; a change of
  // a modifier (Ctrl, Shift, Alt, Super) after another key's change (a key is seen with the
  // modifiers it was pressed with); a key, character, move or scroll after a button change (a
  // press is seen where and with what keys it happened); a move after a scroll (the wheel
  // zooms at the pointer it was turned at); a button change after a scroll. The first event is
  // always taken, so the queue drains.
  InputBatch takeFrame();

 private:
  std::deque<InputEvent> queue_;
};

}  // namespace corbel::editor
