#pragma once
// The Town panel of a selected town object (Kelly & Wonka Sec. 3.7, Fig. 2), right of the 3D
// view: the footprint file (GeoJSON, through the file dialog), the style (one of
// assets/styles/*.json or any style file), the seed and the detail; the town builds as the
// object's Scene build off the UI thread (core/live_sync.h, city/kernel.h) with a progress bar
// and Cancel. Its buildings are listed by footprint id; one is picked from the list or by a
// click in the 3D view, and its type, its profiles per edge orientation or the profile of one
// edge (picked in a plan view of its footprint) are overridden as a Document edit (editor/town_edits.h), so it is
// undoable and only that building is re-extruded.
#include "city/kernel.h"
#include "core/document.h"
#include "render/overlay.h"

#include <functional>
#include <string>
#include <vector>

namespace corbel::editor {

struct TownHost {
  const Document* doc = nullptr;
  ObjectId object = 0;
  const city::TownCache* cache = nullptr;
  bool building = false;         // the Scene is being rebuilt
  bool current = true;           // the Scene shows the current document
  double fraction = 0;           // of that build
  std::string error;             // the kernel's message for the object ("" = fine)
  std::string stylesFolder;      // assets/styles
  std::function<void()> cancel;  // stops the running build (what it extruded stays cached)
  std::function<void()> retry;   // builds a cancelled state again
  bool cancelled = false;        // the current state's build was cancelled
  // The editor's file dialog: title, extensions, start path, what to do with the choice.
  std::function<void(const std::string&, std::vector<std::string>, const std::string&,
                     std::function<void(const std::string&)>)>
      openFile;
  std::function<void(Document, const std::string& label, const std::string& mergeKey)> commit;
  std::function<void(const std::string&, bool)> log;
};

class TownPanel {
 public:
  void draw(const TownHost& host, float x, float y, float w, float h);
  // The selected building's outline in the 3D view.
  void drawOverlay(const TownHost& host, render::Overlay& overlay) const;
  // A click in the 3D view: selects the building under the ray, or, with "move on click", moves
  // the selected street point to where the ray meets the ground.
  void pick(const TownHost& host, const Vec3& origin, const Vec3& dir);
  void reset() {
    selected_.clear();
    street_ = point_ = -1;
    moveOnClick_ = false;
  }

  // Also the actions town.next (select the next building) and town.next_type (override the
  // selected building's type with the style's next type).
  void selectNext(const TownHost& host);
  void overrideNextType(const TownHost& host);
  // Also the actions town.next_edge (pick the selected building's next edge in the plan view)
  // and town.next_edge_profile (give the picked edge the style's next profile, an override of
  // that one edge).
  void selectNextEdge(const TownHost& host);
  void overrideNextEdgeProfile(const TownHost& host);
  // The picked edge (loop, edge) of the selected building, or (-1, -1).
  std::pair<int, int> pickedEdge() const { return edge_; }
  // Also the actions town.add_street (a street along the town's south side, selected) and
  // town.bend_street (the selected street's middle point 10 m further south).
  void addStreet(const TownHost& host);
  void bendStreet(const TownHost& host);

 private:
  void commitOverride(const TownHost& host, const TownOverride& o, const std::string& what);
  void drawStreets(const TownHost& host, const TownSpec& spec);
  void drawEdges(const TownHost& host, const TownSpec& spec, const TownOverride& over);
  bool commitStreets(const TownHost& host, const std::function<void(Document&)>& edit, const std::string& what,
                     const std::string& merge = {});
  std::string selected_;  // footprint id
  std::string edgeOf_;    // the building edge_ belongs to
  std::pair<int, int> edge_{-1, -1};
  bool scrollToSelected_ = false;
  int street_ = -1, point_ = -1;  // the selected street and control point
  bool moveOnClick_ = false;      // a click in the 3D view moves the selected point there
  bool openStreets_ = false;      // open the Streets header on the next frame
};

}  // namespace corbel::editor
