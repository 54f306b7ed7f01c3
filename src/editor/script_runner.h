#pragma once
// Scripted runs of the editor: actions run one per frame (--actions), an edit script run one
// line per frame (--script, with a screenshot after each stage into --script-shots), a
// screenshot and quit after N frames (--screenshot, --quit-after-frames). The editor asks it
// each frame what to do; the doing (running an action, applying an edit, reading pixels) is
// the editor's, through a ScriptHost. No GL or ImGui.
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace corbel::editor {

struct ScriptOptions {
  std::vector<std::string> actions;  // action ids, one per frame from the third frame on
  std::string script;                // an edit script (JSON lines, extrude/edit.h)
  std::string scriptShots;           // a folder: a screenshot after each stage of the script
  std::string screenshot;            // written when the run quits after quitAfterFrames
  int quitAfterFrames = -1;          // > 0: quit after this many frames
};

struct ScriptHost {
  std::function<bool(const std::string& id)> trigger;  // false when unknown or disabled
  // Applies one line of the edit script as one undo step; returns the name of the object it
  // edited (to select it). Throws on a bad line.
  std::function<void(const nlohmann::json& edit)> edit;
  std::function<void(const std::string& line, bool error)> log;
  std::function<void()> reframe;  // frame the view on the new state before a stage's screenshot
};

class ScriptRunner {
 public:
  // Reads the edit script; one that cannot be read fails the run (problem() says why).
  explicit ScriptRunner(ScriptOptions options);
  const std::string& problem() const { return problem_; }

  // Anything scripted at all: such runs wait for every build, so each frame shows its state.
  bool scripted() const;
  // Nothing left to run: no action, script line or stage screenshot pending.
  bool idle() const;
  // At the start of frame `frame`: runs the next action, or the next script line.
  void startFrame(int frame, ScriptHost& host);
  // A stage's screenshot due at `frame` (its path), once; then shotDone().
  std::optional<std::string> dueShot(int frame) const;
  void shotDone(bool ok);
  // After frame `frame` has been drawn: the run should quit now.
  bool quitAfter(int frame) const { return options_.quitAfterFrames > 0 && frame >= options_.quitAfterFrames; }
  const std::string& finalScreenshot() const { return options_.screenshot; }
  // At exit: an error text when the edit script did not complete, else "".
  std::string incomplete() const;

 private:
  void runScriptLine(int frame, ScriptHost& host);
  ScriptOptions options_;
  std::size_t nextAction_ = 0;
  std::vector<std::string> lines_;
  std::size_t nextLine_ = 0;
  int shotAtFrame_ = -1;
  std::string shotPath_;
  int shots_ = 0;
  bool failed_ = false;
  std::string problem_;
};

}  // namespace corbel::editor
