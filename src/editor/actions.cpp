#include "editor/actions.h"

#include <GLFW/glfw3.h>

#include <stdexcept>

namespace corbel::editor {

std::string Shortcut::text() const {
  if (!key) return {};
  std::string s;
  if (ctrl) s += "Ctrl+";
  if (shift) s += "Shift+";
  if (alt) s += "Alt+";
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return s + char('A' + (key - GLFW_KEY_A));
  if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return s + char('0' + (key - GLFW_KEY_0));
  if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12) return s + "F" + std::to_string(key - GLFW_KEY_F1 + 1);
  switch (key) {
    case GLFW_KEY_DELETE:
      return s + "Delete";
    case GLFW_KEY_HOME:
      return s + "Home";
    case GLFW_KEY_KP_1:
      return s + "Num1";
    case GLFW_KEY_KP_3:
      return s + "Num3";
    case GLFW_KEY_KP_5:
      return s + "Num5";
    case GLFW_KEY_ESCAPE:
      return s + "Esc";
    case GLFW_KEY_EQUAL:
      return s + "=";
    case GLFW_KEY_MINUS:
      return s + "-";
    case GLFW_KEY_KP_7:
      return s + "Num7";
    default:
      return s + "Key" + std::to_string(key);
  }
}

Action& ActionRegistry::add(Action action) {
  for (const Action& a : actions_) {
    if (a.id == action.id) throw std::logic_error("duplicate action id " + action.id);
    if (action.shortcut.key && a.shortcut.key == action.shortcut.key && a.shortcut.ctrl == action.shortcut.ctrl &&
        a.shortcut.shift == action.shortcut.shift && a.shortcut.alt == action.shortcut.alt)
      throw std::logic_error("shortcut " + action.shortcut.text() + " of " + action.id + " is taken by " + a.id);
  }
  actions_.push_back(std::move(action));
  return actions_.back();
}

const Action* ActionRegistry::find(const std::string& id) const {
  for (const Action& a : actions_)
    if (a.id == id) return &a;
  return nullptr;
}

bool ActionRegistry::run(const Action& a) {
  if (!isEnabled(a) || !a.run) return false;
  lastRun_ = a.id;
  ++runCount_;
  a.run();
  return true;
}

bool ActionRegistry::trigger(const std::string& id) {
  const Action* a = find(id);
  return a && run(*a);
}

const Action* ActionRegistry::match(int key, bool ctrl, bool shift, bool alt) const {
  for (const Action& a : actions_)
    if (a.shortcut.key == key && a.shortcut.ctrl == ctrl && a.shortcut.shift == shift && a.shortcut.alt == alt)
      return &a;
  return nullptr;
}

}  // namespace corbel::editor
