#pragma once
// The action registry: every user command is declared once (id, menu, label, help, shortcut,
// whether it changes the Document) and menus, shortcuts, the help panel and scripted runs
// (--actions) are all built from it.
#include <functional>
#include <string>
#include <vector>

namespace corbel::editor {

struct Shortcut {
  int key = 0;  // GLFW key code, 0 = none
  bool ctrl = false;
  bool shift = false;
  bool alt = false;
  std::string text() const;  // "Ctrl+Shift+Z"
};

struct Action {
  std::string id;     // "edit.undo": stable, used by scripts and tests
  std::string menu;   // top-level menu it appears in ("" = none)
  std::string label;  // "Undo"
  std::string help;   // one sentence for tooltips and the help panel
  Shortcut shortcut;
  bool undoable = false;  // it changes the Document (and makes an undo step)
  std::function<void()> run;
  std::function<bool()> enabled;  // null = always
  std::function<bool()> checked;  // non-null = a toggle shown with a check mark
  bool separatorBefore = false;
};

class ActionRegistry {
 public:
  // Throws std::logic_error for a duplicate id or shortcut (a programming error).
  Action& add(Action action);
  const Action* find(const std::string& id) const;
  const std::vector<Action>& all() const { return actions_; }
  bool isEnabled(const Action& a) const { return !a.enabled || a.enabled(); }
  // Runs the action if it is enabled; returns whether it ran. Every way of running an action
  // (menu, shortcut, script) comes here, so the last one run and the count are known.
  bool run(const Action& a);
  // Runs the action if it exists and is enabled; returns whether it ran.
  bool trigger(const std::string& id);
  const std::string& lastRun() const { return lastRun_; }
  std::size_t runCount() const { return runCount_; }
  // The action bound to a key press, or nullptr.
  const Action* match(int key, bool ctrl, bool shift, bool alt) const;

 private:
  std::vector<Action> actions_;
  std::string lastRun_;
  std::size_t runCount_ = 0;
};

}  // namespace corbel::editor
