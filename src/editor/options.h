#pragma once
// The editor's command line: what `corbel` is asked to open and do at start, and its CLI11
// declaration. GL-free, so docs/cli.md's generator and the tests can link it.
#include "core/command_line.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace corbel::editor {

struct EditorOptions {
  std::string project;               // opened at start ("" = a new document)
  Size window{1440, 900};            // the window's size in screen pixels
  std::string screenshot;            // write the window to this PNG, then quit
  int quitAfterFrames = -1;          // quit after this many frames (> 0)
  std::vector<std::string> actions;  // action ids run one per frame at start (scripted use)
  std::string script;                // an edit script (JSON lines, extrude/edit.h) run one line per frame
  std::string scriptShots;           // a folder: a screenshot after each stage of the script
  double autosaveSeconds = 60.0;
  enum class Recover { Ask, Yes, No } recover = Recover::Ask;
  std::string stateDir;  // recovery and recent files ("" = defaultStateDir())
  std::string select;    // select the object of this name at start
  std::string testLog;   // write a line per settled frame here (editor/test_log.h)
  std::string latencyLog;  // write a line per frame that shows an input's change (editor/latency.h)
  int frameDelayMs = 0;  // sleep this long in every frame, as a slow machine would (for tests)
};

// `corbel` on `app`: its name, description, --version, every option and the PROJECT positional,
// written into `options` by the parse.
void declareEditorOptions(CLI::App& app, EditorOptions& options);

}  // namespace corbel::editor
