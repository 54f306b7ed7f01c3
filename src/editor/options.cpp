#include "editor/options.h"

#include <map>
#include <sstream>

namespace corbel::editor {

void declareEditorOptions(CLI::App& app, EditorOptions& o) {
  app.name("corbel");
  app.description("corbel: the interactive building modeler (docs/user-guide.md).");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  addVersionFlag(app, "corbel");
  app.add_option("PROJECT", o.project, "The project to open (default: a new one).")->type_name("");
  addSize(app, "--size", o.window, 200, 8192, "The window's size.");
  app.add_option("--screenshot", o.screenshot,
                 "Save the window to a PNG after --quit-after-frames frames (default 10), then quit.")
      ->type_name("OUT.png");
  app.add_option("--quit-after-frames", o.quitAfterFrames, "Quit after N frames (tests and scripted runs).")
      ->check(wholeIn(1, 1000000000))
      ->type_name("N");
  app.add_option_function<std::string>(
         "--actions",
         [&o](const std::string& list) {
           std::stringstream ss(list);
           o.actions.clear();
           for (std::string id; std::getline(ss, id, ',');)
             if (!id.empty()) o.actions.push_back(id);
         },
         "Run these actions one per frame at start (their ids: Help > Keyboard Shortcuts).")
      ->type_name("ID,ID,...");
  app.add_option("--script", o.script, "Run an edit script: JSON lines, one edit per frame (docs/user-guide.md).")
      ->type_name("FILE");
  app.add_option("--script-shots", o.scriptShots, "With --script: save a screenshot to DIR after each stage.")
      ->type_name("DIR");
  app.add_option("--autosave-seconds", o.autosaveSeconds, "The autosave interval while there are unsaved changes (0: after every change).")
      ->check(numberIn(0, 1e9))
      ->type_name("S")
      ->default_str("60");
  static const std::map<std::string, EditorOptions::Recover> recover = {
      {"ask", EditorOptions::Recover::Ask}, {"yes", EditorOptions::Recover::Yes}, {"no", EditorOptions::Recover::No}};
  app.add_option_function<std::string>(
         "--recover", [&o](const std::string& word) { o.recover = recover.at(word); },
         "Unsaved work of editors that are gone: ask (list it), yes (recover the newest), no (discard it).")
      ->check(oneOf({"ask", "yes", "no"}))
      ->type_name("ask|yes|no")
      ->default_str("ask");
  app.add_option("--state-dir", o.stateDir,
                 "Where recovery and recent files live (default $XDG_STATE_HOME/corbel; also CORBEL_STATE_DIR).")
      ->type_name("DIR");
  app.add_option("--select", o.select, "Select the object called NAME (its panel opens).")->type_name("NAME");
  app.add_option("--test-log", o.testLog,
                 "Write a JSON line for each settled frame: the selection, the camera, the last action (for tests).")
      ->type_name("FILE");
  app.add_option("--latency-log", o.latencyLog,
                 "Write a line for each frame that first shows a change made by input: the milliseconds from "
                 "the event to that frame (benchmarks).")
      ->type_name("FILE");
  app.add_option("--frame-delay", o.frameDelayMs, "Sleep MS milliseconds in every frame, as a slow machine would (tests).")
      ->check(wholeIn(0, 10000))
      ->type_name("MS");
}

}  // namespace corbel::editor
