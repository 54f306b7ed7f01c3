// editor/input_queue.h: however slow the frames, every press and release reaches a frame of
// its own, in order, and nothing is lost or reordered.
#include "editor/input_queue.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace corbel::editor {
namespace {

using T = InputEvent::Type;
constexpr int kCtrl = 341, kZ = 90;  // GLFW_KEY_LEFT_CONTROL, GLFW_KEY_Z

InputEvent key(int code, bool down) { return {T::Key, code, down}; }
InputEvent button(int code, bool down) { return {T::Button, code, down}; }
InputEvent move(double x, double y) {
  InputEvent e{T::Move};
  e.x = x, e.y = y;
  return e;
}
InputEvent scroll(double steps) {
  InputEvent e{T::Scroll};
  e.y = steps;
  return e;
}

// What a frame-based UI (ImGui 1.86) sees: each key's and button's state at the end of each
// frame. A press is a frame that ends with it down after one that ended with it up.
struct FrameSeen {
  std::map<int, bool> keys, buttons;
  std::map<int, int> keyPresses, buttonPresses;
  int ctrlZ = 0;  // frames in which Z went down with Ctrl held
  void apply(const InputBatch& batch) {
    std::map<int, bool> keysBefore = keys, buttonsBefore = buttons;
    for (const InputEvent& e : batch.events) {
      if (e.type == T::Key) keys[e.code] = e.down;
      if (e.type == T::Button) buttons[e.code] = e.down;
    }
    for (const auto& [k, down] : keys)
      if (down && !keysBefore[k]) {
        ++keyPresses[k];
        if (k == kZ && keys[kCtrl]) ++ctrlZ;
      }
    for (const auto& [b, down] : buttons)
      if (down && !buttonsBefore[b]) ++buttonPresses[b];
  }
};

TEST(InputQueue, ThreeQuickCtrlZBetweenTwoFramesAreThreePresses) {
  InputQueue q;
  q.push(key(kCtrl, true));
  for (int i = 0; i < 3; ++i) q.push(key(kZ, true)), q.push(key(kZ, false));
  q.push(key(kCtrl, false));
  FrameSeen seen;
  int frames = 0;
  while (!q.empty()) seen.apply(q.takeFrame()), ++frames;
  EXPECT_EQ(seen.ctrlZ, 3);
  EXPECT_EQ(frames, 7);  // Ctrl and Z down; Z up, down, up, down, up; Ctrl up
}

// As xdotool types Ctrl+Z (Ctrl let go before Z), with the press of Ctrl in one frame and the
// rest in the next: Z is still seen with Ctrl held.
TEST(InputQueue, AKeyIsSeenWithTheModifiersItWasPressedWith) {
  InputQueue q;
  q.push(key(kCtrl, true));
  FrameSeen seen;
  seen.apply(q.takeFrame());
  for (const InputEvent& e : {key(kZ, true), key(kCtrl, false), key(kZ, false)}) q.push(e);
  while (!q.empty()) seen.apply(q.takeFrame());
  EXPECT_EQ(seen.ctrlZ, 1);
}

TEST(InputQueue, AClickIsSeenWhereItHappened) {
  InputQueue q;
  q.push(move(10, 20));
  q.push(button(0, true));
  q.push(move(30, 40));
  q.push(button(0, false));
  const InputBatch first = q.takeFrame();
  ASSERT_EQ(first.events.size(), 2u);  // the move to the press, and the press
  EXPECT_EQ(first.events[0].x, 10);
  EXPECT_TRUE(first.events[1].down);
  // The move after the press waits for the next frame, with the button still held (a widget
  // the press grabbed sees the pointer there), and the release comes in the frame after, where
  // the pointer was let go.
  const InputBatch second = q.takeFrame();
  ASSERT_EQ(second.events.size(), 1u);
  EXPECT_EQ(second.events[0].type, T::Move);
  EXPECT_EQ(second.events[0].x, 30);
  const InputBatch third = q.takeFrame();
  ASSERT_EQ(third.events.size(), 1u);
  EXPECT_FALSE(third.events[0].down);
  EXPECT_TRUE(q.empty());
}

TEST(InputQueue, TheWheelZoomsAtThePointerItWasTurnedAt) {
  InputQueue q;
  q.push(move(5, 5));
  q.push(scroll(1));
  q.push(move(500, 5));
  q.push(scroll(2));
  const InputBatch first = q.takeFrame();
  ASSERT_EQ(first.events.size(), 2u);
  EXPECT_EQ(first.events[1].type, T::Scroll);
  const InputBatch second = q.takeFrame();
  ASSERT_EQ(second.events.size(), 2u);
  EXPECT_EQ(second.events[0].x, 500);
}

TEST(InputQueue, TextAndMovesWithoutButtonsPassInOneFrame) {
  InputQueue q;
  for (int i = 0; i < 5; ++i) q.push(move(i, i));
  for (unsigned c : {'a', 'b', 'c'}) {
    InputEvent e{T::Char};
    e.codepoint = c;
    q.push(e);
  }
  EXPECT_EQ(q.takeFrame().events.size(), 8u);
  EXPECT_TRUE(q.empty());
}

// Random streams from several keys and buttons, with moves, scrolls and text between them:
// the batches, one after another, are the stream itself; no batch changes a key or button
// twice; and a frame-based reader counts exactly as many presses as were pushed.
TEST(InputQueue, RandomStreamsLoseAndReorderNothing) {
  std::mt19937 rng(20261204);
  for (int round = 0; round < 300; ++round) {
    InputQueue q;
    std::vector<InputEvent> pushed;
    std::map<int, bool> keyDown, buttonDown;
    std::map<int, int> keyPresses, buttonPresses;
    const int n = std::uniform_int_distribution<int>(1, 60)(rng);
    for (int i = 0; i < n; ++i) {
      InputEvent e;
      switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
        case 0: {
          const int pickKey = std::uniform_int_distribution<int>(0, 4)(rng);
          const int k = pickKey == 4 ? kCtrl : 65 + pickKey;
          e = key(k, !keyDown[k]);
          keyDown[k] = e.down;
          keyPresses[k] += e.down;
          break;
        }
        case 1: {
          const int b = std::uniform_int_distribution<int>(0, 2)(rng);
          e = button(b, !buttonDown[b]);
          buttonDown[b] = e.down;
          buttonPresses[b] += e.down;
          break;
        }
        case 2:
          e = move(i, 2 * i);
          break;
        case 3:
          e = scroll(1);
          break;
        default:
          e = InputEvent{T::Char};
          e.codepoint = 'x';
      }
      e.time = i;
      q.push(e);
      pushed.push_back(e);
    }
    FrameSeen seen;
    std::vector<InputEvent> taken;
    while (!q.empty()) {
      const InputBatch b = q.takeFrame();
      ASSERT_FALSE(b.empty());
      // No modifier changes after another key's change in one frame.
      bool otherKey = false;
      for (const InputEvent& e : b.events) {
        if (e.type != T::Key) continue;
        EXPECT_FALSE(isModifierKey(e.code) && otherKey);
        otherKey = otherKey || !isModifierKey(e.code);
      }
      std::map<int, int> keyChanges, buttonChanges;
      for (const InputEvent& e : b.events) {
        if (e.type == T::Key) {
          EXPECT_EQ(++keyChanges[e.code], 1);
        }
        if (e.type == T::Button) {
          EXPECT_EQ(++buttonChanges[e.code], 1);
        }
        taken.push_back(e);
      }
      seen.apply(b);
    }
    ASSERT_EQ(taken.size(), pushed.size());
    for (std::size_t i = 0; i < taken.size(); ++i) EXPECT_EQ(taken[i].time, pushed[i].time);
    for (const auto& [k, presses] : keyPresses) EXPECT_EQ(seen.keyPresses[k], presses) << "key " << k;
    for (const auto& [b, presses] : buttonPresses) EXPECT_EQ(seen.buttonPresses[b], presses) << "button " << b;
  }
}

}  // namespace
}  // namespace corbel::editor
