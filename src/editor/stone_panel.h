#pragma once
// "Build in stone" in the left panel of a selected extrusion (editor/stone_edits.h): the
// masonry section on or off, its settings (wall thickness, course height, block length, the
// roof's covering weight, tie beams, wind), the walls analysed as coursed blocks carrying the
// roof whenever the extrusion changes (on a worker thread), the two verdicts, and Make It Stand
// (the wall thickness searched; one undo step). The 3D view shows the blocks coloured by their
// share of tension while "Show blocks" is ticked, and the forces as arrows when asked.
#include "editor/statics_panel.h"

#include <memory>
#include <optional>

namespace corbel::editor {

class StonePanel {
 public:
  StonePanel() = default;
  ~StonePanel();
  StonePanel(const StonePanel&) = delete;
  StonePanel& operator=(const StonePanel&) = delete;

  // Once per frame while an extrusion is selected: collects finished work (a finished search is
  // applied as one undo step) and starts the analysis of a changed section.
  void update(const StaticsHost& host);
  // The section, in the current ImGui window.
  void draw(const StaticsHost& host);
  // The blocks and forces of the analysis, in the extrusion's frame, when it is of `spec`.
  void drawOverlay(render::Overlay& overlay, render::Overlay& onTop, const ExtrusionSpec& spec) const;
  void makeItStand(const StaticsHost& host);
  bool searching() const { return search_ != nullptr; }
  void reset();  // another object was selected

 private:
  struct Analysis {
    ExtrusionSpec spec;
    MasonryView view;
  };
  void finishSearch(const StaticsHost& host);
  std::unique_ptr<BackgroundJob> analysis_, search_;
  std::shared_ptr<Analysis> analysing_;
  std::optional<Analysis> shown_;
  std::shared_ptr<statics::SearchResult> searchResult_;
  ExtrusionSpec searchStart_;
  ObjectId searchObject_ = 0;
  std::vector<ParameterChange> lastChanges_;
  bool showBlocks_ = true;
  bool addButtresses_ = false;  // Make It Stand may add buttress steps (frees their depth)
  bool showForces_ = false;  // hundreds of joints: the arrows hide the walls until asked for
};

}  // namespace corbel::editor
