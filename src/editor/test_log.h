#pragma once
// The editor's test log (--test-log FILE): one JSON line for each settled frame (no build,
// job, animation or queued input left) whose state differs from the line before, so a test
// that drives the real window waits for the line it expects instead of sleeping. No GL.
#include "render/camera.h"

#include <cstddef>
#include <array>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace corbel::editor {

struct SettledFrame {
  int frame = 0;
  std::vector<std::string> selection;  // the selected objects' names, the active one last
  std::string active;                  // "" = none
  std::string hover;                   // the object under the pointer in the 3D view ("" = none)
  render::OrbitCamera camera;
  std::string lastAction;              // the id of the last action run ("" = none yet)
  std::size_t actionsRun = 0;          // how many actions have run, by any means
  std::size_t objects = 0;             // in the document
  bool dirty = false;                  // unsaved changes
  std::string undo;                    // the label of the step Undo would revert ("" = none)
  // Where the plan pane shows the active extrusion's corners (window pixels, per loop), for a
  // test to click; empty when no plan pane is open.
  std::vector<std::vector<std::array<float, 2>>> planCorners;
  // Where the profile pane shows the shown profile's points (window pixels); empty without it.
  std::vector<std::array<float, 2>> profilePoints;
  std::string profile;  // the name of the profile the profile pane shows ("" without it)
  std::vector<std::array<int, 2>> planEdges;  // the plan pane's selected edges: (loop, edge)
  // The 3D view's rectangle in window pixels: x, y (top left), width, height.
  std::array<float, 4> view{};
  std::vector<std::string> failed;  // the objects whose last build failed (flagged in the list)
  std::optional<bool> activeInView;   // the active object's bounds lie wholly in the 3D view
  std::optional<std::string> search;  // the command search's text while it is open
  // The tape measure's finished measurement: its ends, how each snapped, and its length.
  struct Tape {
    std::array<double, 3> from{}, to{};
    std::string fromSnap, toSnap;
    double length = 0;
  };
  std::optional<Tape> tape;
  // Named widgets drawn this frame (editor/widget_marks.h): x0, y0, x1, y1 in window pixels.
  std::map<std::string, std::array<float, 4>> widgets;
};

// The line for `s` (one JSON object, no newline).
std::string testLogLine(const SettledFrame& s);

class TestLog {
 public:
  // Opens (truncates) `path`; throws corbel::Error naming it when it cannot be written.
  explicit TestLog(const std::string& path);
  // Writes `s` unless everything but its frame number equals the last line's; flushed at once.
  void write(const SettledFrame& s);

 private:
  std::ofstream out_;
  std::string last_;  // the last line without its frame
};

}  // namespace corbel::editor
