#include "editor/input_queue.h"

#include <set>

namespace corbel::editor {

bool isModifierKey(int code) { return code >= kFirstModifierKey && code <= kLastModifierKey; }

InputBatch InputQueue::takeFrame() {
  InputBatch batch;
  std::set<int> keys, buttons;  // changed in this batch
  bool scrolled = false, keyPressed = false, moved = false;
  using T = InputEvent::Type;
  while (!queue_.empty()) {
    const InputEvent& e = queue_.front();
    bool stop = false;
    switch (e.type) {
      case T::Key:
        // A modifier after another key's change would be seen with that key: Ctrl let go
        // after Z would make Ctrl+Z a plain Z.
        stop = keys.count(e.code) || !buttons.empty() || (isModifierKey(e.code) && keyPressed);
        break;
      case T::Char:
        stop = !buttons.empty();
        break;
      case T::Button:
        // A release after moves waits for the next frame: a frame shows ImGui only where the
        // pointer ends, so a widget held by the button (a splitter, a slider) sees it moved
        // while still held, then let go.
        stop = buttons.count(e.code) || scrolled || (!e.down && moved);
        break;
      case T::Move:
      case T::Leave:
        stop = !buttons.empty() || scrolled;
        break;
      case T::Scroll:
        stop = !buttons.empty();
        break;
    }
    if (stop && !batch.empty()) break;
    if (e.type == T::Key) keys.insert(e.code), keyPressed = keyPressed || !isModifierKey(e.code);
    if (e.type == T::Button) buttons.insert(e.code);
    if (e.type == T::Scroll) scrolled = true;
    if (e.type == T::Move) moved = true;
    batch.events.push_back(e);
    queue_.pop_front();
  }
  return batch;
}

}  // namespace corbel::editor
