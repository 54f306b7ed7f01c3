#include "core/history.h"

namespace corbel {

History::History(Document initial, std::size_t capacity) : capacity_(capacity < 2 ? 2 : capacity) {
  reset(std::move(initial));
}

void History::reset(Document doc) {
  states_.clear();
  states_.push_back({std::move(doc), "", nextId_++});
  index_ = 0;
  savedId_ = states_[0].id;
  mergeKey_.clear();
}

void History::commit(Document next, std::string label, std::string mergeKey) {
  if (next == current()) return;  // nothing changed: no undo step
  states_.resize(index_ + 1);     // drop the redo branch
  const bool merge = !mergeKey.empty() && mergeKey == mergeKey_ && index_ > 0;
  if (merge) {
    states_[index_].doc = std::move(next);
    states_[index_].id = nextId_++;
  } else {
    states_.push_back({std::move(next), std::move(label), nextId_++});
    ++index_;
    if (states_.size() > capacity_) {
      states_.erase(states_.begin());
      --index_;
    }
  }
  mergeKey_ = std::move(mergeKey);
}

bool History::undo() {
  mergeKey_.clear();
  if (!canUndo()) return false;
  --index_;
  return true;
}

bool History::redo() {
  mergeKey_.clear();
  if (!canRedo()) return false;
  ++index_;
  return true;
}

const std::string& History::undoLabel() const {
  static const std::string none;
  return canUndo() ? states_[index_].label : none;
}

const std::string& History::redoLabel() const {
  static const std::string none;
  return canRedo() ? states_[index_ + 1].label : none;
}

}  // namespace corbel
