#pragma once
// What the user has selected: a set of objects, one of them active (the one whose panels
// show), and the object under the pointer. Plain ids, so edits and undo leave it consistent
// through prune(). No GL or ImGui.
#include "core/document.h"

#include <optional>
#include <vector>

namespace corbel::editor {

class Selection {
 public:
  // The active object: the one the panels and single-object commands work on.
  std::optional<ObjectId> active() const { return active_; }
  const std::vector<ObjectId>& ids() const { return ids_; }
  bool contains(ObjectId id) const;
  bool empty() const { return ids_.empty(); }

  void select(ObjectId id);  // this object alone, active
  void add(ObjectId id);     // this object too, and active
  void toggle(ObjectId id);  // in or out; the last one left in is active
  void clear();
  // Drops the objects `doc` no longer has (an undo, a delete).
  void prune(const Document& doc);

  // The object under the pointer in the 3D view, if any.
  std::optional<ObjectId> hover;

 private:
  std::vector<ObjectId> ids_;
  std::optional<ObjectId> active_;
};

}  // namespace corbel::editor
