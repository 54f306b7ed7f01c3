#include "editor/selection.h"

#include <algorithm>

namespace corbel::editor {

bool Selection::contains(ObjectId id) const { return std::find(ids_.begin(), ids_.end(), id) != ids_.end(); }

void Selection::select(ObjectId id) {
  ids_ = {id};
  active_ = id;
}

void Selection::add(ObjectId id) {
  if (!contains(id)) ids_.push_back(id);
  active_ = id;
}

void Selection::toggle(ObjectId id) {
  if (!contains(id)) return add(id);
  std::erase(ids_, id);
  active_ = ids_.empty() ? std::nullopt : std::optional<ObjectId>(ids_.back());
}

void Selection::clear() {
  ids_.clear();
  active_.reset();
}

void Selection::prune(const Document& doc) {
  std::erase_if(ids_, [&](ObjectId id) { return doc.find(id) == nullptr; });
  if (active_ && !contains(*active_)) active_ = ids_.empty() ? std::nullopt : std::optional<ObjectId>(ids_.back());
  if (hover && !doc.find(*hover)) hover.reset();
}

}  // namespace corbel::editor
