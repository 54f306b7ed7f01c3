#pragma once
// The KIFS panel of a selected KIFS building (McGraw, Sec. 4), right of the 3D view: a preset
// picker, a View (shaded, facade ids, floors, the bare fractal), the parameters of Sec. 4 as
// sliders (13 rectilinear, 17 curvilinear, plus Eq. 4's storey offset and scale and Eq. 6's z0)
// and the advanced ones (M, s, R1, bailout, steps), and "Mesh to Scene". Every change is committed as
// a Document edit (editor/kifs_edits.h), so it is undoable, and the 3D view ray-marches the
// new parameters at once (render::KifsPass). Meshing runs as the object's Scene build, off
// the UI thread (core/live_sync.h), with a progress bar; Cancel (or dropping the mesh later)
// returns to ray marching, and the superseded build is cancelled.
#include "core/document.h"

#include <functional>
#include <string>
#include <vector>

namespace corbel::editor {

struct KifsHost {
  const Document* doc = nullptr;
  ObjectId object = 0;
  bool building = false;  // the Scene is being rebuilt (meshing)
  double fraction = 0;    // of that build
  std::string error;      // the kernel's message for the object ("" = fine)
  std::function<void(Document, const std::string& label, const std::string& mergeKey)> commit;
  std::function<void()> endDrag;
  std::function<void(const std::string&, bool)> log;
  // The ids of a town object's buildings as last built, in footprint order (null: none known).
  std::function<std::vector<std::string>(ObjectId town)> townBuildings;
};

// What the 3D view shows of the ray-marched KIFS buildings (render::KifsMode): shaded, their
// facade ids (Fig. 5-6), their storeys, or the fractal without the inner shell (Fig. 3c).
enum class KifsView { Shaded, Facades, Floors, Bare };
const char* kifsViewName(KifsView view);

class KifsPanel {
 public:
  void draw(const KifsHost& host, float x, float y, float w, float h);
  // The panel's View choice; it applies to every ray-marched KIFS building in the view.
  KifsView view() const { return view_; }

 private:
  int resolution_ = 128;  // for "Mesh to Scene"
  KifsView view_ = KifsView::Shaded;
};

}  // namespace corbel::editor
